/* factors.c: a product of float vectors with scalar factors in it, reordered as fxc's optimiser
 * orders it: `attenuation * LightColor[i] * DiffuseIntensity * diffuse * Diff` is written as
 * four vector products, one after the other; multiplying the three scalars first leaves two
 * vector products. The parameter-only factors go first and together, so the preshade pass takes
 * their product (`ks * pow(..) * Specular * d` reads `pow(..) * d * hfx_pre0`, with hfx_pre0 =
 * ks * Specular); then the other scalars; then the other vectors, in their order. A product is
 * rewritten only when that costs fewer component multiplications. The rounding is a reordered
 * product's, as fxc's (without /Gis). Its row in the pass table (passes.c) runs only with
 * preshaders on, so --no-preshaders keeps the order as written. */
#include "ir/ir.h"

enum { MAX_FACTORS = 16 };

typedef struct group { ir_expr *f[MAX_FACTORS]; unsigned n; } group;

/* A product's factors, by kind; `cost`: the component multiplications it does now. */
typedef struct factors {
    ir_ctx *c;
    group uni_scalars, uni_vectors, scalars, vectors;
    unsigned cost;
    bool ok;
} factors;

static bool float_base(const hfx_type *t) { return t->base == B_FLOAT || t->base == B_HALF; }

static bool is_product(const ir_expr *e) {
    return e->kind == IE_BINARY && e->op == OP_MUL && float_base(e->type) &&
           (e->type->kind == TY_SCALAR || e->type->kind == TY_VECTOR);
}

/* The scalar a vector of equal components holds, or NULL. */
static ir_expr *splatted(const ir_expr *e) {
    if (e->kind == IE_CONVERT && e->type->kind == TY_VECTOR && e->a[0]->type->kind == TY_SCALAR &&
        e->a[0]->type->base == e->type->base)
        return e->a[0];
    return NULL;
}

static bool equal_components(const ir_expr *e) {
    if (e->kind != IE_CONST || e->type->kind != TY_VECTOR) return false;
    for (unsigned i = 1; i < e->type->rows * e->type->cols; i++)
        if (e->cval[i] != e->cval[0]) return false;
    return true;
}

static void add(factors *fs, group *g, ir_expr *e) {
    if (g->n == MAX_FACTORS) fs->ok = false;
    else g->f[g->n++] = e;
}

static void collect_scalar(factors *fs, ir_expr *e) {
    if (is_product(e) && e->type->kind == TY_SCALAR) {
        if (!hfx_ir_pre_only(fs->c, e)) fs->cost++;
        collect_scalar(fs, e->a[0]);
        collect_scalar(fs, e->a[1]);
        return;
    }
    add(fs, hfx_ir_pre_only(fs->c, e) ? &fs->uni_scalars : &fs->scalars, e);
}

/* Walks a vector product down to its factors; scalars come out of their splats. */
static void collect(factors *fs, ir_expr *e) {
    ir_ctx *c = fs->c;
    ir_expr *s = splatted(e);
    if (s) {
        collect_scalar(fs, s);
    } else if (equal_components(e)) {
        add(fs, &fs->uni_scalars, hfx_ir_const_scalar(c, hfx_type_scalar(c->types, e->type->base), e->cval[0], e->loc));
    } else if (is_product(e) && e->type->kind == TY_VECTOR) {
        if (!hfx_ir_pre_only(c, e)) fs->cost += e->type->rows * e->type->cols;
        collect(fs, e->a[0]);
        collect(fs, e->a[1]);
    } else {
        add(fs, hfx_ir_pre_only(fs->c, e) ? &fs->uni_vectors : &fs->vectors, e);
    }
}

/* acc * g's factors, left to right (acc NULL: from the first factor). */
static ir_expr *product_of(ir_ctx *c, const group *g, ir_expr *acc, const hfx_type *t) {
    for (unsigned i = 0; i < g->n; i++) acc = acc ? hfx_ir_new_binary(c, OP_MUL, t, acc, g->f[i]) : g->f[i];
    return acc;
}

/* Component multiplications of the reordered product (n components): the parameter-only part
 * is a preshader's; the scalar product (with the parameters' when they are all scalars) is
 * splatted once; then one vector product per further term. */
static unsigned reordered_cost(const factors *fs, unsigned n) {
    bool uni_vector = fs->uni_vectors.n > 0, uni_scalar = fs->uni_scalars.n > 0 && !uni_vector;
    unsigned scalars = fs->scalars.n + uni_scalar, terms = fs->vectors.n + uni_vector + (scalars > 0);
    return (scalars ? scalars - 1 : 0) + (terms ? terms - 1 : 0) * n;
}

static void reorder(ir_ctx *c, ir_expr **slot, void *data) {
    (void)data;
    ir_expr *e = *slot;
    if (!is_product(e) || e->type->kind != TY_VECTOR || hfx_ir_has_side_effects(e)) return;
    factors fs = {.c = c, .ok = true};
    collect(&fs, e);
    unsigned n = e->type->rows * e->type->cols;
    if (!fs.ok || reordered_cost(&fs, n) >= fs.cost) return;
    const hfx_type *scalar = hfx_type_scalar(c->types, e->type->base);
    ir_expr *uni = product_of(c, &fs.uni_scalars, NULL, scalar), *s = NULL;
    if (uni && !fs.uni_vectors.n) s = uni, uni = NULL; /* all scalars: one scalar product */
    else if (uni) uni = hfx_ir_new_convert(c, e->type, uni);
    uni = product_of(c, &fs.uni_vectors, uni, e->type);
    s = product_of(c, &fs.scalars, s, scalar);
    ir_expr *r = s ? hfx_ir_new_convert(c, e->type, s) : NULL;
    if (uni) r = r ? hfx_ir_new_binary(c, OP_MUL, e->type, r, uni) : uni;
    *slot = product_of(c, &fs.vectors, r, e->type);
}

void hfx_ir_pass_factors(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, reorder, NULL);
}
