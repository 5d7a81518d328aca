/* samplers.c: sampler array elements chosen by an index fxc makes a literal.
 *
 * D3D9 has no indexed sampler registers: `tex2D(S[i], uv)` needs i to be a literal once fxc has
 * unrolled and folded (X3512 "sampler array index must be a literal expression" otherwise). fxc
 * unrolls a loop it can count, so a loop counter indexing a sampler array becomes a literal in
 * each copy of the body; hfx does the same here: such a loop is unrolled (its counter a constant
 * in each copy, the step kept so the variable ends as the loop leaves it), and S[k] with k
 * constant after folding becomes element k's own sampler, as ir.c does for a literal k. An
 * index that stays computed is left to limits.c's X3512. This runs on every back end's IR: GLSL
 * and the D3D9 bytecode writer both see the element samplers only. */
#include <strings.h>

#include "eval.h"
#include "ir/ir.h"

static bool is_sampler_array(const ir_expr *e) {
    return e->kind == IE_VAR && e->var->kind == IRV_UNIFORM && e->var->decl && e->var->type->kind == TY_ARRAY &&
           e->var->type->elem->kind == TY_SAMPLER;
}

static bool reads(const ir_expr *e, const ir_var *v) {
    if (!e) return false;
    if (e->kind == IE_VAR) return e->var == v;
    for (uint32_t i = 0; i < e->n; i++)
        if (reads(e->a[i], v)) return true;
    return false;
}

typedef struct indexed { const ir_var *counter; bool found; } indexed;

static void note_index(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    indexed *x = data;
    const ir_expr *e = *slot;
    if (e->kind == IE_INDEX && is_sampler_array(e->a[0]) && reads(e->a[1], x->counter)) x->found = true;
}

/* A break or continue that would leave (or restart) the loop being unrolled. */
static bool jumps(const ir_stmt *s) {
    if (!s) return false;
    if (s->kind == IS_BREAK || s->kind == IS_CONTINUE) return true;
    for (uint32_t i = 0; i < s->count; i++)
        if (jumps(s->body[i])) return true;
    return jumps(s->init) || jumps(s->then_s) || jumps(s->else_s);
}

/* A copy's variables: the ones the body declares get their own (each copy declares them once),
 * and the counter reads as this iteration's value. */
typedef struct copy { ir_var_map fresh; const ir_var *counter; const ir_expr *value; bool failed; } copy;

static void rename_one(ir_ctx *c, ir_expr **slot, void *data) {
    copy *k = data;
    ir_expr *e = *slot;
    if (e->kind != IE_VAR) return;
    if (e->var == k->counter) *slot = hfx_ir_clone_expr(c, k->value);
    else {
        ir_var *v = hfx_ir_var_map_get(&k->fresh, e->var);
        if (v) e->var = v;
    }
}

static ir_expr *copy_expr(ir_ctx *c, copy *k, const ir_expr *e) {
    ir_expr *r = hfx_ir_clone_expr(c, e);
    hfx_ir_walk_expr(c, &r, rename_one, k);
    return r;
}

static ir_stmt *copy_stmt(ir_ctx *c, copy *k, const ir_stmt *s) {
    if (!s) return NULL;
    ir_stmt *r = hfx_ir_new_stmt(c, s->kind, s->loc);
    if (!r) return k->failed = true, NULL;
    *r = *s;
    if (s->kind == IS_DECL && s->var) {
        ir_var *v = HFX_NEW(c->arena, ir_var);
        if (!v || !hfx_ir_var_map_put(c, &k->fresh, s->var, v)) return k->failed = true, NULL;
        *v = *s->var;
        r->var = v;
    }
    r->init = copy_stmt(c, k, s->init);
    r->expr = copy_expr(c, k, s->expr);
    r->step = copy_expr(c, k, s->step);
    if (s->count) {
        r->body = HFX_NEW_ARRAY(c->arena, ir_stmt *, s->count);
        if (!r->body) return k->failed = true, NULL;
        for (uint32_t i = 0; i < s->count; i++) r->body[i] = copy_stmt(c, k, s->body[i]);
    }
    r->then_s = copy_stmt(c, k, s->then_s);
    r->else_s = copy_stmt(c, k, s->else_s);
    return r;
}

/* The counter's value on iteration n, computed as the loop steps it (a float counter rounds to
 * float at each step, as the GPU's register does). */
static double counter_value(const ir_var *v, double start, double step, int n) {
    double x = start;
    for (int i = 0; i < n; i++) x = v->type->base == B_FLOAT || v->type->base == B_HALF ? (double)(float)(x + step) : x + step;
    return x;
}

/* { init; { body with i = start } step; { body with i = start + step } step; ... }, or s itself
 * when it is no loop to unroll (or memory ran out). */
static ir_stmt *unroll(ir_ctx *c, ir_stmt *s) {
    const ir_var *v;
    double start, step;
    int trips = hfx_ir_loop_trips(s, &v, &start, &step);
    /* [loop] asks fxc to keep the loop: its index stays computed (X3512) */
    if (trips < 0 || v->hoisted || jumps(s->then_s) || (s->hint && strcasecmp(s->hint, "loop") == 0)) return s;
    indexed x = {v, false};
    hfx_ir_walk_stmt_exprs(c, s->then_s, note_index, &x);
    if (!x.found) return s;
    ir_stmt *b = hfx_ir_new_stmt(c, IS_BLOCK, s->loc);
    if (!b || !(b->body = HFX_NEW_ARRAY(c->arena, ir_stmt *, 1 + 2 * (uint32_t)trips))) return s;
    b->body[b->count++] = s->init;
    for (int n = 0; n < trips; n++) {
        copy k = {{0}, v, hfx_ir_const_scalar(c, v->type, counter_value(v, start, step, n), s->loc), false};
        ir_stmt *body = copy_stmt(c, &k, s->then_s), *next = hfx_ir_new_stmt(c, IS_EXPR, s->loc);
        if (k.failed || !k.value || !body || !next) return s;
        next->expr = hfx_ir_clone_expr(c, s->step);
        b->body[b->count++] = body;
        b->body[b->count++] = next;
    }
    return b;
}

/* ---- the counter after an unrolled loop ---- */

typedef struct last_value { const ir_var *counter; const ir_expr *value; } last_value;

static void put_last(ir_ctx *c, ir_expr **slot, void *data) {
    const last_value *l = data;
    if ((*slot)->kind == IE_VAR && (*slot)->var == l->counter) *slot = hfx_ir_clone_expr(c, l->value);
}

static void index_after(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    if (e->kind == IE_INDEX && is_sampler_array(e->a[0])) hfx_ir_walk_expr(c, &e->a[1], put_last, data);
}

/* `int i; for (i = 0; i < 2; i++) ...; tex2D(S[i], uv)`: a counter declared before the loop
 * leaves it with its last value, which fxc's unrolled code knows; S[i] in the statements after
 * the loop (until one writes i) reads that element. Only sampler indexes take the value: what
 * else reads i is left as written. */
static void after_loop(ir_ctx *c, const ir_stmt *loop, ir_stmt *block, uint32_t from) {
    const ir_var *v;
    double start, step;
    int trips = hfx_ir_loop_trips(loop, &v, &start, &step);
    if (trips < 0 || (loop->init && loop->init->kind == IS_DECL && loop->init->var == v)) return;
    last_value l = {v, hfx_ir_const_scalar(c, v->type, counter_value(v, start, step, trips), loop->loc)};
    if (!l.value) return;
    for (uint32_t j = from; j < block->count; j++) {
        ir_uses u = {v, false, 0, 0, NULL};
        hfx_ir_count_uses(&u, block->body[j]);
        if (u.writes) return;
        hfx_ir_walk_stmt_exprs(c, block->body[j], index_after, &l);
    }
}

static ir_stmt *unroll_in(ir_ctx *c, ir_stmt *s) {
    if (!s) return NULL;
    if (s->kind == IS_FOR) s = unroll(c, s);
    for (uint32_t i = 0; i < s->count; i++) {
        ir_stmt *was = s->body[i];
        s->body[i] = unroll_in(c, was);
        if (was && was->kind == IS_FOR && s->body[i] != was) after_loop(c, was, s, i + 1);
    }
    s->then_s = unroll_in(c, s->then_s);
    s->else_s = unroll_in(c, s->else_s);
    return s;
}

typedef struct pick { ir_shader *sh; } pick;

/* S[k] with k folding to a constant in range: element k's sampler. */
static void pick_element(ir_ctx *c, ir_expr **slot, void *data) {
    pick *p = data;
    ir_expr *e = *slot;
    if (e->kind != IE_INDEX || !is_sampler_array(e->a[0]) || !c->fx) return;
    const hfx_decl *d = e->a[0]->var->decl;
    if (d->index >= c->fx->top_param_count) return;
    hfx_ir_fold_value(c, &e->a[1]);
    const ir_expr *k = e->a[1];
    if (!hfx_ir_is_const(k) || k->type->kind != TY_SCALAR || k->cval[0] < 0 ||
        k->cval[0] >= c->fx->params[d->index].child_count)
        return;
    ir_var *v = hfx_ir_sampler_element(c, p->sh, d, (uint32_t)hfx_ev_uint(k->cval[0]));
    ir_expr *r = v ? hfx_ir_new_expr(c, IE_VAR, v->type, e->loc, 0) : NULL;
    if (!r) return;
    r->var = v;
    *slot = r;
}

/* ---- local samplers ---- */

/* D3D9 has no sampler values: a local sampler names a sampler register, so it must be set where
 * it is declared (`sampler2D s = Global;`, which reads as Global) and never again. One declared
 * without a value and read is fxc's read-before-write error, X4000 (Microsoft's list of HLSL
 * errors: "the specified variable is used without having been completely initialized"). */
typedef struct alias { const ir_var *local; ir_var *target; } alias;

static void put_alias(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    const alias *a = data;
    if ((*slot)->kind == IE_VAR && (*slot)->var == a->local) (*slot)->var = a->target;
}

/* Whether the declaration at b->body[at] of a local sampler went (its reads now read its value). */
static bool local_sampler(ir_ctx *c, ir_func *f, ir_stmt *b, uint32_t at) {
    const ir_stmt *d = b->body[at];
    if (d->kind != IS_DECL || !d->var || d->var->kind != IRV_LOCAL || d->var->type->kind != TY_SAMPLER) return false;
    ir_uses u = {d->var, false, 0, 0, NULL};
    hfx_ir_count_uses(&u, f->body);
    if (u.writes || (d->expr && d->expr->kind != IE_VAR)) return false;
    if (!d->expr && u.reads) {
        hfx_error(c->diags, (*u.slot)->loc, 4000, "variable '%s' used without having been completely initialized", d->var->name);
        return false;
    }
    if (d->expr) { /* the value it names, where it is read */
        alias a = {d->var, d->expr->var};
        hfx_ir_walk_stmt_exprs(c, f->body, put_alias, &a);
    }
    hfx_ir_remove_stmt(b, at);
    return true;
}

static void local_samplers(ir_ctx *c, ir_func *f, ir_stmt *s) {
    if (!s) return;
    for (uint32_t i = 0; i < s->count; i++) {
        if (s->kind == IS_BLOCK && local_sampler(c, f, s, i)) { i--; continue; }
        local_samplers(c, f, s->body[i]);
    }
    local_samplers(c, f, s->init);
    local_samplers(c, f, s->then_s);
    local_samplers(c, f, s->else_s);
}

void hfx_ir_pass_samplers(ir_ctx *c, ir_shader *sh) {
    pick p = {sh};
    for (uint32_t i = 0; i < sh->func_count; i++) {
        ir_func *f = sh->funcs[i];
        local_samplers(c, f, f->body);
        f->body = unroll_in(c, f->body);
        hfx_ir_walk_stmt_exprs(c, f->body, pick_element, &p);
    }
}
