/* walk.c: traversals of the IR tree shared by the passes: walks, comparisons, what a statement
 * reads and writes, and the small edits the passes that move code make. */
#include <string.h>

#include "ir/ir.h"

/* Operands first, then the node. A leaf operand is visited here rather than through a call of
 * its own: about half the nodes are leaves, and the walks are most of the lowering's time. */
void hfx_ir_walk_expr(ir_ctx *c, ir_expr **slot, ir_expr_fn fn, void *data) {
    ir_expr *e = *slot;
    if (!e) return;
    for (uint32_t i = 0; i < e->n; i++) {
        const ir_expr *k = e->a[i];
        if (k && k->n) hfx_ir_walk_expr(c, &e->a[i], fn, data);
        else if (k) fn(c, &e->a[i], data);
    }
    fn(c, slot, data);
}

void hfx_ir_walk_stmt_exprs(ir_ctx *c, ir_stmt *s, ir_expr_fn fn, void *data) {
    if (!s) return;
    if (s->init) hfx_ir_walk_stmt_exprs(c, s->init, fn, data);
    hfx_ir_walk_expr(c, &s->expr, fn, data);
    hfx_ir_walk_expr(c, &s->step, fn, data);
    for (uint32_t i = 0; i < s->count; i++) hfx_ir_walk_stmt_exprs(c, s->body[i], fn, data);
    hfx_ir_walk_stmt_exprs(c, s->then_s, fn, data);
    hfx_ir_walk_stmt_exprs(c, s->else_s, fn, data);
}

void hfx_ir_walk_stmt_roots(ir_ctx *c, ir_stmt *s, ir_expr_fn fn, void *data) {
    if (!s) return;
    if (s->init) hfx_ir_walk_stmt_roots(c, s->init, fn, data);
    if (s->expr) fn(c, &s->expr, data);
    if (s->step) fn(c, &s->step, data);
    for (uint32_t i = 0; i < s->count; i++) hfx_ir_walk_stmt_roots(c, s->body[i], fn, data);
    hfx_ir_walk_stmt_roots(c, s->then_s, fn, data);
    hfx_ir_walk_stmt_roots(c, s->else_s, fn, data);
}

ir_expr *hfx_ir_clone_expr(ir_ctx *c, const ir_expr *e) {
    if (!e) return NULL;
    ir_expr *r = hfx_ir_new_expr(c, e->kind, e->type, e->loc, 0);
    ir_expr **args = r->a;
    *r = *e;
    r->a = args;
    if (e->n) {
        r->a = HFX_NEW_ARRAY(c->arena, ir_expr *, e->n);
        for (uint32_t i = 0; i < e->n; i++) r->a[i] = hfx_ir_clone_expr(c, e->a[i]);
    }
    return r;
}

bool hfx_ir_same_expr(const ir_expr *a, const ir_expr *b) {
    if (a == b) return true;
    if (!a || !b || a->kind != b->kind || a->op != b->op || a->n != b->n || !hfx_type_equal(a->type, b->type) ||
        a->var != b->var || a->fn != b->fn || a->intrin != b->intrin || a->field != b->field ||
        a->comp_count != b->comp_count || memcmp(a->comps, b->comps, a->comp_count) != 0)
        return false;
    if (a->kind == IE_CONST && memcmp(a->cval, b->cval, hfx_type_components(a->type) * sizeof *a->cval) != 0) return false;
    for (uint32_t i = 0; i < a->n; i++)
        if (!hfx_ir_same_expr(a->a[i], b->a[i])) return false;
    return true;
}

bool hfx_ir_has_side_effects(const ir_expr *e) {
    if (!e) return false;
    if (e->kind == IE_ASSIGN || e->kind == IE_CALL) return true;
    if (e->kind == IE_UNARY && e->op >= OP_PREINC && e->op <= OP_POSTDEC) return true;
    if (e->kind == IE_INTRIN && (e->intrin == HFX_INTR_CLIP || e->intrin == HFX_INTR_SINCOS || e->intrin == HFX_INTR_MODF ||
                                 e->intrin == HFX_INTR_FREXP))
        return true;
    for (uint32_t i = 0; i < e->n; i++)
        if (hfx_ir_has_side_effects(e->a[i])) return true;
    return false;
}

bool hfx_ir_writes_operand(const ir_expr *e, uint32_t i) {
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
ir_var *hfx_ir_lvalue_root(const ir_expr *e) {
    while (e && (e->kind == IE_SWIZZLE || e->kind == IE_INDEX || e->kind == IE_FIELD)) e = e->a[0];
    return e && e->kind == IE_VAR ? e->var : NULL;
}

/* ---- shared by the passes that move code ---- */

bool hfx_ir_var_set_has(const ir_var_set *s, const ir_var *v) {
    for (uint32_t i = 0; i < s->count; i++)
        if (s->vars[i] == v) return true;
    return false;
}

void hfx_ir_var_set_add(ir_ctx *c, ir_var_set *s, const ir_var *v) {
    if (!v) { s->unknown = true; return; }
    if (hfx_ir_var_set_has(s, v)) return;
    if (HFX_ARENA_GROW(c->arena, s->vars, s->count, s->cap, 16)) s->vars[s->count++] = v;
    else s->unknown = true;
}

static void note_target(ir_ctx *c, ir_var_set *s, const ir_expr *t) {
    if (t->kind != IE_CONSTRUCT) { hfx_ir_var_set_add(c, s, hfx_ir_lvalue_root(t)); return; }
    for (uint32_t i = 0; i < t->n; i++) note_target(c, s, t->a[i]); /* float4(a, b) = v */
}

static void note_write(ir_ctx *c, ir_expr **slot, void *data) {
    ir_var_set *s = data;
    const ir_expr *e = *slot;
    if (e->kind == IE_CALL) s->calls = true;
    for (uint32_t i = 0; i < e->n; i++)
        if (hfx_ir_writes_operand(e, i)) note_target(c, s, e->a[i]);
}

static void note_decls(ir_ctx *c, ir_var_set *s, const ir_stmt *st) {
    if (!st) return;
    if (st->kind == IS_DECL) hfx_ir_var_set_add(c, s, st->var);
    note_decls(c, s, st->init);
    for (uint32_t i = 0; i < st->count; i++) note_decls(c, s, st->body[i]);
    note_decls(c, s, st->then_s);
    note_decls(c, s, st->else_s);
}

void hfx_ir_note_writes(ir_ctx *c, ir_stmt *s, ir_var_set *w) {
    hfx_ir_walk_stmt_exprs(c, s, note_write, w);
    note_decls(c, w, s);
}

void hfx_ir_remove_stmt(ir_stmt *b, uint32_t at) {
    for (uint32_t k = at; k + 1 < b->count; k++) b->body[k] = b->body[k + 1];
    b->count--;
}

static void put_value(ir_ctx *c, ir_expr **slot, void *data) {
    const ir_expr *value = (*slot)->kind == IE_VAR ? hfx_ir_var_map_get(data, (*slot)->var) : NULL;
    if (value) *slot = hfx_ir_clone_expr(c, value);
}

void hfx_ir_put_values(ir_ctx *c, ir_stmt *s, const ir_var_map *values) {
    if (values->count) hfx_ir_walk_stmt_exprs(c, s, put_value, (void *)values);
}

bool hfx_ir_insert_stmts(ir_ctx *c, ir_stmt *b, uint32_t at, ir_stmt *const *s, uint32_t n) {
    ir_stmt **body = HFX_NEW_ARRAY(c->arena, ir_stmt *, b->count + n);
    if (!body) return false;
    for (uint32_t k = 0; k < at; k++) body[k] = b->body[k];
    for (uint32_t k = 0; k < n; k++) body[at + k] = s[k];
    for (uint32_t k = at; k < b->count; k++) body[k + n] = b->body[k];
    b->body = body;
    b->count += n;
    return true;
}

bool hfx_ir_intrinsic_movable(ir_intrin id) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of((int)id);
    if (!info || info->sig == SIG_TEX) return false; /* sampling: derivatives depend on where it runs */
    return id != HFX_INTR_DDX && id != HFX_INTR_DDY && id != HFX_INTR_FWIDTH && id != HFX_INTR_CLIP &&
           id != HFX_INTR_NOISE && id != HFX_INTR_SINCOS && id != HFX_INTR_MODF && id != HFX_INTR_FREXP;
}

bool hfx_ir_integer_division(const ir_expr *e) {
    return e->kind == IE_BINARY && (e->op == OP_DIV || e->op == OP_MOD) && e->type->base != B_FLOAT &&
           e->type->base != B_HALF;
}

static void count_in(ir_uses *u, ir_expr **slot, bool lvalue);

static void count_args(ir_uses *u, ir_expr *e) {
    for (uint32_t i = 0; i < e->n; i++) {
        bool target = hfx_ir_writes_operand(e, i);
        if (target && e->kind == IE_ASSIGN && e->op != OP_NONE) count_in(u, &e->a[i], false); /* += reads too */
        count_in(u, &e->a[i], target);
    }
}

/* Reads and writes of u->v in *slot (lvalue: the place is written, through swizzles, indexes
 * and fields, whose indexes are read). */
static void count_in(ir_uses *u, ir_expr **slot, bool lvalue) {
    ir_expr *e = *slot;
    if (!e) return;
    if (e->kind == IE_VAR) {
        if (e->var != u->v) return;
        if (lvalue) u->writes++;
        else u->reads++, u->slot = slot;
        return;
    }
    if (lvalue && (e->kind == IE_SWIZZLE || e->kind == IE_FIELD || e->kind == IE_INDEX)) {
        count_in(u, &e->a[0], true);
        for (uint32_t i = 1; i < e->n; i++) count_in(u, &e->a[i], false);
        return;
    }
    if (lvalue && e->kind == IE_CONSTRUCT) { /* float4(a, b) = v */
        for (uint32_t i = 0; i < e->n; i++) count_in(u, &e->a[i], true);
        return;
    }
    count_args(u, e);
}

void hfx_ir_count_uses(ir_uses *u, ir_stmt *s) {
    if (!s) return;
    if (u->decls && s->kind == IS_DECL && s->var == u->v) u->writes++;
    hfx_ir_count_uses(u, s->init);
    count_in(u, &s->expr, false);
    count_in(u, &s->step, false);
    for (uint32_t i = 0; i < s->count; i++) hfx_ir_count_uses(u, s->body[i]);
    hfx_ir_count_uses(u, s->then_s);
    hfx_ir_count_uses(u, s->else_s);
}

bool hfx_ir_has_jumps(const ir_stmt *s) {
    if (!s) return false;
    if (s->kind == IS_BREAK || s->kind == IS_CONTINUE || s->kind == IS_RETURN || s->kind == IS_DISCARD) return true;
    for (uint32_t i = 0; i < s->count; i++)
        if (hfx_ir_has_jumps(s->body[i])) return true;
    return hfx_ir_has_jumps(s->init) || hfx_ir_has_jumps(s->then_s) || hfx_ir_has_jumps(s->else_s);
}
