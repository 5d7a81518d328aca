/* var_map.c: a pass's facts about variables, kept by the pass (a constant's value in fold, a
 * bound argument in calls, a variable seen in uses) instead of in fields of ir_var that every
 * other pass carries; and the builder's declarations and functions (ir.c). Open addressing on
 * the pointer, in the arena; at most half full. */
#include <stdint.h>

#include "ir/ir.h"

static uint32_t slot_of(const void *v, uint32_t cap) {
    uint64_t h = (uint64_t)(uintptr_t)v * 0x9E3779B97F4A7C15u; /* Fibonacci hashing: the high bits mix */
    return (uint32_t)(h >> 32) & (cap - 1);
}

static void place(ir_var_map *m, const void *v, void *val) {
    uint32_t i = slot_of(v, m->cap);
    while (m->keys[i] && m->keys[i] != v) i = (i + 1) & (m->cap - 1);
    m->count += m->keys[i] == NULL;
    m->keys[i] = v;
    m->vals[i] = val;
}

/* Twice the capacity (16 at first), every entry placed again. */
static bool grow(ir_ctx *c, ir_var_map *m) {
    uint32_t cap = m->cap ? m->cap * 2 : 16;
    const void **keys = HFX_NEW_ARRAY(c->arena, const void *, cap);
    void **vals = HFX_NEW_ARRAY(c->arena, void *, cap);
    if (!keys || !vals) return false;
    ir_var_map old = *m;
    *m = (ir_var_map){keys, vals, 0, cap};
    for (uint32_t i = 0; i < old.cap; i++)
        if (old.keys[i]) place(m, old.keys[i], old.vals[i]);
    return true;
}

bool hfx_ir_var_map_put(ir_ctx *c, ir_var_map *m, const void *v, void *val) {
    if ((m->count + 1) * 2 > m->cap && !grow(c, m)) return false;
    place(m, v, val);
    return true;
}

void *hfx_ir_var_map_get(const ir_var_map *m, const void *v) {
    if (!m || !m->count || !v) return NULL;
    for (uint32_t i = slot_of(v, m->cap); m->keys[i]; i = (i + 1) & (m->cap - 1))
        if (m->keys[i] == v) return m->vals[i];
    return NULL;
}
