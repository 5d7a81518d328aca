/* bc_expr.c: expressions to registers. A variable's value is its registers (no code); arithmetic
 * takes fresh temporaries (an add of a product is one mad); bools are 0.0 / 1.0 and comparisons
 * are slt / sge (vertex) or cmp (pixel) as fxc writes them; selects are cmp (pixel) or lrp (vertex).
 * Matrices live in registers by row, or by column for column_major parameters: a product picks
 * dp4 on the side whose registers hold what it dots, mul / mad chains on the other. */
#include "bytecode/bc_int.h"

static bool injective_val(const bc_val *v) {
    for (unsigned i = 0; i < v->n; i++)
        for (unsigned j = i + 1; j < v->n; j++) if (v->sw[i] == v->sw[j]) return false;
    return true;
}

/* Whether e's value comes in column registers (a column_major parameter, a transpose). */
static bool bc_expr_is_cols(bc_gen *g, const ir_expr *e) {
    (void)g;
    return e->type->kind == TY_MATRIX && e->kind != IE_CONSTRUCT && e->kind != IE_CONST;
}

static bc_obj one(bc_gen *g, bc_val v) {
    bc_obj o = {HFX_NEW(g->c->arena, bc_val), 1, false};
    o.slot[0] = v;
    return o;
}

static unsigned width(const hfx_type *t) {
    return t->kind == TY_SCALAR ? 1 : t->kind == TY_VECTOR ? t->cols : 4;
}

bc_val hfx_bc_own(bc_gen *g, bc_val v) {
    if (v.own) return v;
    return hfx_bc_op1(g, D3D9_MOV, v.n, v);
}

/* --- constants --- */

bool hfx_bc_try_const(bc_gen *g, const ir_expr *e, double *out) {
    double a, b;
    switch (e->kind) {
    case IE_CONST:
        if (e->type->kind != TY_SCALAR) return false;
        *out = e->cval[0];
        return true;
    case IE_VAR: {
        bc_binding *x = hfx_bc_bind(g, e->var);
        if (x && x->is_const) { *out = x->konst; return true; }
        return false;
    }
    case IE_CONVERT:
        if (e->type->kind != TY_SCALAR || !hfx_bc_try_const(g, e->a[0], &a)) return false;
        *out = e->type->base == B_BOOL ? a != 0 : e->type->base == B_INT || e->type->base == B_UINT ? (double)hfx_ev_int(a) : a;
        return true;
    case IE_UNARY:
        if (!hfx_bc_try_const(g, e->a[0], &a)) return false;
        if (e->op == OP_NEG) *out = -a;
        else if (e->op == OP_NOT) *out = a == 0;
        else return false;
        return true;
    case IE_BINARY:
        if (e->type->kind != TY_SCALAR || !hfx_bc_try_const(g, e->a[0], &a) || !hfx_bc_try_const(g, e->a[1], &b)) return false;
        switch (e->op) {
        case OP_ADD: *out = a + b; break;
        case OP_SUB: *out = a - b; break;
        case OP_MUL: *out = a * b; break;
        case OP_DIV:
            if (b == 0) return false;
            *out = a / b;
            if (e->type->base == B_INT || e->type->base == B_UINT) *out = (double)hfx_ev_int(*out);
            break;
        case OP_LT: *out = a < b; break;
        case OP_GT: *out = a > b; break;
        case OP_LE: *out = a <= b; break;
        case OP_GE: *out = a >= b; break;
        case OP_EQ: *out = a == b; break;
        case OP_NE: *out = a != b; break;
        case OP_AND: *out = a != 0 && b != 0; break;
        case OP_OR: *out = a != 0 || b != 0; break;
        default: return false;
        }
        return true;
    default: return false;
    }
}

static bc_obj constant(bc_gen *g, const ir_expr *e) {
    const hfx_type *t = e->type;
    if (t->kind == TY_SCALAR || t->kind == TY_VECTOR) {
        float v[4];
        for (unsigned i = 0; i < width(t); i++) v[i] = (float)e->cval[i];
        return one(g, hfx_bc_const(g, v, width(t)));
    }
    if (t->kind == TY_MATRIX) {
        bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, t->rows), t->rows, false};
        for (unsigned r = 0; r < t->rows; r++) {
            float v[4];
            for (unsigned c = 0; c < t->cols; c++) v[c] = (float)e->cval[r * t->cols + c];
            o.slot[r] = hfx_bc_const(g, v, t->cols);
        }
        return o;
    }
    hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer does not handle a constant of this type yet");
    return one(g, hfx_bc_constf(g, 0));
}

/* --- matrices --- */

bc_val hfx_bc_matrix_elem(bc_obj m, unsigned row, unsigned col) {
    bc_val s = m.cols ? m.slot[col < m.count ? col : 0] : m.slot[row < m.count ? row : 0];
    return hfx_bc_scalar_of(s, m.cols ? row : col);
}

static bc_val gather(bc_gen *g, const bc_val *parts, unsigned n) {
    int r = hfx_bc_temp(g);
    bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), n);
    for (unsigned i = 0; i < n; i++) {
        unsigned j = i;
        bc_val src = parts[i];
        /* neighbours from the same register go in one mov */
        while (j + 1 < n && parts[j + 1].type == src.type && parts[j + 1].num == src.num && parts[j + 1].mod == src.mod &&
               parts[j + 1].rel == src.rel && j + 1 - i < 4) j++;
        bc_val t = hfx_bc_reg(D3D9_REG_TEMP, d.num, j - i + 1), s = src;
        s.n = (uint8_t)(j - i + 1);
        s.own = false;
        for (unsigned k = i; k <= j; k++) { t.sw[k - i] = (uint8_t)k; s.sw[k - i] = parts[k].sw[0]; }
        hfx_bc_store(g, t, s, false);
        i = j;
    }
    d.own = r >= 0;
    return d;
}

bc_val hfx_bc_gather(bc_gen *g, const bc_val *parts, unsigned n) { return gather(g, parts, n); }

bc_val hfx_bc_matrix_row(bc_gen *g, bc_obj m, const hfx_type *t, unsigned row) {
    if (!m.cols) return m.slot[row < m.count ? row : 0];
    bc_val parts[4];
    for (unsigned c = 0; c < t->cols; c++) parts[c] = hfx_bc_matrix_elem(m, row, c);
    return gather(g, parts, t->cols);
}

/* --- comparisons and selects --- */

static bc_val one_c(bc_gen *g) { return hfx_bc_constf(g, 1); }
static bc_val zero_c(bc_gen *g) { return hfx_bc_constf(g, 0); }

static bool is_zero_const(bc_gen *g, const bc_val *v) {
    if (v->type != D3D9_REG_CONST || v->rel) return false;
    for (uint32_t d = 0; d < g->def_count; d++)
        if (g->defs[d].num == v->num) {
            for (unsigned i = 0; i < v->n; i++) if (g->defs[d].v[v->sw[i]] != 0) return false;
            return true;
        }
    return false;
}

bc_val hfx_bc_not(bc_gen *g, bc_val a) { return hfx_bc_op2(g, D3D9_ADD, a.n, hfx_bc_neg(a), one_c(g)); }

bc_val hfx_bc_select(bc_gen *g, bc_val c, bc_val a, bc_val b) {
    unsigned n = a.n > b.n ? a.n : b.n;
    if (g->stage == D3D9_PS) return hfx_bc_op3(g, D3D9_CMP, n, hfx_bc_neg(c), b, a);
    return hfx_bc_op3(g, D3D9_LRP, n, c, a, b);
}

static bc_val compare(bc_gen *g, hfx_op op, bc_val a, bc_val b) {
    unsigned n = a.n > b.n ? a.n : b.n;
    if (op == OP_EQ || op == OP_NE) {
        bc_val d = is_zero_const(g, &b) ? a : hfx_bc_op2(g, D3D9_ADD, n, a, hfx_bc_neg(b));
        bc_val dd = d;
        dd.own = false;
        bc_val sq = hfx_bc_op2(g, D3D9_MUL, n, d, dd);
        bc_val s2 = sq;
        s2.own = false;
        if (g->stage == D3D9_VS) return hfx_bc_op2(g, op == OP_EQ ? D3D9_SGE : D3D9_SLT, n, hfx_bc_neg(sq), s2);
        return hfx_bc_op3(g, D3D9_CMP, n, hfx_bc_neg(sq), op == OP_EQ ? one_c(g) : zero_c(g), op == OP_EQ ? zero_c(g) : one_c(g));
    }
    if (op == OP_GT || op == OP_LE) { bc_val t = a; a = b; b = t; op = op == OP_GT ? OP_LT : OP_GE; }
    if (g->stage == D3D9_VS) return hfx_bc_op2(g, op == OP_LT ? D3D9_SLT : D3D9_SGE, n, a, b);
    bc_val d = is_zero_const(g, &b) ? a : hfx_bc_op2(g, D3D9_ADD, n, a, hfx_bc_neg(b));
    return hfx_bc_op3(g, D3D9_CMP, n, d, op == OP_GE ? one_c(g) : zero_c(g), op == OP_GE ? zero_c(g) : one_c(g));
}

/* `a < b ? x : y` in a pixel shader: one cmp on a - b (>= 0 picks y), not the comparison's 0 / 1
 * and a cmp on it, as fxc writes it (>: b - a < 0; <=: b - a >= 0; >=: a - b >= 0). Vectors and
 * scalars; matrices, structs and arrays take the general path. */
static bool select_compare(bc_gen *g, const ir_expr *e, bc_obj *out) {
    const ir_expr *c = e->a[0];
    if (g->stage != D3D9_PS || (e->type->kind != TY_SCALAR && e->type->kind != TY_VECTOR) || c->kind != IE_BINARY ||
        (c->op != OP_LT && c->op != OP_GT && c->op != OP_LE && c->op != OP_GE))
        return false;
    bc_val a = hfx_bc_expr1(g, c->a[0]), b = hfx_bc_expr1(g, c->a[1]);
    hfx_op op = c->op;
    if (op == OP_GT || op == OP_LE) { bc_val t = a; a = b; b = t; op = op == OP_GT ? OP_LT : OP_GE; }
    unsigned n = a.n > b.n ? a.n : b.n;
    bc_val d = is_zero_const(g, &b) ? a : hfx_bc_op2(g, D3D9_ADD, n, a, hfx_bc_neg(b));
    bc_val x = hfx_bc_expr1(g, e->a[1]), y = hfx_bc_expr1(g, e->a[2]);
    unsigned m = x.n > y.n ? x.n : y.n;
    *out = one(g, op == OP_LT ? hfx_bc_op3(g, D3D9_CMP, m, d, y, x) : hfx_bc_op3(g, D3D9_CMP, m, d, x, y));
    return true;
}

/* --- arithmetic --- */

/* v's values when it reads a def register (its modifier applied), for folding. */
static bool def_values(const bc_gen *g, bc_val v, float *out) {
    if (v.type != D3D9_REG_CONST || v.rel || (v.mod != D3D9_SMOD_NONE && v.mod != D3D9_SMOD_NEG)) return false;
    for (uint32_t d = 0; d < g->def_count; d++)
        if (g->defs[d].num == v.num) {
            for (unsigned i = 0; i < v.n; i++) out[i] = v.mod == D3D9_SMOD_NEG ? -g->defs[d].v[v.sw[i]] : g->defs[d].v[v.sw[i]];
            return true;
        }
    return false;
}

/* Per component: rcp, rsq, exp, log take one component each; components reading the same
 * source components share one instruction (its result is replicated to the whole mask: x / 16
 * on a float4 is one rcp, as fxc writes it). The reciprocal of a literal is a literal. */
bc_val hfx_bc_per_comp(bc_gen *g, uint16_t op, bc_val a, const bc_val *b) {
    float k[4];
    if (op == D3D9_RCP && !b && def_values(g, a, k)) {
        bool nonzero = true;
        for (unsigned i = 0; i < a.n; i++) { nonzero &= k[i] != 0; k[i] = 1.0f / k[i]; }
        if (nonzero) return hfx_bc_const(g, k, a.n);
    }
    int r = hfx_bc_temp(g);
    bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), a.n);
    for (unsigned i = 0; i < a.n; i++) {
        unsigned mask = 1u << i;
        bool done = false;
        for (unsigned j = 0; j < i; j++) done |= a.sw[j] == a.sw[i] && (!b || b->sw[j < b->n ? j : 0] == b->sw[i < b->n ? i : 0]);
        if (done) continue;
        for (unsigned j = i + 1; j < a.n; j++)
            if (a.sw[j] == a.sw[i] && (!b || b->sw[j < b->n ? j : 0] == b->sw[i < b->n ? i : 0])) mask |= 1u << j;
        bc_val s[2] = {hfx_bc_scalar_of(a, i), b ? hfx_bc_scalar_of(*b, i) : hfx_bc_scalar_of(a, i)};
        hfx_bc_emit(g, op, &d, mask, s, b ? 2 : 1);
    }
    hfx_bc_release(g, a);
    if (b) hfx_bc_release(g, *b);
    d.own = r >= 0;
    if (a.n == 1) g->last_fresh = g->failed ? -1 : (int)g->inst_count - 1;
    return d;
}

static bc_val trunc_val(bc_gen *g, bc_val x) {
    bc_val xs = x;
    xs.own = false;
    bc_val fl = hfx_bc_floor(g, xs);                       /* floor(x) */
    bc_val nx = hfx_bc_neg(xs);
    bc_val f2 = hfx_bc_op1(g, D3D9_FRC, x.n, nx);           /* frc(-x) */
    bc_val ce = hfx_bc_op2(g, D3D9_ADD, x.n, xs, f2);       /* ceil(x) */
    bc_val r;
    if (g->stage == D3D9_PS) r = hfx_bc_op3(g, D3D9_CMP, x.n, xs, fl, ce);
    else {
        bc_val ge = hfx_bc_op2(g, D3D9_SGE, x.n, xs, zero_c(g));
        r = hfx_bc_op3(g, D3D9_LRP, x.n, ge, fl, ce);
    }
    hfx_bc_release(g, x);
    return r;
}

bc_val hfx_bc_trunc(bc_gen *g, bc_val x) { return trunc_val(g, x); }

static bool is_float(const hfx_type *t) { return t->base == B_FLOAT || t->base == B_HALF || t->base == B_DOUBLE || t->base == B_MIN16FLOAT; }

static bc_val divide(bc_gen *g, bc_val a, bc_val b, const hfx_type *t) {
    bc_val rb = hfx_bc_per_comp(g, D3D9_RCP, b, NULL);
    if (rb.n < a.n && rb.n == 1) { /* replicated */ }
    bc_val q = hfx_bc_op2(g, D3D9_MUL, a.n > rb.n ? a.n : rb.n, a, rb);
    return is_float(t) ? q : trunc_val(g, q);
}

bc_val hfx_bc_fmod(bc_gen *g, bc_val a, bc_val b) {
    /* fxc: q = a / b; r = frc(|q|) * sign(q) * b */
    bc_val bs = b;
    bs.own = false;
    unsigned n = a.n > b.n ? a.n : b.n;
    bc_val rb = hfx_bc_per_comp(g, D3D9_RCP, bs, NULL);
    bc_val q = hfx_bc_op2(g, D3D9_MUL, n, a, rb);
    bc_val qs = q;
    qs.own = false;
    bc_val aq = hfx_bc_op1(g, D3D9_ABS, n, qs);
    bc_val f = hfx_bc_op1(g, D3D9_FRC, n, aq);
    bc_val fs = f;
    fs.own = false;
    bc_val s = g->stage == D3D9_PS ? hfx_bc_op3(g, D3D9_CMP, n, qs, fs, hfx_bc_neg(fs))
                                   : hfx_bc_op3(g, D3D9_LRP, n, hfx_bc_op2(g, D3D9_SGE, n, qs, zero_c(g)), fs, hfx_bc_neg(fs));
    hfx_bc_release(g, f);
    hfx_bc_release(g, q);
    return hfx_bc_op2(g, D3D9_MUL, n, s, b);
}

static bool is_mul(const ir_expr *e) {
    return e->kind == IE_BINARY && e->op == OP_MUL && is_float(e->type) && e->type->kind != TY_MATRIX;
}

static bc_val binary_vals(bc_gen *g, hfx_op op, bc_val a, bc_val b, const hfx_type *t) {
    unsigned n = a.n > b.n ? a.n : b.n;
    switch (op) {
    case OP_ADD: return hfx_bc_op2(g, D3D9_ADD, n, a, b);
    case OP_SUB: return hfx_bc_op2(g, D3D9_ADD, n, a, hfx_bc_neg(b));
    case OP_MUL: return hfx_bc_op2(g, D3D9_MUL, n, a, b);
    case OP_DIV: return divide(g, a, b, t);
    case OP_MOD: return hfx_bc_fmod(g, a, b);
    case OP_AND: return hfx_bc_op2(g, D3D9_MUL, n, a, b);
    case OP_OR: return hfx_bc_op2(g, D3D9_MAX, n, a, b);
    case OP_LT: case OP_GT: case OP_LE: case OP_GE: case OP_EQ: case OP_NE: return compare(g, op, a, b);
    default:
        hfx_bc_fail(g, g->loc, X_BC_UNSUPPORTED, "integer bit operations have no D3D9 instruction (SM2 / SM3 compute on floats)");
        return a;
    }
}

/* x + y * z (either order) and y * z - x as one mad. */
static bool fused(bc_gen *g, const ir_expr *e, bc_val *out) {
    if (!is_float(e->type) || e->type->kind == TY_MATRIX || (e->op != OP_ADD && e->op != OP_SUB)) return false;
    int m = is_mul(e->a[0]) ? 0 : is_mul(e->a[1]) ? 1 : -1;
    if (m < 0) return false;
    const ir_expr *p = e->a[m], *q = e->a[1 - m];
    bc_val x = hfx_bc_expr1(g, p->a[0]), y = hfx_bc_expr1(g, p->a[1]), z = hfx_bc_expr1(g, q);
    if (e->op == OP_SUB) { if (m == 0) z = hfx_bc_neg(z); else x = hfx_bc_neg(x); }
    unsigned n = width(e->type);
    *out = hfx_bc_op3(g, D3D9_MAD, n, x, y, z);
    return true;
}

static bc_obj binary(bc_gen *g, const ir_expr *e) {
    bc_val r;
    if (fused(g, e, &r)) return one(g, r);
    if (e->type->kind == TY_MATRIX) {
        int splat = e->a[1]->kind == IE_CONVERT && e->a[1]->a[0]->type->kind == TY_SCALAR ? 1
                  : e->a[0]->kind == IE_CONVERT && e->a[0]->a[0]->type->kind == TY_SCALAR ? 0 : -1;
        if (splat >= 0) { /* matrix op scalar: each register of the matrix, in its own layout */
            bc_obj m = hfx_bc_expr(g, e->a[1 - splat]);
            bc_val s = hfx_bc_expr1(g, e->a[splat]->a[0]);
            bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, m.count), m.count, m.cols};
            for (uint32_t k = 0; k < m.count; k++) {
                bc_val x = m.slot[k], y = s;
                y.own = false;
                o.slot[k] = splat ? binary_vals(g, e->op, x, y, e->type) : binary_vals(g, e->op, y, x, e->type);
            }
            hfx_bc_release(g, s);
            return o;
        }
        bc_obj a = hfx_bc_expr(g, e->a[0]), b = hfx_bc_expr(g, e->a[1]);
        if (a.cols == b.cols) {
            bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, a.count), a.count, a.cols};
            for (uint32_t k = 0; k < a.count; k++) o.slot[k] = binary_vals(g, e->op, a.slot[k], b.slot[k], e->type);
            return o;
        }
        bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, e->type->rows), e->type->rows, false};
        for (unsigned k = 0; k < e->type->rows; k++) {
            bc_val x = hfx_bc_matrix_row(g, a, e->type, k), y = hfx_bc_matrix_row(g, b, e->type, k);
            o.slot[k] = binary_vals(g, e->op, x, y, e->type);
        }
        return o;
    }
    bc_val a = hfx_bc_expr1(g, e->a[0]), b = hfx_bc_expr1(g, e->a[1]);
    return one(g, binary_vals(g, e->op, a, b, e->a[0]->type));
}

/* --- reads of parts --- */

static bc_obj sub(bc_gen *g, bc_obj o, uint32_t first, uint32_t n) {
    bc_obj r = {o.slot + first, n, o.cols};
    for (uint32_t k = 0; k < o.count; k++)
        if (k < first || k >= first + n) hfx_bc_release(g, o.slot[k]);
    (void)g;
    return r;
}

static bc_obj field(bc_gen *g, const ir_expr *e) {
    bc_obj o = hfx_bc_expr(g, e->a[0]);
    const hfx_type *t = e->a[0]->type;
    uint32_t first = 0;
    for (uint32_t i = 0; i < e->field && i < t->st->field_count; i++) first += hfx_bc_slots(t->st->fields[i].type, o.cols);
    return sub(g, o, first, hfx_bc_slots(t->st->fields[e->field].type, o.cols));
}

/* c[a0.x + n]: the vertex shader's relative read of a parameter array. */
static bc_obj relative(bc_gen *g, bc_obj o, const ir_expr *idx, uint32_t per) {
    if (g->stage != D3D9_VS || !o.count || o.slot[0].type != D3D9_REG_CONST) {
        hfx_bc_fail(g, idx->loc, X_BC_UNSUPPORTED, "the bytecode writer indexes arrays by a computed index only in vertex shaders' parameters");
        return o;
    }
    bc_val i = hfx_bc_expr1(g, idx);
    if (per != 1) i = hfx_bc_op2(g, D3D9_MUL, 1, i, hfx_bc_constf(g, (float)per));
    bc_val a0 = hfx_bc_reg(D3D9_REG_ADDR, 0, 1);
    hfx_bc_emit(g, D3D9_MOVA, &a0, 1, &i, 1);
    hfx_bc_release(g, i);
    bc_obj r = {HFX_NEW_ARRAY(g->c->arena, bc_val, per), per, o.cols};
    for (uint32_t k = 0; k < per; k++) { r.slot[k] = o.slot[k]; r.slot[k].rel = true; r.slot[k].own = false; }
    return r;
}

static bc_obj index_of(bc_gen *g, const ir_expr *e) {
    const hfx_type *t = e->a[0]->type;
    bc_obj o = hfx_bc_expr(g, e->a[0]);
    double k;
    if (t->kind == TY_ARRAY) {
        uint32_t per = hfx_bc_slots(t->elem, o.cols);
        bc_obj by_aL;
        if (!hfx_bc_try_const(g, e->a[1], &k) && hfx_bc_loop_index(g, o, e->a[1], per, &by_aL)) return by_aL;
        if (!hfx_bc_try_const(g, e->a[1], &k))
            return hfx_bc_addressable(g, o) ? relative(g, o, e->a[1], per) : hfx_bc_index_select(g, o, t, e->a[1]);
        uint32_t i = k < 0 || k >= t->array_len ? 0 : hfx_ev_uint(k);
        return sub(g, o, i * per, per);
    }
    if (!hfx_bc_try_const(g, e->a[1], &k)) return hfx_bc_index_select(g, o, t, e->a[1]);
    unsigned i = k < 0 ? 0 : hfx_ev_uint(k);
    if (t->kind == TY_MATRIX && !o.cols) return sub(g, o, i < o.count ? i : 0, 1);
    if (t->kind == TY_MATRIX) return one(g, hfx_bc_matrix_row(g, o, t, i < t->rows ? i : 0));
    bc_val v = o.slot[0];
    v.n = 1;
    v.sw[0] = o.slot[0].sw[i < o.slot[0].n ? i : 0];
    return one(g, v);
}

static bc_obj swizzle(bc_gen *g, const ir_expr *e) {
    const hfx_type *t = e->a[0]->type;
    bc_obj o = hfx_bc_expr(g, e->a[0]);
    if (t->kind == TY_MATRIX) {
        bc_val parts[4] = {{0}};
        for (unsigned i = 0; i < e->comp_count && i < 4; i++)
            parts[i] = hfx_bc_matrix_elem(o, e->comps[i] / t->cols, e->comps[i] % t->cols);
        bool same = true;
        for (unsigned i = 1; i < e->comp_count; i++) same &= parts[i].num == parts[0].num && parts[i].type == parts[0].type;
        if (same) {
            bc_val v = parts[0];
            for (unsigned i = 0; i < e->comp_count; i++) v.sw[i] = parts[i].sw[0];
            v.n = e->comp_count;
            return one(g, v);
        }
        return one(g, gather(g, parts, e->comp_count));
    }
    bc_val b = o.slot[0], v = b;
    for (unsigned i = 0; i < e->comp_count && i < 4; i++) v.sw[i] = b.sw[e->comps[i] < b.n ? e->comps[i] : 0];
    v.n = e->comp_count;
    return one(g, v);
}

/* --- construction and conversion --- */

static bc_obj construct(bc_gen *g, const ir_expr *e) {
    const hfx_type *t = e->type;
    uint32_t total = hfx_type_components(t);
    bc_val parts[16] = {{0}};
    uint32_t n = 0;
    bool all_const = true;
    bc_val *vals = HFX_NEW_ARRAY(g->c->arena, bc_val, e->n ? e->n : 1);
    if (t->kind == TY_STRUCT || t->kind == TY_ARRAY) return hfx_bc_construct_aggregate(g, e);
    for (uint32_t i = 0; i < e->n; i++) {
        double k;
        all_const &= e->a[i]->kind == IE_CONST || (e->a[i]->type->kind == TY_SCALAR && hfx_bc_try_const(g, e->a[i], &k));
    }
    if (all_const && total <= 16) {
        float v[16];
        for (uint32_t i = 0; i < e->n; i++) {
            double k = 0;
            if (e->a[i]->kind == IE_CONST)
                for (unsigned c = 0; c < hfx_type_components(e->a[i]->type) && n < 16; c++) v[n++] = (float)e->a[i]->cval[c];
            else if (hfx_bc_try_const(g, e->a[i], &k) && n < 16) v[n++] = (float)k;
        }
        if (t->kind != TY_MATRIX) return one(g, hfx_bc_const(g, v, total));
        bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, t->rows), t->rows, false};
        for (unsigned r = 0; r < t->rows; r++) o.slot[r] = hfx_bc_const(g, v + r * t->cols, t->cols);
        return o;
    }
    if (t->kind == TY_MATRIX && e->n == t->rows) { /* one vector per row: the rows as they are */
        bool rows = true;
        for (uint32_t i = 0; i < e->n; i++) rows &= e->a[i]->type->kind == TY_VECTOR && e->a[i]->type->cols == t->cols;
        if (rows) {
            bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, t->rows), t->rows, false};
            for (uint32_t i = 0; i < e->n; i++) o.slot[i] = hfx_bc_expr1(g, e->a[i]);
            return o;
        }
    }
    for (uint32_t i = 0; i < e->n; i++) {
        const hfx_type *at = e->a[i]->type;
        if (at->kind == TY_MATRIX) {
            bc_obj m = hfx_bc_expr(g, e->a[i]);
            for (unsigned r = 0; r < at->rows; r++)
                for (unsigned c = 0; c < at->cols && n < 16; c++) parts[n++] = hfx_bc_matrix_elem(m, r, c);
            continue;
        }
        vals[i] = hfx_bc_expr1(g, e->a[i]);
        for (unsigned c = 0; c < vals[i].n && n < 16; c++) parts[n++] = hfx_bc_scalar_of(vals[i], c);
    }
    if (e->n == 1 && vals[0].n == total && t->kind != TY_MATRIX) return one(g, vals[0]);
    bc_obj o;
    if (t->kind == TY_MATRIX) {
        o = (bc_obj){HFX_NEW_ARRAY(g->c->arena, bc_val, t->rows), t->rows, false};
        for (unsigned r = 0; r < t->rows; r++) o.slot[r] = gather(g, parts + r * t->cols, t->cols);
    } else o = one(g, gather(g, parts, total));
    for (uint32_t i = 0; i < e->n; i++) if (e->a[i]->type->kind != TY_MATRIX) hfx_bc_release(g, vals[i]);
    return o;
}

static bc_obj convert(bc_gen *g, const ir_expr *e) {
    const hfx_type *to = e->type, *from = e->a[0]->type;
    if (to->kind == TY_MATRIX && from->kind == TY_MATRIX) {
        bc_obj m = hfx_bc_expr(g, e->a[0]);
        bc_obj o = {m.slot, m.cols ? to->cols : to->rows, m.cols};
        o.slot = HFX_NEW_ARRAY(g->c->arena, bc_val, o.count);
        for (uint32_t k = 0; k < o.count; k++) { o.slot[k] = m.slot[k]; o.slot[k].n = (uint8_t)(m.cols ? to->rows : to->cols); }
        return o;
    }
    if (to->kind == TY_MATRIX && from->kind == TY_SCALAR) { /* a splat: every row the scalar */
        bc_val v = hfx_bc_expr1(g, e->a[0]);
        bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, to->rows), to->rows, false};
        for (unsigned r = 0; r < to->rows; r++) {
            o.slot[r] = v;
            o.slot[r].own = r == 0 && v.own;
            for (unsigned c = 1; c < 4; c++) o.slot[r].sw[c] = v.sw[0];
            o.slot[r].n = to->cols;
        }
        return o;
    }
    if ((to->kind == TY_STRUCT || to->kind == TY_ARRAY) && from->kind == TY_SCALAR) { /* (VSOutput)0: every slot */
        bc_val v = hfx_bc_expr1(g, e->a[0]);
        if (v.own) v = hfx_bc_own(g, v);
        bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, hfx_bc_slots(to, false) ? hfx_bc_slots(to, false) : 1), hfx_bc_slots(to, false), false};
        for (uint32_t k = 0; k < o.count; k++) {
            o.slot[k] = v;
            o.slot[k].own = false;
            for (unsigned c = 1; c < 4; c++) o.slot[k].sw[c] = v.sw[0];
            o.slot[k].n = (uint8_t)hfx_bc_slot_width(to, false, k);
        }
        if (v.own && o.count) o.slot[0].own = true; /* freed once, by whoever takes the first slot */
        return o;
    }
    if (to->kind == TY_STRUCT || to->kind == TY_ARRAY || to->kind == TY_MATRIX || from->kind == TY_MATRIX) {
        if (hfx_type_equal(to, from)) return hfx_bc_expr(g, e->a[0]);
        return hfx_bc_reshape(g, e);
    }
    bc_val v = hfx_bc_expr1(g, e->a[0]);
    unsigned n = width(to);
    if (v.n == 1 && n > 1) { for (unsigned i = 1; i < 4; i++) v.sw[i] = v.sw[0]; }
    v.n = (uint8_t)n;
    bool fi = is_float(from) && (to->base == B_INT || to->base == B_UINT);
    if (fi) return one(g, trunc_val(g, v));
    if (to->base == B_BOOL && from->base != B_BOOL) return one(g, compare(g, OP_NE, v, zero_c(g)));
    return one(g, v);
}

/* --- assignment --- */

/* The binding slots an l-value names: a variable, its fields, constant indexes, a swizzle of one
 * slot (comps, n; n == 0: whole slots). False when it is none of those. */
typedef bc_lval lval;

static bool lval_path(bc_gen *g, const ir_expr *e, lval *l);

/* A binding in the column layout (an interface struct holding a matrix) is written only outside
 * its matrices. */
static bool lval_of(bc_gen *g, const ir_expr *e, lval *l) {
    return lval_path(g, e, l) && (!l->b->obj.cols || !hfx_bc_has_matrix(e->type));
}

static bool lval_path(bc_gen *g, const ir_expr *e, lval *l) {
    double k;
    switch (e->kind) {
    case IE_VAR:
        l->b = hfx_bc_bind(g, e->var);
        if (!l->b || l->b->is_const || (l->b->obj.cols && e->type->kind == TY_MATRIX) || l->b->var->kind == IRV_UNIFORM) return false;
        l->first = 0;
        l->count = l->b->obj.count;
        l->n = 0;
        return l->count <= 64;
    case IE_FIELD: {
        if (!lval_path(g, e->a[0], l) || l->n) return false;
        const hfx_type *t = e->a[0]->type;
        for (uint32_t i = 0; i < e->field; i++) l->first += hfx_bc_slots(t->st->fields[i].type, l->b->obj.cols);
        l->count = hfx_bc_slots(t->st->fields[e->field].type, l->b->obj.cols);
        return true;
    }
    case IE_INDEX: {
        const hfx_type *t = e->a[0]->type;
        if (!hfx_bc_try_const(g, e->a[1], &k) || k < 0 || !lval_path(g, e->a[0], l) || l->n) return false;
        if (t->kind == TY_VECTOR) { /* v[k]: v.x, v.y... */
            if (k >= t->cols || l->count != 1) return false;
            l->comps[0] = (uint8_t)hfx_ev_uint(k);
            l->n = 1;
            return true;
        }
        if (t->kind == TY_ARRAY) {
            uint32_t per = hfx_bc_slots(t->elem, l->b->obj.cols);
            if (k >= t->array_len) return false;
            l->first += hfx_ev_uint(k) * per;
            l->count = per;
            return true;
        }
        if (t->kind != TY_MATRIX || k >= t->rows || l->b->obj.cols) return false;
        l->first += hfx_ev_uint(k);
        l->count = 1;
        return true;
    }
    case IE_SWIZZLE:
        if (e->a[0]->type->kind == TY_MATRIX || !lval_path(g, e->a[0], l) || l->n || l->count != 1) return false;
        for (unsigned i = 0; i < e->comp_count; i++) l->comps[i] = e->comps[i];
        l->n = e->comp_count;
        return true;
    default: return false;
    }
}

/* Registers nothing writes while the shader runs: a slot may simply name them. */
bool hfx_bc_immutable(const bc_gen *g, const bc_val *v) {
    if (v->rel) return false;
    if (v->type == D3D9_REG_CONST || v->type == D3D9_REG_MISC) return true;
    return (v->type == D3D9_REG_INPUT || (v->type == D3D9_REG_ADDR && g->stage == D3D9_PS)) && !v->mod;
}

/* Slot k of the binding as a temporary of its own (copying what it named when part is kept). */
static void own_slot(bc_gen *g, bc_binding *b, uint32_t k, bool keep) {
    bc_val *v = &b->obj.slot[k];
    if (v->type == D3D9_REG_TEMP && (b->owned >> k & 1)) return;
    bc_val old = *v;
    old.own = false;
    int r = hfx_bc_temp(g);
    bc_val t = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), old.n);
    if (keep) hfx_bc_store(g, t, old, false);
    *v = t;
    b->owned |= 1ull << k;
}

/* lhs = rhs by slots: a whole slot takes an immutable register's view or a fresh temporary as
 * is (no mov); the rest is written into temporaries of the binding's own. */
static bool assign_slots(bc_gen *g, const lval *l, bc_obj src, bool sat) {
    bc_binding *b = l->b;
    for (uint32_t k = 0; k < l->count && k < src.count; k++) {
        uint32_t at = l->first + k;
        bc_val v = src.slot[k], *dst = &b->obj.slot[at];
        bool whole = !l->n || l->n == dst->n;
        for (unsigned i = 0; whole && l->n && i < l->n; i++) whole = l->comps[i] == i;
        if (whole && !sat && v.n == dst->n && (hfx_bc_immutable(g, &v) || (v.own && v.type == D3D9_REG_TEMP && !v.mod && injective_val(&v)))) {
            bc_val old = *dst;
            old.own = (b->owned >> at & 1) && old.type == D3D9_REG_TEMP;
            hfx_bc_release(g, old);
            *dst = v;
            dst->own = false;
            if (v.own) b->owned |= 1ull << at;
            else b->owned &= ~(1ull << at);
            continue;
        }
        own_slot(g, b, at, !whole);
        bc_val t = *dst;
        if (l->n) {
            t.n = l->n;
            for (unsigned i = 0; i < l->n; i++) t.sw[i] = dst->sw[l->comps[i]];
        }
        hfx_bc_store(g, t, v, sat);
    }
    return true;
}

/* Slot k of matrix m in the layout `cols` (a view when m has it; a splat stays a view). */
static bc_val layout_slot(bc_gen *g, bc_obj m, const hfx_type *t, bool cols, unsigned k) {
    if (m.cols == cols) {
        bc_val v = m.slot[k < m.count ? k : 0];
        v.own = false;
        return v;
    }
    unsigned n = cols ? t->rows : t->cols;
    bc_val parts[4];
    bool splat = true;
    for (unsigned i = 0; i < n; i++) {
        parts[i] = cols ? hfx_bc_matrix_elem(m, i, k) : hfx_bc_matrix_elem(m, k, i);
        splat &= parts[i].type == parts[0].type && parts[i].num == parts[0].num && parts[i].mod == parts[0].mod &&
                 parts[i].sw[0] == parts[0].sw[0] && !parts[i].rel;
    }
    if (!splat) return gather(g, parts, n);
    bc_val v = parts[0];
    v.n = (uint8_t)n;
    for (unsigned c = 1; c < 4; c++) v.sw[c] = v.sw[0];
    return v;
}

/* m += x (or -=, or += x * w) on a matrix variable: computed in x's layout, so that a column_major
 * parameter's columns (skinning's Bones[i] * w) add up without a transpose, and the variable takes
 * the result's registers. Under a flattened condition the variable keeps its layout (both sides
 * of the if must agree). */
static bool matrix_update(bc_gen *g, const ir_expr *e) {
    const ir_expr *lhs = e->a[0], *rhs = e->a[1], *m = rhs, *w = NULL;
    bc_binding *b = lhs->kind == IE_VAR ? hfx_bc_bind(g, lhs->var) : NULL;
    if (!b || b->is_const || b->var->kind == IRV_UNIFORM || (e->op != OP_ADD && e->op != OP_SUB) || b->obj.count > 64)
        return false;
    const hfx_type *t = e->type;
    if (e->op == OP_ADD && rhs->kind == IE_BINARY && rhs->op == OP_MUL && rhs->type->kind == TY_MATRIX)
        for (int s = 0; s < 2 && !w; s++)
            if (rhs->a[s]->kind == IE_CONVERT && rhs->a[s]->a[0]->type->kind == TY_SCALAR) { w = rhs->a[s]->a[0]; m = rhs->a[1 - s]; }
    bc_obj r = hfx_bc_expr(g, m);
    bc_val wv = w ? hfx_bc_expr1(g, w) : zero_c(g);
    bool cols = g->cond.n ? b->obj.cols : r.cols;
    unsigned count = cols ? t->cols : t->rows;
    bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, count), count, cols};
    for (unsigned k = 0; k < count; k++) {
        bc_val cur = layout_slot(g, b->obj, t, cols, k), x = layout_slot(g, r, t, cols, k), ww = wv;
        ww.own = false;
        o.slot[k] = w ? hfx_bc_op3(g, D3D9_MAD, x.n, x, ww, cur) : binary_vals(g, e->op, cur, x, t);
        if (!o.slot[k].own || o.slot[k].type != D3D9_REG_TEMP || o.slot[k].mod) o.slot[k] = hfx_bc_op1(g, D3D9_MOV, o.slot[k].n, o.slot[k]);
    }
    hfx_bc_release(g, wv);
    hfx_bc_release_obj(g, r);
    for (uint32_t k = 0; k < b->obj.count; k++) {
        bc_val old = b->obj.slot[k];
        old.own = (b->owned >> k & 1) && old.type == D3D9_REG_TEMP;
        hfx_bc_release(g, old);
    }
    b->obj = o;
    b->owned = 0;
    for (uint32_t k = 0; k < count; k++) { b->owned |= 1ull << k; b->obj.slot[k].own = false; }
    return true;
}

/* Component j of an l-value as a one-component lval: a matrix swizzle's element (the row-major
 * binding's slot `row`, component `col`), or a vector l-value's j-th written component. */
static bool component_lval(bc_gen *g, const ir_expr *a, unsigned j, lval *l) {
    if (a->kind == IE_SWIZZLE && a->a[0]->type->kind == TY_MATRIX) {
        const ir_expr *m = a->a[0];
        if (j >= a->comp_count || !lval_of(g, m, l) || l->n) return false;
        l->first += a->comps[j] / m->type->cols;
        l->count = 1;
        l->comps[0] = (uint8_t)(a->comps[j] % m->type->cols);
        l->n = 1;
        return true;
    }
    if (!lval_of(g, a, l) || l->count != 1) return false;
    l->comps[0] = l->n ? l->comps[j < l->n ? j : 0] : (uint8_t)j;
    l->n = 1;
    return true;
}

static unsigned components(const hfx_type *t) { return t->kind == TY_VECTOR ? t->cols : 1; }

/* m._11_22 = v (the IR spells the left side a matrix swizzle, or a construct of one-element
 * swizzles): each component written where it lives; reading the left side would give a gathered
 * copy that the writes would miss. */
static bc_obj assign_components(bc_gen *g, const ir_expr *e) {
    const ir_expr *lhs = e->a[0];
    bool construct = lhs->kind == IE_CONSTRUCT;
    if (e->op != OP_NONE) {
        hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer does not update these matrix components yet");
        return (bc_obj){0};
    }
    bc_obj src = hfx_bc_expr(g, e->a[1]);
    unsigned at = 0, parts = construct ? lhs->n : 1;
    for (unsigned p = 0; p < parts && src.count && !g->failed; p++) {
        const ir_expr *a = construct ? lhs->a[p] : lhs;
        unsigned n = construct ? components(a->type) : lhs->comp_count;
        for (unsigned j = 0; j < n && !g->failed; j++, at++) {
            lval l;
            if (!component_lval(g, a, j, &l)) {
                hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer does not write these components yet");
                break;
            }
            assign_slots(g, &l, one(g, hfx_bc_scalar_of(src.slot[0], at)), false);
        }
    }
    hfx_bc_release_obj(g, src);
    return hfx_bc_expr(g, lhs);
}

static bc_obj assign(bc_gen *g, const ir_expr *e) {
    const ir_expr *lhs = e->a[0];
    bc_obj dyn;
    if (hfx_bc_assign_dynamic(g, e, &dyn)) return dyn;
    if ((lhs->kind == IE_SWIZZLE && lhs->a[0]->type->kind == TY_MATRIX) || lhs->kind == IE_CONSTRUCT)
        return assign_components(g, e);
    if (lhs->kind == IE_VAR) {
        bc_binding *b = hfx_bc_bind(g, lhs->var);
        if (b && b->is_const) { /* a counter written with a computed value: give it a register */
            bc_val r = hfx_bc_own(g, hfx_bc_constf(g, (float)b->konst));
            b->is_const = false;
            b->obj = one(g, r);
            b->obj.slot[0].own = false;
            b->owned = ~0ull;
        }
    }
    bool sat = false;
    lval l;
    if (e->op == OP_NONE && lval_of(g, lhs, &l) && (lhs->type->kind != TY_MATRIX || !bc_expr_is_cols(g, e->a[1]))) {
        const ir_expr *rhs = e->a[1];
        if (rhs->kind == IE_INTRIN && rhs->intrin == HFX_INTR_SATURATE && hfx_bc_can_sat(g)) { sat = true; rhs = rhs->a[0]; }
        bc_obj src = hfx_bc_expr(g, rhs);
        lval_of(g, lhs, &l); /* again: the right side may have added bindings (and moved them) */
        if (!src.cols) {
            assign_slots(g, &l, src, sat);
            return hfx_bc_expr(g, lhs);
        }
        bc_obj dst = hfx_bc_expr(g, lhs);
        for (uint32_t k = 0; k < l.count; k++) own_slot(g, l.b, l.first + k, true);
        dst = hfx_bc_expr(g, lhs);
        hfx_bc_assign(g, dst, src, e->type, sat);
        return dst;
    }
    if (e->op != OP_NONE && lhs->type->kind == TY_MATRIX && matrix_update(g, e)) return hfx_bc_expr(g, lhs);
    if (e->op != OP_NONE && lhs->type->kind != TY_MATRIX && lval_of(g, lhs, &l)) {
        /* x op= y as x = x op y: the current value is read where it is (a zero it starts as
         * folds away, a product added is one mad) and the result taken as an assignment's */
        bc_val cur = hfx_bc_expr1(g, lhs), r;
        cur.own = false;
        if (e->op == OP_ADD && is_mul(e->a[1]))
            r = hfx_bc_op3(g, D3D9_MAD, width(e->type), hfx_bc_expr1(g, e->a[1]->a[0]), hfx_bc_expr1(g, e->a[1]->a[1]), cur);
        else r = binary_vals(g, e->op, cur, hfx_bc_expr1(g, e->a[1]), e->type);
        if (lval_of(g, lhs, &l)) assign_slots(g, &l, one(g, r), false);
        return hfx_bc_expr(g, lhs);
    }
    if (lval_of(g, lhs, &l)) /* a compound assignment or a matrix: writable temporaries first */
        for (uint32_t k = 0; k < l.count; k++) own_slot(g, l.b, l.first + k, true);
    bc_obj dst = hfx_bc_expr(g, lhs);
    const ir_expr *rhs = e->a[1];
    if (e->op == OP_NONE && rhs->kind == IE_INTRIN && rhs->intrin == HFX_INTR_SATURATE && hfx_bc_can_sat(g)) { sat = true; rhs = rhs->a[0]; }
    bc_obj src;
    if (e->op != OP_NONE && e->type->kind == TY_MATRIX) { /* by rows of the variable */
        bc_obj r = hfx_bc_expr(g, rhs);
        src = (bc_obj){HFX_NEW_ARRAY(g->c->arena, bc_val, dst.count), dst.count, false};
        for (uint32_t k = 0; k < dst.count; k++) {
            bc_val cur = dst.slot[k];
            cur.own = false;
            src.slot[k] = binary_vals(g, e->op, cur, hfx_bc_matrix_row(g, r, e->type, k), e->type);
        }
        hfx_bc_release_obj(g, r);
    } else if (e->op != OP_NONE) {
        bc_val cur = dst.slot[0];
        cur.own = false;
        if (e->op == OP_ADD && is_mul(rhs)) {
            bc_val x = hfx_bc_expr1(g, rhs->a[0]), y = hfx_bc_expr1(g, rhs->a[1]);
            src = one(g, hfx_bc_op3(g, D3D9_MAD, width(e->type), x, y, cur));
        } else src = one(g, binary_vals(g, e->op, cur, hfx_bc_expr1(g, rhs), e->type));
    } else src = hfx_bc_expr(g, rhs);
    hfx_bc_assign(g, dst, src, e->type, sat);
    return dst;
}

static bc_obj incdec(bc_gen *g, const ir_expr *e) {
    lval l; /* writable temporaries first: an input (PSIn.TexCoords.y--) is copied on write */
    if (lval_of(g, e->a[0], &l))
        for (uint32_t k = 0; k < l.count; k++) own_slot(g, l.b, l.first + k, true);
    bc_obj dst = hfx_bc_expr(g, e->a[0]);
    bc_val cur = dst.slot[0];
    cur.own = false;
    bool post = e->op == OP_POSTINC || e->op == OP_POSTDEC;
    bc_val old = post ? hfx_bc_own(g, cur) : cur;
    bc_val nv = hfx_bc_op2(g, D3D9_ADD, cur.n, cur, hfx_bc_constf(g, e->op == OP_PREINC || e->op == OP_POSTINC ? 1.0f : -1.0f));
    hfx_bc_store(g, dst.slot[0], nv, false);
    return one(g, post ? old : dst.slot[0]);
}

/* --- the dispatcher --- */

bc_obj hfx_bc_expr(bc_gen *g, const ir_expr *e) {
    if (g->failed) return one(g, hfx_bc_reg(D3D9_REG_CONST, 0, 4));
    switch (e->kind) {
    case IE_CONST: return constant(g, e);
    case IE_VAR: {
        bc_binding *b = hfx_bc_bind(g, e->var);
        if (b && b->is_const) return one(g, hfx_bc_constf(g, (float)b->konst));
        if (!b) {
            hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer has no register for '%s'", e->var->name);
            return one(g, zero_c(g));
        }
        bc_obj o = b->obj;
        o.slot = HFX_NEW_ARRAY(g->c->arena, bc_val, o.count ? o.count : 1);
        memcpy(o.slot, b->obj.slot, o.count * sizeof *o.slot);
        for (uint32_t k = 0; k < o.count; k++) o.slot[k].own = false;
        return o;
    }
    case IE_UNARY:
        if (e->op == OP_NEG) {
            bc_obj o = hfx_bc_expr(g, e->a[0]);
            for (uint32_t k = 0; k < o.count; k++) o.slot[k] = hfx_bc_neg(o.slot[k]);
            return o;
        }
        if (e->op == OP_NOT) return one(g, hfx_bc_not(g, hfx_bc_expr1(g, e->a[0])));
        if (e->op == OP_POS) return hfx_bc_expr(g, e->a[0]);
        if (e->op == OP_BITNOT) break;
        return incdec(g, e);
    case IE_BINARY: return binary(g, e);
    case IE_SELECT: {
        bc_obj fused;
        if (select_compare(g, e, &fused)) return fused;
        bc_val c = hfx_bc_expr1(g, e->a[0]);
        bc_obj a = hfx_bc_expr(g, e->a[1]), b = hfx_bc_expr(g, e->a[2]);
        bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, a.count ? a.count : 1), a.count, false};
        for (uint32_t k = 0; k < a.count; k++) {
            bc_val ck = c;
            ck.own = false;
            bc_val x = e->type->kind == TY_MATRIX ? hfx_bc_matrix_row(g, a, e->type, k) : a.slot[k];
            bc_val y = e->type->kind == TY_MATRIX ? hfx_bc_matrix_row(g, b, e->type, k) : b.slot[k];
            o.slot[k] = hfx_bc_select(g, ck, x, y);
        }
        hfx_bc_release(g, c);
        return o;
    }
    case IE_ASSIGN: return assign(g, e);
    case IE_COMMA: {
        for (uint32_t i = 0; i + 1 < e->n; i++) hfx_bc_release_obj(g, hfx_bc_expr(g, e->a[i]));
        return hfx_bc_expr(g, e->a[e->n - 1]);
    }
    case IE_CALL: {
        bc_obj o = {0};
        hfx_bc_call(g, e, &o);
        if (!o.count) o = one(g, zero_c(g));
        return o;
    }
    case IE_INTRIN: return hfx_bc_intrinsic(g, e);
    case IE_CONSTRUCT: return construct(g, e);
    case IE_CONVERT: return convert(g, e);
    case IE_SWIZZLE: return swizzle(g, e);
    case IE_INDEX: return index_of(g, e);
    case IE_FIELD: return field(g, e);
    }
    hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer does not handle this expression yet");
    return one(g, zero_c(g));
}

bc_val hfx_bc_expr1(bc_gen *g, const ir_expr *e) {
    bc_obj o = hfx_bc_expr(g, e);
    if (o.count != 1) {
        hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer expected a scalar or vector here");
        return zero_c(g);
    }
    return o.slot[0];
}

void hfx_bc_init_binding(bc_gen *g, bc_binding *b, bc_obj src) {
    lval l = {b, 0, b->obj.count, {0}, 0};
    if (!src.cols) { assign_slots(g, &l, src, false); return; }
    for (uint32_t k = 0; k < b->obj.count; k++) own_slot(g, b, k, false);
    hfx_bc_assign(g, b->obj, src, b->var->type, false);
}

void hfx_bc_assign_expr(bc_gen *g, const ir_expr *lhs, bc_obj src, uint64_t owned) {
    lval l;
    for (uint32_t k = 0; k < src.count && k < 64; k++) src.slot[k].own = (owned >> k & 1) != 0;
    if (lval_of(g, lhs, &l) && !src.cols) { assign_slots(g, &l, src, false); return; }
    if (lval_of(g, lhs, &l))
        for (uint32_t k = 0; k < l.count; k++) own_slot(g, l.b, l.first + k, true);
    hfx_bc_assign(g, hfx_bc_expr(g, lhs), src, lhs->type, false);
}

bool hfx_bc_lval(bc_gen *g, const ir_expr *e, bc_lval *l) { return lval_of(g, e, l); }
void hfx_bc_own_slot(bc_gen *g, bc_binding *b, uint32_t k, bool keep) { own_slot(g, b, k, keep); }
bc_val hfx_bc_binary(bc_gen *g, hfx_op op, bc_val a, bc_val b, const hfx_type *t) { return binary_vals(g, op, a, b, t); }
