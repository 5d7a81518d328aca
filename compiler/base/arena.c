#include "base/arena.h"
#include "base/sbuf.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct hfx_arena_block {
    hfx_arena_block *next;
    size_t used, size;
    _Alignas(16) unsigned char data[];
};

enum { BLOCK_SIZE = 64 * 1024 };

void hfx_arena_init(hfx_arena *a) {
    a->head = NULL;
    a->cur = a->end = NULL;
    a->total = 0;
}

void hfx_arena_free(hfx_arena *a) {
    hfx_arena_block *b = a->head;
    while (b) {
        hfx_arena_block *next = b->next;
        free(b);
        b = next;
    }
    hfx_arena_init(a);
}

/* Zeroes only what is handed out: most compilations use a small part of their last block. */
void *hfx_arena_alloc_slow(hfx_arena *a, size_t size) {
    size = (size + 15) & ~(size_t)15;
    size_t cap = size > BLOCK_SIZE ? size : BLOCK_SIZE;
    hfx_arena_block *b = malloc(sizeof *b + cap);
    if (!b) return NULL;
    b->size = cap;
    if (size > BLOCK_SIZE / 4 && a->head) {
        /* a big allocation gets a block of its own behind the current one, keeping its free space */
        b->next = a->head->next;
        a->head->next = b;
    } else {
        b->next = a->head;
        a->head = b;
        a->cur = b->data + size;
        a->end = b->data + cap;
    }
    b->used = size;
    a->total += size;
    return memset(b->data, 0, size);
}

char *hfx_arena_strndup(hfx_arena *a, const char *s, size_t n) {
    char *p = hfx_arena_alloc(a, n + 1);
    if (!p) return NULL;
    memcpy(p, s, n);
    p[n] = 0;
    return p;
}

char *hfx_arena_strdup(hfx_arena *a, const char *s) { return hfx_arena_strndup(a, s, strlen(s)); }

/* Formatted by sb_vprintf (vsnprintf measured and wrote twice, and was most of the cost). */
char *hfx_arena_printf(hfx_arena *a, const char *fmt, ...) {
    sbuf b = {.d = NULL};
    va_list ap;
    va_start(ap, fmt);
    sb_vprintf(&b, fmt, ap);
    va_end(ap);
    char *p = b.oom ? NULL : hfx_arena_strndup(a, b.d ? b.d : "", b.len);
    free(b.d);
    return p;
}

void *hfx_arena_grow(void *arena, void *old, size_t old_bytes, size_t new_bytes) {
    void *p = hfx_arena_alloc(arena, new_bytes);
    if (p && old_bytes) memcpy(p, old, old_bytes);
    return p;
}
