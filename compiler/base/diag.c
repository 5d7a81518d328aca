#include "base/diag.h"
#include "base/sbuf.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void hfx_diags_init(hfx_diags *d, hfx_arena *arena, unsigned flags) {
    memset(d, 0, sizeof *d);
    d->arena = arena;
    d->flags = flags;
    d->dump_text.arena = arena; /* the dumps live as long as the messages */
}

uint32_t hfx_diags_add_file(hfx_diags *d, const char *name, const char *path, const char *text, uint32_t size) {
    if (!HFX_ARENA_GROW(d->arena, d->files, d->file_count, d->file_cap, 8)) return 0; /* out of memory: the first file stands in */
    hfx_source *s = &d->files[d->file_count];
    s->name = hfx_arena_strdup(d->arena, name);
    s->path = path ? hfx_arena_strdup(d->arena, path) : NULL;
    s->text = text;
    s->size = size;
    return d->file_count++;
}

static void add(hfx_diags *d, hfxc_severity sev, hfx_loc loc, unsigned code, const char *fmt, va_list ap) {
    if (sev == HFXC_WARNING && (d->flags & HFXC_NO_WARNINGS)) return;
    if (sev == HFXC_WARNING && (d->flags & HFXC_WERROR)) sev = HFXC_ERROR;
    char buf[1024];
    vsnprintf(buf, sizeof buf, fmt, ap);
    /* the message first: a failure escaping from either allocation leaves no half-made item */
    char *message = hfx_arena_strdup(d->arena, buf);
    if (!message || !HFX_ARENA_GROW(d->arena, d->items, d->count, d->cap, 16)) return;
    hfxc_diag *g = &d->items[d->count++];
    g->severity = sev;
    g->file = loc.file < d->file_count ? d->files[loc.file].name : "<unknown>";
    g->line = loc.line;
    g->col = loc.col;
    g->code = code;
    g->message = message;
    if (sev == HFXC_ERROR) d->errors++;
    else if (sev == HFXC_WARNING) d->warnings++;
}

void hfx_error(hfx_diags *d, hfx_loc loc, unsigned code, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    add(d, HFXC_ERROR, loc, code, fmt, ap);
    va_end(ap);
}

void hfx_warning(hfx_diags *d, hfx_loc loc, unsigned code, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    add(d, HFXC_WARNING, loc, code, fmt, ap);
    va_end(ap);
}

void hfx_note(hfx_diags *d, hfx_loc loc, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    add(d, HFXC_NOTE, loc, 0, fmt, ap);
    va_end(ap);
}

/* The text of line `line` of a file, for the caret display. */
static const char *line_start(const hfx_source *s, uint32_t line, size_t *len) {
    const char *p = s->text;
    if (!p) return NULL;
    for (uint32_t l = 1; l < line && *p; p++)
        if (*p == '\n') l++;
    size_t n = 0;
    while (p[n] && p[n] != '\n' && p[n] != '\r') n++;
    *len = n;
    return p;
}

char *hfx_diags_format(const hfx_diags *d, int caret) {
    sbuf b = {0};
    hfx_sb_putn(&b, "", 0);
    for (uint32_t i = 0; i < d->count; i++) {
        const hfxc_diag *g = &d->items[i];
        static const char *const kinds[] = {"error", "warning", "note"};
        char head[1400];
        int n;
        if (g->severity == HFXC_NOTE)
            n = snprintf(head, sizeof head, "%s(%u,%u): note: %s\n", g->file, g->line, g->col, g->message);
        else
            n = snprintf(head, sizeof head, "%s(%u,%u): %s X%04u: %s\n", g->file, g->line, g->col,
                         kinds[g->severity], g->code, g->message);
        hfx_sb_putn(&b, head, n < (int)sizeof head ? (size_t)n : sizeof head - 1);
        if (!caret || !g->line) continue;
        for (uint32_t f = 0; f < d->file_count; f++) {
            if (strcmp(d->files[f].name, g->file) != 0) continue;
            size_t ln;
            const char *src = line_start(&d->files[f], g->line, &ln);
            if (!src) break;
            hfx_sb_putn(&b, "  ", 2);
            hfx_sb_putn(&b, src, ln);
            hfx_sb_putn(&b, "\n  ", 3);
            for (unsigned c = 1; c < g->col && c <= ln; c++)
                hfx_sb_putn(&b, src[c - 1] == '\t' ? "\t" : " ", 1);
            hfx_sb_putn(&b, "^\n", 2);
            break;
        }
    }
    return hfx_sb_take(&b);
}
