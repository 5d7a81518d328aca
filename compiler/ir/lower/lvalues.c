/* lvalues.c: assignment targets GLSL has no form for. `m._11_22 = v` (a swizzle of several
 * matrix components) becomes `float2(m._11, m._22) = v`, which the GLSL printer writes as a
 * helper with one out parameter per component; `m._11_22 += v` reads the components first. */
#include "ir/ir.h"

static bool matrix_multi_swizzle(const ir_expr *x) {
    return x->kind == IE_SWIZZLE && x->a[0]->type->kind == TY_MATRIX && x->comp_count > 1;
}

/* float_k(m._a, m._b, ...) with one single-component swizzle per component of x. */
static ir_expr *split(ir_ctx *c, const ir_expr *x) {
    ir_expr *ctor = hfx_ir_new_expr(c, IE_CONSTRUCT, x->type, x->loc, x->comp_count);
    const hfx_type *scalar = hfx_type_scalar(c->types, x->type->base);
    for (unsigned i = 0; i < x->comp_count; i++) {
        ir_expr *one = hfx_ir_new_expr(c, IE_SWIZZLE, scalar, x->loc, 1);
        one->a[0] = i ? hfx_ir_clone_expr(c, x->a[0]) : x->a[0];
        one->comp_count = 1;
        one->comps[0] = x->comps[i];
        ctor->a[i] = one;
    }
    return ctor;
}

static void lower_assign(ir_ctx *c, ir_expr **slot, void *data) {
    (void)data;
    ir_expr *e = *slot;
    if (e->kind != IE_ASSIGN || !matrix_multi_swizzle(e->a[0]) || hfx_ir_has_side_effects(e->a[0])) return;
    if (e->op != OP_NONE) { /* x op= y is x = x op y: the target has no side effects, reading it twice is safe */
        ir_expr *value = hfx_ir_new_expr(c, IE_BINARY, e->a[0]->type, e->loc, 2);
        value->op = e->op;
        value->a[0] = hfx_ir_clone_expr(c, e->a[0]);
        value->a[1] = e->a[1];
        e->a[1] = value;
        e->op = OP_NONE;
    }
    e->a[0] = split(c, e->a[0]);
}

void hfx_ir_pass_lvalues(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, lower_assign, NULL);
}
