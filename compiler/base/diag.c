#include "base/diag.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void hfx_diags_init(hfx_diags *d, hfx_arena *arena, unsigned flags) {
    memset(d, 0, sizeof *d);
    d->arena = arena;
    d->flags = flags;
}

uint32_t hfx_diags_add_file(hfx_diags *d, const char *name, const char *path, const char *text, uint32_t size) {
    if (d->file_count == d->file_cap) {
        uint32_t cap = d->file_cap ? d->file_cap * 2 : 8;
        hfx_source *files = HFX_NEW_ARRAY(d->arena, hfx_source, cap);
        if (d->file_count) memcpy(files, d->files, sizeof *files * d->file_count);
        d->files = files;
        d->file_cap = cap;
    }
    hfx_source *s = &d->files[d->file_count];
    s->name = hfx_arena_strdup(d->arena, name);
    s->path = hfx_arena_strdup(d->arena, path ? path : name);
    s->text = text;
    s->size = size;
    return d->file_count++;
}

static void add(hfx_diags *d, hfxc_severity sev, hfx_loc loc, unsigned code, const char *fmt, va_list ap) {
    if (sev == HFXC_WARNING && (d->flags & HFXC_NO_WARNINGS)) return;
    if (sev == HFXC_WARNING && (d->flags & HFXC_WERROR)) sev = HFXC_ERROR;
    if (d->count == d->cap) {
        uint32_t cap = d->cap ? d->cap * 2 : 16;
        hfxc_diag *items = HFX_NEW_ARRAY(d->arena, hfxc_diag, cap);
        if (d->count) memcpy(items, d->items, sizeof *items * d->count);
        d->items = items;
        d->cap = cap;
    }
    char buf[1024];
    vsnprintf(buf, sizeof buf, fmt, ap);
    hfxc_diag *g = &d->items[d->count++];
    g->severity = sev;
    g->file = loc.file < d->file_count ? d->files[loc.file].name : "<unknown>";
    g->line = loc.line;
    g->col = loc.col;
    g->code = code;
    g->message = hfx_arena_strdup(d->arena, buf);
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

static void append(char **buf, size_t *len, size_t *cap, const char *s, size_t n) {
    if (*len + n + 1 > *cap) {
        while (*len + n + 1 > *cap) *cap = *cap ? *cap * 2 : 256;
        *buf = realloc(*buf, *cap);
    }
    memcpy(*buf + *len, s, n);
    *len += n;
    (*buf)[*len] = 0;
}

char *hfx_diags_format(const hfx_diags *d, int caret) {
    char *buf = NULL;
    size_t len = 0, cap = 0;
    append(&buf, &len, &cap, "", 0);
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
        append(&buf, &len, &cap, head, n < (int)sizeof head ? (size_t)n : sizeof head - 1);
        if (!caret || !g->line) continue;
        for (uint32_t f = 0; f < d->file_count; f++) {
            if (strcmp(d->files[f].name, g->file) != 0) continue;
            size_t ln;
            const char *src = line_start(&d->files[f], g->line, &ln);
            if (!src) break;
            append(&buf, &len, &cap, "  ", 2);
            append(&buf, &len, &cap, src, ln);
            append(&buf, &len, &cap, "\n  ", 3);
            for (unsigned c = 1; c < g->col && c <= ln; c++)
                append(&buf, &len, &cap, src[c - 1] == '\t' ? "\t" : " ", 1);
            append(&buf, &len, &cap, "^\n", 2);
            break;
        }
    }
    return buf;
}
