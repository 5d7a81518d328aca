/* distances.c: `distance(P, L)` in a function that also computes `L - P` (a light's direction,
 * normalize(L - P), and its distance: point.fx, spot.fx) is `length(L - P)`. The value is the
 * same (IEEE subtraction is symmetric: L - P is exactly -(P - L)), and the driver can then share
 * the subtraction and the dot product under the square root with the direction's, where
 * `distance(P, L)` subtracts the other way round and shares nothing: 2.4 % of point.fx's
 * pixel-bound frame on llvmpipe (331.6 -> 323.7 M instructions). */
#include "ir/ir.h"

typedef struct differences { ir_expr **subs; uint32_t count, cap; } differences;

static void note_difference(ir_ctx *c, ir_expr **slot, void *data) {
    differences *d = data;
    ir_expr *e = *slot;
    if (e->kind != IE_BINARY || e->op != OP_SUB || hfx_ir_has_side_effects(e)) return;
    if (HFX_ARENA_GROW(c->arena, d->subs, d->count, d->cap, 8)) d->subs[d->count++] = e;
}

/* A noted `a - b` of the type the distance subtracts in. */
static const ir_expr *difference(const differences *d, const ir_expr *a, const ir_expr *b) {
    for (uint32_t i = 0; i < d->count; i++) {
        const ir_expr *s = d->subs[i];
        if (hfx_type_equal(s->type, a->type) && hfx_ir_same_expr(s->a[0], a) && hfx_ir_same_expr(s->a[1], b)) return s;
    }
    return NULL;
}

static void to_length(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    if (e->kind != IE_INTRIN || e->intrin != HFX_INTR_DISTANCE || e->n != 2) return;
    const ir_expr *s = difference(data, e->a[1], e->a[0]);
    if (!s) return;
    e->intrin = HFX_INTR_LENGTH;
    e->a[0] = hfx_ir_clone_expr(c, s);
    e->n = 1;
}

void hfx_ir_pass_distances(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) {
        differences d = {0};
        hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, note_difference, &d);
        if (d.count) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, to_length, &d);
    }
}
