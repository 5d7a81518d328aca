/* bc_intrin.c: the intrinsics, one table: each row names the function that writes its
 * instructions (the column check/intrinsics.def may take later), and the models that have it.
 * Intrinsics without a row are refused with X5006, never guessed. */
#include "bytecode/bc_int.h"

static bc_obj one(bc_gen *g, bc_val v) {
    bc_obj o = {HFX_NEW(g->c->arena, bc_val), 1, false};
    o.slot[0] = v;
    return o;
}

static bc_val keep(bc_val v) { v.own = false; return v; }
static unsigned width_of(const hfx_type *t) { return t->kind == TY_SCALAR ? 1 : t->cols; }
static unsigned nmax(bc_val a, bc_val b) { return a.n > b.n ? a.n : b.n; }

bc_val hfx_bc_dot(bc_gen *g, bc_val a, bc_val b) {
    unsigned n = nmax(a, b);
    if (n == 1) return hfx_bc_op2(g, D3D9_MUL, 1, a, b);
    if (n == 2 && g->stage == D3D9_PS) return hfx_bc_op3(g, D3D9_DP2ADD, 1, a, b, hfx_bc_constf(g, 0));
    if (n == 2) {
        bc_val p = hfx_bc_op2(g, D3D9_MUL, 1, hfx_bc_scalar_of(a, 0), hfx_bc_scalar_of(b, 0));
        bc_val r = hfx_bc_op3(g, D3D9_MAD, 1, hfx_bc_scalar_of(a, 1), hfx_bc_scalar_of(b, 1), p);
        hfx_bc_release(g, a);
        hfx_bc_release(g, b);
        return r;
    }
    return hfx_bc_op2(g, n == 3 ? D3D9_DP3 : D3D9_DP4, 1, a, b);
}

bc_val hfx_bc_floor(bc_gen *g, bc_val x) {
    bc_val f = hfx_bc_op1(g, D3D9_FRC, x.n, keep(x));
    return hfx_bc_op2(g, D3D9_ADD, x.n, x, hfx_bc_neg(f));
}

static bc_val i_abs(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_op1(g, D3D9_ABS, a[0].n, a[0]); }
static bc_val i_max(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_op2(g, D3D9_MAX, nmax(a[0], a[1]), a[0], a[1]); }
static bc_val i_min(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_op2(g, D3D9_MIN, nmax(a[0], a[1]), a[0], a[1]); }
static bc_val i_clamp(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val m = hfx_bc_op2(g, D3D9_MAX, nmax(a[0], a[1]), a[0], a[1]);
    return hfx_bc_op2(g, D3D9_MIN, m.n, m, a[2]);
}
static bc_val i_frac(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_op1(g, D3D9_FRC, a[0].n, a[0]); }
static bc_val i_floor(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_floor(g, a[0]); }
static bc_val i_ceil(bc_gen *g, const ir_expr *e, bc_val *a) { /* x + frc(-x) */
    (void)e;
    bc_val f = hfx_bc_op1(g, D3D9_FRC, a[0].n, hfx_bc_neg(keep(a[0])));
    return hfx_bc_op2(g, D3D9_ADD, a[0].n, a[0], f);
}
static bc_val i_round(bc_gen *g, const ir_expr *e, bc_val *a) { /* floor(x + 0.5) */
    (void)e;
    return hfx_bc_floor(g, hfx_bc_op2(g, D3D9_ADD, a[0].n, a[0], hfx_bc_constf(g, 0.5f)));
}
static bc_val i_dot(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_dot(g, a[0], a[1]); }
static bc_val i_lerp(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    unsigned n = nmax(a[0], a[1]) > a[2].n ? nmax(a[0], a[1]) : a[2].n;
    return hfx_bc_op3(g, D3D9_LRP, n, a[2], a[1], a[0]);
}
static bc_val i_rsqrt(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_per_comp(g, D3D9_RSQ, a[0], NULL); }
static bc_val i_sqrt(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_per_comp(g, D3D9_RCP, hfx_bc_per_comp(g, D3D9_RSQ, a[0], NULL), NULL); }
static bc_val i_exp2(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_per_comp(g, D3D9_EXP, a[0], NULL); }
static bc_val i_log2(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_per_comp(g, D3D9_LOG, a[0], NULL); }
static bc_val i_exp(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    return hfx_bc_per_comp(g, D3D9_EXP, hfx_bc_op2(g, D3D9_MUL, a[0].n, a[0], hfx_bc_constf(g, 1.44269502f)), NULL);
}
static bc_val i_log(bc_gen *g, const ir_expr *e, bc_val *a) {
    float k = e->intrin == HFX_INTR_LOG10 ? 0.30103001f : 0.693147182f;
    bc_val l = hfx_bc_per_comp(g, D3D9_LOG, a[0], NULL);
    return hfx_bc_op2(g, D3D9_MUL, l.n, l, hfx_bc_constf(g, k));
}
/* Distinct components of x (with y's beside them when y): the instructions hfx_bc_per_comp writes. */
static unsigned distinct_lanes(const bc_val *x, const bc_val *y) {
    unsigned count = 0;
    for (unsigned i = 0; i < x->n; i++) {
        bool seen = false;
        for (unsigned j = 0; j < i; j++) seen |= x->sw[j] == x->sw[i] && (!y || y->sw[j] == y->sw[i]);
        count += !seen;
    }
    return count;
}

/* pow is a macro of three slots (log, mul, exp: |x|^y, as log reads |x| too), one component each;
 * over a vector, fxc writes a log per component, one mul and an exp per component when that is
 * shorter (three lights' specular: 7 slots, not 9). Each lane's operations are pow's own. */
static bc_val i_pow(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val b = a[1];
    if (b.n < a[0].n) { for (unsigned i = b.n; i < 4; i++) b.sw[i] = b.sw[0]; b.n = a[0].n; }
    unsigned pows = distinct_lanes(&a[0], &b), logs = distinct_lanes(&a[0], NULL);
    if (logs + 1 + a[0].n >= 3 * pows) return hfx_bc_per_comp(g, D3D9_POW, a[0], &b);
    bc_val l = hfx_bc_per_comp(g, D3D9_LOG, a[0], NULL);
    return hfx_bc_per_comp(g, D3D9_EXP, hfx_bc_op2(g, D3D9_MUL, l.n, l, b), NULL);
}
static bc_val i_saturate(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    bc_val v = a[0];
    if (!hfx_bc_can_sat(g)) { /* vs_2_x has no _sat: max then min, as fxc writes it */
        bc_val m = hfx_bc_op2(g, D3D9_MAX, v.n, v, hfx_bc_constf(g, 0));
        return hfx_bc_op2(g, D3D9_MIN, m.n, m, hfx_bc_constf(g, 1));
    }
    if (v.own && g->last_fresh == (int)g->inst_count - 1 && g->last_fresh >= 0 &&
        g->insts[g->last_fresh].dst.num == v.num && g->insts[g->last_fresh].dst.type == D3D9_REG_TEMP) {
        g->insts[g->last_fresh].dst.mods |= D3D9_DMOD_SAT;
        return v;
    }
    bc_val r = hfx_bc_op1(g, D3D9_MOV, v.n, v);
    if (g->inst_count) g->insts[g->inst_count - 1].dst.mods |= D3D9_DMOD_SAT;
    return r;
}
static bc_val i_normalize(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    if (a[0].n == 3) return hfx_bc_op1(g, D3D9_NRM, 3, a[0]);
    bc_val d = hfx_bc_dot(g, keep(a[0]), keep(a[0]));
    bc_val r = hfx_bc_per_comp(g, D3D9_RSQ, d, NULL);
    return hfx_bc_op2(g, D3D9_MUL, a[0].n, a[0], r);
}
static bc_val i_length(bc_gen *g, const ir_expr *e, bc_val *a) {
    (void)e;
    if (a[0].n == 1) return hfx_bc_op1(g, D3D9_ABS, 1, a[0]);
    bc_val d = hfx_bc_dot(g, keep(a[0]), keep(a[0]));
    hfx_bc_release(g, a[0]);
    return hfx_bc_per_comp(g, D3D9_RCP, hfx_bc_per_comp(g, D3D9_RSQ, d, NULL), NULL);
}
static bc_val i_distance(bc_gen *g, const ir_expr *e, bc_val *a) {
    bc_val d = hfx_bc_op2(g, D3D9_ADD, nmax(a[0], a[1]), a[1], hfx_bc_neg(a[0]));
    return i_length(g, e, &d);
}
static bc_val i_reflect(bc_gen *g, const ir_expr *e, bc_val *a) { /* i - 2 dot(n, i) n */
    (void)e;
    bc_val d = hfx_bc_dot(g, keep(a[1]), keep(a[0]));
    bc_val d2 = hfx_bc_op2(g, D3D9_ADD, 1, keep(d), keep(d));
    hfx_bc_release(g, d);
    return hfx_bc_op3(g, D3D9_MAD, a[0].n, a[1], hfx_bc_neg(d2), a[0]);
}
static bc_val i_cross(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_cross(g, a[0], a[1]); }
bc_val hfx_bc_cross(bc_gen *g, bc_val x, bc_val y) { /* a.yzx * b.zxy - a.zxy * b.yzx */
    bc_val x1 = keep(x), y1 = keep(y), x2 = keep(x), y2 = keep(y);
    static const uint8_t yzx[3] = {1, 2, 0}, zxy[3] = {2, 0, 1};
    for (int i = 0; i < 3; i++) {
        x1.sw[i] = x.sw[zxy[i]]; y1.sw[i] = y.sw[yzx[i]];
        x2.sw[i] = x.sw[yzx[i]]; y2.sw[i] = y.sw[zxy[i]];
    }
    x1.n = y1.n = x2.n = y2.n = 3;
    bc_val p = hfx_bc_op2(g, D3D9_MUL, 3, x1, y1);
    bc_val r = hfx_bc_op3(g, D3D9_MAD, 3, x2, y2, hfx_bc_neg(p));
    hfx_bc_release(g, x);
    hfx_bc_release(g, y);
    return r;
}
static bc_val i_step(bc_gen *g, const ir_expr *e, bc_val *a) { /* x >= a */
    (void)e;
    unsigned n = nmax(a[0], a[1]);
    if (g->stage == D3D9_VS) return hfx_bc_op2(g, D3D9_SGE, n, a[1], a[0]);
    bc_val d = hfx_bc_op2(g, D3D9_ADD, n, a[1], hfx_bc_neg(a[0]));
    return hfx_bc_op3(g, D3D9_CMP, n, d, hfx_bc_constf(g, 1), hfx_bc_constf(g, 0));
}
static bc_val i_saturate(bc_gen *g, const ir_expr *e, bc_val *a);
static bc_val i_smoothstep(bc_gen *g, const ir_expr *e, bc_val *a) { /* t = saturate((x - a) / (b - a)); t * t * (3 - 2 t) */
    (void)e;
    unsigned n = nmax(a[0], a[1]) > a[2].n ? nmax(a[0], a[1]) : a[2].n;
    bc_val w = hfx_bc_op2(g, D3D9_ADD, n, a[1], hfx_bc_neg(keep(a[0])));
    bc_val rw = hfx_bc_per_comp(g, D3D9_RCP, w, NULL);
    bc_val d = hfx_bc_op2(g, D3D9_ADD, n, a[2], hfx_bc_neg(a[0]));
    bc_val t = hfx_bc_op2(g, D3D9_MUL, n, d, rw);
    t = i_saturate(g, e, &t); /* _sat on the product, or a mov_sat when it folded to a literal or a copy */
    bc_val k = hfx_bc_op3(g, D3D9_MAD, n, keep(t), hfx_bc_constf(g, -2), hfx_bc_constf(g, 3));
    bc_val t2 = hfx_bc_op2(g, D3D9_MUL, n, keep(t), t);
    return hfx_bc_op2(g, D3D9_MUL, n, t2, k);
}
/* sin / cos: reduced to [-pi, pi] (mad, frc, mad), then sincos; SM2 takes fxc's two constants. */
static bc_val sincos_val(bc_gen *g, bc_val x, int which) {
    int r = hfx_bc_temp(g);
    bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), x.n);
    for (unsigned i = 0; i < x.n && !g->failed; i++) {
        bc_val t = hfx_bc_op3(g, D3D9_MAD, 1, hfx_bc_scalar_of(x, i), hfx_bc_constf(g, 0.159154937f), hfx_bc_constf(g, 0.5f));
        bc_val f = hfx_bc_op1(g, D3D9_FRC, 1, t);
        bc_val y = hfx_bc_op3(g, D3D9_MAD, 1, f, hfx_bc_constf(g, 6.28318548f), hfx_bc_constf(g, -3.14159274f));
        int s = hfx_bc_temp(g);
        bc_val sc = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(s < 0 ? 0 : s), 2);
        bc_val src[3] = {y};
        unsigned n = 1;
        if (g->model < D3D9_SM(3, 0)) {
            static const float c1[4] = {-1.55009923e-006f, -2.17013894e-005f, 0.00260416674f, 0.00026041668f};
            static const float c2[4] = {-0.020833334f, -0.125f, 1.0f, 0.5f};
            src[1] = hfx_bc_const(g, c1, 4);
            src[2] = hfx_bc_const(g, c2, 4);
            n = 3;
        }
        hfx_bc_emit(g, D3D9_SINCOS, &sc, which < 0 ? 3 : which == 0 ? 1 : 2, src, n);
        hfx_bc_release(g, y);
        bc_val out = hfx_bc_reg(D3D9_REG_TEMP, d.num, 1);
        out.sw[0] = (uint8_t)i;
        bc_val res = sc;
        res.n = 1;
        res.sw[0] = (uint8_t)(which == 0 ? 0 : 1);
        hfx_bc_store(g, out, res, false);
        sc.own = s >= 0;
        hfx_bc_release(g, sc);
    }
    hfx_bc_release(g, x);
    d.own = r >= 0;
    return d;
}
static bc_val i_fmod(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return hfx_bc_fmod(g, a[0], a[1]); }
static bc_val i_sin(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return sincos_val(g, a[0], 1); }
static bc_val i_cos(bc_gen *g, const ir_expr *e, bc_val *a) { (void)e; return sincos_val(g, a[0], 0); }
static bc_val i_tan(bc_gen *g, const ir_expr *e, bc_val *a) { /* sin / cos */
    (void)e;
    bc_val s = sincos_val(g, keep(a[0]), 1), c = sincos_val(g, a[0], 0);
    return hfx_bc_op2(g, D3D9_MUL, s.n, s, hfx_bc_per_comp(g, D3D9_RCP, c, NULL));
}
static bc_val i_radians(bc_gen *g, const ir_expr *e, bc_val *a) {
    float k = e->intrin == HFX_INTR_RADIANS ? 0.0174532924f : 57.2957802f;
    return hfx_bc_op2(g, D3D9_MUL, a[0].n, a[0], hfx_bc_constf(g, k));
}
static bc_val i_ddx(bc_gen *g, const ir_expr *e, bc_val *a) {
    return hfx_bc_op1(g, e->intrin == HFX_INTR_DDX ? D3D9_DSX : D3D9_DSY, a[0].n, a[0]);
}
static bc_val i_any(bc_gen *g, const ir_expr *e, bc_val *a) { /* any: a sum of squares not zero */
    (void)e;
    bc_val d = hfx_bc_dot(g, keep(a[0]), keep(a[0]));
    hfx_bc_release(g, a[0]);
    bc_val n = hfx_bc_op2(g, D3D9_ADD, 1, hfx_bc_constf(g, 0), d); /* keeps d's register read once */
    if (g->stage == D3D9_VS) return hfx_bc_op2(g, D3D9_SLT, 1, hfx_bc_constf(g, 0), n);
    return hfx_bc_op3(g, D3D9_CMP, 1, hfx_bc_neg(n), hfx_bc_constf(g, 0), hfx_bc_constf(g, 1));
}
static bc_val i_sign(bc_gen *g, const ir_expr *e, bc_val *a) { /* (x > 0) - (x < 0) */
    (void)e;
    unsigned n = a[0].n;
    bc_val pos, neg;
    if (g->stage == D3D9_VS) {
        pos = hfx_bc_op2(g, D3D9_SLT, n, hfx_bc_constf(g, 0), keep(a[0]));
        neg = hfx_bc_op2(g, D3D9_SLT, n, keep(a[0]), hfx_bc_constf(g, 0));
    } else {
        pos = hfx_bc_op3(g, D3D9_CMP, n, hfx_bc_neg(keep(a[0])), hfx_bc_constf(g, 0), hfx_bc_constf(g, 1));
        neg = hfx_bc_op3(g, D3D9_CMP, n, keep(a[0]), hfx_bc_constf(g, 0), hfx_bc_constf(g, 1));
    }
    hfx_bc_release(g, a[0]);
    return hfx_bc_op2(g, D3D9_ADD, n, pos, hfx_bc_neg(neg));
}

/* A 1D coordinate t as (t, 0.5): D3D9 has no 1D textures (a sampler is declared 2D and texld
 * reads .xy), so tex1D samples the middle row of the 2D texture that stands for it, as the GLSL
 * back end's `vec2(t, 0.5)` does; left unwritten, .y was whatever the register held (MojoShader's
 * GLSL then read an uninitialised component, which llvmpipe crashed on). */
static bc_val one_d(bc_gen *g, bc_val t) {
    bc_val parts[2] = {t, hfx_bc_constf(g, 0.5f)};
    bc_val uv = hfx_bc_gather(g, parts, 2);
    hfx_bc_release(g, t);
    return uv;
}

/* Sampling: texld (texldp / texldb by the control bits), texldl, texldd. ps_2_0 reads the
 * coordinate from a register with no swizzle. */
static bc_obj tex(bc_gen *g, const ir_expr *e) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of(e->intrin);
    bc_binding *b = e->n && e->a[0]->kind == IE_VAR ? hfx_bc_bind(g, e->a[0]->var) : NULL;
    if (!b || !b->obj.count) {
        hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer samples named samplers only");
        return one(g, hfx_bc_constf(g, 0));
    }
    int form = e->n == 4 ? TEXF_GRAD : (int)info->tex_form;
    if (g->stage == D3D9_VS && form != TEXF_LOD) {
        hfx_bc_fail(g, e->loc, 3004, "vertex shaders sample with tex*Dlod only");
        return one(g, hfx_bc_constf(g, 0));
    }
    if ((form == TEXF_LOD && g->model < D3D9_SM(3, 0)) || (form == TEXF_GRAD && g->model < D3D9_SM(2, 1))) {
        hfx_bc_fail(g, e->loc, 4121, "%s needs a higher shader model than %s", info->name, g->profile);
        return one(g, hfx_bc_constf(g, 0));
    }
    bc_val uv = hfx_bc_expr1(g, e->a[1]);
    if (uv.n == 1) uv = one_d(g, uv);
    bool plain = uv.type == D3D9_REG_TEMP || uv.type == D3D9_REG_ADDR || uv.type == D3D9_REG_INPUT;
    for (unsigned i = 0; i < uv.n; i++) plain &= uv.sw[i] == i;
    if (!plain || uv.mod || (g->model < D3D9_SM(3, 0) && uv.type == D3D9_REG_INPUT && g->stage == D3D9_PS)) {
        bc_val m = hfx_bc_op1(g, D3D9_MOV, uv.n, uv);
        uv = m;
    }
    bc_val c = uv;
    c.n = 4;
    for (unsigned i = 0; i < 4; i++) c.sw[i] = (uint8_t)i;
    bc_val src[4] = {c, b->obj.slot[0]};
    unsigned n = 2;
    uint16_t op = form == TEXF_LOD ? D3D9_TEXLDL : form == TEXF_GRAD ? D3D9_TEXLDD : D3D9_TEX;
    if (form == TEXF_GRAD) {
        src[2] = hfx_bc_expr1(g, e->a[2]);
        src[3] = hfx_bc_expr1(g, e->a[3]);
        n = 4;
    }
    src[1].own = false;
    bc_val r = hfx_bc_op(g, op, 4, src, n);
    if (r.own) g->insts[g->inst_count - 1].control = form == TEXF_PROJ ? 1 : form == TEXF_BIAS ? 2 : 0;
    hfx_bc_release(g, uv);
    return one(g, r);
}

/* A scalar the last instruction just computed into a fresh temporary, computed into all four
 * components there instead (each source's component replicated): texkill reads it without a
 * mov, as fxc's `cmp r1, r1.w, c0.w, c0.z` / `texkill r1`. */
static bool widen_last(bc_gen *g, bc_val *x) {
    if (x->n != 1 || x->type != D3D9_REG_TEMP || x->mod || x->rel || !x->own || g->last_fresh < 0 ||
        (uint32_t)g->last_fresh + 1 != g->inst_count)
        return false;
    d3d9_inst *in = &g->insts[g->last_fresh];
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    unsigned c = x->sw[0];
    if (!info || !in->has_dst || in->predicated || in->dst.type != D3D9_REG_TEMP || in->dst.num != x->num ||
        in->dst.mask != 1u << c || (info->flags & (D3D9_OPF_FLOW | D3D9_OPF_MATRIX | D3D9_OPF_TEX)))
        return false;
    switch (in->op) {
    case D3D9_ADD: case D3D9_MUL: case D3D9_MAD: case D3D9_CMP: case D3D9_MIN: case D3D9_MAX: case D3D9_MOV:
    case D3D9_FRC: case D3D9_LRP: case D3D9_ABS:
        for (unsigned k = 0; k < in->src_count; k++) in->src[k].swizzle = (uint8_t)((in->src[k].swizzle >> (2 * c) & 3) * 0x55u);
        break;
    case D3D9_DP3: case D3D9_DP4: case D3D9_RCP: case D3D9_RSQ: case D3D9_EXP: case D3D9_LOG: break;
    default: return false;
    }
    in->dst.mask = 0xf;
    *x = hfx_bc_reg(D3D9_REG_TEMP, x->num, 4);
    x->own = true;
    return true;
}

/* texkill on x (up to three components, the last replicated into the rest). */
static void kill(bc_gen *g, bc_val x) {
    if (widen_last(g, &x)) {
        hfx_bc_emit(g, D3D9_TEXKILL, &x, 0xf, NULL, 0);
        hfx_bc_release(g, x);
        return;
    }
    bc_val k = x;
    bool plain = x.type == D3D9_REG_TEMP && !x.rel && !x.mod && x.n == 3; /* texkill only reads it */
    for (unsigned i = 0; i < x.n && plain; i++) plain &= x.sw[i] == i;
    if (!plain) {
        bc_val s = x;
        s.n = 4;
        for (unsigned i = x.n; i < 4; i++) s.sw[i] = x.sw[x.n - 1];
        k = hfx_bc_op1(g, D3D9_MOV, 4, s);
    }
    hfx_bc_emit(g, D3D9_TEXKILL, &k, 0xf, NULL, 0);
    hfx_bc_release(g, k);
}

/* clip: texkill tests three components; a float4 takes two (xyz, then w), as fxc writes it. */
static bc_obj clip(bc_gen *g, const ir_expr *e) {
    if (g->stage != D3D9_PS) { hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "clip in a vertex shader"); return one(g, hfx_bc_constf(g, 0)); }
    bc_val x = hfx_bc_expr1(g, e->a[0]);
    if (g->cond.n) x = hfx_bc_select(g, keep(g->cond), x, hfx_bc_constf(g, 0));
    if (x.n > 3) {
        bc_val xyz = keep(x), w = hfx_bc_scalar_of(x, 3);
        xyz.n = 3;
        kill(g, xyz);
        kill(g, w);
        hfx_bc_release(g, x);
    } else kill(g, x);
    return one(g, hfx_bc_reg(BC_REG_NONE, 0, 1)); /* void */
}

/* --- mul --- */

static bc_val vec_times_mat(bc_gen *g, bc_val v, bc_obj m, const hfx_type *mt) {
    unsigned rows = mt->rows, cols = mt->cols;
    int r = hfx_bc_temp(g);
    bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), cols);
    if (m.cols && rows >= 3) { /* d.j = dot(v, column j) */
        for (unsigned j = 0; j < cols; j++) {
            bc_val s[2] = {keep(v), m.slot[j]};
            s[0].n = s[1].n = (uint8_t)rows;
            hfx_bc_emit(g, rows == 3 ? D3D9_DP3 : D3D9_DP4, &d, 1u << j, s, 2);
        }
    } else { /* d = v.x row0 + v.y row1 ... */
        bc_val acc = hfx_bc_reg(D3D9_REG_TEMP, d.num, cols);
        for (unsigned i = 0; i < rows; i++) {
            bc_val row = hfx_bc_matrix_row(g, m, mt, i);
            bc_val s[3] = {hfx_bc_scalar_of(v, i), keep(row), acc};
            hfx_bc_emit(g, i ? D3D9_MAD : D3D9_MUL, &d, (1u << cols) - 1, s, i ? 3 : 2);
            hfx_bc_release(g, row);
        }
    }
    hfx_bc_release(g, v);
    d.own = r >= 0;
    return d;
}

static bc_val mat_times_vec(bc_gen *g, bc_obj m, const hfx_type *mt, bc_val v) {
    unsigned rows = mt->rows, cols = mt->cols;
    int r = hfx_bc_temp(g);
    bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), rows);
    if (!m.cols && cols >= 3) {
        for (unsigned i = 0; i < rows; i++) {
            bc_val s[2] = {m.slot[i], keep(v)};
            s[0].n = s[1].n = (uint8_t)cols;
            hfx_bc_emit(g, cols == 3 ? D3D9_DP3 : D3D9_DP4, &d, 1u << i, s, 2);
        }
    } else {
        bc_val acc = hfx_bc_reg(D3D9_REG_TEMP, d.num, rows);
        for (unsigned j = 0; j < cols; j++) {
            bc_val col = m.cols ? m.slot[j] : hfx_bc_matrix_row(g, (bc_obj){m.slot, m.count, true}, mt, j);
            if (!m.cols) { /* a column of a row-layout matrix: gather */
                hfx_bc_release(g, col);
                bc_val parts[4];
                for (unsigned i = 0; i < rows; i++) parts[i] = hfx_bc_matrix_elem(m, i, j);
                int t = hfx_bc_temp(g);
                col = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(t < 0 ? 0 : t), rows);
                for (unsigned i = 0; i < rows; i++) { bc_val o = hfx_bc_reg(D3D9_REG_TEMP, col.num, 1); o.sw[0] = (uint8_t)i; hfx_bc_store(g, o, parts[i], false); }
                col.own = t >= 0;
            }
            bc_val s[3] = {keep(col), hfx_bc_scalar_of(v, j), acc};
            hfx_bc_emit(g, j ? D3D9_MAD : D3D9_MUL, &d, (1u << rows) - 1, s, j ? 3 : 2);
            hfx_bc_release(g, col);
        }
    }
    hfx_bc_release(g, v);
    d.own = r >= 0;
    return d;
}

static bc_obj mul(bc_gen *g, const ir_expr *e) {
    const hfx_type *ta = e->a[0]->type, *tb = e->a[1]->type;
    bool ma = ta->kind == TY_MATRIX, mb = tb->kind == TY_MATRIX;
    if (!ma && !mb) {
        bc_val a = hfx_bc_expr1(g, e->a[0]), b = hfx_bc_expr1(g, e->a[1]);
        if (ta->kind == TY_VECTOR && tb->kind == TY_VECTOR) return one(g, hfx_bc_dot(g, a, b));
        return one(g, hfx_bc_op2(g, D3D9_MUL, nmax(a, b), a, b));
    }
    bc_obj a = hfx_bc_expr(g, e->a[0]), b = hfx_bc_expr(g, e->a[1]);
    if (!ma && ta->kind == TY_VECTOR) return one(g, vec_times_mat(g, a.slot[0], b, tb));
    if (!mb && tb->kind == TY_VECTOR) return one(g, mat_times_vec(g, a, ta, b.slot[0]));
    if (!ma || !mb) { /* scalar * matrix */
        bc_obj m = ma ? a : b;
        bc_val s = ma ? b.slot[0] : a.slot[0];
        bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, m.count), m.count, m.cols};
        for (uint32_t k = 0; k < m.count; k++) o.slot[k] = hfx_bc_op2(g, D3D9_MUL, m.slot[k].n, m.slot[k], keep(s));
        return o;
    }
    /* matrix * matrix: rows of the result from A's rows, or columns from A's columns */
    const hfx_type *rt = e->type;
    bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, a.cols ? rt->cols : rt->rows), a.cols ? rt->cols : rt->rows, a.cols};
    if (!a.cols) {
        for (unsigned i = 0; i < rt->rows; i++) o.slot[i] = vec_times_mat(g, keep(a.slot[i]), b, tb);
    } else {
        for (unsigned j = 0; j < rt->cols; j++) {
            bc_val parts[4];
            for (unsigned k = 0; k < tb->rows; k++) parts[k] = hfx_bc_matrix_elem(b, k, j);
            int t = hfx_bc_temp(g);
            bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(t < 0 ? 0 : t), rt->rows);
            for (unsigned k = 0; k < ta->cols; k++) {
                bc_val s[3] = {a.slot[k], parts[k], d};
                s[0].own = false;
                hfx_bc_emit(g, k ? D3D9_MAD : D3D9_MUL, &d, (1u << rt->rows) - 1, s, k ? 3 : 2);
            }
            d.own = t >= 0;
            o.slot[j] = d;
        }
    }
    hfx_bc_release_obj(g, a);
    hfx_bc_release_obj(g, b);
    return o;
}

static bc_obj transpose(bc_gen *g, const ir_expr *e) {
    bc_obj m = hfx_bc_expr(g, e->a[0]);
    m.cols = !m.cols; /* the same registers, read the other way */
    return m;
}

/* Intrinsics with out arguments. */
static bc_obj sincos_intrin(bc_gen *g, const ir_expr *e) { /* by slots: a matrix componentwise */
    bc_obj x = hfx_bc_expr(g, e->a[0]);
    bc_obj so = {HFX_NEW_ARRAY(g->c->arena, bc_val, x.count ? x.count : 1), x.count, x.cols}, co = so;
    co.slot = HFX_NEW_ARRAY(g->c->arena, bc_val, x.count ? x.count : 1);
    uint64_t owned = 0;
    for (uint32_t k = 0; k < x.count && !g->failed; k++) {
        so.slot[k] = sincos_val(g, keep(x.slot[k]), 1);
        co.slot[k] = sincos_val(g, x.slot[k], 0);
        if (so.slot[k].own && k < 64) owned |= 1ull << k;
    }
    hfx_bc_assign_expr(g, e->a[1], so, owned); /* the out arguments written as assignments are */
    hfx_bc_assign_expr(g, e->a[2], co, owned);
    return one(g, hfx_bc_reg(BC_REG_NONE, 0, 1)); /* void */
}

/* lerp(a, b, t) = a + t (b - a): two mads when b is a product (fxc's form; lrp takes two slots). */
static bc_obj lerp(bc_gen *g, const ir_expr *e) {
    const ir_expr *b = e->a[1];
    bc_val a = hfx_bc_expr1(g, e->a[0]), d;
    unsigned n = width_of(e->type);
    if (b->kind == IE_BINARY && b->op == OP_MUL && b->type->kind != TY_MATRIX) {
        bc_val x = hfx_bc_expr1(g, b->a[0]), y = hfx_bc_expr1(g, b->a[1]);
        d = hfx_bc_op3(g, D3D9_MAD, n, x, y, hfx_bc_neg(keep(a)));
    } else d = hfx_bc_op2(g, D3D9_ADD, n, hfx_bc_expr1(g, b), hfx_bc_neg(keep(a)));
    bc_val t = hfx_bc_expr1(g, e->a[2]);
    return one(g, hfx_bc_op3(g, D3D9_MAD, n, t, d, a));
}

/* The column: intrinsic -> the function writing it (ps_first: the pixel model it needs). */
static const bc_intrin_row rows[] = {
    {HFX_INTR_ABS, i_abs, 0}, {HFX_INTR_MAX, i_max, 0}, {HFX_INTR_MIN, i_min, 0}, {HFX_INTR_CLAMP, i_clamp, 0},
    {HFX_INTR_FRAC, i_frac, 0}, {HFX_INTR_FLOOR, i_floor, 0}, {HFX_INTR_CEIL, i_ceil, 0}, {HFX_INTR_ROUND, i_round, 0},
    {HFX_INTR_DOT, i_dot, 0}, {HFX_INTR_LERP, i_lerp, 0}, {HFX_INTR_RSQRT, i_rsqrt, 0}, {HFX_INTR_SQRT, i_sqrt, 0},
    {HFX_INTR_EXP2, i_exp2, 0}, {HFX_INTR_LOG2, i_log2, 0}, {HFX_INTR_EXP, i_exp, 0}, {HFX_INTR_LOG, i_log, 0},
    {HFX_INTR_LOG10, i_log, 0}, {HFX_INTR_POW, i_pow, 0}, {HFX_INTR_SATURATE, i_saturate, 0},
    {HFX_INTR_NORMALIZE, i_normalize, 0}, {HFX_INTR_LENGTH, i_length, 0}, {HFX_INTR_DISTANCE, i_distance, 0},
    {HFX_INTR_REFLECT, i_reflect, 0}, {HFX_INTR_CROSS, i_cross, 0}, {HFX_INTR_STEP, i_step, 0},
    {HFX_INTR_SMOOTHSTEP, i_smoothstep, 0}, {HFX_INTR_SIN, i_sin, 0}, {HFX_INTR_COS, i_cos, 0}, {HFX_INTR_TAN, i_tan, 0},
    {HFX_INTR_RADIANS, i_radians, 0}, {HFX_INTR_DEGREES, i_radians, 0}, {HFX_INTR_DDX, i_ddx, D3D9_SM(2, 1)},
    {HFX_INTR_DDY, i_ddx, D3D9_SM(2, 1)}, {HFX_INTR_FMOD, i_fmod, 0}, {HFX_INTR_ANY, i_any, 0}, {HFX_INTR_SIGN, i_sign, 0},
};

bc_obj hfx_bc_intrinsic(bc_gen *g, const ir_expr *e) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of(e->intrin);
    if (info && info->sig == SIG_TEX) return tex(g, e);
    switch (e->intrin) {
    case HFX_INTR_MUL: return mul(g, e);
    case HFX_INTR_LERP: return lerp(g, e);
    case HFX_INTR_CLIP: return clip(g, e);
    case HFX_INTR_TRANSPOSE: return transpose(g, e);
    case HFX_INTR_SINCOS: return sincos_intrin(g, e);
    default: break;
    }
    bc_obj o;
    if (hfx_bc_math_obj(g, e, &o)) return o;
    const bc_intrin_row *row = hfx_bc_math_row((int)e->intrin);
    for (size_t r = 0; r < sizeof rows / sizeof *rows && !row; r++)
        if (rows[r].id == (int)e->intrin) row = &rows[r];
    if (row) {
        if (g->stage == D3D9_PS && row->ps_first > g->model) {
            hfx_bc_fail(g, e->loc, 4121, "%s needs ps_2_a or a higher model than %s", info->name, g->profile);
            return one(g, hfx_bc_constf(g, 0));
        }
        if (g->stage == D3D9_VS && row->ps_first) {
            hfx_bc_fail(g, e->loc, 4121, "%s is for pixel shaders only", info->name);
            return one(g, hfx_bc_constf(g, 0));
        }
        bc_val a[4];
        for (uint32_t i = 0; i < e->n && i < 4; i++) a[i] = hfx_bc_expr1(g, e->a[i]);
        if (g->failed) return one(g, hfx_bc_constf(g, 0));
        return one(g, row->fn(g, e, a));
    }
    hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer does not expand %s yet", info ? info->name : "this intrinsic");
    return one(g, hfx_bc_constf(g, 0));
}
