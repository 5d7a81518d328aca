/* fold.c: constant folding of the IR with common/eval, the evaluator every phase shares (ints
 * wrap at 32 bits and divide toward zero, floats are single precision, conversions truncate).
 * In shader code intrinsics are left alone (the GPU computes them as the shader would); a value
 * outside shader code (hfx_ir_fold_value: a state value) folds them too, as fxc does, since nothing
 * but the CPU ever computes it. The one tree walk over constant expressions. */
#include <math.h>

#include "ir/ir.h"

static hfx_ev_base ev(const hfx_type *t) { return hfx_base_ev(t->base); }

/* GLSL has no literal for infinities and NaNs: those results are left to the GPU. */
static bool printable(hfx_ev_base b, double v) { return b != HFX_EV_FLOAT || isfinite(v); }

static unsigned comps(const hfx_type *t) { return hfx_type_is_numeric(t) ? hfx_type_components(t) : 0; }

/* any_value: a value outside shader code, which no GLSL literal has to spell. */
static ir_expr *fold_binary(ir_ctx *c, ir_expr *e, bool any_value) {
    ir_expr *x = e->a[0], *y = e->a[1];
    if (!hfx_ir_is_const(x) || !hfx_ir_is_const(y)) {
        /* false && e, true || e: the right side matters only for its effects */
        if ((e->op == OP_AND || e->op == OP_OR) && hfx_ir_is_const(x) && comps(x->type) == 1 &&
            hfx_ir_const_truth(x) == (e->op == OP_OR) && !hfx_ir_has_side_effects(y))
            return hfx_ir_const_scalar(c, e->type, e->op == OP_OR, e->loc);
        return e;
    }
    unsigned n = comps(e->type), nx = comps(x->type), ny = comps(y->type);
    if (!n || n > 16 || !nx || !ny) return e;
    hfx_ev_op op;
    if (!hfx_op_ev(e->op, &op)) return e;
    ir_expr *r = hfx_ir_new_expr(c, IE_CONST, e->type, e->loc, 0);
    hfx_ev_base b = ev(x->type), rb = hfx_ev_result_base(op, b);
    for (unsigned i = 0; i < n; i++) {
        double v;
        if (!hfx_ev_binary(op, b, x->cval[nx == 1 ? 0 : i], y->cval[ny == 1 ? 0 : i], &v)) return e;
        r->cval[i] = hfx_ev_convert(rb, ev(e->type), v);
        if (!any_value && !printable(ev(e->type), r->cval[i])) return e;
    }
    return r;
}

static ir_expr *fold_unary(ir_ctx *c, ir_expr *e) {
    ir_expr *x = e->a[0];
    hfx_ev_op op;
    if (!hfx_ir_is_const(x) || (e->op != OP_NEG && e->op != OP_NOT && e->op != OP_BITNOT) || !hfx_op_ev(e->op, &op)) return e;
    unsigned n = comps(e->type);
    if (!n || n > 16) return e;
    ir_expr *r = hfx_ir_new_expr(c, IE_CONST, e->type, e->loc, 0);
    hfx_ev_base b = ev(x->type);
    for (unsigned i = 0; i < n; i++) {
        double v;
        if (!hfx_ev_unary(op, b, x->cval[i], &v)) return e;
        r->cval[i] = hfx_ev_convert(hfx_ev_result_base(op, b), ev(e->type), v);
    }
    return r;
}

/* Component i of the converted value: matrices keep (row, col), other shapes keep order. */
static double convert_comp(const ir_expr *x, const hfx_type *to, unsigned i) {
    const hfx_type *from = x->type;
    if (comps(from) == 1) return x->cval[0];
    if (from->kind == TY_MATRIX && to->kind == TY_MATRIX) return x->cval[(i / to->cols) * from->cols + i % to->cols];
    return x->cval[i];
}

static ir_expr *fold_convert(ir_ctx *c, ir_expr *e) {
    ir_expr *x = e->a[0];
    unsigned n = comps(e->type);
    if (!hfx_ir_is_const(x) || !n || n > 16 || !comps(x->type)) return e;
    if (comps(x->type) != 1 && comps(x->type) < n) return e;
    ir_expr *r = hfx_ir_new_expr(c, IE_CONST, e->type, e->loc, 0);
    for (unsigned i = 0; i < n; i++) r->cval[i] = hfx_ev_convert(ev(x->type), ev(e->type), convert_comp(x, e->type, i));
    return r;
}

static ir_expr *fold_construct(ir_ctx *c, ir_expr *e) {
    unsigned n = comps(e->type), k = 0;
    if (!n || n > 16) return e;
    for (uint32_t i = 0; i < e->n; i++)
        if (!hfx_ir_is_const(e->a[i]) || !comps(e->a[i]->type)) return e;
    ir_expr *r = hfx_ir_new_expr(c, IE_CONST, e->type, e->loc, 0);
    for (uint32_t i = 0; i < e->n; i++)
        for (unsigned j = 0; j < comps(e->a[i]->type) && k < 16; j++)
            r->cval[k++] = hfx_ev_convert(ev(e->a[i]->type), ev(e->type), e->a[i]->cval[j]);
    if (k == 1 && n > 1) /* a scalar spread over the type */
        for (unsigned j = 1; j < n; j++) r->cval[j] = r->cval[0];
    else if (k != n) return e;
    return r;
}

static ir_expr *fold_swizzle(ir_ctx *c, ir_expr *e) {
    ir_expr *x = e->a[0];
    if (!hfx_ir_is_const(x)) return e;
    ir_expr *r = hfx_ir_new_expr(c, IE_CONST, e->type, e->loc, 0);
    for (unsigned i = 0; i < e->comp_count && i < 16; i++) r->cval[i] = x->cval[e->comps[i] < 16 ? e->comps[i] : 0];
    return r;
}

static ir_expr *fold_select(ir_ctx *c, ir_expr *e) {
    ir_expr *cond = e->a[0];
    if (!hfx_ir_is_const(cond) || comps(cond->type) != 1) return e;
    ir_expr *other = hfx_ir_const_truth(cond) ? e->a[2] : e->a[1];
    return hfx_ir_has_side_effects(other) ? e : hfx_ir_const_truth(cond) ? e->a[1] : e->a[2];
}

static void fold_one(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    switch (e->kind) {
    case IE_UNARY: *slot = fold_unary(c, e); break;
    case IE_BINARY: *slot = fold_binary(c, e, data != NULL); break;
    case IE_CONVERT: *slot = fold_convert(c, e); break;
    case IE_CONSTRUCT: *slot = fold_construct(c, e); break;
    case IE_SWIZZLE: *slot = fold_swizzle(c, e); break;
    case IE_SELECT: *slot = fold_select(c, e); break;
    default: break;
    }
}

/* An intrinsic of constants (values only): its arguments at their own base, the result at the
 * checker's type. */
static ir_expr *fold_call(ir_ctx *c, ir_expr *e) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of((int)e->intrin);
    unsigned n = comps(e->type);
    if (!info || info->fold == HFX_EV_FN_NONE || (int)e->n != hfx_ev_fn_args(info->fold) || !n || n > 16) return e;
    hfx_ev_value args[3], r;
    hfx_ev_base base = HFX_EV_BOOL; /* the evaluator takes one base: the largest, as BINARY's */
    for (uint32_t i = 0; i < e->n; i++) {
        if (!hfx_ir_is_const(e->a[i]) || !comps(e->a[i]->type) || comps(e->a[i]->type) > 16) return e;
        if (ev(e->a[i]->type) > base) base = ev(e->a[i]->type);
    }
    for (uint32_t i = 0; i < e->n; i++) {
        args[i].base = base;
        args[i].n = (uint8_t)comps(e->a[i]->type);
        for (unsigned j = 0; j < args[i].n; j++) args[i].c[j] = hfx_ev_convert(ev(e->a[i]->type), base, e->a[i]->cval[j]);
    }
    if (!hfx_ev_call(info->fold, args, e->n, &r) || (r.n != n && r.n != 1)) return e;
    ir_expr *out = hfx_ir_new_expr(c, IE_CONST, e->type, e->loc, 0);
    for (unsigned i = 0; i < n; i++) out->cval[i] = hfx_ev_convert(r.base, ev(e->type), r.c[r.n == 1 ? 0 : i]);
    return out;
}

static void fold_value_one(ir_ctx *c, ir_expr **slot, void *data) {
    if ((*slot)->kind == IE_INTRIN) *slot = fold_call(c, *slot);
    else fold_one(c, slot, data);
}

void hfx_ir_fold_value(ir_ctx *c, ir_expr **slot) {
    static const bool any_value = true; /* fold_one's data: set for values */
    hfx_ir_walk_expr(c, slot, fold_value_one, (void *)&any_value);
}

static bool is_const_var(const ir_var *v) {
    return v->decl && (v->decl->mods & MOD_CONST) && hfx_type_is_numeric(v->type) &&
           (v->kind == IRV_LOCAL || (v->kind == IRV_PRIVATE && !v->copy_of));
}

/* The values of `const` locals and `static const` globals whose initialiser folded (this
 * pass's own table: calls runs the pass again on its copies, whose locals are new). */
typedef struct consts { ir_var_map values; } consts;

/* Adds the constant locals declared in s; true when there is one. */
static bool find_const_locals(ir_ctx *c, consts *k, ir_stmt *s) {
    if (!s) return false;
    bool found = false;
    if (s->kind == IS_DECL && hfx_ir_is_const(s->expr) && is_const_var(s->var))
        found = hfx_ir_var_map_put(c, &k->values, s->var, s->expr);
    found |= find_const_locals(c, k, s->init);
    for (uint32_t i = 0; i < s->count; i++) found |= find_const_locals(c, k, s->body[i]);
    found |= find_const_locals(c, k, s->then_s);
    found |= find_const_locals(c, k, s->else_s);
    return found;
}

static void propagate(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    const ir_expr *value = e->kind == IE_VAR ? hfx_ir_var_map_get(&((consts *)data)->values, e->var) : NULL;
    if (value) *slot = hfx_ir_clone_expr(c, value);
    else fold_one(c, slot, NULL);
}

void hfx_ir_pass_fold(ir_ctx *c, ir_shader *sh) {
    bool const_globals = false;
    consts k = {{0}};
    for (uint32_t i = 0; i < sh->global_count; i++) {
        ir_var *g = sh->globals[i];
        hfx_ir_walk_expr(c, &g->init, fold_one, NULL);
        if (hfx_ir_is_const(g->init) && is_const_var(g)) const_globals |= hfx_ir_var_map_put(c, &k.values, g, g->init);
    }
    /* constants flow into their uses (so `static const bool on = false; if (on)` dies), and
     * what they make constant folds in the same walk. Without a constant to propagate the walk
     * would only fold again what the first one left: nothing (the first walk went operands
     * first, so each node it kept had its final operands when it was tried). */
    for (uint32_t i = 0; i < sh->func_count; i++) {
        hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, fold_one, NULL);
        if (find_const_locals(c, &k, sh->funcs[i]->body) || const_globals)
            hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, propagate, &k);
    }
}
