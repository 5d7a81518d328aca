/* licm.c: loop-invariant code motion. A loop body often recomputes what no iteration changes
 * (pointlights.fx normalises the interpolated normal and view vector once per light), and
 * llvmpipe does not move such work out of a loop itself: its loops keep values in masked
 * allocas. Each maximal pure subexpression of a loop (condition, step or body) whose variables
 * the loop never writes, and that computes something, becomes a local (hfx_invN) declared with
 * that expression right before the loop; the loop reads the local. The value is the same
 * expression's, evaluated once. Evaluating it when the loop runs zero times, or on a path the
 * body would not take, is harmless for pure math (GLSL has no traps); integer division, which
 * may trap on some drivers, stays where it is.
 *
 * Conservative on purpose: a variable counts as written when the loop declares it, assigns
 * it (through swizzles, fields, indexes or as an out argument) or when its for-init declares
 * it; a call of a user function in the loop makes every private global written (the callee
 * may assign it); an l-value whose variable cannot be told stops the loop's hoisting. Texture
 * sampling, derivatives, clip, calls and anything with side effects are never moved. Inner
 * loops go first, so what an outer loop does not change moves out of it too. */
#include "ir/ir.h"

typedef struct licm {
    ir_ctx *c;
    ir_var_set w;  /* what the loop at hand may change (unknown: hoist nothing) */
    ir_stmt **decls; uint32_t decl_count, decl_cap; /* the locals hoisted out of the loop at hand */
    unsigned next;                                  /* hfx_invN: N, unique in the function */
} licm;

/* The loop's writes, its for-init included (what it declares is not in scope before it; a
 * variable declared inside takes a new value each iteration). */
static void find_writes(licm *l, ir_stmt *loop) {
    l->w.count = 0;
    l->w.calls = l->w.unknown = false;
    hfx_ir_note_writes(l->c, loop, &l->w);
}

/* ---- what may move ---- */

static bool invariant_var(const licm *l, const ir_var *v) {
    if (l->w.calls && v->kind == IRV_PRIVATE) return false;
    return !hfx_ir_var_set_has(&l->w, v);
}

/* The node itself may be computed before the loop, its operands aside. */
static bool movable_node(const licm *l, const ir_expr *e) {
    switch (e->kind) {
    case IE_CONST: return true;
    case IE_VAR: return invariant_var(l, e->var);
    case IE_UNARY: return e->op == OP_NEG || e->op == OP_NOT || e->op == OP_BITNOT;
    case IE_BINARY: return !hfx_ir_integer_division(e);
    case IE_SELECT: case IE_CONSTRUCT: case IE_CONVERT: case IE_SWIZZLE: case IE_INDEX: case IE_FIELD: return true;
    case IE_INTRIN: return hfx_ir_intrinsic_movable(e->intrin);
    default: return false; /* assignments, calls, commas */
    }
}

/* Worth a local: it computes (an operator, an intrinsic, a select, a guarded array read), not
 * only moves components. */
static bool computes(const ir_expr *e) {
    if (e->kind == IE_BINARY || e->kind == IE_INTRIN || e->kind == IE_SELECT) return true;
    if (e->kind == IE_INDEX && !hfx_ir_is_const(e->a[1])) return true;
    for (uint32_t i = 0; i < e->n; i++)
        if (computes(e->a[i])) return true;
    return false;
}

/* A type a local can hold in every GLSL target (no arrays, structs, samplers or bool matrices). */
static bool local_type(const hfx_type *t) {
    return hfx_type_is_numeric(t) && !(t->kind == TY_MATRIX && t->base == B_BOOL);
}

/* ---- moving ---- */

static ir_stmt *new_decl(licm *l, ir_expr *value) {
    ir_var *v = HFX_NEW(l->c->arena, ir_var);
    ir_stmt *d = HFX_NEW(l->c->arena, ir_stmt);
    if (!v || !d || !HFX_ARENA_GROW(l->c->arena, l->decls, l->decl_count, l->decl_cap, 4)) return NULL;
    v->kind = IRV_LOCAL;
    v->name = v->glsl = hfx_arena_printf(l->c->arena, "hfx_inv%u", l->next++);
    v->type = value->type;
    v->param = HFX_NONE;
    d->kind = IS_DECL;
    d->loc = value->loc;
    d->var = v;
    d->expr = value;
    l->decls[l->decl_count++] = d;
    return d;
}

/* *slot, invariant, computed into a new local before the loop; the loop reads the local. */
static void move_out(licm *l, ir_expr **slot) {
    ir_expr *e = *slot;
    if (!local_type(e->type) || !computes(e)) return;
    ir_expr *r = hfx_ir_new_expr(l->c, IE_VAR, e->type, e->loc, 0);
    ir_stmt *d = r ? new_decl(l, e) : NULL;
    if (!d) return;
    r->var = d->var;
    *slot = r;
}

/* Whether *slot is invariant in the loop; the invariant parts of what is not move out. */
static bool visit(licm *l, ir_expr **slot, int depth) {
    ir_expr *e = *slot;
    if (!e || depth > 200) return false;
    bool local[8], *inv = e->n <= 8 ? local : HFX_NEW_ARRAY(l->c->arena, bool, e->n);
    if (!inv) return false;
    bool all = movable_node(l, e);
    for (uint32_t i = 0; i < e->n; i++) all &= inv[i] = visit(l, &e->a[i], depth + 1);
    if (all) return true;
    for (uint32_t i = 0; i < e->n; i++)
        if (inv[i]) move_out(l, &e->a[i]);
    return false;
}

/* A statement's own expression: moved whole when invariant, unless the statement is only that
 * expression (kept for its effect, and an invariant one has none). */
static void visit_root(licm *l, ir_expr **slot, bool whole) {
    if (visit(l, slot, 0) && whole) move_out(l, slot);
}

/* Every expression the loop evaluates each iteration: condition, step, and the body's. */
static void visit_stmt(licm *l, ir_stmt *s) {
    if (!s) return;
    visit_stmt(l, s->init); /* for-init of an inner loop: runs each outer iteration */
    if (s->expr) visit_root(l, &s->expr, s->kind != IS_EXPR && s->kind != IS_CASE);
    if (s->step) visit_root(l, &s->step, false);
    for (uint32_t i = 0; i < s->count; i++) visit_stmt(l, s->body[i]);
    visit_stmt(l, s->then_s);
    visit_stmt(l, s->else_s);
}

static bool is_loop(const ir_stmt *s) { return s && (s->kind == IS_FOR || s->kind == IS_WHILE || s->kind == IS_DO); }

/* The locals to declare before `loop` (l->decls), its for-init left where it runs. */
static void hoist_loop(licm *l, ir_stmt *loop) {
    l->decl_count = 0;
    find_writes(l, loop);
    if (l->w.unknown) return;
    if (loop->expr) visit_root(l, &loop->expr, true);
    if (loop->step) visit_root(l, &loop->step, false);
    visit_stmt(l, loop->then_s);
}

static void licm_stmt(licm *l, ir_stmt **slot);

/* Statement i of block b, a loop: its locals go in before it. */
static uint32_t hoist_in_block(licm *l, ir_stmt *b, uint32_t i) {
    hoist_loop(l, b->body[i]);
    uint32_t n = l->decl_count;
    if (!n) return i + 1;
    return hfx_ir_insert_stmts(l->c, b, i, l->decls, n) ? i + n + 1 : i + 1;
}

/* A loop that is not in a block (an if's branch, another loop's whole body, a case) gets one, unless
 * its for-init variable outlives it (HLSL scoping: the printer declares it before the loop). */
static void hoist_alone(licm *l, ir_stmt **slot) {
    ir_stmt *loop = *slot, *b = HFX_NEW(l->c->arena, ir_stmt);
    ir_stmt **body = HFX_NEW_ARRAY(l->c->arena, ir_stmt *, 1);
    if (!b || !body || (loop->init && loop->init->kind == IS_DECL && loop->init->var->hoisted)) return;
    b->kind = IS_BLOCK;
    b->loc = loop->loc;
    b->body = body;
    b->body[0] = loop;
    b->count = 1;
    hoist_in_block(l, b, 0);
    if (b->count > 1) *slot = b;
}

/* A block's or a switch's statements; in a switch a loop's locals get a block of their own
 * (declared among the cases, a later case would see them undefined). */
static void licm_block(licm *l, ir_stmt *b) {
    for (uint32_t i = 0; i < b->count;) {
        licm_stmt(l, &b->body[i]);
        if (!is_loop(b->body[i])) i++;
        else if (b->kind == IS_SWITCH) hoist_alone(l, &b->body[i++]);
        else i = hoist_in_block(l, b, i);
    }
}

/* A loop's body or an if's branch; when it is a loop itself, that loop's locals need a block. */
static void licm_branch(licm *l, ir_stmt **slot) {
    licm_stmt(l, slot);
    if (is_loop(*slot)) hoist_alone(l, slot);
}

/* Inner statements first: an inner loop's locals are then the outer loop's to move further. */
static void licm_stmt(licm *l, ir_stmt **slot) {
    ir_stmt *s = *slot;
    if (!s) return;
    if (s->kind == IS_BLOCK || s->kind == IS_SWITCH) { licm_block(l, s); return; }
    if (!is_loop(s) && s->kind != IS_IF) return;
    licm_branch(l, &s->then_s);
    if (s->kind == IS_IF) licm_branch(l, &s->else_s);
}

void hfx_ir_pass_licm(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) {
        licm l = {c, {NULL, 0, 0, false, false}, NULL, 0, 0, 0};
        if (sh->funcs[i]->body) licm_stmt(&l, &sh->funcs[i]->body);
    }
}
