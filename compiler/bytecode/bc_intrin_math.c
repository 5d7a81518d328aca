/* bc_intrin_math.c: the intrinsics D3D9 has no instruction for, expanded as fxc expands them:
 * asin / acos / atan / atan2 as the polynomials of docs/conventions.md (the GLSL helpers and
 * eval.c compute the same arithmetic), the hyperbolic functions through exp, frexp / modf /
 * trunc through frc, lit and dst by their instructions in vertex shaders and by parts in pixel
 * shaders, determinant by cofactors, the classifications as compares. Comparisons give 0 / 1:
 * slt / sge in vertex shaders, cmp (a >= 0 ? b : c) in pixel shaders, whose else side a NaN
 * takes. */
#include <float.h>

#include "bytecode/bc_int.h"

static bc_val keep(bc_val v) { v.own = false; return v; }
static unsigned nmax(bc_val a, bc_val b) { return a.n > b.n ? a.n : b.n; }
static bc_val kf(bc_gen *g, float v) { return hfx_bc_constf(g, v); }
static bool vs(const bc_gen *g) { return g->stage == D3D9_VS; }

static bc_obj one(bc_gen *g, bc_val v) {
    bc_obj o = {HFX_NEW(g->c->arena, bc_val), 1, false};
    o.slot[0] = v;
    return o;
}

/* A fresh temporary whose components are written part by part (hfx_bc_store). */
static bc_val fresh(bc_gen *g, unsigned n) {
    int r = hfx_bc_temp(g);
    bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), n);
    d.own = r >= 0;
    return d;
}

/* Component i of the temporary d, as a target for hfx_bc_store. */
static bc_val part(bc_val d, unsigned i) {
    bc_val t = hfx_bc_reg(D3D9_REG_TEMP, d.num, 1);
    t.sw[0] = (uint8_t)i;
    return t;
}

/* x < 0 as 0 / 1 (-0 is not below 0: cmp takes it as >= 0, slt as not less). */
static bc_val below0(bc_gen *g, bc_val x) {
    if (vs(g)) return hfx_bc_op2(g, D3D9_SLT, x.n, x, kf(g, 0));
    return hfx_bc_op3(g, D3D9_CMP, x.n, x, kf(g, 0), kf(g, 1));
}

/* a < b as 0 / 1. */
static bc_val less(bc_gen *g, bc_val a, bc_val b) {
    unsigned n = nmax(a, b);
    if (vs(g)) return hfx_bc_op2(g, D3D9_SLT, n, a, b);
    return hfx_bc_op3(g, D3D9_CMP, n, hfx_bc_op2(g, D3D9_ADD, n, a, hfx_bc_neg(b)), kf(g, 0), kf(g, 1));
}

/* x < 0 ? -r : r */
static bc_val negate_below0(bc_gen *g, bc_val x, bc_val r) {
    if (!vs(g)) return hfx_bc_op3(g, D3D9_CMP, r.n, x, keep(r), hfx_bc_neg(r));
    bc_val m = hfx_bc_op3(g, D3D9_MAD, x.n, below0(g, x), kf(g, -2), kf(g, 1));
    return hfx_bc_op2(g, D3D9_MUL, r.n, r, m);
}

static bc_val sqrt_of(bc_gen *g, bc_val x) {
    return hfx_bc_per_comp(g, D3D9_RCP, hfx_bc_per_comp(g, D3D9_RSQ, x, NULL), NULL);
}

/* --- inverse trigonometry --- */

/* acos: r = p(|x|) sqrt(1 - |x|), and r + (pi - 2 r) where x < 0. */
static bc_val acos_of(bc_gen *g, bc_val x) {
    unsigned n = x.n;
    bc_val a = hfx_bc_op1(g, D3D9_ABS, n, keep(x));
    bc_val p = hfx_bc_op3(g, D3D9_MAD, n, keep(a), kf(g, -0.0187292993f), kf(g, 0.0742610022f));
    p = hfx_bc_op3(g, D3D9_MAD, n, p, keep(a), kf(g, -0.212114394f));
    p = hfx_bc_op3(g, D3D9_MAD, n, p, keep(a), kf(g, 1.57072878f));
    bc_val s = sqrt_of(g, hfx_bc_op2(g, D3D9_ADD, n, hfx_bc_neg(a), kf(g, 1)));
    bc_val r = hfx_bc_op2(g, D3D9_MUL, n, p, s);
    bc_val k = hfx_bc_op3(g, D3D9_MAD, n, keep(r), kf(g, -2), kf(g, 3.14159274f));
    return hfx_bc_op3(g, D3D9_MAD, n, below0(g, x), k, r);
}
static bc_val i_acos(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return acos_of(g, a[0]); }
static bc_val i_asin(bc_gen *g, const ir_expr *e, bc_val *a) { /* pi/2 - acos(x) */
    (void)e;
    bc_val r = acos_of(g, a[0]);
    return hfx_bc_op2(g, D3D9_ADD, r.n, hfx_bc_neg(r), kf(g, 1.57079637f));
}

/* The odd polynomial of atan on 0..1: a (((((0.0208351 s - 0.085133) s + 0.180141) s - 0.3303) s + 0.999866), s = a^2. */
static bc_val atan01(bc_gen *g, bc_val a) {
    unsigned n = a.n;
    bc_val s = hfx_bc_op2(g, D3D9_MUL, n, keep(a), keep(a));
    bc_val p = hfx_bc_op3(g, D3D9_MAD, n, keep(s), kf(g, 0.0208350997f), kf(g, -0.0851330012f));
    p = hfx_bc_op3(g, D3D9_MAD, n, p, keep(s), kf(g, 0.180141002f));
    p = hfx_bc_op3(g, D3D9_MAD, n, p, keep(s), kf(g, -0.330299497f));
    p = hfx_bc_op3(g, D3D9_MAD, n, p, s, kf(g, 0.999866009f));
    return hfx_bc_op2(g, D3D9_MUL, n, a, p);
}

/* The angle of min(u, v) / max(u, v) for magnitudes u (|x|) and v (|y|): the polynomial, then
 * pi/2 - r where u < v (the larger magnitude was y's). */
static bc_val atan_ratio(bc_gen *g, bc_val u, bc_val v) {
    unsigned n = nmax(u, v);
    bc_val mn = hfx_bc_op2(g, D3D9_MIN, n, keep(u), keep(v));
    bc_val mx = hfx_bc_per_comp(g, D3D9_RCP, hfx_bc_op2(g, D3D9_MAX, n, keep(u), keep(v)), NULL);
    bc_val r = atan01(g, hfx_bc_op2(g, D3D9_MUL, n, mn, mx));
    bc_val k = hfx_bc_op3(g, D3D9_MAD, n, keep(r), kf(g, -2), kf(g, 1.57079637f));
    return hfx_bc_op3(g, D3D9_MAD, n, less(g, u, v), k, r); /* |x| < |y|: pi/2 - r */
}

static bc_val i_atan(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val x = a[0];
    bc_val r = atan_ratio(g, kf(g, 1), hfx_bc_op1(g, D3D9_ABS, x.n, keep(x)));
    r = negate_below0(g, keep(x), r);
    hfx_bc_release(g, x);
    return r;
}

/* atan2(y, x): the ratio's angle, minus pi where x < 0, negated where min(x, y) < 0 <= max(x, y). */
static bc_val i_atan2(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val y = a[0], x = a[1];
    unsigned n = nmax(x, y);
    bc_val r = atan_ratio(g, hfx_bc_op1(g, D3D9_ABS, x.n, keep(x)), hfx_bc_op1(g, D3D9_ABS, y.n, keep(y)));
    r = hfx_bc_op3(g, D3D9_MAD, n, below0(g, keep(x)), kf(g, -3.14159274f), r);
    bc_val lo = hfx_bc_op2(g, D3D9_MIN, n, keep(x), keep(y)), hi = hfx_bc_op2(g, D3D9_MAX, n, x, y);
    if (!vs(g)) { /* lo >= 0 ? r : (hi >= 0 ? -r : r) */
        bc_val in = hfx_bc_op3(g, D3D9_CMP, n, hi, hfx_bc_neg(keep(r)), keep(r));
        return hfx_bc_op3(g, D3D9_CMP, n, lo, r, in);
    }
    bc_val flip = hfx_bc_op2(g, D3D9_MUL, n, below0(g, lo), hfx_bc_op2(g, D3D9_SGE, n, hi, kf(g, 0)));
    return hfx_bc_op2(g, D3D9_MUL, n, r, hfx_bc_op3(g, D3D9_MAD, n, flip, kf(g, -2), kf(g, 1)));
}

/* --- exponentials --- */

static bc_val exp_scaled(bc_gen *g, bc_val x, float k) { /* 2^(k x) per component */
    return hfx_bc_per_comp(g, D3D9_EXP, hfx_bc_op2(g, D3D9_MUL, x.n, x, kf(g, k)), NULL);
}

static bc_val i_sinh(bc_gen *g, const ir_expr *e, bc_val *a) { /* (e^x -+ e^-x) / 2 */
    bc_val p = exp_scaled(g, keep(a[0]), 1.44269502f), m = exp_scaled(g, a[0], -1.44269502f);
    bc_val d = hfx_bc_op2(g, D3D9_ADD, p.n, p, e->intrin == HFX_INTR_SINH ? hfx_bc_neg(m) : m);
    return hfx_bc_op2(g, D3D9_MUL, d.n, d, kf(g, 0.5f));
}

/* tanh = 1 - 2 / (e^2x + 1): (e - 1) / (e + 1) without inf / inf where e^2x overflows. */
static bc_val i_tanh(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val x = exp_scaled(g, a[0], 2.88539004f);
    bc_val q = hfx_bc_per_comp(g, D3D9_RCP, hfx_bc_op2(g, D3D9_ADD, x.n, x, kf(g, 1)), NULL);
    return hfx_bc_op3(g, D3D9_MAD, q.n, q, kf(g, -2), kf(g, 1));
}

static bc_val i_ldexp(bc_gen *g, const ir_expr *e, bc_val *a) { /* x * 2^e */
    (void)e;
    bc_val p = hfx_bc_per_comp(g, D3D9_EXP, a[1], NULL);
    return hfx_bc_op2(g, D3D9_MUL, nmax(a[0], p), a[0], p);
}

/* --- arithmetic and derivatives --- */

static bc_val i_mad(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    unsigned n = nmax(a[0], a[1]) > a[2].n ? nmax(a[0], a[1]) : a[2].n;
    return hfx_bc_op3(g, D3D9_MAD, n, a[0], a[1], a[2]);
}
static bc_val i_trunc(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_trunc(g, a[0]); }
static bc_val i_fwidth(bc_gen *g, const ir_expr *e, bc_val *a) { /* |ddx| + |ddy| */
    (void)e;
    bc_val x = hfx_bc_op1(g, D3D9_ABS, a[0].n, hfx_bc_op1(g, D3D9_DSX, a[0].n, keep(a[0])));
    bc_val y = hfx_bc_op1(g, D3D9_ABS, a[0].n, hfx_bc_op1(g, D3D9_DSY, a[0].n, a[0]));
    return hfx_bc_op2(g, D3D9_ADD, x.n, x, y);
}
/* int4(c.zyxw * 255.001953), truncated as every int conversion on float registers */
static bc_val i_d3dcolor(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val c = a[0], s = c;
    static const uint8_t zyxw[4] = {2, 1, 0, 3};
    for (unsigned i = 0; i < 4; i++) s.sw[i] = c.sw[zyxw[i] < c.n ? zyxw[i] : 0];
    s.n = 4;
    return hfx_bc_trunc(g, hfx_bc_op2(g, D3D9_MUL, 4, s, kf(g, 255.001953f)));
}

/* --- classification and all() --- */

/* |x| <= FLT_MAX: finite (a NaN fails every comparison). */
static bc_val i_isfinite(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val m = hfx_bc_op1(g, D3D9_ABS, a[0].n, a[0]);
    if (vs(g)) return hfx_bc_op2(g, D3D9_SGE, m.n, kf(g, FLT_MAX), m);
    return hfx_bc_op3(g, D3D9_CMP, m.n, hfx_bc_op2(g, D3D9_ADD, m.n, hfx_bc_neg(m), kf(g, FLT_MAX)), kf(g, 1), kf(g, 0));
}
/* |x| > FLT_MAX; pixel shaders: |x| / 2 - FLT_MAX >= 0, which only an infinity passes (a NaN
 * fails every comparison, FLT_MAX itself halves below it). */
static bc_val i_isinf(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val m = hfx_bc_op1(g, D3D9_ABS, a[0].n, a[0]);
    if (vs(g)) return hfx_bc_op2(g, D3D9_SLT, m.n, kf(g, FLT_MAX), m);
    bc_val d = hfx_bc_op3(g, D3D9_MAD, m.n, m, kf(g, 0.5f), kf(g, -FLT_MAX));
    return hfx_bc_op3(g, D3D9_CMP, d.n, d, kf(g, 1), kf(g, 0));
}
/* neither x >= 0 nor x < 0 */
static bc_val i_isnan(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val x = a[0];
    if (!vs(g)) return hfx_bc_op3(g, D3D9_CMP, x.n, keep(x), kf(g, 0), hfx_bc_op3(g, D3D9_CMP, x.n, hfx_bc_neg(x), kf(g, 0), kf(g, 1)));
    bc_val s = hfx_bc_op2(g, D3D9_ADD, x.n, hfx_bc_op2(g, D3D9_SGE, x.n, keep(x), kf(g, 0)), hfx_bc_op2(g, D3D9_SLT, x.n, x, kf(g, 0)));
    return hfx_bc_op2(g, D3D9_ADD, s.n, hfx_bc_neg(s), kf(g, 1));
}
/* all: the smallest magnitude is not zero */
static bc_val i_all(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val m = hfx_bc_op1(g, D3D9_ABS, a[0].n, a[0]), lo = hfx_bc_scalar_of(m, 0);
    for (unsigned i = 1; i < m.n; i++) {
        bc_val next = hfx_bc_op2(g, D3D9_MIN, 1, lo, hfx_bc_scalar_of(m, i));
        lo = next;
    }
    if (m.n > 1) hfx_bc_release(g, m);
    else lo.own = m.own;
    if (vs(g)) return hfx_bc_op2(g, D3D9_SLT, 1, kf(g, 0), lo);
    return hfx_bc_op3(g, D3D9_CMP, 1, hfx_bc_neg(lo), kf(g, 0), kf(g, 1));
}

/* --- geometry --- */

/* refract(i, n, eta): k = 1 - eta^2 (1 - dot(n, i)^2); k < 0 ? 0 : eta i - (eta dot(n, i) + sqrt(k)) n */
static bc_val i_refract(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val i = a[0], nn = a[1], eta = a[2];
    unsigned n = nmax(i, nn);
    bc_val d = hfx_bc_dot(g, keep(nn), keep(i));
    bc_val t = hfx_bc_op3(g, D3D9_MAD, 1, hfx_bc_neg(keep(d)), keep(d), kf(g, 1));
    bc_val e2 = hfx_bc_op2(g, D3D9_MUL, 1, keep(eta), keep(eta));
    bc_val k = hfx_bc_op3(g, D3D9_MAD, 1, hfx_bc_neg(e2), t, kf(g, 1));
    bc_val u = hfx_bc_op3(g, D3D9_MAD, 1, keep(eta), d, sqrt_of(g, keep(k)));
    bc_val r = hfx_bc_op3(g, D3D9_MAD, n, hfx_bc_neg(u), nn, hfx_bc_op2(g, D3D9_MUL, n, eta, i));
    if (!vs(g)) return hfx_bc_op3(g, D3D9_CMP, n, k, r, kf(g, 0));
    return hfx_bc_op2(g, D3D9_MUL, n, r, hfx_bc_op2(g, D3D9_SGE, 1, k, kf(g, 0)));
}

/* faceforward(n, i, ng) = dot(ng, i) < 0 ? n : -n */
static bc_val i_faceforward(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val n = a[0], d = hfx_bc_dot(g, a[2], a[1]);
    if (!vs(g)) return hfx_bc_op3(g, D3D9_CMP, n.n, d, hfx_bc_neg(keep(n)), n);
    bc_val m = hfx_bc_op3(g, D3D9_MAD, 1, below0(g, d), kf(g, 2), kf(g, -1));
    return hfx_bc_op2(g, D3D9_MUL, n.n, n, m);
}

/* lit(l, h, m) = (1, max(l, 0), l < 0 or h < 0 ? 0 : h^m, 1): the lit instruction in vertex
 * shaders (x, y and w of its source), by parts in pixel shaders, which have none. */
static bc_val i_lit(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val d = fresh(g, 4);
    if (vs(g)) {
        bc_val s = fresh(g, 4);
        hfx_bc_store(g, part(s, 0), a[0], false);
        hfx_bc_store(g, part(s, 1), a[1], false);
        hfx_bc_store(g, part(s, 3), a[2], false);
        bc_val src = keep(s);
        hfx_bc_emit(g, D3D9_LIT, &d, 0xf, &src, 1);
        hfx_bc_release(g, s);
        return d;
    }
    static const float ones[2] = {1, 1};
    bc_val xw = hfx_bc_reg(D3D9_REG_TEMP, d.num, 2);
    xw.sw[1] = 3;
    hfx_bc_store(g, xw, hfx_bc_const(g, ones, 2), false);
    hfx_bc_store(g, part(d, 1), hfx_bc_op2(g, D3D9_MAX, 1, keep(a[0]), kf(g, 0)), false);
    bc_val p = hfx_bc_per_comp(g, D3D9_POW, keep(a[1]), &a[2]);
    bc_val lo = hfx_bc_op2(g, D3D9_MIN, 1, a[0], a[1]);
    hfx_bc_store(g, part(d, 2), hfx_bc_op3(g, D3D9_CMP, 1, lo, p, kf(g, 0)), false);
    return d;
}

/* dst(a, b) = (1, a.y b.y, a.z, b.w): the dst instruction in vertex shaders, by parts in pixel shaders. */
static bc_val i_dst(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val d = fresh(g, 4);
    if (vs(g)) {
        bc_val s[2] = {keep(a[0]), keep(a[1])};
        hfx_bc_emit(g, D3D9_DST, &d, 0xf, s, 2);
    } else {
        hfx_bc_store(g, part(d, 0), kf(g, 1), false);
        hfx_bc_store(g, part(d, 1), hfx_bc_op2(g, D3D9_MUL, 1, hfx_bc_scalar_of(a[0], 1), hfx_bc_scalar_of(a[1], 1)), false);
        hfx_bc_store(g, part(d, 2), hfx_bc_scalar_of(a[0], 2), false);
        hfx_bc_store(g, part(d, 3), hfx_bc_scalar_of(a[1], 3), false);
    }
    hfx_bc_release(g, a[0]);
    hfx_bc_release(g, a[1]);
    return d;
}

static const bc_intrin_row math_rows[] = {
    {HFX_INTR_ACOS, i_acos, 0}, {HFX_INTR_ASIN, i_asin, 0}, {HFX_INTR_ATAN, i_atan, 0}, {HFX_INTR_ATAN2, i_atan2, 0},
    {HFX_INTR_SINH, i_sinh, 0}, {HFX_INTR_COSH, i_sinh, 0}, {HFX_INTR_TANH, i_tanh, 0}, {HFX_INTR_LDEXP, i_ldexp, 0},
    {HFX_INTR_MAD, i_mad, 0}, {HFX_INTR_TRUNC, i_trunc, 0}, {HFX_INTR_FWIDTH, i_fwidth, D3D9_SM(2, 1)},
    {HFX_INTR_D3DCOLORTOUBYTE4, i_d3dcolor, 0}, {HFX_INTR_ISFINITE, i_isfinite, 0}, {HFX_INTR_ISINF, i_isinf, 0},
    {HFX_INTR_ISNAN, i_isnan, 0}, {HFX_INTR_ALL, i_all, 0}, {HFX_INTR_REFRACT, i_refract, 0},
    {HFX_INTR_FACEFORWARD, i_faceforward, 0}, {HFX_INTR_LIT, i_lit, 0}, {HFX_INTR_DST, i_dst, 0},
};

const bc_intrin_row *hfx_bc_math_row(int intrin) {
    for (size_t r = 0; r < sizeof math_rows / sizeof *math_rows; r++)
        if (math_rows[r].id == intrin) return &math_rows[r];
    return NULL;
}

/* --- intrinsics on whole values: out arguments, matrices, bit casts --- */

/* modf(x, out ip): ip = trunc(x), x - ip; both keep x's sign. */
static bc_obj modf_of(bc_gen *g, const ir_expr *e) {
    bc_val x = hfx_bc_expr1(g, e->a[0]);
    bc_val ip = hfx_bc_trunc(g, keep(x));
    bc_val f = hfx_bc_op2(g, D3D9_ADD, x.n, x, hfx_bc_neg(keep(ip)));
    hfx_bc_assign_expr(g, e->a[1], one(g, ip), ip.own ? 1 : 0);
    return one(g, f);
}

/* frexp(x, out e): e = floor(log2 |x|) + 1, x * 2^-e; 0 gives 0 and 0 (log reads 1 there, then
 * the exponent is cleared). */
static bc_obj frexp_of(bc_gen *g, const ir_expr *e) {
    bc_val x = hfx_bc_expr1(g, e->a[0]);
    unsigned n = x.n;
    bc_val m = hfx_bc_op1(g, D3D9_ABS, n, keep(x));
    bc_val z = vs(g) ? hfx_bc_op2(g, D3D9_SGE, n, hfx_bc_neg(keep(m)), kf(g, 0))
                     : hfx_bc_op3(g, D3D9_CMP, n, hfx_bc_neg(keep(m)), kf(g, 1), kf(g, 0));
    bc_val l = hfx_bc_per_comp(g, D3D9_LOG, hfx_bc_op2(g, D3D9_ADD, n, m, keep(z)), NULL);
    bc_val fl = hfx_bc_floor(g, l);
    bc_val nz = hfx_bc_op2(g, D3D9_ADD, n, hfx_bc_neg(z), kf(g, 1));
    bc_val ex = hfx_bc_op3(g, D3D9_MAD, n, fl, keep(nz), nz);
    bc_val p = hfx_bc_per_comp(g, D3D9_EXP, hfx_bc_neg(keep(ex)), NULL);
    bc_val r = hfx_bc_op2(g, D3D9_MUL, n, x, p);
    hfx_bc_assign_expr(g, e->a[1], one(g, ex), ex.own ? 1 : 0);
    return one(g, r);
}

/* determinant: rows (or columns: det(M) = det(M^T), so either layout's registers serve). */
static bc_obj determinant_of(bc_gen *g, const ir_expr *e) {
    const hfx_type *t = e->a[0]->type;
    bc_obj m = hfx_bc_expr(g, e->a[0]);
    unsigned n = t->kind == TY_MATRIX ? t->rows : 1;
    if (g->failed || m.count < n) return one(g, kf(g, 0));
    bc_val *r = m.slot, d;
    if (n == 1) d = hfx_bc_op1(g, D3D9_MOV, 1, hfx_bc_scalar_of(r[0], 0));
    else if (n == 2) { /* r0.x r1.y - r0.y r1.x */
        bc_val p = hfx_bc_op2(g, D3D9_MUL, 1, hfx_bc_scalar_of(r[0], 1), hfx_bc_scalar_of(r[1], 0));
        d = hfx_bc_op3(g, D3D9_MAD, 1, hfx_bc_scalar_of(r[0], 0), hfx_bc_scalar_of(r[1], 1), hfx_bc_neg(p));
    } else if (n == 3) d = hfx_bc_op2(g, D3D9_DP3, 1, keep(r[0]), hfx_bc_cross(g, keep(r[1]), keep(r[2])));
    else { /* the 2x2 minors of rows 0-1 and of rows 2-3, paired */
        static const uint8_t s_a[4] = {0, 0, 0, 1}, s_b[4] = {1, 2, 3, 2}, c_a[4] = {2, 1, 1, 0}, c_b[4] = {3, 3, 2, 3};
        static const uint8_t s2_a[2] = {1, 2}, s2_b[2] = {3, 3}, c2_a[2] = {0, 0}, c2_b[2] = {2, 1};
        bc_val minors[4];
        const uint8_t *sw[4][2] = {{s_a, s_b}, {s2_a, s2_b}, {c_a, c_b}, {c2_a, c2_b}};
        for (unsigned k = 0; k < 4; k++) { /* x.a * y.b - y.a * x.b */
            bc_val x = keep(r[k < 2 ? 0 : 2]), y = keep(r[k < 2 ? 1 : 3]);
            bc_val xa = x, yb = y, ya = y, xb = x;
            unsigned w = k & 1 ? 2 : 4;
            for (unsigned i = 0; i < w; i++) {
                xa.sw[i] = x.sw[sw[k][0][i]]; ya.sw[i] = y.sw[sw[k][0][i]];
                yb.sw[i] = y.sw[sw[k][1][i]]; xb.sw[i] = x.sw[sw[k][1][i]];
            }
            xa.n = yb.n = ya.n = xb.n = (uint8_t)w;
            minors[k] = hfx_bc_op3(g, D3D9_MAD, w, xa, yb, hfx_bc_neg(hfx_bc_op2(g, D3D9_MUL, w, ya, xb)));
        }
        static const float signs[4] = {1, -1, 1, 1};
        bc_val c = hfx_bc_op2(g, D3D9_MUL, 4, minors[2], hfx_bc_const(g, signs, 4));
        bc_val s = hfx_bc_op2(g, D3D9_DP4, 1, minors[0], c); /* s0 c5 - s1 c4 + s2 c3 + s3 c2 */
        s = hfx_bc_op3(g, D3D9_MAD, 1, hfx_bc_neg(hfx_bc_scalar_of(minors[1], 0)), hfx_bc_scalar_of(minors[3], 0), s);
        d = hfx_bc_op3(g, D3D9_MAD, 1, hfx_bc_scalar_of(minors[1], 1), hfx_bc_scalar_of(minors[3], 1), s);
        hfx_bc_release(g, minors[1]);
        hfx_bc_release(g, minors[3]);
    }
    hfx_bc_release_obj(g, m);
    return one(g, d);
}

static bool float_base(hfx_base b) { return b == B_FLOAT || b == B_HALF || b == B_DOUBLE || b == B_MIN16FLOAT; }

/* asfloat / asint / asuint: float registers hold values, not bits. A cast to the argument's own
 * type is the value, a cast of a cast back is the original value, a constant's bits are
 * reinterpreted here; anything else cannot be done on D3D9's registers. */
static bc_obj bitcast(bc_gen *g, const ir_expr *e) {
    const ir_expr *x = e->a[0];
    hfx_base to = e->type->base;
    if (x->type->base == to) return hfx_bc_expr(g, x);
    if (x->kind == IE_INTRIN && (x->intrin == HFX_INTR_ASFLOAT || x->intrin == HFX_INTR_ASINT || x->intrin == HFX_INTR_ASUINT) &&
        x->a[0]->type->base == to)
        return hfx_bc_expr(g, x->a[0]);
    unsigned n = hfx_type_components(e->type);
    float v[4];
    double k;
    bool konst = n <= 4 && (x->kind == IE_CONST || (n == 1 && hfx_bc_try_const(g, x, &k)));
    for (unsigned i = 0; konst && i < n; i++) {
        double c = x->kind == IE_CONST ? x->cval[i] : k;
        uint32_t bits;
        if (float_base(x->type->base)) { float f = (float)c; memcpy(&bits, &f, 4); }
        else bits = x->type->base == B_UINT ? hfx_ev_uint(c) : (uint32_t)hfx_ev_int(c);
        if (to == B_INT) v[i] = (float)(int32_t)bits;
        else if (to == B_UINT) v[i] = (float)bits;
        else memcpy(&v[i], &bits, 4);
    }
    if (konst) return one(g, hfx_bc_const(g, v, n));
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of(e->intrin);
    hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "%s of a computed value reinterprets bits, which D3D9's float registers do not hold",
                info ? info->name : "a bit cast");
    return one(g, kf(g, 0));
}

bool hfx_bc_math_obj(bc_gen *g, const ir_expr *e, bc_obj *out) {
    switch (e->intrin) {
    case HFX_INTR_MODF: *out = modf_of(g, e); return true;
    case HFX_INTR_FREXP: *out = frexp_of(g, e); return true;
    case HFX_INTR_DETERMINANT: *out = determinant_of(g, e); return true;
    case HFX_INTR_ASFLOAT: case HFX_INTR_ASINT: case HFX_INTR_ASUINT: *out = bitcast(g, e); return true;
    default: return false;
    }
}
