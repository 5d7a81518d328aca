/* intrinsics.c: rewrites intrinsic calls into forms every GLSL target expresses directly.
 * mul(float3, float4x4) reaches the IR as mul(v, (float3x4)M); since
 * mul(v, M3x4) = mul(float4(v, 0), M4x4).xyzw, the truncated matrix becomes a padded vector,
 * which needs no non-square matrix type (GLSL 110 has none) and no matrix copy. The rest of
 * the intrinsics map one to one in glsl_intrin.c. */
#include "ir/ir.h"

static bool truncated_matrix(const ir_expr *e) {
    if (e->kind != IE_CONVERT || e->type->kind != TY_MATRIX) return false;
    const hfx_type *from = e->a[0]->type;
    return from->kind == TY_MATRIX && from->rows >= e->type->rows && from->cols >= e->type->cols &&
           from->rows > 1 && from->cols > 1 && e->type->rows > 1 && e->type->cols > 1 && from->base == e->type->base;
}

/* v padded with zeros to n components. */
static ir_expr *pad(ir_ctx *c, ir_expr *v, unsigned n) {
    unsigned have = hfx_type_components(v->type);
    if (have == n) return v;
    ir_expr *r = ir_new_expr(c, IE_CONSTRUCT, hfx_type_vector(c->types, v->type->base, n), v->loc, 1 + (n - have));
    r->a[0] = v;
    for (unsigned i = 1; i <= n - have; i++) r->a[i] = ir_const_scalar(c, hfx_type_scalar(c->types, v->type->base), 0, v->loc);
    return r;
}

/* The first n components of a vector. */
static ir_expr *first(ir_ctx *c, ir_expr *v, const hfx_type *ty) {
    unsigned n = hfx_type_components(ty);
    if (hfx_type_components(v->type) == n) return v;
    ir_expr *s = ir_new_expr(c, IE_SWIZZLE, ty, v->loc, 1);
    s->a[0] = v;
    s->comp_count = (uint8_t)n;
    for (unsigned i = 0; i < n; i++) s->comps[i] = (uint8_t)i;
    return s;
}

static void lower_mul(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    if (e->kind != IE_INTRIN || e->intrin != HFX_INTR_MUL || e->n != 2 || e->type->kind != TY_VECTOR) return;
    ir_expr *a = e->a[0], *b = e->a[1];
    if (a->type->kind == TY_VECTOR && truncated_matrix(b) && a->type->cols == b->type->rows) {
        const hfx_type *m = b->a[0]->type;
        ir_expr *r = ir_new_expr(c, IE_INTRIN, hfx_type_vector(c->types, e->type->base, m->cols), e->loc, 2);
        r->intrin = HFX_INTR_MUL;
        r->a[0] = pad(c, a, m->rows);
        r->a[1] = b->a[0];
        *slot = first(c, r, e->type);
    } else if (b->type->kind == TY_VECTOR && truncated_matrix(a) && b->type->cols == a->type->cols) {
        const hfx_type *m = a->a[0]->type;
        ir_expr *r = ir_new_expr(c, IE_INTRIN, hfx_type_vector(c->types, e->type->base, m->rows), e->loc, 2);
        r->intrin = HFX_INTR_MUL;
        r->a[0] = a->a[0];
        r->a[1] = pad(c, b, m->cols);
        *slot = first(c, r, e->type);
    }
}

void ir_pass_intrinsics(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) ir_walk_stmt_exprs(c, sh->funcs[i]->body, lower_mul, NULL);
}
