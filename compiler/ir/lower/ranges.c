/* ranges.c: what a for loop's counter tells of the array reads it indexes. A uniform array read
 * at a dynamic index goes through a guard that returns zero past either end (D3D9's unset
 * registers; hfx_glsl_expr.c print_guarded_read). Inside the body of
 *     for (int i = C; i < X; i += K)      (or i <= X; ++i, i++; C >= 0, K > 0 constants)
 * where nothing but the step writes i, i is never negative, and when X is a constant it is
 * at most X - 1 (X for <=): a read arr[i] in that body is marked IR_RANGE_NONNEG, or
 * IR_RANGE_IN_BOUNDS when the bound fits arr's length, so the printer drops the half of the
 * guard that cannot fail, or the whole guard. An index anything else computes stays
 * IR_RANGE_ANY: zero past the end is kept for every index that can be out of range.
 * Overflow: the counter steps by K only after a check that it is below X, so with K = 1 and a
 * strict < it stays at most INT_MAX; other steps need a constant bound far enough from it. */
#include <stdint.h>

#include "ir/ir.h"

enum { INT_TOP = 2147483647 };

typedef struct counter {
    const ir_var *v;
    int64_t lo, hi, step; /* hi: the largest value the body sees (INT64_MAX: no constant bound) */
    bool strict;          /* the bound is a `<` (needed without a constant bound) */
} counter;

static bool int_scalar(const hfx_type *t) { return t->kind == TY_SCALAR && t->base == B_INT; }

static bool int_const(const ir_expr *e, int64_t *out) {
    if (!hfx_ir_is_const(e) || !int_scalar(e->type)) return false;
    *out = hfx_ev_int(e->cval[0]);
    return true;
}

static bool local_int(const ir_var *v) {
    return (v->kind == IRV_LOCAL || v->kind == IRV_PARAM) && int_scalar(v->type);
}

/* `int i = C` or `i = C`, C >= 0. */
static bool counter_init(const ir_stmt *s, counter *k) {
    if (s && s->kind == IS_DECL && s->var && local_int(s->var) && s->expr && int_const(s->expr, &k->lo))
        k->v = s->var;
    else if (s && s->kind == IS_EXPR && s->expr && s->expr->kind == IE_ASSIGN && s->expr->op == OP_NONE &&
             s->expr->a[0]->kind == IE_VAR && local_int(s->expr->a[0]->var) && int_const(s->expr->a[1], &k->lo))
        k->v = s->expr->a[0]->var;
    return k->v && k->lo >= 0;
}

static bool is_counter(const ir_expr *e, const counter *k) { return e->kind == IE_VAR && e->var == k->v; }

/* `i++`, `++i` or `i += K`, K > 0. */
static bool counter_step(const ir_expr *e, counter *k) {
    if (!e) return false;
    if (e->kind == IE_UNARY && (e->op == OP_PREINC || e->op == OP_POSTINC) && is_counter(e->a[0], k)) k->step = 1;
    else if (!(e->kind == IE_ASSIGN && e->op == OP_ADD && is_counter(e->a[0], k) && int_const(e->a[1], &k->step)))
        return false;
    return k->step > 0;
}

/* `i < X`, `i <= X` (or X > i, X >= i), or such a test and-ed with others: the tightest. */
static void counter_bound(const ir_expr *e, counter *k) {
    if (!e || e->kind != IE_BINARY) return;
    if (e->op == OP_AND) { counter_bound(e->a[0], k); counter_bound(e->a[1], k); return; }
    bool flip = e->op == OP_GT || e->op == OP_GE, strict = e->op == OP_LT || e->op == OP_GT;
    const ir_expr *x = e->a[flip ? 0 : 1];
    if (!(strict || e->op == OP_LE || e->op == OP_GE) || !is_counter(e->a[flip ? 1 : 0], k) || !int_scalar(x->type))
        return;
    k->strict |= strict;
    int64_t c;
    if (int_const(x, &c) && c - (strict ? 1 : 0) < k->hi) k->hi = c - (strict ? 1 : 0);
}

/* The counter's writes outside the step (note_write's count). */
typedef struct writes { const ir_var *v; unsigned count; } writes;

static void count_target(writes *w, const ir_expr *e, const ir_expr *target) {
    if (e->kind == IE_ASSIGN && target->kind == IE_CONSTRUCT) { /* float4(a, b) = v */
        for (uint32_t k = 0; k < target->n; k++) count_target(w, e, target->a[k]);
        return;
    }
    const ir_var *root = hfx_ir_lvalue_root(target);
    if (!root || root == w->v) w->count++; /* a target that cannot be told counts */
}

static void note_write(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    const ir_expr *e = *slot;
    for (uint32_t i = 0; i < e->n; i++)
        if (hfx_ir_writes_operand(e, i)) count_target(data, e, e->a[i]);
}

static bool only_step_writes(ir_ctx *c, ir_stmt *loop, const counter *k) {
    writes w = {k->v, 0};
    hfx_ir_walk_expr(c, &loop->expr, note_write, &w);
    hfx_ir_walk_stmt_exprs(c, loop->then_s, note_write, &w);
    return w.count == 0;
}

/* The loop's counter, or false when what it is cannot be told. */
static bool find_counter(ir_ctx *c, ir_stmt *loop, counter *k) {
    *k = (counter){NULL, 0, INT64_MAX, 0, false};
    if (!counter_init(loop->init, k) || !counter_step(loop->step, k) || hfx_ir_has_side_effects(loop->expr)) return false;
    counter_bound(loop->expr, k);
    bool no_overflow = k->hi != INT64_MAX ? k->hi + k->step <= INT_TOP : k->step == 1 && k->strict;
    return no_overflow && only_step_writes(c, loop, k);
}

static void mark(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    const counter *k = data;
    ir_expr *e = *slot;
    if (e->kind != IE_INDEX || !is_counter(e->a[1], k) || e->a[0]->type->kind != TY_ARRAY) return;
    e->range = k->hi < (int64_t)e->a[0]->type->array_len ? IR_RANGE_IN_BOUNDS : IR_RANGE_NONNEG;
}

static void ranges_stmt(ir_ctx *c, ir_stmt *s) {
    if (!s) return;
    counter k;
    if (s->kind == IS_FOR && find_counter(c, s, &k)) hfx_ir_walk_stmt_exprs(c, s->then_s, mark, &k);
    for (uint32_t i = 0; i < s->count; i++) ranges_stmt(c, s->body[i]);
    ranges_stmt(c, s->then_s);
    ranges_stmt(c, s->else_s);
}

void hfx_ir_pass_ranges(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) ranges_stmt(c, sh->funcs[i]->body);
}
