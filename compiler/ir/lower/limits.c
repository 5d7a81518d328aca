/* limits.c: what GLSL cannot express, reported at the HLSL source position (never a crash
 * in the printer). */
#include "ir/ir.h"

static void check_expr(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    int *bad = data;
    if (e->kind == IE_INTRIN && e->intrin == HFX_INTR_NOISE) {
        hfx_error(c->diags, e->loc, X_UNSUPPORTED, "'noise': intrinsic is not supported in shaders");
        (*bad)++;
    }
    if (e->kind == IE_ASSIGN && e->a[0]->kind == IE_SWIZZLE && e->a[0]->a[0]->type->kind == TY_MATRIX &&
        e->a[0]->comp_count > 1) {
        hfx_error(c->diags, e->loc, X_UNSUPPORTED, "assignment to a multi-component matrix swizzle is not supported");
        (*bad)++;
    }
    if (e->kind == IE_INDEX && e->a[0]->type->kind == TY_ARRAY && e->a[0]->type->elem->kind == TY_SAMPLER) {
        hfx_error(c->diags, e->loc, X_UNSUPPORTED, "arrays of samplers are not supported");
        (*bad)++;
    }
}

int ir_pass_check(ir_ctx *c, ir_shader *sh) {
    int bad = 0;
    for (uint32_t i = 0; i < sh->func_count; i++) ir_walk_stmt_exprs(c, sh->funcs[i]->body, check_expr, &bad);
    return bad ? -1 : 0;
}
