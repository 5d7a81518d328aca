/* sbuf.c: the one growable text buffer (GLSL printer, IR and AST dumps, diagnostics, SPIR-V rewrite,
 * preprocessed text). */
#include <stdarg.h>
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

void sb_putn(sbuf *b, const char *s, size_t n) {
    if (b->oom) return;
    if (b->len + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 256;
        while (cap < b->len + n + 1) cap *= 2;
        char *d = grow_text(b, cap);
        if (!d) { b->oom = true; return; }
        b->d = d;
        b->cap = cap;
    }
    memcpy(b->d + b->len, s, n);
    b->len += n;
    b->d[b->len] = 0;
}

void sb_put(sbuf *b, const char *s) { sb_putn(b, s, strlen(s)); }

void sb_printf(sbuf *b, const char *fmt, ...) {
    char small[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(small, sizeof small, fmt, ap);
    va_end(ap);
    if (n < 0) return;
    if ((size_t)n < sizeof small) { sb_putn(b, small, (size_t)n); return; }
    /* in an arena buffer the long piece comes from the arena too: nothing to lose if growing
     * the buffer escapes (base/arena.h) */
    char *big = b->arena ? hfx_arena_alloc_raw(b->arena, (size_t)n + 1) : malloc((size_t)n + 1);
    if (!big) { b->oom = true; return; }
    va_start(ap, fmt);
    vsnprintf(big, (size_t)n + 1, fmt, ap);
    va_end(ap);
    sb_putn(b, big, (size_t)n);
    if (!b->arena) free(big);
}

char *sb_take(sbuf *b) {
    if (b->oom) {
        sb_free(b);
        b->d = NULL;
    }
    if (b->arena && b->d) return strdup(b->d);
    return b->d;
}

void sb_free(sbuf *b) {
    if (!b->arena) free(b->d);
}
