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

struct hfx_arena_cleanup {
    void (*fn)(void *ctx);
    void *ctx;
    hfx_arena_cleanup *next;
};

enum { BLOCK_SIZE = 64 * 1024 };

void hfx_arena_init(hfx_arena *a) { memset(a, 0, sizeof *a); }

void hfx_arena_free(hfx_arena *a) {
    hfx_arena_block *b = a->head;
    while (b) {
        hfx_arena_block *next = b->next;
        free(b);
        b = next;
    }
    hfx_arena_init(a);
}

void hfx_arena_escape_on(hfx_arena *a) { a->escape_depth++; }
void hfx_arena_escape_off(hfx_arena *a) { a->escape_depth--; }

/* The one way out of a failed allocation: marked, then longjmp or NULL. */
static void *fail(hfx_arena *a, bool over_limit) {
    a->failed = true;
    a->over_limit |= over_limit;
    if (a->escape_depth > 0 && a->escape) longjmp(*a->escape, 1);
    return NULL;
}

hfx_arena_cleanup *hfx_arena_on_escape(hfx_arena *a, void (*fn)(void *ctx), void *ctx) {
    hfx_arena_cleanup *c = hfx_arena_alloc(a, sizeof *c);
    if (!c) return NULL;
    c->fn = fn;
    c->ctx = ctx;
    c->next = a->cleanups;
    a->cleanups = c;
    return c;
}

void hfx_arena_forget(hfx_arena *a, hfx_arena_cleanup *c) {
    for (hfx_arena_cleanup **p = &a->cleanups; c && *p; p = &(*p)->next)
        if (*p == c) {
            *p = c->next;
            return;
        }
}

void hfx_arena_run_cleanups(hfx_arena *a) {
    hfx_arena_cleanup *c = a->cleanups;
    a->cleanups = NULL;
    for (; c; c = c->next) c->fn(c->ctx);
}

/* Zeroes nothing: hfx_arena_alloc_slow zeroes only what it hands out (most compilations use a
 * small part of their last block), and raw allocations (a file's text copy) need no zeroing. */
void *hfx_arena_alloc_slow_raw(hfx_arena *a, size_t size) {
    size = (size + 15) & ~(size_t)15;
    size_t cap = size > BLOCK_SIZE ? size : BLOCK_SIZE;
    if (a->limit && (size > a->limit || a->total > a->limit - size)) return fail(a, true);
    hfx_arena_block *b = malloc(sizeof *b + cap);
    if (!b) return fail(a, false);
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
    return b->data;
}

void *hfx_arena_alloc_slow(hfx_arena *a, size_t size) {
    void *p = hfx_arena_alloc_slow_raw(a, size);
    return p ? memset(p, 0, (size + 15) & ~(size_t)15) : NULL;
}

char *hfx_arena_strndup(hfx_arena *a, const char *s, size_t n) {
    char *p = hfx_arena_alloc(a, n + 1);
    if (!p) return NULL;
    memcpy(p, s, n);
    p[n] = 0;
    return p;
}

char *hfx_arena_strdup(hfx_arena *a, const char *s) { return hfx_arena_strndup(a, s, strlen(s)); }

/* Formatted by hfx_sb_vprintf into the arena itself (vsnprintf measured and wrote twice, and was
 * most of the cost; no malloc, so an escaping allocation failure loses nothing). */
char *hfx_arena_printf(hfx_arena *a, const char *fmt, ...) {
    sbuf b = {.arena = a};
    va_list ap;
    va_start(ap, fmt);
    hfx_sb_vprintf(&b, fmt, ap);
    va_end(ap);
    if (b.oom) return NULL;
    return b.d ? b.d : hfx_arena_strdup(a, "");
}

/* Not zeroed: hfx_grow, whose allocator this is, zeroes the part the old contents leave. */
void *hfx_arena_grow(void *arena, void *old, size_t old_bytes, size_t new_bytes) {
    void *p = hfx_arena_alloc_raw(arena, new_bytes);
    if (p && old_bytes) memcpy(p, old, old_bytes);
    return p;
}
