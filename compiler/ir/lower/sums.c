/* sums.c: the loop-invariant terms of a sum a loop accumulates, added once. pointlights.fx adds
 * `AmbientColor * AmbientIntensity` to its colour once per light; a hand-written shader adds it
 * times the number of lights, before the loop. For a counted loop
 *     for (int i = C; i < N; i++) body      (C a constant, N parameter-only, i not assigned in
 *                                            the body, no break, continue, return or discard)
 * a statement `acc += t1 + t2 + ...` directly in the body, acc a local the loop reads and writes
 * nowhere else, gives its parameter-only terms (or a local licm declared from parameters alone
 * right before the loop) to one statement before the loop:
 *     acc += (t1 + ...) * (float)(N > C ? N - C : 0);
 * which the preshade pass then takes whole, leaving one addition per pixel. The result is the
 * same sum added in another order (float rounding aside). Its row in the pass table (passes.c)
 * runs only with preshaders on, so --no-preshaders keeps the loop as written. */
#include "ir/ir.h"

enum { MAX_TERMS = 16 };

typedef struct counted { const ir_var *i; double from; ir_expr *bound; } counted;

static bool is_var(const ir_expr *e, const ir_var *v) { return e && e->kind == IE_VAR && e->var == v; }

static bool int_scalar(const hfx_type *t) { return t->kind == TY_SCALAR && t->base == B_INT; }

/* ---- the loop's shape ---- */

static const ir_var *counter_start(const ir_stmt *init, double *from) {
    if (!init) return NULL;
    if (init->kind == IS_DECL && init->expr && init->expr->kind == IE_CONST && int_scalar(init->var->type)) {
        *from = init->expr->cval[0];
        return init->var;
    }
    const ir_expr *e = init->kind == IS_EXPR ? init->expr : NULL;
    if (e && e->kind == IE_ASSIGN && e->op == OP_NONE && e->a[0]->kind == IE_VAR && e->a[1]->kind == IE_CONST &&
        int_scalar(e->a[0]->type)) {
        *from = e->a[1]->cval[0];
        return e->a[0]->var;
    }
    return NULL;
}

static bool steps_by_one(const ir_expr *e, const ir_var *i) {
    if (!e) return false;
    if (e->kind == IE_UNARY && (e->op == OP_POSTINC || e->op == OP_PREINC)) return is_var(e->a[0], i);
    return e->kind == IE_ASSIGN && e->op == OP_ADD && is_var(e->a[0], i) && e->a[1]->kind == IE_CONST &&
           e->a[1]->cval[0] == 1;
}

static bool counted_loop(const ir_ctx *c, const ir_stmt *loop, counted *out) {
    const ir_expr *cond = loop->expr;
    if (loop->kind != IS_FOR || loop->max_iterations || !cond || cond->kind != IE_BINARY || cond->op != OP_LT) return false;
    out->i = counter_start(loop->init, &out->from);
    if (!out->i || !is_var(cond->a[0], out->i) || !int_scalar(cond->a[1]->type) || !hfx_ir_pre_only(c, cond->a[1]) ||
        !steps_by_one(loop->step, out->i))
        return false;
    ir_uses u = {out->i, true, 0, 0, NULL};
    hfx_ir_count_uses(&u, loop->then_s);
    out->bound = cond->a[1];
    return !hfx_ir_has_jumps(loop->then_s) && u.writes == 0;
}

/* ---- the sum ---- */

/* A loop's moves: the statements to run before it, and the locals whose values moved. */
typedef struct moves { ir_stmt *before[MAX_TERMS]; const ir_var *locals[MAX_TERMS]; unsigned nb, nl; } moves;

typedef struct terms { ir_expr *kept[MAX_TERMS], *moved[MAX_TERMS]; unsigned nk, nm; bool ok; } terms;

/* The parameter-only value of term t, before the loop at b->body[at]: t itself, or the
 * initialiser of a local declared (licm's) among the declarations right before the loop. */
static ir_expr *invariant_value(const ir_ctx *c, const ir_stmt *b, uint32_t at, ir_expr *t, moves *m) {
    if (hfx_ir_pre_only(c, t)) return t;
    if (t->kind != IE_VAR || t->var->kind != IRV_LOCAL) return NULL;
    for (uint32_t k = at; k-- > 0 && b->body[k]->kind == IS_DECL;) {
        if (b->body[k]->var != t->var) continue;
        if (!b->body[k]->expr || !hfx_ir_pre_only(c, b->body[k]->expr) || m->nl == MAX_TERMS) return NULL;
        m->locals[m->nl++] = t->var;
        return b->body[k]->expr;
    }
    return NULL;
}

static void split(const ir_ctx *c, const ir_stmt *b, uint32_t at, ir_expr *e, const hfx_type *ty, terms *ts, moves *m) {
    if (e->kind == IE_BINARY && e->op == OP_ADD && e->type == ty) {
        split(c, b, at, e->a[0], ty, ts, m);
        split(c, b, at, e->a[1], ty, ts, m);
        return;
    }
    ir_expr *v = ts->nk == MAX_TERMS || ts->nm == MAX_TERMS ? NULL : invariant_value(c, b, at, e, m);
    if (ts->nk == MAX_TERMS || ts->nm == MAX_TERMS) ts->ok = false;
    else if (v) ts->moved[ts->nm++] = v;
    else ts->kept[ts->nk++] = e;
}

static ir_expr *sum_of(ir_ctx *c, ir_expr *const *t, unsigned n, const hfx_type *ty, bool clone) {
    ir_expr *s = NULL;
    for (unsigned k = 0; k < n; k++) {
        ir_expr *x = clone ? hfx_ir_clone_expr(c, t[k]) : t[k];
        s = s ? hfx_ir_new_binary(c, OP_ADD, ty, s, x) : x;
    }
    return s;
}

/* (float)(N > C ? N - C : 0), as acc's type: how many times the loop runs. */
static ir_expr *trips(ir_ctx *c, const counted *k, const hfx_type *ty) {
    const hfx_type *i = k->bound->type, *f = hfx_type_scalar(c->types, ty->base);
    hfx_loc loc = k->bound->loc;
    ir_expr *from = hfx_ir_const_scalar(c, i, k->from, loc), *n = hfx_ir_clone_expr(c, k->bound);
    ir_expr *sel = hfx_ir_new_expr(c, IE_SELECT, i, loc, 3);
    sel->a[0] = hfx_ir_new_binary(c, OP_GT, hfx_type_scalar(c->types, B_BOOL), n, from);
    sel->a[1] = k->from == 0 ? hfx_ir_clone_expr(c, k->bound) : hfx_ir_new_binary(c, OP_SUB, i, hfx_ir_clone_expr(c, k->bound), hfx_ir_clone_expr(c, from));
    sel->a[2] = hfx_ir_const_scalar(c, i, 0, loc);
    ir_expr *r = hfx_ir_new_convert(c, f, sel);
    return ty->kind == TY_SCALAR ? r : hfx_ir_new_convert(c, ty, r);
}

/* `acc += ...` in the loop's body whose invariant terms may move; acc the local it adds to. */
static const ir_var *accumulator(const ir_stmt *s, ir_stmt *loop) {
    const ir_expr *e = s->kind == IS_EXPR ? s->expr : NULL;
    if (!e || e->kind != IE_ASSIGN || e->op != OP_ADD || e->a[0]->kind != IE_VAR) return NULL;
    const ir_var *acc = e->a[0]->var;
    if (acc->kind != IRV_LOCAL || (acc->type->base != B_FLOAT && acc->type->base != B_HALF) ||
        (acc->type->kind != TY_SCALAR && acc->type->kind != TY_VECTOR))
        return NULL;
    ir_uses u = {acc, true, 0, 0, NULL};
    hfx_ir_count_uses(&u, loop);
    return u.reads == 1 && u.writes == 1 ? acc : NULL; /* the += alone */
}

/* The invariant part of body statement s, as a statement to run before the loop, or NULL. */
static ir_stmt *take_invariant(ir_ctx *c, ir_stmt *b, uint32_t at, ir_stmt *s, const counted *k, moves *m) {
    const ir_var *acc = accumulator(s, b->body[at]);
    if (!acc) return NULL;
    ir_expr *e = s->expr;
    terms ts = {.ok = true};
    unsigned locals = m->nl;
    split(c, b, at, e->a[1], acc->type, &ts, m);
    if (!ts.ok || !ts.nm) {
        m->nl = locals;
        return NULL;
    }
    ir_stmt *before = hfx_ir_new_stmt(c, IS_EXPR, e->loc);
    ir_expr *add = before ? hfx_ir_new_expr(c, IE_ASSIGN, acc->type, e->loc, 2) : NULL;
    if (!add) return NULL;
    add->op = OP_ADD;
    add->a[0] = hfx_ir_clone_expr(c, e->a[0]);
    add->a[1] = hfx_ir_new_binary(c, OP_MUL, acc->type, sum_of(c, ts.moved, ts.nm, acc->type, true), trips(c, k, acc->type));
    before->expr = add;
    if (ts.nk) e->a[1] = sum_of(c, ts.kept, ts.nk, acc->type, false);
    else s->kind = IS_BLOCK, s->expr = NULL, s->count = 0; /* nothing left to add in the loop */
    return before;
}

/* The declarations of the locals whose values moved, when nothing reads them any more. */
static uint32_t drop_unread(ir_stmt *b, uint32_t at, const moves *m) {
    for (uint32_t j = 0; j < at;) {
        ir_uses u = {b->body[j]->var, false, 0, 0, NULL};
        bool moved = false;
        for (unsigned k = 0; k < m->nl; k++) moved |= b->body[j]->kind == IS_DECL && m->locals[k] == u.v;
        if (moved) hfx_ir_count_uses(&u, b);
        if (!moved || u.reads) { j++; continue; }
        hfx_ir_remove_stmt(b, j);
        at--;
    }
    return at;
}

/* Statement `at` of block b, a loop: its sums' invariant terms go in before it. Returns the
 * loop's index afterwards. */
static uint32_t sums_of_loop(ir_ctx *c, ir_stmt *b, uint32_t at) {
    counted k;
    moves m = {0};
    ir_stmt *loop = b->body[at], *body = loop->then_s;
    if (!counted_loop(c, loop, &k) || !body) return at;
    ir_stmt **list = body->kind == IS_BLOCK ? body->body : &loop->then_s;
    uint32_t n = body->kind == IS_BLOCK ? body->count : 1;
    for (uint32_t s = 0; s < n && m.nb < MAX_TERMS; s++) {
        ir_stmt *before = take_invariant(c, b, at, list[s], &k, &m);
        if (before) m.before[m.nb++] = before;
    }
    if (!m.nb || !hfx_ir_insert_stmts(c, b, at, m.before, m.nb)) return at;
    return drop_unread(b, at + m.nb, &m);
}

static void sums_stmt(ir_ctx *c, ir_stmt *s) {
    if (!s) return;
    for (uint32_t k = 0; k < s->count; k++) {
        sums_stmt(c, s->body[k]);
        if (s->kind == IS_BLOCK && s->body[k]->kind == IS_FOR) k = sums_of_loop(c, s, k);
    }
    sums_stmt(c, s->then_s);
    sums_stmt(c, s->else_s);
}

void hfx_ir_pass_sums(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) sums_stmt(c, sh->funcs[i]->body);
}
