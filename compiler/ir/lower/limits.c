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
    if (e->type->kind == TY_MATRIX && e->type->base == B_BOOL && e->type->rows > 1 && e->type->cols > 1 &&
        !(e->kind == IE_VAR && e->var->kind == IRV_UNIFORM)) {
        hfx_error(c->diags, e->loc, X_UNSUPPORTED,
                  "a bool matrix is supported only converted whole to a numeric matrix or indexed by a constant");
        (*bad)++;
        return;
    }
    if (hfx_ir_integer_division(e) && hfx_ir_is_const(e->a[1])) { /* fxc refuses an integer / or % by a constant 0 */
        for (unsigned i = 0; i < hfx_type_components(e->a[1]->type) && i < 16; i++)
            if (e->a[1]->cval[i] == 0) {
                hfx_error(c->diags, e->a[1]->loc, 3033, "division by zero");
                (*bad)++;
                break;
            }
    }
    if (e->kind == IE_INDEX && e->a[0]->type->kind == TY_ARRAY && e->a[0]->type->elem->kind == TY_SAMPLER) {
        /* the samplers pass took every index that unrolling and folding make a literal, as fxc
         * needs; what is left stays computed on the GPU, which D3D9 cannot index samplers by */
        hfx_error(c->diags, e->loc, 3512, "sampler array index must be a literal expression");
        (*bad)++;
    }
}

/* Whether every path through s ends in a return or a discard (switches: not counted). */
static bool always_returns(const ir_stmt *s) {
    if (!s) return false;
    switch (s->kind) {
    case IS_RETURN: case IS_DISCARD: return true;
    case IS_BLOCK:
        for (uint32_t i = 0; i < s->count; i++)
            if (always_returns(s->body[i])) return true;
        return false;
    case IS_IF: /* a condition the pass's uniform arguments made constant picks its branch */
        if (s->expr && hfx_ir_is_const(s->expr) && hfx_type_components(s->expr->type) == 1)
            return always_returns(hfx_ir_const_truth(s->expr) ? s->then_s : s->else_s);
        return always_returns(s->then_s) && always_returns(s->else_s);
    case IS_DO: return always_returns(s->then_s);
    default: return false;
    }
}

/* The checker's X3507, for an entry point with uniform parameters, once this pass's compile
 * arguments fixed them. A function called with constant arguments is fxc's to inline and
 * fold; hfx keeps it a function and cannot tell, so it reports nothing there. */
static int check_returns(ir_ctx *c, const ir_func *f) {
    if (!f->is_entry || !f->src || !f->src->returns_per_pass || !f->ret || f->ret->kind == TY_VOID ||
        always_returns(f->body))
        return 0;
    hfx_error(c->diags, f->src->loc, X_NOT_ALL_PATHS, "'%s': Not all control paths return a value", f->src->name);
    return 1;
}

int hfx_ir_pass_check(ir_ctx *c, ir_shader *sh) {
    int bad = hfx_ir_check_model(c, sh);
    for (uint32_t i = 0; i < sh->func_count; i++) {
        hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, check_expr, &bad);
        bad += check_returns(c, sh->funcs[i]);
    }
    return bad ? -1 : 0;
}
