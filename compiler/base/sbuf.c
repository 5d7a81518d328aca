/* sbuf.c: the one growable text buffer (GLSL printer, IR and AST dumps, diagnostics,
 * preprocessed text). */
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/sbuf.h"
#include "base/arena.h"

/* A bigger block for the text: realloc, or a new arena block holding the old text. */
static char *grow_text(sbuf *b, size_t cap) {
    if (!b->arena) return realloc(b->d, cap);
    char *d = hfx_arena_alloc_raw(b->arena, cap);
    if (d && b->len) memcpy(d, b->d, b->len + 1);
    return d;
}

/* Room for n more bytes and the NUL; false (and oom) when it cannot be had. */
static bool reserve(sbuf *b, size_t n) {
    if (b->oom) return false;
    if (b->len + n + 1 <= b->cap) return true;
    size_t cap = b->cap ? b->cap : 256;
    while (cap < b->len + n + 1) cap *= 2;
    char *d = grow_text(b, cap);
    if (!d) { b->oom = true; return false; }
    b->d = d;
    b->cap = cap;
    return true;
}

void hfx_sb_putn(sbuf *b, const char *s, size_t n) {
    if (!reserve(b, n)) return;
    memcpy(b->d + b->len, s, n);
    b->len += n;
    b->d[b->len] = 0;
}

void hfx_sb_put(sbuf *b, const char *s) { hfx_sb_putn(b, s, strlen(s)); }

/* One conversion of a format: %[flags][width][.precision][length]conv. */
typedef struct fmt_spec {
    const char *start; /* the '%' */
    size_t len;        /* through the conversion character */
    int stars;         /* '*' widths / precisions taken from the arguments */
    int length;        /* 0 none, 'h', 'l', 'L' (long long), 'z', 'j', 't', 'q' (long double) */
    bool plain;        /* no flags, width or precision */
    bool star_precision_only;
    char conv;
} fmt_spec;

static const char *parse_length(const char *p, int *length) {
    switch (*p) {
    case 'h': *length = 'h'; return p[1] == 'h' ? p + 2 : p + 1;
    case 'l': *length = p[1] == 'l' ? 'L' : 'l'; return p[1] == 'l' ? p + 2 : p + 1;
    case 'z': case 'j': case 't': *length = *p; return p + 1;
    case 'L': *length = 'q'; return p + 1;
    default: *length = 0; return p;
    }
}

static fmt_spec parse_spec(const char *p) {
    fmt_spec s = {.start = p};
    const char *q = p + 1;
    while (*q == '-' || *q == '+' || *q == ' ' || *q == '#' || *q == '0') q++;
    while ((*q >= '0' && *q <= '9') || *q == '*') s.stars += *q++ == '*';
    bool width = q != p + 1;
    if (*q == '.') {
        q++;
        s.star_precision_only = !width && *q == '*';
        while ((*q >= '0' && *q <= '9') || *q == '*') s.stars += *q++ == '*';
    }
    s.plain = q == p + 1;
    q = parse_length(q, &s.length);
    s.conv = *q;
    s.len = (size_t)(q - p) + (*q != 0);
    return s;
}

static void put_unsigned(sbuf *b, unsigned long long v, bool negative) {
    char buf[24];
    char *e = buf + sizeof buf, *p = e;
    do *--p = (char)('0' + v % 10); while ((v /= 10) != 0);
    if (negative) *--p = '-';
    hfx_sb_putn(b, p, (size_t)(e - p));
}

static long long signed_arg(int length, va_list *ap) {
    switch (length) {
    case 'l': return va_arg(*ap, long);
    case 'L': return va_arg(*ap, long long);
    case 'z': case 't': return (long long)va_arg(*ap, ptrdiff_t);
    case 'j': return (long long)va_arg(*ap, intmax_t);
    default: return va_arg(*ap, int);
    }
}

static unsigned long long unsigned_arg(int length, va_list *ap) {
    switch (length) {
    case 'l': return va_arg(*ap, unsigned long);
    case 'L': return va_arg(*ap, unsigned long long);
    case 'z': case 't': return va_arg(*ap, size_t);
    case 'j': return (unsigned long long)va_arg(*ap, uintmax_t);
    default: return va_arg(*ap, unsigned);
    }
}

/* The conversions the printers use most, written directly: vsnprintf's stream set-up cost a
 * third of a whole compile when the GLSL printer went through it. */
static bool put_plain(sbuf *b, const fmt_spec *s, va_list *ap) {
    switch (s->conv) {
    case 's': { const char *str = va_arg(*ap, const char *); hfx_sb_put(b, str ? str : "(null)"); return true; }
    case 'd': case 'i': {
        long long v = signed_arg(s->length, ap);
        put_unsigned(b, v < 0 ? 0ull - (unsigned long long)v : (unsigned long long)v, v < 0);
        return true;
    }
    case 'u': put_unsigned(b, unsigned_arg(s->length, ap), false); return true;
    case 'c': { char c = (char)va_arg(*ap, int); hfx_sb_putn(b, &c, 1); return true; }
    case '%': hfx_sb_putn(b, "%", 1); return true;
    default: return false;
    }
}

/* snprintf of one conversion with its '*' values and its one argument; `out` has `size` bytes. */
#define HFX_FMT_ONE(out, size, s, spec, star, arg) \
    ((s)->stars == 0   ? snprintf(out, size, spec, arg) \
     : (s)->stars == 1 ? snprintf(out, size, spec, (star)[0], arg) \
                       : snprintf(out, size, spec, (star)[0], (star)[1], arg))

/* Appends what HFX_FMT_ONE gives: through a line buffer, or straight into the text when longer
 * (no malloc of its own: an arena buffer's allocation failure may longjmp; base/arena.h). */
#define HFX_FMT_PUT(b, s, spec, star, arg) \
    do { \
        char small_[256]; \
        int n_ = HFX_FMT_ONE(small_, sizeof small_, s, spec, star, arg); \
        if (n_ < 0) break; \
        if ((size_t)n_ < sizeof small_) { hfx_sb_putn(b, small_, (size_t)n_); break; } \
        if (!reserve(b, (size_t)n_)) break; \
        HFX_FMT_ONE((b)->d + (b)->len, (size_t)n_ + 1, s, spec, star, arg); \
        (b)->len += (size_t)n_; \
    } while (0)

static void put_integer(sbuf *b, const fmt_spec *s, const char *spec, const int *star, va_list *ap) {
    bool is_signed = s->conv == 'd' || s->conv == 'i' || s->conv == 'c';
    if (s->length == 'L' || s->length == 'j') {
        long long v = is_signed ? signed_arg(s->length, ap) : (long long)unsigned_arg(s->length, ap);
        HFX_FMT_PUT(b, s, spec, star, v);
    } else if (s->length) {
        long v = is_signed ? (long)signed_arg(s->length, ap) : (long)unsigned_arg(s->length, ap);
        HFX_FMT_PUT(b, s, spec, star, v);
    } else {
        int v = va_arg(*ap, int);
        HFX_FMT_PUT(b, s, spec, star, v);
    }
}

/* Any other conversion, by snprintf with its one argument (and its '*' values). */
static void put_other(sbuf *b, const fmt_spec *s, va_list *ap) {
    char spec[32];
    if (s->len >= sizeof spec) { b->oom = true; return; }
    memcpy(spec, s->start, s->len);
    spec[s->len] = 0;
    int star[2] = {0, 0};
    for (int i = 0; i < s->stars && i < 2; i++) star[i] = va_arg(*ap, int);
    if (s->conv == 's' && s->star_precision_only) {
        const char *str = va_arg(*ap, const char *);
        hfx_sb_putn(b, str, strnlen(str, star[0] < 0 ? SIZE_MAX : (size_t)star[0]));
    } else if (s->conv && strchr("eEfFgGaA", s->conv)) {
        if (s->length == 'q') { long double v = va_arg(*ap, long double); HFX_FMT_PUT(b, s, spec, star, v); }
        else { double v = va_arg(*ap, double); HFX_FMT_PUT(b, s, spec, star, v); }
    } else if (s->conv && strchr("diouxXc", s->conv)) {
        put_integer(b, s, spec, star, ap);
    } else if (s->conv == 's' || s->conv == 'p') {
        const void *v = va_arg(*ap, const void *);
        HFX_FMT_PUT(b, s, spec, star, v);
    } else {
        hfx_sb_putn(b, s->start, s->len); /* not a conversion: as written */
    }
}

void hfx_sb_vprintf(sbuf *b, const char *fmt, va_list ap) {
    va_list args;
    va_copy(args, ap);
    for (const char *p = fmt; *p;) {
        const char *pct = p;
        while (*pct && *pct != '%') pct++; /* formats are short: cheaper than strchr's set-up */
        if (pct > p) hfx_sb_putn(b, p, (size_t)(pct - p));
        if (!*pct) break;
        fmt_spec s = parse_spec(pct);
        if (!s.plain || !put_plain(b, &s, &args)) put_other(b, &s, &args);
        p = pct + s.len;
    }
    va_end(args);
}

void hfx_sb_printf(sbuf *b, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    hfx_sb_vprintf(b, fmt, ap);
    va_end(ap);
}

char *hfx_sb_take(sbuf *b) {
    if (b->oom) {
        hfx_sb_free(b);
        b->d = NULL;
    }
    if (b->arena && b->d) return strdup(b->d);
    return b->d;
}

void hfx_sb_free(sbuf *b) {
    if (!b->arena) free(b->d);
}
