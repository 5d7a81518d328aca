/* grow.h: the one growable array of hfx. An array is a pointer, a count and a capacity; before
 * adding an element, hfx_grow makes room for one more by doubling the capacity (from `first`).
 * The memory comes from realloc, or from an allocator such as the compiler's arena (whose old
 * block is simply abandoned). New elements are zeroed. */
#ifndef HFX_COMMON_GROW_H
#define HFX_COMMON_GROW_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Returns a block of new_bytes holding old's first old_bytes (old may be NULL), or NULL. */
typedef void *(*hfx_grow_alloc)(void *ctx, void *old, size_t old_bytes, size_t new_bytes);

/* Room for element `count` in *items (elements of elem bytes, *cap of them); false when out of
 * memory (nothing changed). alloc NULL: realloc. */
bool hfx_grow(void **items, size_t elem, uint32_t count, uint32_t *cap, uint32_t first, hfx_grow_alloc alloc, void *ctx);

#define HFX_GROW(arr, count, cap, first) \
    hfx_grow((void **)&(arr), sizeof *(arr), (count), &(cap), (first), NULL, NULL)

#endif
