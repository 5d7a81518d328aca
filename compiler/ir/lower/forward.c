/* forward.c: two rewrites that let the preshade pass see what a shader does on parameters
 * across statements, as fxc's optimiser does:
 * - a numeric local declared with an initialiser and read once, in the very next statement of
 *   its block (a plain expression, declaration or return), takes its initialiser's place there:
 *   `float4 v = mul(p, View); o.Pos = mul(v, Projection);` becomes
 *   `o.Pos = mul(mul(p, View), Projection);` (the value is computed once either way);
 * - mul(mul(x, A), B) with A and B parameter-only matrices is mul(x, mul(A, B)), and
 *   mul(B, mul(A, x)) is mul(mul(B, A), x): the matrix product becomes a preshader and each
 *   vertex does one vector product instead of two (the rounding is a matrix product's, as in
 *   the hand-written GLSL that multiplies World, View and Projection on the CPU);
 * - mul(x, B) with x a local set once by `x = mul(y, A)`, y a constructor with a constant
 *   component (`float4(p, 1)`) of values the function never changes: mul(y, mul(A, B)). The
 *   driver then skips the constant component's products (a position's w = 1), as the
 *   hand-written `mvp * vec4(p, 1.0)` does, and mul(A, B) is a preshader.
 * Its row in the pass table (passes.c) runs only with preshaders on, so --no-preshaders leaves
 * the shaders as written. */
#include "ir/ir.h"

/* ---- forward substitution ---- */

/* The next statement may take the initialiser: straight-line, and nothing in it runs before the
 * read that could change what the initialiser reads (no calls, no assignments but its own). */
static bool simple_next(const ir_stmt *s) {
    if (s->kind != IS_EXPR && s->kind != IS_DECL && s->kind != IS_RETURN) return false;
    const ir_expr *e = s->expr;
    if (e && s->kind == IS_EXPR && e->kind == IE_ASSIGN) return !hfx_ir_has_side_effects(e->a[0]) && !hfx_ir_has_side_effects(e->a[1]);
    return !hfx_ir_has_side_effects(e);
}

/* Statement i of block b declares a local the next statement reads once and nothing else
 * touches: the read becomes the initialiser and the declaration goes. */
static bool substitute(ir_stmt *fn_body, ir_stmt *b, uint32_t i) {
    ir_stmt *d = b->body[i], *next = i + 1 < b->count ? b->body[i + 1] : NULL;
    if (d->kind != IS_DECL || !d->var || d->var->kind != IRV_LOCAL || d->var->hoisted || !d->expr || !next ||
        !simple_next(next) || !hfx_type_is_numeric(d->var->type) || hfx_ir_has_side_effects(d->expr))
        return false;
    ir_uses all = {d->var, false, 0, 0, NULL}, here = {d->var, false, 0, 0, NULL};
    hfx_ir_count_uses(&here, next); /* first: most locals fail here, and the whole body costs more */
    if (here.reads != 1 || here.writes) return false;
    hfx_ir_count_uses(&all, fn_body);
    if (all.reads != 1 || all.writes) return false;
    *here.slot = d->expr;
    hfx_ir_remove_stmt(b, i);
    return true;
}

static void forward_block(ir_stmt *fn_body, ir_stmt *s) {
    if (!s) return;
    if (s->kind == IS_BLOCK)
        for (uint32_t i = 0; i < s->count;)
            if (!substitute(fn_body, s, i)) forward_block(fn_body, s->body[i++]);
    forward_block(fn_body, s->then_s);
    forward_block(fn_body, s->else_s);
}

/* ---- reassociation ---- */

static bool is_mul(const ir_expr *e) { return e->kind == IE_INTRIN && e->intrin == HFX_INTR_MUL && e->n == 2; }

static bool float_matrix(const ir_expr *e) {
    return e->type->kind == TY_MATRIX && (e->type->base == B_FLOAT || e->type->base == B_HALF);
}

static ir_expr *product(ir_ctx *c, ir_expr *a, ir_expr *b, const hfx_type *ty, hfx_loc loc) {
    ir_expr *m = hfx_ir_new_expr(c, IE_INTRIN, ty, loc, 2);
    m->intrin = HFX_INTR_MUL;
    m->a[0] = a;
    m->a[1] = b;
    return m;
}

static void reassociate(ir_ctx *c, ir_expr **slot, void *data) {
    (void)data;
    ir_expr *e = *slot;
    if (!is_mul(e) || e->type->kind != TY_VECTOR) return;
    ir_expr *in = e->a[0], *B = e->a[1];
    if (is_mul(in) && in->type->kind == TY_VECTOR && float_matrix(in->a[1]) && float_matrix(B) &&
        in->a[0]->type->kind == TY_VECTOR && hfx_ir_pre_only(c, in->a[1]) && hfx_ir_pre_only(c, B)) {
        const hfx_type *ab = hfx_type_matrix(c->types, B_FLOAT, in->a[1]->type->rows, B->type->cols);
        if (ab) e->a[0] = in->a[0], e->a[1] = product(c, in->a[1], B, ab, e->loc);
        return;
    }
    in = e->a[1], B = e->a[0];
    if (is_mul(in) && in->type->kind == TY_VECTOR && float_matrix(in->a[0]) && float_matrix(B) &&
        in->a[1]->type->kind == TY_VECTOR && hfx_ir_pre_only(c, in->a[0]) && hfx_ir_pre_only(c, B)) {
        const hfx_type *ba = hfx_type_matrix(c->types, B_FLOAT, B->type->rows, in->a[0]->type->cols);
        if (ba) e->a[0] = product(c, B, in->a[0], ba, e->loc), e->a[1] = in->a[1];
    }
}

/* ---- a product taken from its source ---- */

static ir_stmt *decl_of(ir_stmt *s, const ir_var *v) {
    if (!s) return NULL;
    if (s->kind == IS_DECL && s->var == v) return s;
    ir_stmt *found = decl_of(s->init, v);
    for (uint32_t i = 0; !found && i < s->count; i++) found = decl_of(s->body[i], v);
    if (!found) found = decl_of(s->then_s, v);
    return found ? found : decl_of(s->else_s, v);
}

static bool never_written(ir_stmt *body, const ir_var *v) {
    ir_uses u = {v, false, 0, 0, NULL};
    hfx_ir_count_uses(&u, body);
    return u.writes == 0;
}

/* Every variable e reads keeps its value through the function (parameters and locals only:
 * a callee may change a private global). */
static bool unchanging(ir_stmt *body, const ir_expr *e) {
    if (e->kind == IE_VAR)
        return (e->var->kind == IRV_PARAM || e->var->kind == IRV_LOCAL || e->var->kind == IRV_UNIFORM) &&
               never_written(body, e->var);
    if (e->kind == IE_CALL || hfx_ir_has_side_effects(e)) return false;
    for (uint32_t i = 0; i < e->n; i++)
        if (!unchanging(body, e->a[i])) return false;
    return true;
}

static bool has_constant_part(const ir_expr *y) {
    if (y->kind != IE_CONSTRUCT) return false;
    for (uint32_t i = 0; i < y->n; i++)
        if (hfx_ir_is_const(y->a[i])) return true;
    return false;
}

/* x's value when it is mul(y, A) (row form; A first for the column form), set once by its
 * declaration from values that do not change, with y's constant component; else NULL. */
static const ir_expr *source_product(const ir_ctx *c, ir_stmt *body, const ir_expr *x, bool row) {
    if (x->kind != IE_VAR || x->var->kind != IRV_LOCAL) return NULL;
    const ir_stmt *d = decl_of(body, x->var);
    const ir_expr *m = d ? d->expr : NULL;
    if (!m || !is_mul(m) || !never_written(body, x->var)) return NULL;
    const ir_expr *y = m->a[row ? 0 : 1], *A = m->a[row ? 1 : 0];
    if (y->type != x->type || !float_matrix(A) || !hfx_ir_pre_only(c, A) || !has_constant_part(y) || !unchanging(body, y))
        return NULL;
    return m;
}

static void from_source(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    if (!is_mul(e) || e->type->kind != TY_VECTOR) return;
    bool row = e->a[0]->type->kind == TY_VECTOR;
    ir_expr *x = e->a[row ? 0 : 1], *B = e->a[row ? 1 : 0];
    const ir_expr *m = float_matrix(B) && hfx_ir_pre_only(c, B) ? source_product(c, data, x, row) : NULL;
    if (!m) return;
    const ir_expr *A = m->a[row ? 1 : 0];
    const hfx_type *ab = row ? hfx_type_matrix(c->types, B_FLOAT, A->type->rows, B->type->cols)
                             : hfx_type_matrix(c->types, B_FLOAT, B->type->rows, A->type->cols);
    if (!ab) return;
    ir_expr *y = hfx_ir_clone_expr(c, m->a[row ? 0 : 1]), *a = hfx_ir_clone_expr(c, A);
    e->a[row ? 0 : 1] = y;
    e->a[row ? 1 : 0] = row ? product(c, a, B, ab, e->loc) : product(c, B, a, ab, e->loc);
}

void hfx_ir_pass_forward(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) {
        forward_block(sh->funcs[i]->body, sh->funcs[i]->body);
        hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, reassociate, NULL);
        hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, from_source, sh->funcs[i]->body);
    }
}
