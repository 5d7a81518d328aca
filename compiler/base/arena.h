/* arena.h: one bump allocator per compilation. Everything the front end and the IR allocate
 * lives here and is freed at once, so passes never free nodes one by one. */
#ifndef HFX_ARENA_H
#define HFX_ARENA_H

#include <setjmp.h>
#include <stdbool.h>
#include <stddef.h>
#include <string.h>

#include "grow.h"

typedef struct hfx_arena_block hfx_arena_block;
typedef struct hfx_arena_cleanup hfx_arena_cleanup;

/* When an allocation fails (malloc refused, or `limit` would be passed), the arena is marked
 * `failed`; then, inside hfx_arena_escape_on(), it longjmps to `escape` instead of returning
 * NULL, so a compile stops at once wherever it was (the phases need not check every node) and
 * its owner reports "out of memory" after running the cleanups registered for malloc'ed
 * memory alive at that moment. Outside, allocations return NULL as usual. */
typedef struct hfx_arena {
    hfx_arena_block *head;
    unsigned char *cur, *end; /* free space of the head block */
    size_t total;
    size_t limit;             /* bytes the arena may hold; 0 = no limit */
    bool failed, over_limit;  /* an allocation failed; because of `limit` */
    int escape_depth;         /* > 0: failures longjmp to *escape */
    jmp_buf *escape;
    hfx_arena_cleanup *cleanups;
} hfx_arena;

void hfx_arena_init(hfx_arena *a);
void hfx_arena_free(hfx_arena *a);
/* Failures longjmp to *escape between on and off (they nest); off restores NULL returns. */
void hfx_arena_escape_on(hfx_arena *a);
void hfx_arena_escape_off(hfx_arena *a);
/* Registers fn(ctx) to free malloc'ed memory if a failure escapes; ctx must outlive the
 * escape (not on the stack of a function the longjmp leaves). Returns the registration for
 * hfx_arena_forget, once the memory is freed or handed over; NULL-safe. */
hfx_arena_cleanup *hfx_arena_on_escape(hfx_arena *a, void (*fn)(void *ctx), void *ctx);
void hfx_arena_forget(hfx_arena *a, hfx_arena_cleanup *c);
void hfx_arena_run_cleanups(hfx_arena *a); /* after an escape: every registered fn, newest first */
void *hfx_arena_alloc_slow(hfx_arena *a, size_t size);       /* a new block; use hfx_arena_alloc */
void *hfx_arena_alloc_slow_raw(hfx_arena *a, size_t size);   /* the same, not zeroed */

/* Zeroed, 16-byte aligned; NULL only if out of memory. Inline because the lexer and parser
 * allocate a node or a token at a time. */
static inline void *hfx_arena_alloc(hfx_arena *a, size_t size) {
    size = (size + 15) & ~(size_t)15;
    if ((size_t)(a->end - a->cur) >= size) {
        void *p = a->cur;
        a->cur += size;
        a->total += size;
        return memset(p, 0, size);
    }
    return hfx_arena_alloc_slow(a, size);
}
/* Not zeroed, for what the caller fills whole at once: the lexer makes a token per few bytes
 * of source, and zeroing each one first cost as much as filling it. 16-byte aligned; NULL
 * only if out of memory. */
static inline void *hfx_arena_alloc_raw(hfx_arena *a, size_t size) {
    size = (size + 15) & ~(size_t)15;
    if ((size_t)(a->end - a->cur) >= size) {
        void *p = a->cur;
        a->cur += size;
        a->total += size;
        return p;
    }
    return hfx_arena_alloc_slow_raw(a, size);
}
char *hfx_arena_strdup(hfx_arena *a, const char *s);
char *hfx_arena_strndup(hfx_arena *a, const char *s, size_t n);
char *hfx_arena_printf(hfx_arena *a, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* hfx_grow's allocator in an arena: new space with the old contents (the rest not zeroed: hfx_grow
 * does that); the old space stays. */
void *hfx_arena_grow(void *arena, void *old, size_t old_bytes, size_t new_bytes);
#define HFX_ARENA_GROW(arena, arr, count, cap, first) \
    hfx_grow((void **)&(arr), sizeof *(arr), (count), &(cap), (first), hfx_arena_grow, (arena))

#define HFX_NEW(arena, T) ((T *)hfx_arena_alloc((arena), sizeof(T)))
#define HFX_NEW_ARRAY(arena, T, n) ((T *)hfx_arena_alloc((arena), sizeof(T) * (size_t)(n)))

#endif
