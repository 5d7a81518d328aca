/* preshade.c: preshaders. fxc moves the work a shader does on parameters alone (say
 * `mul(World, mul(View, Projection))` per vertex, `cos(ConeAngle)` per pixel) out of the shader
 * into code the runtime runs on the CPU once per change; this pass does the same. Each maximal
 * uniform-only subexpression that computes something (an operator, an intrinsic, a select, a
 * varying index) becomes a private global, hfx_preN, which main reads from registers of hfx_c
 * (codegen gives them after the program's parameters); its eval_code program (ir/pre_code.c)
 * goes into the compiled effect. Equal expressions share one global. Its row in the pass table
 * (passes.c) runs when parameters are packed and preshaders are on, after the rows that reorder
 * what fxc's optimiser reorders, so more work reads parameters alone: a loop's invariant sum
 * terms (sums.c), locals forwarded and matrix chains regrouped (forward.c), scalar and
 * parameter factors first (factors.c); the uses pass runs again after it when it made a
 * preshader (parameters read only by preshaders leave the GLSL). */
#include <string.h>

#include "ir/ir.h"

/* What visit finds of a subtree: a preshader can compute it, it computes something, it reads a
 * parameter (an expression of constants alone is the folder's, not a preshader's). */
enum { UNI = 1, WORK = 2, READS = 4, HOIST = UNI | WORK | READS };

typedef struct pre {
    ir_ctx *c;
    ir_shader *sh;
    uint32_t regs; /* registers the stage uses so far */
} pre;

static unsigned regs_of(const hfx_type *t) { return t->kind == TY_MATRIX ? t->rows : 1; }

static bool result_ok(const hfx_type *t) {
    return hfx_type_is_numeric(t) && (t->base == B_FLOAT || t->base == B_HALF) && hfx_type_components(t) <= 16;
}

static ir_var *same_preshader(const pre *p, const hfx_type *t, const uint32_t *code, uint32_t words) {
    for (uint32_t i = 0; i < p->sh->pre_count; i++) {
        ir_var *v = p->sh->pres[i];
        if (v->type == t && v->pre_words == words && memcmp(v->pre_code, code, words * sizeof *code) == 0) return v;
    }
    return NULL;
}

static ir_var *new_preshader(pre *p, const ir_expr *e, uint32_t *code, uint32_t words) {
    if (p->regs + regs_of(e->type) > IR_STAGE_REGS ||
        !HFX_ARENA_GROW(p->c->arena, p->sh->pres, p->sh->pre_count, p->sh->pre_cap, 8))
        return NULL;
    ir_var *v = HFX_NEW(p->c->arena, ir_var);
    *v = (ir_var){0};
    v->kind = IRV_PRIVATE;
    v->name = v->glsl = hfx_arena_printf(p->c->arena, "hfx_pre%u", (unsigned)p->sh->pre_count);
    v->type = e->type;
    v->param = HFX_NONE;
    v->pre = e;
    v->pre_code = code;
    v->pre_words = words;
    v->pre_text = hfx_ir_pre_text(p->c, e);
    p->regs += regs_of(e->type);
    p->sh->pres[p->sh->pre_count++] = v;
    return v;
}

/* *slot, uniform-only and computing, read from a preshader; false when it cannot be one. */
static bool hoist(pre *p, ir_expr **slot) {
    ir_expr *e = *slot;
    uint32_t words = 0, *code = result_ok(e->type) ? hfx_ir_pre_code(p->c, e, &words) : NULL;
    if (!code) return false;
    ir_var *v = same_preshader(p, e->type, code, words);
    if (!v && !(v = new_preshader(p, e, code, words))) return false;
    ir_expr *r = hfx_ir_new_expr(p->c, IE_VAR, e->type, e->loc, 0);
    r->var = v;
    *slot = r;
    return true;
}

static unsigned visit(pre *p, ir_expr **slot, int depth);

/* The uniform-only, computing arguments of a node that is not, each hoisted (or, when one
 * cannot be, its own such parts). */
static void hoist_parts(pre *p, ir_expr *e, const unsigned *flags, int depth) {
    for (uint32_t i = 0; i < e->n; i++) {
        if ((flags ? flags[i] : visit(p, &e->a[i], depth + 1)) != HOIST) continue;
        if (!hoist(p, &e->a[i])) hoist_parts(p, e->a[i], NULL, depth + 1);
    }
}

/* The flags of *slot; the uniform-only parts of what is not are hoisted on the way. */
static unsigned visit(pre *p, ir_expr **slot, int depth) {
    ir_expr *e = *slot;
    if (!e || depth > 200) return 0;
    unsigned local[8], *flags = e->n <= 8 ? local : HFX_NEW_ARRAY(p->c->arena, unsigned, e->n);
    unsigned all = UNI, more = (hfx_ir_pre_work(e) ? WORK : 0) | (e->kind == IE_VAR ? READS : 0);
    if (!flags) return 0;
    for (uint32_t i = 0; i < e->n; i++) {
        flags[i] = visit(p, &e->a[i], depth + 1);
        all &= flags[i];
        more |= flags[i] & (WORK | READS);
    }
    if (all && hfx_ir_pre_node(p->c, e)) return UNI | more;
    hoist_parts(p, e, flags, depth);
    return 0;
}

static void root(ir_ctx *c, ir_expr **slot, void *data) {
    pre *p = data;
    (void)c;
    if (visit(p, slot, 0) == HOIST && !hoist(p, slot)) hoist_parts(p, *slot, NULL, 0);
}

/* The private copies the entry's first statements have assigned so far. */
typedef struct assigned { const ir_var **vars; uint32_t count, cap; } assigned;

static bool was_assigned(const assigned *a, const ir_var *v) {
    for (uint32_t i = 0; i < a->count; i++)
        if (a->vars[i] == v) return true;
    return false;
}

/* A read of a private copy not assigned yet reads its uniform instead: what the copy still holds. */
static void read_uniforms(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    ir_expr *e = *slot;
    if (e->kind == IE_VAR && e->var->copy_of && !was_assigned(data, e->var)) e->var = e->var->copy_of;
}

/* The reads of v that negate it (`-Light`). */
typedef struct negations { const ir_var *v; unsigned count; } negations;

static void count_negation(ir_ctx *c, ir_expr **slot, void *data) {
    negations *n = data;
    const ir_expr *e = *slot;
    (void)c;
    n->count += e->kind == IE_UNARY && e->op == OP_NEG && e->a[0]->kind == IE_VAR && e->a[0]->var == n->v;
}

/* The shader writes v once, with `assign`, and reads it elsewhere only negated: the negation
 * can be the preshader's. (Reads of both v and -v would take two registers for one, each read
 * costing llvmpipe more than the negation it saves.) A private global's initialiser, which
 * runs before the entry, must not read it. */
static bool only_negated(pre *p, const ir_var *v, ir_stmt *assign) {
    ir_uses all = {v, false, 0, 0, NULL}, own = {v, false, 0, 0, NULL}, init = {v, false, 0, 0, NULL};
    negations neg = {v, 0}, own_neg = {v, 0};
    for (uint32_t i = 0; i < p->sh->func_count; i++) {
        hfx_ir_count_uses(&all, p->sh->funcs[i]->body);
        hfx_ir_walk_stmt_exprs(p->c, p->sh->funcs[i]->body, count_negation, &neg);
    }
    hfx_ir_count_uses(&own, assign); /* `Light = normalize(Light)` reads it too */
    hfx_ir_walk_stmt_exprs(p->c, assign, count_negation, &own_neg);
    for (uint32_t i = 0; i < p->sh->global_count; i++) {
        ir_stmt s = {.kind = IS_EXPR, .expr = p->sh->globals[i]->init};
        hfx_ir_count_uses(&init, &s);
    }
    unsigned reads = all.reads - own.reads;
    return all.writes == 1 && reads && neg.count - own_neg.count == reads && !init.reads;
}

/* A statement the entry's leading assignments may pass: a local declared with a constant or
 * nothing (`float4 color = 0;`), which reads no parameter. */
static bool passable(const ir_stmt *s) {
    return s->kind == IS_DECL && (!s->expr || s->expr->kind == IE_CONST);
}

enum { KEPT, DROPPED, STOP };

/* One leading `copy = value;`: a preshader's value, or, when the copy is read only negated,
 * the value itself in those reads (the statement goes). STOP when the list of assigned
 * copies cannot grow: a later read must not take the parameter for the copy. */
static int leading_assignment(pre *p, ir_stmt *block, uint32_t i, assigned *done) {
    if (!HFX_ARENA_GROW(p->c->arena, done->vars, done->count, done->cap, 4)) return STOP;
    ir_expr *e = block->body[i]->expr;
    ir_var *copy = e->a[0]->var;
    ir_expr *value = hfx_ir_clone_expr(p->c, e->a[1]);
    hfx_ir_walk_expr(p->c, &value, read_uniforms, done);
    bool hoistable = visit(p, &value, 0) == HOIST;
    ir_var_map values = {0}; /* the copy's reads take the value */
    if (hoistable && only_negated(p, copy, block->body[i]) && hfx_ir_var_map_put(p->c, &values, copy, value)) {
        hfx_ir_remove_stmt(block, i);
        for (uint32_t f = 0; f < p->sh->func_count; f++) hfx_ir_put_values(p->c, p->sh->funcs[f]->body, &values);
        return DROPPED;
    }
    if (hoistable && hoist(p, &value)) e->a[1] = value;
    done->vars[done->count++] = copy;
    return KEPT;
}

/* The leading statements of a block (and of a block leading it); false where they end. */
static bool leading_assignments(pre *p, ir_stmt *block, assigned *done) {
    for (uint32_t i = 0; i < block->count;) {
        ir_stmt *s = block->body[i];
        ir_expr *e = s->kind == IS_EXPR ? s->expr : NULL;
        if (e && e->kind == IE_ASSIGN && e->op == OP_NONE && e->a[0]->kind == IE_VAR && e->a[0]->var->copy_of) {
            int r = leading_assignment(p, block, i, done);
            if (r == STOP) return false;
            i += r == KEPT;
        } else if (passable(s)) {
            i++;
        } else if (s->kind == IS_BLOCK) {
            if (!leading_assignments(p, s, done)) return false;
            i++;
        } else {
            return false;
        }
    }
    return true;
}

/* `Light = normalize(Light);` at the top of the entry, on a parameter the shader writes (its
 * private copy): the copy still holds the parameter there, so the right side is parameter-only
 * work too. Such assignments, in order until another statement, read a preshader. When the
 * shader writes the copy nowhere else and reads it only negated, those reads read the value
 * instead and the assignment goes: `dot(-Light, N)` negates on the CPU, in the preshader, not
 * per pixel (3.4 M instructions of directional.fx's 2048 x 2048 frame on llvmpipe). */
static void entry_assignments(pre *p) {
    ir_stmt *body = p->sh->entry->body;
    if (!body || body->kind != IS_BLOCK) return;
    assigned done = {0};
    leading_assignments(p, body, &done);
}

uint32_t hfx_ir_stage_regs(const ir_ctx *c, const ir_shader *sh) {
    uint32_t n = 0;
    for (uint32_t i = 0; i < sh->global_count; i++) {
        const ir_var *v = sh->globals[i];
        if (v->kind == IRV_UNIFORM && v->param != HFX_NONE) n += hfx_fx_param_packable(c->fx, v->param);
    }
    for (uint32_t i = 0; i < sh->pre_count; i++) n += regs_of(sh->pres[i]->type);
    return n;
}

void hfx_ir_pass_preshade(ir_ctx *c, ir_shader *sh) {
    pre p = {c, sh, hfx_ir_stage_regs(c, sh)};
    entry_assignments(&p);
    for (uint32_t i = 0; i < sh->func_count; i++) hfx_ir_walk_stmt_roots(c, sh->funcs[i]->body, root, &p);
    for (uint32_t i = 0; i < sh->global_count; i++)
        if (sh->globals[i]->kind == IRV_PRIVATE && sh->globals[i]->init) root(c, &sh->globals[i]->init, &p);
}
