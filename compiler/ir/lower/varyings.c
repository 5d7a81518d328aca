/* varyings.c: derived varyings. A vertex output the pixel stage can compute from another output
 * and parameters is not interpolated: pointlights.fx writes `V = camPosition - worldPosition`
 * beside `WorldPosition = worldPosition`, and a hand-written shader passes the position alone
 * and subtracts per pixel. On llvmpipe every interpolated component costs triangle setup and a
 * per-pixel step; the three of V were most of what hfx cost over the hand-written GLSL.
 *
 * Why it is exact: perspective-correct interpolation is a weighted sum whose weights sum to 1,
 * so for f affine (f(x) = A x + b, A and b the same over the triangle) interp(f(X)) =
 * f(interp(X)); only the rounding differs. f is taken as an expression of the value X the vertex
 * shader writes to output W (structurally the same expression, read from the same variables)
 * and of parameters and constants: sums and differences, negation, products and quotients by
 * parameter-only values, swizzles and float conversions (truncation), at most MAX_WORK
 * operations on X (they run per pixel instead of the interpolation). The parameter part only
 * moves values (a parameter, a constant, a swizzle of one): work on parameters would run per
 * pixel, and whether a preshader could take it depends on the options.
 *
 * Conservative on purpose, per program (a pair of stages, which both IR know):
 * - O and W are written once each by a top-level `place = value;` of the vertex entry, nothing
 *   writes them afterwards, the entry has no return but its last statement, and no statement
 *   between the two writes a variable X reads (a call there, when X reads a private global);
 * - O and W are float scalars or vectors reached by fields alone, with the same types in both
 *   stages, the same interpolation modifiers, and not POSITION, PSIZE, FOG, COLOR (D3D9 clamps
 *   colours), VPOS, VFACE or DEPTH; W stays a varying (it is not derived itself);
 * - the pixel entry reads both O and W (each as an input of its own), writes neither, and the
 *   parameters it needs are not ones it writes.
 * Stages are shared between programs (codegen.c), so a rewrite works on copies of the two entries
 * (new top-level blocks; the statements themselves are shared and left alone): the vertex copy
 * drops O's statement, the pixel copy starts with `input.O = f(input.W);`, and the uses pass runs
 * again on both (a parameter only O read leaves the vertex stage, one f reads joins the pixel
 * stage). codegen leaves O out of the varyings of both stages. */
#include <string.h>

#include "ir/ir.h"

enum { MAX_WORK = 2 };

enum { INTERP_MODS = MOD_LINEAR | MOD_CENTROID | MOD_NOINTERPOLATION | MOD_NOPERSPECTIVE | MOD_SAMPLE };

/* A place in a stage: a variable and the struct fields down from it. */
typedef struct place { const ir_var *root; const uint32_t *fields; uint32_t depth; } place;

typedef struct pair {
    ir_ctx *c;
    const ir_shader *vs, *ps;
    ir_leaf *out, *in;
    int out_count, in_count;
    const ir_var *ret;          /* the local the vertex entry returns (NULL: none) */
    const ir_stmt *body;        /* the vertex entry's top-level block */
    ir_var **added; uint32_t added_count, added_cap; /* pixel-stage copies of parameters */
} pair;

/* ---- places ---- */

static bool interpolated(const char *sem) {
    static const char *const fixed[] = {"POSITION", "PSIZE", "FOG", "COLOR", "VPOS", "VFACE", "DEPTH"};
    for (size_t i = 0; i < sizeof fixed / sizeof *fixed; i++)
        if (strncmp(sem, fixed[i], strlen(fixed[i])) == 0) return false;
    return true;
}

static bool float_value(const hfx_type *t) {
    return (t->kind == TY_SCALAR || t->kind == TY_VECTOR) && (t->base == B_FLOAT || t->base == B_HALF);
}

static bool plain_leaf(const ir_leaf *l) { return !l->indexed && interpolated(l->semantic) && float_value(l->type); }

static const ir_leaf *leaf_of(const ir_leaf *l, int n, const char *sem) {
    for (int i = 0; i < n; i++)
        if (strcmp(l[i].semantic, sem) == 0) return &l[i];
    return NULL;
}

static place place_of(const ir_leaf *l, const ir_var *ret) {
    return (place){l->root ? l->root : ret, l->fields, l->depth};
}

/* Whether a write of target t may change some of pl (an index or a swizzle: all of what is
 * below it). */
static bool overlaps(const ir_expr *t, const place *pl) {
    if (t->kind == IE_CONSTRUCT) { /* float4(a, b) = v */
        for (uint32_t i = 0; i < t->n; i++)
            if (overlaps(t->a[i], pl)) return true;
        return false;
    }
    uint32_t rev[16], n = 0;
    for (; t->kind == IE_SWIZZLE || t->kind == IE_INDEX || t->kind == IE_FIELD; t = t->a[0]) {
        if (t->kind != IE_FIELD) n = 0;
        else if (n == 16) return true;
        else rev[n++] = t->field;
    }
    if (t->kind != IE_VAR) return true;
    if (t->var != pl->root) return false;
    for (uint32_t k = 0; k < n && k < pl->depth; k++)
        if (rev[n - 1 - k] != pl->fields[k]) return false;
    return true;
}

/* e is exactly pl. */
static bool is_place(const ir_expr *e, const place *pl) {
    for (uint32_t k = pl->depth; k-- > 0; e = e->a[0])
        if (e->kind != IE_FIELD || e->field != pl->fields[k]) return false;
    return e->kind == IE_VAR && e->var == pl->root;
}

/* pl as an expression. */
static ir_expr *place_expr(ir_ctx *c, ir_var *root, const place *pl, hfx_loc loc) {
    ir_expr *e = hfx_ir_new_expr(c, IE_VAR, root->type, loc, 0);
    e->var = root;
    for (uint32_t k = 0; k < pl->depth; k++) {
        ir_expr *f = hfx_ir_new_expr(c, IE_FIELD, e->type->st->fields[pl->fields[k]].type, loc, 1);
        f->field = pl->fields[k];
        f->a[0] = e;
        e = f;
    }
    return e;
}

/* ---- the vertex stage: who writes what ---- */

typedef struct counter { const place *pl; unsigned writes; } counter;

static void count_writes(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    counter *k = data;
    const ir_expr *e = *slot;
    for (uint32_t i = 0; i < e->n; i++)
        if (hfx_ir_writes_operand(e, i) && overlaps(e->a[i], k->pl)) k->writes++;
}

static unsigned writes_in(ir_ctx *c, ir_stmt *s, const place *pl) {
    counter k = {pl, 0};
    if (s->kind == IS_DECL && s->var == pl->root) k.writes++;
    hfx_ir_walk_stmt_exprs(c, s, count_writes, &k);
    return k.writes;
}

/* The top-level statement that gives pl its final value, `pl = value;` with nothing after it
 * writing pl; -1 when there is none. */
static int final_write(const pair *p, const place *pl) {
    int last = -1;
    unsigned n = 0;
    for (uint32_t i = 0; i < p->body->count; i++) {
        unsigned k = writes_in(p->c, p->body->body[i], pl);
        if (k) last = (int)i, n = k;
    }
    if (last < 0 || n != 1) return -1;
    const ir_stmt *s = p->body->body[last];
    const ir_expr *e = s->kind == IS_EXPR ? s->expr : NULL;
    if (!e || e->kind != IE_ASSIGN || e->op != OP_NONE || !is_place(e->a[0], pl) || hfx_ir_has_side_effects(e->a[1]))
        return -1;
    return last;
}

static unsigned returns_in(const ir_stmt *s) {
    if (!s) return 0;
    unsigned n = s->kind == IS_RETURN;
    for (uint32_t i = 0; i < s->count; i++) n += returns_in(s->body[i]);
    return n + returns_in(s->init) + returns_in(s->then_s) + returns_in(s->else_s);
}

/* Every top-level statement runs: the only return, if any, is the last statement. */
static bool straight(const ir_stmt *body) {
    unsigned n = returns_in(body);
    return n == 0 || (n == 1 && body->count && body->body[body->count - 1]->kind == IS_RETURN);
}

/* The local the entry returns as its last statement, or NULL. */
static const ir_var *returned_local(const ir_stmt *body) {
    const ir_stmt *s = body->count ? body->body[body->count - 1] : NULL;
    return s && s->kind == IS_RETURN && s->expr && s->expr->kind == IE_VAR && s->expr->var->kind == IRV_LOCAL ? s->expr->var : NULL;
}

/* ---- the value X: the same in both statements ---- */

static void note_read(ir_ctx *c, ir_expr **slot, void *data) {
    if ((*slot)->kind == IE_VAR) hfx_ir_var_set_add(c, data, (*slot)->var);
}

/* X, computed by statement `from`, has the same value at statement `to` (either order): the
 * statements between write none of its variables, and it reads no output. */
static bool stable(const pair *p, ir_expr *x, uint32_t from, uint32_t to) {
    ir_var_set reads = {0}, writes = {0};
    hfx_ir_walk_expr(p->c, &x, note_read, &reads);
    if (reads.unknown || hfx_ir_var_set_has(&reads, p->ret)) return false;
    for (uint32_t i = 0; i < reads.count; i++)
        if (reads.vars[i]->kind == IRV_PARAM && (reads.vars[i]->mods & MOD_OUT)) return false;
    uint32_t lo = from < to ? from : to, hi = from < to ? to : from;
    for (uint32_t i = lo + 1; i < hi; i++) hfx_ir_note_writes(p->c, p->body->body[i], &writes);
    if (writes.unknown) return false;
    for (uint32_t i = 0; i < reads.count; i++)
        if (hfx_ir_var_set_has(&writes, reads.vars[i]) || (writes.calls && reads.vars[i]->kind == IRV_PRIVATE)) return false;
    return true;
}

/* ---- f: affine in X ---- */

/* A parameter-only value that computes nothing: a parameter, a constant, a swizzle of one. */
static bool moved_uniform(const ir_expr *e) {
    switch (e->kind) {
    case IE_CONST: return hfx_type_is_numeric(e->type);
    case IE_VAR: return e->var->kind == IRV_UNIFORM && e->var->param != HFX_NONE && hfx_type_is_numeric(e->type) &&
                        e->type->kind != TY_ARRAY;
    case IE_SWIZZLE: case IE_CONVERT: return moved_uniform(e->a[0]);
    default: return false;
    }
}

/* What stands for X in O's value: the expression W was given, or (O written after W) W's place
 * itself, which holds X from then on (`wp = p * 2; v = Cam - wp.xyz;` with out parameters). */
typedef struct source { const ir_expr *x; const place *w; bool place_holds; } source;

static bool is_x(const ir_expr *e, const source *s) {
    return hfx_ir_same_expr(e, s->x) || (s->place_holds && is_place(e, s->w));
}

/* 1 when e is an affine function of X (operations on it counted in *work), 0 when it is a
 * parameter-only value, -1 otherwise. */
static int affine(const ir_expr *e, const source *x, int *work) {
    if (is_x(e, x)) return 1;
    if (moved_uniform(e)) return 0;
    if (!float_value(e->type) || !e->n || e->n > 2) return -1;
    for (uint32_t i = 0; i < e->n; i++)
        if (!float_value(e->a[i]->type)) return -1;
    int a = affine(e->a[0], x, work), b = e->n > 1 ? affine(e->a[1], x, work) : 0;
    if (a < 0 || b < 0 || !(a | b)) return -1; /* work on parameters alone is not moved per pixel */
    switch (e->kind) {
    case IE_SWIZZLE: case IE_CONVERT: return 1;
    case IE_UNARY:
        if (e->op != OP_NEG && e->op != OP_POS) return -1;
        *work += e->op == OP_NEG;
        return 1;
    case IE_BINARY:
        if (e->op == OP_ADD || e->op == OP_SUB || (e->op == OP_MUL && !(a && b)) || (e->op == OP_DIV && !b)) {
            (*work)++;
            return 1;
        }
        return -1;
    default: return -1;
    }
}

/* ---- the pixel stage ---- */

static bool pixel_reads(const ir_expr *e, const place *pl) {
    const ir_expr *t = e;
    while (t->kind == IE_FIELD) t = t->a[0];
    if (t->kind == IE_VAR) return t->var == pl->root && overlaps(e, pl);
    for (uint32_t i = 0; i < e->n; i++)
        if (e->a[i] && pixel_reads(e->a[i], pl)) return true;
    return false;
}

typedef struct finder { const place *pl; bool found; } finder;

static void find_read(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    finder *f = data;
    f->found |= pixel_reads(*slot, f->pl);
}

/* The pixel entry reads pl somewhere and writes no input. */
static bool reads_input(ir_ctx *c, const ir_shader *ps, const place *pl) {
    finder f = {pl, false};
    if (writes_in(c, ps->entry->body, &(place){pl->root, NULL, 0})) return false;
    hfx_ir_walk_stmt_roots(c, ps->entry->body, find_read, &f);
    return f.found;
}

/* The pixel stage's variable for the vertex stage's parameter v: its own, or a copy made once. */
static ir_var *pixel_var(pair *p, const ir_var *v) {
    for (uint32_t i = 0; i < p->ps->global_count; i++) {
        ir_var *g = p->ps->globals[i];
        if (g->kind == IRV_UNIFORM && g->param == v->param) return g->priv ? NULL : g;
    }
    for (uint32_t i = 0; i < p->added_count; i++)
        if (p->added[i]->param == v->param) return p->added[i];
    ir_var *n = HFX_NEW(p->c->arena, ir_var);
    if (!n || !HFX_ARENA_GROW(p->c->arena, p->added, p->added_count, p->added_cap, 4)) return NULL;
    *n = *v;
    n->priv = n->copy_of = NULL;
    return p->added[p->added_count++] = n;
}

/* f's value in the pixel stage: x read from the input w, parameters from its own variables. */
static ir_expr *to_pixels(pair *p, const ir_expr *e, const source *x, const ir_expr *w) {
    if (is_x(e, x)) return hfx_ir_clone_expr(p->c, w);
    ir_expr *r = hfx_ir_new_expr(p->c, e->kind, e->type, e->loc, e->n);
    if (!r) return NULL;
    ir_expr **args = r->a;
    *r = *e;
    r->a = args;
    if (e->kind == IE_VAR && !(r->var = pixel_var(p, e->var))) return NULL;
    for (uint32_t i = 0; i < e->n; i++)
        if (!(r->a[i] = to_pixels(p, e->a[i], x, w))) return NULL;
    return r;
}

/* ---- one output ---- */

typedef struct derived {
    uint32_t stmt;        /* the vertex statement that stops */
    ir_stmt *compute;     /* the pixel statement that computes it */
} derived;

/* The leaves of O and W in both stages agree (type, modifiers) and both are plain. */
static bool leaves_agree(const pair *p, const ir_leaf *vo, const ir_leaf *vw, const ir_leaf **po, const ir_leaf **pw) {
    *po = leaf_of(p->in, p->in_count, vo->semantic);
    *pw = leaf_of(p->in, p->in_count, vw->semantic);
    if (vo == vw || !*po || !*pw || !plain_leaf(vo) || !plain_leaf(vw) || !plain_leaf(*po) || !plain_leaf(*pw)) return false;
    if (!(*po)->root || !(*pw)->root || !hfx_type_equal(vo->type, (*po)->type) || !hfx_type_equal(vw->type, (*pw)->type))
        return false;
    return ((vo->mods | (*po)->mods) & INTERP_MODS) == ((vw->mods | (*pw)->mods) & INTERP_MODS);
}

/* O computed from W: fills *d; false when it cannot be. */
static bool derive_from(pair *p, const ir_leaf *vo, const ir_leaf *vw, derived *d) {
    const ir_leaf *po, *pw;
    if (!leaves_agree(p, vo, vw, &po, &pw)) return false;
    place o = place_of(vo, p->ret), w = place_of(vw, p->ret);
    if (!o.root || !w.root) return false;
    int io = final_write(p, &o), iw = io < 0 ? -1 : final_write(p, &w);
    if (iw < 0) return false;
    ir_expr *ov = p->body->body[io]->expr->a[1];
    source x = {p->body->body[iw]->expr->a[1], &w, iw < io};
    int work = 0;
    if (affine(ov, &x, &work) != 1 || work > MAX_WORK || !stable(p, p->body->body[iw]->expr->a[1], (uint32_t)iw, (uint32_t)io))
        return false;
    place pin_o = place_of(po, NULL), pin_w = place_of(pw, NULL);
    if (!reads_input(p->c, p->ps, &pin_o) || !reads_input(p->c, p->ps, &pin_w)) return false;
    ir_expr *value = to_pixels(p, ov, &x, place_expr(p->c, pw->root, &pin_w, ov->loc));
    ir_expr *set = value ? hfx_ir_new_expr(p->c, IE_ASSIGN, po->type, ov->loc, 2) : NULL;
    ir_stmt *s = set ? hfx_ir_new_stmt(p->c, IS_EXPR, ov->loc) : NULL;
    if (!s) return false;
    set->op = OP_NONE;
    set->a[0] = place_expr(p->c, po->root, &pin_o, ov->loc);
    set->a[1] = value;
    s->expr = set;
    *d = (derived){(uint32_t)io, s};
    return true;
}

/* ---- the copies ---- */

/* A copy of sh with an entry and a top-level block of its own, room for `extra` statements more. */
static ir_shader *own_entry(ir_ctx *c, const ir_shader *sh, uint32_t extra) {
    ir_shader *r = HFX_NEW(c->arena, ir_shader);
    ir_func *f = HFX_NEW(c->arena, ir_func);
    ir_stmt *b = HFX_NEW(c->arena, ir_stmt);
    ir_func **funcs = HFX_NEW_ARRAY(c->arena, ir_func *, sh->func_count + 1);
    ir_stmt **body = HFX_NEW_ARRAY(c->arena, ir_stmt *, sh->entry->body->count + extra + 1);
    ir_var **pres = HFX_NEW_ARRAY(c->arena, ir_var *, sh->pre_count + 1);
    if (!r || !f || !b || !funcs || !body || !pres) return NULL;
    *r = *sh, *f = *sh->entry, *b = *sh->entry->body;
    if (b->count) memcpy(body, b->body, b->count * sizeof *body); /* (memcpy from NULL is undefined, even of 0 bytes) */
    if (sh->pre_count) memcpy(pres, sh->pres, sh->pre_count * sizeof *pres);
    for (uint32_t i = 0; i < sh->func_count; i++) funcs[i] = sh->funcs[i] == sh->entry ? f : sh->funcs[i];
    b->body = body;
    f->body = b;
    r->entry = f;
    r->funcs = funcs;
    r->func_cap = r->func_count;
    r->pres = pres;
    r->pre_cap = r->pre_count;
    return r;
}

/* The stages with the derived outputs' work moved; false (stages untouched) when registers
 * would not fit. */
static bool rewrite(pair *p, const derived *d, uint32_t n, bool pack, ir_shader **vs, ir_shader **ps) {
    ir_shader *v = own_entry(p->c, p->vs, 0), *q = own_entry(p->c, p->ps, n);
    if (!v || !q) return false;
    ir_stmt *b = v->entry->body, *pb = q->entry->body;
    uint32_t kept = 0;
    for (uint32_t i = 0; i < b->count; i++) {
        bool gone = false;
        for (uint32_t k = 0; k < n; k++) gone |= d[k].stmt == i;
        if (!gone) b->body[kept++] = b->body[i];
    }
    b->count = kept;
    memmove(pb->body + n, pb->body, pb->count * sizeof *pb->body);
    for (uint32_t k = 0; k < n; k++) pb->body[k] = d[k].compute;
    pb->count += n;
    hfx_ir_pass_uses(p->c, v); /* O's value read parameters only, never a preshader: they all stay */
    hfx_ir_pass_uses(p->c, q);
    if (pack && hfx_ir_stage_regs(p->c, q) > IR_STAGE_REGS) return false;
    *vs = v;
    *ps = q;
    return true;
}

/* The role of each vertex output so far: a source W stays a varying, a derived O is gone. */
enum { FREE, SOURCE, DERIVED };

uint32_t hfx_ir_pass_varyings(ir_ctx *c, ir_shader **vs, ir_shader **ps, bool pack, const char ***derived_out) {
    *derived_out = NULL;
    if (!*vs || !*ps || !(*vs)->entry->body || (*vs)->entry->body->kind != IS_BLOCK || !(*ps)->entry->body ||
        (*ps)->entry->body->kind != IS_BLOCK)
        return 0;
    pair p = {c, *vs, *ps, NULL, NULL, 0, 0, NULL, (*vs)->entry->body, NULL, 0, 0};
    p.out_count = hfx_ir_entry_leaves(c, p.vs->entry, true, &p.out);
    p.in_count = hfx_ir_entry_leaves(c, p.ps->entry, false, &p.in);
    if (p.out_count <= 0 || p.in_count <= 0 || !straight(p.body)) return 0;
    p.ret = returned_local(p.body);
    unsigned char *role = HFX_NEW_ARRAY(c->arena, unsigned char, (uint32_t)p.out_count);
    derived *d = HFX_NEW_ARRAY(c->arena, derived, (uint32_t)p.out_count);
    const char **sems = HFX_NEW_ARRAY(c->arena, const char *, (uint32_t)p.out_count);
    uint32_t n = 0;
    if (!role || !d || !sems) return 0;
    for (int o = 0; o < p.out_count; o++)
        for (int w = 0; w < p.out_count && role[o] == FREE; w++) {
            if (role[w] == DERIVED || !derive_from(&p, &p.out[o], &p.out[w], &d[n])) continue;
            role[o] = DERIVED;
            role[w] = SOURCE;
            sems[n++] = p.out[o].semantic;
        }
    if (!n || !rewrite(&p, d, n, pack, vs, ps)) return 0;
    *derived_out = sems;
    return n;
}
