/* walk.c: generic traversals of the IR tree shared by the passes. */
#include <string.h>

#include "ir/ir.h"

/* Operands first, then the node. A leaf operand is visited here rather than through a call of
 * its own: about half the nodes are leaves, and the walks are most of the lowering's time. */
void ir_walk_expr(ir_ctx *c, ir_expr **slot, ir_expr_fn fn, void *data) {
    ir_expr *e = *slot;
    if (!e) return;
    for (uint32_t i = 0; i < e->n; i++) {
        const ir_expr *k = e->a[i];
        if (k && k->n) ir_walk_expr(c, &e->a[i], fn, data);
        else if (k) fn(c, &e->a[i], data);
    }
    fn(c, slot, data);
}

void ir_walk_stmt_exprs(ir_ctx *c, ir_stmt *s, ir_expr_fn fn, void *data) {
    if (!s) return;
    if (s->init) ir_walk_stmt_exprs(c, s->init, fn, data);
    ir_walk_expr(c, &s->expr, fn, data);
    ir_walk_expr(c, &s->step, fn, data);
    for (uint32_t i = 0; i < s->count; i++) ir_walk_stmt_exprs(c, s->body[i], fn, data);
    ir_walk_stmt_exprs(c, s->then_s, fn, data);
    ir_walk_stmt_exprs(c, s->else_s, fn, data);
}

void ir_walk_stmt_roots(ir_ctx *c, ir_stmt *s, ir_expr_fn fn, void *data) {
    if (!s) return;
    if (s->init) ir_walk_stmt_roots(c, s->init, fn, data);
    if (s->expr) fn(c, &s->expr, data);
    if (s->step) fn(c, &s->step, data);
    for (uint32_t i = 0; i < s->count; i++) ir_walk_stmt_roots(c, s->body[i], fn, data);
    ir_walk_stmt_roots(c, s->then_s, fn, data);
    ir_walk_stmt_roots(c, s->else_s, fn, data);
}

ir_expr *ir_clone_expr(ir_ctx *c, const ir_expr *e) {
    if (!e) return NULL;
    ir_expr *r = ir_new_expr(c, e->kind, e->type, e->loc, 0);
    ir_expr **args = r->a;
    *r = *e;
    r->a = args;
    if (e->n) {
        r->a = HFX_NEW_ARRAY(c->arena, ir_expr *, e->n);
        for (uint32_t i = 0; i < e->n; i++) r->a[i] = ir_clone_expr(c, e->a[i]);
    }
    return r;
}

bool ir_same_expr(const ir_expr *a, const ir_expr *b) {
    if (a == b) return true;
    if (!a || !b || a->kind != b->kind || a->op != b->op || a->n != b->n || !hfx_type_equal(a->type, b->type) ||
        a->var != b->var || a->fn != b->fn || a->intrin != b->intrin || a->field != b->field ||
        a->comp_count != b->comp_count || memcmp(a->comps, b->comps, a->comp_count) != 0)
        return false;
    if (a->kind == IE_CONST && memcmp(a->cval, b->cval, hfx_type_components(a->type) * sizeof *a->cval) != 0) return false;
    for (uint32_t i = 0; i < a->n; i++)
        if (!ir_same_expr(a->a[i], b->a[i])) return false;
    return true;
}

bool ir_has_side_effects(const ir_expr *e) {
    if (!e) return false;
    if (e->kind == IE_ASSIGN || e->kind == IE_CALL) return true;
    if (e->kind == IE_UNARY && e->op >= OP_PREINC && e->op <= OP_POSTDEC) return true;
    if (e->kind == IE_INTRIN && (e->intrin == HFX_INTR_CLIP || e->intrin == HFX_INTR_SINCOS || e->intrin == HFX_INTR_MODF ||
                                 e->intrin == HFX_INTR_FREXP))
        return true;
    for (uint32_t i = 0; i < e->n; i++)
        if (ir_has_side_effects(e->a[i])) return true;
    return false;
}

bool ir_writes_operand(const ir_expr *e, uint32_t i) {
    switch (e->kind) {
    case IE_ASSIGN: return i == 0;
    case IE_UNARY: return e->op >= OP_PREINC && e->op <= OP_POSTDEC;
    case IE_CALL: return i < e->fn->param_count && (e->fn->params[i]->mods & MOD_OUT);
    case IE_INTRIN:
        if (e->intrin == HFX_INTR_SINCOS) return e->n == 3 && i > 0;
        return (e->intrin == HFX_INTR_MODF || e->intrin == HFX_INTR_FREXP) && e->n == 2 && i == 1;
    default: return false;
    }
}

/* The variable an l-value expression writes (through swizzles, indexes and fields). */
ir_var *ir_lvalue_root(const ir_expr *e) {
    while (e && (e->kind == IE_SWIZZLE || e->kind == IE_INDEX || e->kind == IE_FIELD)) e = e->a[0];
    return e && e->kind == IE_VAR ? e->var : NULL;
}
