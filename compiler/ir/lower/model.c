/* model.c: what the shader model of `compile ps_2_0 ...` refuses, as fxc refuses it (the check
 * pass runs it; errors at the HLSL position).
 *
 * X4502, interface semantics the model has no register for (D3D9's register pages):
 * - ps_1_x / ps_2_x inputs are the colour registers v0-v1 (COLOR0, COLOR1) and the texture
 *   coordinate registers t0-t7 (TEXCOORD0..7); VPOS and VFACE are ps_3_0's. An input is
 *   refused only when the entry reads it: a vertex shader's output struct with a POSITION
 *   member is the usual pixel input of ps_2_0 effects, and fxc declares what is read (a
 *   struct handed to a function: the members that function reads, as fxc inlines it).
 * - ps_3_0 inputs are v0-v9 with any usage and index 0..15 (dcl_usage), except POSITION0,
 *   the one fxc keeps for the position (its message: "Legal indices are in [1,15]").
 * - pixel outputs are oC0-oC3 (COLOR0..3) and oDepth (DEPTH0), in every model.
 * - vs_1_x / vs_2_x outputs are oPos, oPts, oFog, oD0-oD1 and oT0-oT7: POSITION0, PSIZE0,
 *   FOG0, COLOR0..1, TEXCOORD0..7; vs_3_0's o0-o11 take any usage.
 *
 * X3511, a loop marked [unroll] (no count) that fxc cannot unroll: a for loop whose counter
 * starts at a constant and steps by one, tested against a value no constant folds to, with no
 * break or return that could end it early; or one that runs past fxc's 1024 iterations. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "ir/ir.h"

enum { UNROLL_LIMIT = 1024 };

/* ---- interface semantics ---- */

/* The profile's model: 2 for "ps_2_0", 3 for "vs_3_0" (0: none given). */
static int model_major(const ir_shader *sh) {
    const char *p = sh->compile ? sh->compile->profile : NULL;
    return p && strlen(p) > 3 && isdigit((unsigned char)p[3]) ? p[3] - '0' : 0;
}

/* "TEXCOORD3" -> name length 8, index 3. */
static size_t split(const char *sem, unsigned *index) {
    size_t n = strlen(sem);
    while (n && isdigit((unsigned char)sem[n - 1])) n--;
    *index = (unsigned)strtoul(sem + n, NULL, 10);
    return n;
}

static bool named(const char *sem, size_t n, const char *name) { return n == strlen(name) && strncmp(sem, name, n) == 0; }

/* One register class: semantic name, highest index. */
typedef struct reg_class { const char *name; unsigned last; } reg_class;

/* Reports X4502 when sem is none of the classes (NULL-terminated), or past one's last index. */
static int check_in(ir_ctx *c, const ir_leaf *l, const char *what, const char *profile, const reg_class *classes) {
    unsigned index;
    size_t n = split(l->semantic, &index);
    for (const reg_class *k = classes; k->name; k++) {
        if (!named(l->semantic, n, k->name)) continue;
        if (index <= k->last) return 0;
        hfx_error(c->diags, l->loc, 4502, "invalid %s semantic '%s': Legal indices are in [0,%u]", what, l->semantic, k->last);
        return 1;
    }
    hfx_error(c->diags, l->loc, 4502, "invalid %s %s semantic '%s'", profile, what, l->semantic);
    return 1;
}

/* A read of an entry parameter or of fields of it: the parameter, then the fields in order. */
typedef struct read_path { const ir_var *root; uint32_t fields[IR_LEAF_DEPTH]; uint32_t depth; } read_path;
typedef struct reads { read_path *items; uint32_t count, cap; } reads;

/* What is being followed: `var` (an entry parameter, or a callee's parameter it was handed to)
 * stands for root's value at the fields of `at`. fxc inlines calls, so a struct handed whole to
 * a function reads the members that function reads. */
typedef struct follow { const ir_var *var; read_path at; unsigned depth; } follow;

static void reads_in_stmt(ir_ctx *c, reads *r, const follow *f, const ir_stmt *s);

/* e's field chain down to f->var: how many fields (in `chain`, innermost last), or -1. */
static int chain_to(const ir_expr *e, const follow *f, uint32_t chain[32]) {
    int n = 0;
    for (; e->kind == IE_FIELD; e = e->a[0])
        if (n < 32) chain[n++] = e->field;
    return e->kind == IE_VAR && e->var == f->var ? n : -1;
}

static read_path extend(const follow *f, const uint32_t chain[32], int n) {
    read_path p = f->at;
    while (n && p.depth < IR_LEAF_DEPTH) p.fields[p.depth++] = chain[--n];
    return p;
}

static void reads_in(ir_ctx *c, reads *r, const follow *f, const ir_expr *e) {
    if (!e) return;
    uint32_t chain[32];
    int n = chain_to(e, f, chain);
    if (n >= 0) {
        if (HFX_ARENA_GROW(c->arena, r->items, r->count, r->cap, 8)) r->items[r->count++] = extend(f, chain, n);
        return;
    }
    for (uint32_t i = 0; i < e->n; i++) {
        const ir_expr *a = e->a[i];
        int k = e->kind == IE_CALL && e->fn && i < e->fn->param_count && f->depth < 16 ? chain_to(a, f, chain) : -1;
        if (k < 0) { reads_in(c, r, f, a); continue; }
        follow inner = {e->fn->params[i], extend(f, chain, k), f->depth + 1};
        reads_in_stmt(c, r, &inner, e->fn->body);
    }
}

static void reads_in_stmt(ir_ctx *c, reads *r, const follow *f, const ir_stmt *s) {
    if (!s) return;
    reads_in(c, r, f, s->expr);
    reads_in(c, r, f, s->step);
    reads_in_stmt(c, r, f, s->init);
    for (uint32_t i = 0; i < s->count; i++) reads_in_stmt(c, r, f, s->body[i]);
    reads_in_stmt(c, r, f, s->then_s);
    reads_in_stmt(c, r, f, s->else_s);
}

/* Whether a read covers the leaf: the same parameter, one field path a prefix of the other. */
static bool is_read(const reads *r, const ir_leaf *l) {
    for (uint32_t i = 0; i < r->count; i++) {
        const read_path *p = &r->items[i];
        if (p->root != l->root) continue;
        uint32_t n = p->depth < l->depth ? p->depth : l->depth, k = 0;
        while (k < n && p->fields[k] == l->fields[k]) k++;
        if (k == n) return true;
    }
    return false;
}

/* The entry's inputs or outputs; a leaf's own error (X3502...) is left to the code generator,
 * which asks again and reports it once. */
static int leaves_of(ir_ctx *c, const ir_shader *sh, bool outputs, ir_leaf **l) {
    uint32_t count = c->diags->count, errors = c->diags->errors, warnings = c->diags->warnings;
    int n = hfx_ir_entry_leaves(c, sh->entry, outputs, l);
    if (n < 0) c->diags->count = count, c->diags->errors = errors, c->diags->warnings = warnings;
    return n;
}

static int check_semantics(ir_ctx *c, const ir_shader *sh) {
    static const reg_class ps2_in[] = {{"COLOR", 1}, {"TEXCOORD", 7}, {NULL, 0}};
    static const reg_class ps_out[] = {{"COLOR", 3}, {"DEPTH", 0}, {NULL, 0}};
    static const reg_class vs2_out[] = {{"POSITION", 0}, {"PSIZE", 0}, {"FOG", 0}, {"COLOR", 1}, {"TEXCOORD", 7}, {NULL, 0}};
    int major = model_major(sh), bad = 0;
    if (!major || !sh->entry) return 0;
    const char *profile = sh->compile->profile;
    ir_leaf *l;
    int n;
    if (sh->stage == IR_VERTEX) {
        if (major >= 3 || (n = leaves_of(c, sh, true, &l)) < 0) return 0;
        for (int i = 0; i < n; i++) bad += check_in(c, &l[i], "output", profile, vs2_out);
        return bad;
    }
    if ((n = leaves_of(c, sh, true, &l)) > 0)
        for (int i = 0; i < n; i++) bad += check_in(c, &l[i], "output", profile, ps_out);
    if ((n = leaves_of(c, sh, false, &l)) <= 0) return bad;
    reads r = {0};
    for (uint32_t i = 0; i < sh->entry->param_count; i++) {
        follow f = {sh->entry->params[i], {sh->entry->params[i], {0}, 0}, 0};
        reads_in_stmt(c, &r, &f, sh->entry->body);
    }
    for (int i = 0; i < n; i++) {
        if (!is_read(&r, &l[i])) continue;
        if (major < 3) bad += check_in(c, &l[i], "input", profile, ps2_in);
        else if (strcmp(l[i].semantic, "POSITION0") == 0) {
            hfx_error(c->diags, l[i].loc, 4502, "invalid input semantic '%s': Legal indices are in [1,15]", l[i].semantic);
            bad++;
        }
    }
    return bad;
}

/* ---- [unroll] ---- */

static bool counter_start(const ir_stmt *s, const ir_var **v, double *start) {
    const ir_expr *val = NULL;
    if (s && s->kind == IS_DECL && s->var) *v = s->var, val = s->expr;
    else if (s && s->kind == IS_EXPR && s->expr && s->expr->kind == IE_ASSIGN && s->expr->op == OP_NONE &&
             s->expr->a[0]->kind == IE_VAR)
        *v = s->expr->a[0]->var, val = s->expr->a[1];
    if (!val || !hfx_ir_is_const(val) || val->type->kind != TY_SCALAR) return false;
    *start = val->cval[0];
    return true;
}

static bool is_var(const ir_expr *e, const ir_var *v) { return e && e->kind == IE_VAR && e->var == v; }

/* i++, ++i, i--, --i, i += K, i -= K (K a constant): the step. */
static bool counter_step(const ir_expr *e, const ir_var *v, double *step) {
    if (!e) return false;
    if (e->kind == IE_UNARY && is_var(e->a[0], v)) {
        if (e->op == OP_PREINC || e->op == OP_POSTINC) return *step = 1, true;
        if (e->op == OP_PREDEC || e->op == OP_POSTDEC) return *step = -1, true;
        return false;
    }
    if (e->kind != IE_ASSIGN || (e->op != OP_ADD && e->op != OP_SUB) || !is_var(e->a[0], v) || !hfx_ir_is_const(e->a[1]))
        return false;
    *step = e->op == OP_ADD ? e->a[1]->cval[0] : -e->a[1]->cval[0];
    return *step != 0;
}

static bool compare(hfx_op op, double a, double b) {
    switch (op) {
    case OP_LT: return a < b;
    case OP_LE: return a <= b;
    case OP_GT: return a > b;
    case OP_GE: return a >= b;
    case OP_NE: return a != b;
    default: return false;
    }
}

static bool exits(const ir_stmt *s) {
    if (!s) return false;
    if (s->kind == IS_BREAK || s->kind == IS_RETURN) return true;
    for (uint32_t i = 0; i < s->count; i++)
        if (exits(s->body[i])) return true;
    return exits(s->init) || exits(s->then_s) || exits(s->else_s);
}

/* How many times the for loop s runs, when fxc can count it as it unrolls: a counter that
 * starts at a constant and steps by one, tested against a constant, and no break or return or
 * write of the counter in the body; -1 otherwise (or past fxc's 1024 iterations). */
int hfx_ir_loop_trips(const ir_stmt *s, const ir_var **counter, double *start, double *step) {
    const ir_var *v = NULL;
    double at;
    const ir_expr *e = s->expr;
    if (s->kind != IS_FOR || !counter_start(s->init, &v, &at) || !counter_step(s->step, v, step) || !e ||
        e->kind != IE_BINARY || exits(s->then_s))
        return -1;
    ir_uses u = {v, true, 0, 0, NULL};
    hfx_ir_count_uses(&u, s->then_s);
    bool left = is_var(e->a[0], v);
    if (u.writes || (!left && !is_var(e->a[1], v)) || !hfx_ir_is_const(e->a[left ? 1 : 0])) return -1;
    double b = e->a[left ? 1 : 0]->cval[0];
    *counter = v;
    *start = at;
    for (int k = 0; k <= UNROLL_LIMIT; k++, at += *step)
        if (!(left ? compare(e->op, at, b) : compare(e->op, b, at))) return k;
    return -1;
}

/* Whether fxc cannot unroll this [unroll] loop (see the top). */
static bool cannot_unroll(const ir_stmt *s) {
    const ir_var *v = NULL;
    double at, step;
    const ir_expr *e = s->expr;
    if (!counter_start(s->init, &v, &at) || !counter_step(s->step, v, &step) || !e || e->kind != IE_BINARY ||
        exits(s->then_s))
        return false;
    ir_uses u = {v, true, 0, 0, NULL};
    hfx_ir_count_uses(&u, s->then_s);
    if (u.writes) return false;
    bool left = is_var(e->a[0], v);
    if (!left && !is_var(e->a[1], v)) return false;
    const ir_expr *bound = e->a[left ? 1 : 0];
    if (!hfx_ir_is_const(bound)) return !hfx_ir_has_side_effects(bound);
    double b = bound->cval[0];
    for (unsigned k = 0; k <= UNROLL_LIMIT; k++, at += step)
        if (!(left ? compare(e->op, at, b) : compare(e->op, b, at))) return false;
    return true;
}

static int check_loops(ir_ctx *c, const ir_stmt *s) {
    if (!s) return 0;
    int bad = 0;
    if (s->kind == IS_FOR && s->hint && strcasecmp(s->hint, "unroll") == 0 && !s->max_iterations && cannot_unroll(s)) {
        hfx_error(c->diags, s->loc, 3511, "unable to unroll loop, loop does not appear to terminate in a timely manner (%u iterations)",
                  UNROLL_LIMIT);
        bad++;
    }
    for (uint32_t i = 0; i < s->count; i++) bad += check_loops(c, s->body[i]);
    return bad + check_loops(c, s->then_s) + check_loops(c, s->else_s);
}

int hfx_ir_check_model(ir_ctx *c, ir_shader *sh) {
    int bad = check_semantics(c, sh);
    for (uint32_t i = 0; i < sh->func_count; i++) bad += check_loops(c, sh->funcs[i]->body);
    return bad;
}
