/* grow.c: hfx_grow (grow.h). */
#include "grow.h"

#include <stdlib.h>
#include <string.h>

static void *heap(void *ctx, void *old, size_t old_bytes, size_t new_bytes) {
    (void)ctx;
    (void)old_bytes;
    return realloc(old, new_bytes);
}

bool hfx_grow(void **items, size_t elem, uint32_t count, uint32_t *cap, uint32_t first, hfx_grow_alloc alloc, void *ctx) {
    if (count < *cap) return true;
    uint32_t n = *cap ? *cap * 2 : (first ? first : 8);
    if (n <= *cap || elem > SIZE_MAX / n) return false; /* the count would overflow */
    void *p = (alloc ? alloc : heap)(ctx, *items, elem * *cap, elem * n);
    if (!p) return false;
    memset((char *)p + elem * *cap, 0, elem * (n - *cap));
    *items = p;
    *cap = n;
    return true;
}
