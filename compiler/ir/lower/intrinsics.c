/* intrinsics.c: rewrites intrinsic calls into forms every target expresses directly, by the
 * IR column of check/intrinsics.def (LOWER_*), the same for every back end.
 * LOWER_MUL: mul(float3, float4x4) reaches the IR as mul(v, (float3x4)M); since
 * mul(v, M3x4) = mul(float4(v, 0), M4x4).xyzw, the truncated matrix becomes a padded vector,
 * which needs no non-square matrix type (GLSL 110 has none) and no matrix copy.
 * LOWER_ROWS: componentwise intrinsics of matrices (abs(M), lerp(M, N, t), saturate(M)...),
 * which GLSL and D3D9 bytecode have only for vectors, become a matrix built row by row; so do
 * bool matrices (M <= d), whatever the operator. The rest of the intrinsics reach each back
 * end's emitter as they are (glsl_intrin.c for GLSL). */
#include "ir/ir.h"

/* The IR rewrite of the row of an intrinsic call. */
static hfx_intr_lower lowering_of(const ir_expr *e) {
    const hfx_intrinsic_info *info = e->kind == IE_INTRIN ? hfx_intrinsic_info_of((int)e->intrin) : NULL;
    return info ? info->lower : LOWER_NONE;
}

static bool truncated_matrix(const ir_expr *e) {
    if (e->kind != IE_CONVERT || e->type->kind != TY_MATRIX) return false;
    const hfx_type *from = e->a[0]->type;
    return from->kind == TY_MATRIX && from->rows >= e->type->rows && from->cols >= e->type->cols &&
           from->rows > 1 && from->cols > 1 && e->type->rows > 1 && e->type->cols > 1 && from->base == e->type->base;
}

/* v padded with zeros to n components. */
static ir_expr *pad(ir_ctx *c, ir_expr *v, unsigned n) {
    unsigned have = hfx_type_components(v->type);
    if (have == n) return v;
    ir_expr *r = hfx_ir_new_expr(c, IE_CONSTRUCT, hfx_type_vector(c->types, v->type->base, n), v->loc, 1 + (n - have));
    r->a[0] = v;
    for (unsigned i = 1; i <= n - have; i++) r->a[i] = hfx_ir_const_scalar(c, hfx_type_scalar(c->types, v->type->base), 0, v->loc);
    return r;
}

/* The first n components of a vector. */
static ir_expr *first(ir_ctx *c, ir_expr *v, const hfx_type *ty) {
    unsigned n = hfx_type_components(ty);
    if (hfx_type_components(v->type) == n) return v;
    ir_expr *s = hfx_ir_new_expr(c, IE_SWIZZLE, ty, v->loc, 1);
    s->a[0] = v;
    s->comp_count = (uint8_t)n;
    for (unsigned i = 0; i < n; i++) s->comps[i] = (uint8_t)i;
    return s;
}

static void lower_mul(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    if (lowering_of(e) != LOWER_MUL || e->n != 2 || e->type->kind != TY_VECTOR) return;
    ir_expr *a = e->a[0], *b = e->a[1];
    if (a->type->kind == TY_VECTOR && truncated_matrix(b) && a->type->cols == b->type->rows) {
        const hfx_type *m = b->a[0]->type;
        ir_expr *r = hfx_ir_new_expr(c, IE_INTRIN, hfx_type_vector(c->types, e->type->base, m->cols), e->loc, 2);
        r->intrin = e->intrin;
        r->a[0] = pad(c, a, m->rows);
        r->a[1] = b->a[0];
        *slot = first(c, r, e->type);
    } else if (b->type->kind == TY_VECTOR && truncated_matrix(a) && b->type->cols == a->type->cols) {
        const hfx_type *m = a->a[0]->type;
        ir_expr *r = hfx_ir_new_expr(c, IE_INTRIN, hfx_type_vector(c->types, e->type->base, m->rows), e->loc, 2);
        r->intrin = e->intrin;
        r->a[0] = a->a[0];
        r->a[1] = pad(c, b, m->cols);
        *slot = first(c, r, e->type);
    }
}

static bool componentwise_on_matrix(const ir_expr *e) {
    if (lowering_of(e) != LOWER_ROWS || e->type->kind != TY_MATRIX || e->type->rows < 2 || e->type->cols < 2) return false;
    for (uint32_t i = 0; i < e->n; i++)
        if (!hfx_type_equal(e->a[i]->type, e->type) || hfx_ir_has_side_effects(e->a[i])) return false;
    return true;
}

/* Row r of a matrix expression (the argument is read once per row: it has no side effects). */
static ir_expr *row_of(ir_ctx *c, ir_expr *m, unsigned r) {
    const hfx_type *row = hfx_type_vector(c->types, m->type->base, m->type->cols);
    if (m->kind == IE_CONVERT && hfx_type_components(m->a[0]->type) == 1) { /* a splatted scalar */
        ir_expr *x = hfx_ir_new_expr(c, IE_CONVERT, row, m->loc, 1);
        x->a[0] = r ? hfx_ir_clone_expr(c, m->a[0]) : m->a[0];
        return x;
    }
    if (m->kind == IE_CONST) {
        ir_expr *x = hfx_ir_new_expr(c, IE_CONST, row, m->loc, 0);
        for (unsigned i = 0; i < row->cols; i++) x->cval[i] = m->cval[r * m->type->cols + i];
        return x;
    }
    ir_expr *x = hfx_ir_new_expr(c, IE_INDEX, row, m->loc, 2);
    x->a[0] = r ? hfx_ir_clone_expr(c, m) : m;
    x->a[1] = hfx_ir_const_scalar(c, hfx_type_scalar(c->types, B_INT), r, m->loc);
    return x;
}

static void lower_matrix_componentwise(ir_ctx *c, ir_expr **slot, void *data) {
    (void)data;
    ir_expr *e = *slot;
    if (!componentwise_on_matrix(e)) return;
    const hfx_type *row = hfx_type_vector(c->types, e->type->base, e->type->cols);
    ir_expr *m = hfx_ir_new_expr(c, IE_CONSTRUCT, e->type, e->loc, e->type->rows);
    for (unsigned r = 0; r < e->type->rows; r++) {
        ir_expr *call = hfx_ir_new_expr(c, IE_INTRIN, row, e->loc, e->n);
        call->intrin = e->intrin;
        for (uint32_t i = 0; i < e->n; i++) call->a[i] = row_of(c, e->a[i], r);
        m->a[r] = call;
    }
    *slot = m;
}

/* Bool matrices (M <= d, !M, M && N), which GLSL lacks, live only row by row: converted to a
 * numeric matrix ((float2x2)(samples <= depth)) or indexed with a constant ((M > 6)[1]). */
static bool is_bool_matrix(const ir_expr *e) {
    return e->type->kind == TY_MATRIX && e->type->base == B_BOOL && e->type->rows > 1 && e->type->cols > 1;
}

static ir_expr *bool_row(ir_ctx *c, ir_expr *e, unsigned r) {
    const hfx_type *bvec = hfx_type_vector(c->types, B_BOOL, e->type->cols);
    if (e->kind == IE_CONVERT && e->a[0]->type->kind == TY_MATRIX && e->a[0]->type->rows == e->type->rows &&
        e->a[0]->type->cols == e->type->cols && !hfx_ir_has_side_effects(e)) { /* (bool2x2)m: a row of m */
        ir_expr *x = hfx_ir_new_expr(c, IE_CONVERT, bvec, e->loc, 1);
        if (!(x->a[0] = is_bool_matrix(e->a[0]) ? bool_row(c, e->a[0], r) : row_of(c, e->a[0], r))) return NULL;
        return x;
    }
    bool binary = e->kind == IE_BINARY && e->op >= OP_LT && e->op <= OP_OR;
    bool negation = e->kind == IE_UNARY && e->op == OP_NOT;
    if ((!binary && !negation) || hfx_ir_has_side_effects(e)) return NULL;
    ir_expr *x = hfx_ir_new_expr(c, e->kind, bvec, e->loc, e->n);
    x->op = e->op;
    for (uint32_t i = 0; i < e->n; i++) {
        ir_expr *a = e->a[i];
        if (!(x->a[i] = is_bool_matrix(a) ? bool_row(c, a, r) : row_of(c, a, r))) return NULL;
    }
    return x;
}

/* `M > 6 ? M : -M`: a bool matrix choosing between two matrices, row by row. */
static void select_rows(ir_ctx *c, ir_expr **slot) {
    ir_expr *e = *slot;
    const hfx_type *t = e->type;
    if (t->kind != TY_MATRIX || t->rows != e->a[0]->type->rows || t->cols != e->a[0]->type->cols ||
        hfx_ir_has_side_effects(e->a[1]) || hfx_ir_has_side_effects(e->a[2]))
        return;
    ir_expr *m = hfx_ir_new_expr(c, IE_CONSTRUCT, t, e->loc, t->rows);
    for (unsigned r = 0; r < t->rows; r++) {
        ir_expr *x = hfx_ir_new_expr(c, IE_SELECT, hfx_type_vector(c->types, t->base, t->cols), e->loc, 3);
        if (!(x->a[0] = bool_row(c, e->a[0], r))) return;
        x->a[1] = row_of(c, e->a[1], r);
        x->a[2] = row_of(c, e->a[2], r);
        m->a[r] = x;
    }
    *slot = m;
}

static void lower_bool_matrix(ir_ctx *c, ir_expr **slot, void *data) {
    (void)data;
    ir_expr *e = *slot;
    if (e->kind == IE_SELECT && is_bool_matrix(e->a[0])) {
        select_rows(c, slot);
        return;
    }
    if (e->kind == IE_INDEX && is_bool_matrix(e->a[0]) && hfx_ir_is_const(e->a[1])) {
        ir_expr *row = bool_row(c, e->a[0], hfx_ev_uint(e->a[1]->cval[0]));
        if (row) *slot = row;
        return;
    }
    if (e->kind != IE_CONVERT || !is_bool_matrix(e->a[0]) || e->type->kind != TY_MATRIX || e->type->rows != e->a[0]->type->rows ||
        e->type->cols != e->a[0]->type->cols)
        return;
    ir_expr *m = hfx_ir_new_expr(c, IE_CONSTRUCT, e->type, e->loc, e->type->rows);
    for (unsigned r = 0; r < e->type->rows; r++) {
        ir_expr *row = bool_row(c, e->a[0], r);
        if (!row) return;
        ir_expr *conv = hfx_ir_new_expr(c, IE_CONVERT, hfx_type_vector(c->types, e->type->base, e->type->cols), e->loc, 1);
        conv->a[0] = row;
        m->a[r] = conv;
    }
    *slot = m;
}

/* ---- which rewrites a function needs ---- */

/* One read-only walk says which of the three rewrites may apply, each by a test that every
 * node it rewrites passes; the rewrites make no node that would pass another's test (they
 * build vectors, and matrices only of a type already there), so a walk found needless in the
 * function as it stands stays needless after the others. Most functions then take one walk. */
typedef struct needs { bool mul, componentwise, bool_matrix; } needs;

static void find_needs(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    const ir_expr *e = *slot;
    needs *n = data;
    if (!e->type) return;
    if (lowering_of(e) == LOWER_MUL && e->n == 2 && e->type->kind == TY_VECTOR)
        n->mul |= truncated_matrix(e->a[0]) || truncated_matrix(e->a[1]);
    if (e->kind == IE_INTRIN && e->type->kind == TY_MATRIX) n->componentwise = true;
    if (is_bool_matrix(e)) n->bool_matrix = true;
}

void hfx_ir_pass_intrinsics(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) {
        needs n = {false, false, false};
        hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, find_needs, &n);
        if (n.mul) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, lower_mul, NULL);
        if (n.componentwise) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, lower_matrix_componentwise, NULL);
        if (n.bool_matrix) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, lower_bool_matrix, NULL);
    }
}
