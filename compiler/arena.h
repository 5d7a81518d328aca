/* arena.h: one bump allocator per compilation. Everything the front end and the IR allocate
 * lives here and is freed at once, so passes never free nodes one by one. */
#ifndef HFX_ARENA_H
#define HFX_ARENA_H

#include <stddef.h>

typedef struct hfx_arena_block hfx_arena_block;
typedef struct hfx_arena {
    hfx_arena_block *head;
    size_t total;
} hfx_arena;

void hfx_arena_init(hfx_arena *a);
void hfx_arena_free(hfx_arena *a);
void *hfx_arena_alloc(hfx_arena *a, size_t size);            /* zeroed, 16-byte aligned; NULL only if out of memory */
char *hfx_arena_strdup(hfx_arena *a, const char *s);
char *hfx_arena_strndup(hfx_arena *a, const char *s, size_t n);
char *hfx_arena_printf(hfx_arena *a, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#define HFX_NEW(arena, T) ((T *)hfx_arena_alloc((arena), sizeof(T)))
#define HFX_NEW_ARRAY(arena, T, n) ((T *)hfx_arena_alloc((arena), sizeof(T) * (size_t)(n)))

#endif
