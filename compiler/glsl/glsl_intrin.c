/* glsl_intrin.c: HLSL intrinsics in GLSL, with HLSL's meaning where the two differ (pow
 * raises |x| as D3D9's pow instruction does):
 * log, sqrt and rsqrt take |x| as D3D9's log and rsq do, log(0) is -FLT_MAX and rsqrt(0) FLT_MAX,
 * frac is x - floor(x) (fract), fmod truncates (x - y * trunc(x / y), not GLSL mod), round is
 * floor(x + 0.5) as fxc's ps_2/3 code computes it, ddy is -dFdy (D3D's screen y goes down),
 * tex2Dlod/bias take the level from .w.
 * This is the GLSL back end's column of check/intrinsics.def: every row names its emitter here
 * (emit_<how>) and, for the emitters that call one, the GLSL function; the IR has already done
 * the back-end-neutral rewrites (ir/lower/intrinsics.c). */
#include <string.h>

#include "glsl/glsl_int.h"

static unsigned ncomp(const hfx_type *t) { return hfx_type_is_numeric(t) ? hfx_type_components(t) : 0; }
static bool is_float(hfx_base b) { return b == B_FLOAT || b == B_HALF || b == B_DOUBLE || b == B_MIN16FLOAT; }

static void args(gp *p, const char *fn, ir_expr *const *a, uint32_t n) {
    hfx_sb_printf(p->out, "%s(", fn);
    for (uint32_t i = 0; i < n; i++) {
        if (i) hfx_sb_put(p->out, ", ");
        hfx_glsl_expr(p, a[i], PREC_ASSIGN);
    }
    hfx_sb_put(p->out, ")");
}

/* f(x, out y): modf, frexp. */
static void args_out2(gp *p, const char *fn, ir_expr *const *a) {
    hfx_sb_printf(p->out, "%s(", fn);
    hfx_glsl_expr(p, a[0], PREC_ASSIGN);
    hfx_sb_put(p->out, ", ");
    hfx_glsl_lvalue(p, a[1], PREC_ASSIGN);
    hfx_sb_put(p->out, ")");
}

static void wrap_open(gp *p, int prec, int max) { if (prec > max) hfx_sb_put(p->out, "("); }
static void wrap_close(gp *p, int prec, int max) { if (prec > max) hfx_sb_put(p->out, ")"); }

static const char *ty(gp *p, const hfx_type *t) { return hfx_glsl_type(p, t); }

/* `x` as a float type (dot, any/all of non-bool values). */
static void as_float(gp *p, const ir_expr *x) {
    if (is_float(x->type->base)) { hfx_glsl_expr(p, x, PREC_ASSIGN); return; }
    unsigned n = ncomp(x->type);
    hfx_sb_printf(p->out, n > 1 ? "vec%u(" : "float(", n);
    hfx_glsl_expr(p, x, PREC_ASSIGN);
    hfx_sb_put(p->out, ")");
}

static void all_any(gp *p, const ir_expr *e, const char *fn) {
    const ir_expr *x = e->a[0];
    unsigned n = ncomp(x->type);
    if (n == 1) {
        if (x->type->base == B_BOOL) hfx_glsl_expr(p, x, PREC_ASSIGN);
        else { hfx_sb_put(p->out, "bool("); hfx_glsl_expr(p, x, PREC_ASSIGN); hfx_sb_put(p->out, ")"); }
        return;
    }
    hfx_sb_printf(p->out, "%s(", fn);
    if (x->type->base == B_BOOL) hfx_glsl_expr(p, x, PREC_ASSIGN);
    else {
        hfx_sb_put(p->out, "notEqual(");
        hfx_glsl_expr(p, x, PREC_ASSIGN);
        hfx_sb_put(p->out, ", ");
        hfx_glsl_zero(p, x->type);
        hfx_sb_put(p->out, ")");
    }
    hfx_sb_put(p->out, ")");
}

static void helper_lit(gp *p) {
    if (hfx_glsl_helper(p, "lit"))
        hfx_sb_put(&p->helpers,
               "vec4 hfx_lit(float n_dot_l, float n_dot_h, float m)\n{\n"
               "    return vec4(1.0, max(n_dot_l, 0.0), (n_dot_l < 0.0 || n_dot_h < 0.0) ? 0.0 : pow(n_dot_h, m), 1.0);\n}\n");
}

static void helper_typed(gp *p, const char *name, const hfx_type *t, const char *fmt) {
    const char *tn = ty(p, t);
    if (!hfx_glsl_helper(p, hfx_arena_printf(p->c->arena, "%s %s", name, tn))) return;
    /* fmt writes $T for the type and $N for its component count */
    const char *s = fmt;
    for (; *s; s++) {
        if (s[0] == '$' && s[1] == 'T') { hfx_sb_put(&p->helpers, tn); s++; continue; }
        if (s[0] == '$' && s[1] == 'N') { hfx_sb_printf(&p->helpers, "%u", ncomp(t)); s++; continue; } /* components */
        char c[2] = { *s, 0 };
        hfx_sb_put(&p->helpers, c);
    }
}

static void helper_clip(gp *p, const hfx_type *t) {
    unsigned n = ncomp(t);
    if (n == 1) helper_typed(p, "clip", t, "void hfx_clip($T x) { if (x < 0.0) discard; }\n");
    else helper_typed(p, "clip", t, "void hfx_clip($T x) { if (any(lessThan(x, $T(0.0)))) discard; }\n");
}

static void print_mul(gp *p, const ir_expr *e, int max) {
    const ir_expr *a = e->a[0], *b = e->a[1];
    const hfx_type *ta = a->type, *tb = b->type;
    unsigned na = ncomp(ta), nb = ncomp(tb);
    bool ma = hfx_glsl_is_matrix(ta), mb = hfx_glsl_is_matrix(tb);
    if (na == 1 || nb == 1 || (!ma && !mb && ncomp(e->type) > 1)) { /* scalar times anything; row x column */
        wrap_open(p, PREC_MUL, max);
        hfx_glsl_expr(p, a, PREC_MUL);
        hfx_sb_put(p->out, " * ");
        hfx_glsl_expr(p, b, PREC_UNARY);
        wrap_close(p, PREC_MUL, max);
        return;
    }
    if (!ma && !mb) { /* vector . vector */
        bool conv = !is_float(e->type->base);
        if (conv) hfx_sb_printf(p->out, "%s(", ty(p, e->type));
        hfx_sb_put(p->out, "dot(");
        as_float(p, a);
        hfx_sb_put(p->out, ", ");
        as_float(p, b);
        hfx_sb_put(p->out, conv ? "))" : ")");
        return;
    }
    /* column i of the GLSL matrix is HLSL row i: every product reverses */
    wrap_open(p, PREC_MUL, max);
    hfx_glsl_expr(p, b, PREC_MUL);
    hfx_sb_put(p->out, " * ");
    hfx_glsl_expr(p, a, PREC_UNARY);
    wrap_close(p, PREC_MUL, max);
}

/* The coordinate part `.xy` of a packed float4 argument (lod, bias, proj forms). */
static void coord_part(gp *p, const ir_expr *t, unsigned n) {
    hfx_glsl_expr(p, t, PREC_POSTFIX);
    hfx_sb_printf(p->out, ".%.*s", (int)n, "xyzw");
}

/* The GLSL sampling function of a dimension and form (GLSL 110: texture2D... and no gradients). */
static const char *tex_function(gp *p, hfx_dim dim, hfx_tex_form form) {
    bool cube = dim == DIM_CUBE;
    if (p->legacy) {
        const char *d = cube ? "Cube" : dim == DIM_3D ? "3D" : "2D";
        const char *f = form == TEXF_LOD ? "Lod" : form == TEXF_PROJ && !cube ? "Proj" : "";
        return hfx_arena_printf(p->c->arena, "texture%s%s", d, f);
    }
    if (form == TEXF_GRAD) return "textureGrad";
    if (form == TEXF_LOD) return "textureLod";
    return form == TEXF_PROJ && !cube && dim != DIM_1D ? "textureProj" : "texture";
}

/* A 1D coordinate as the vec2 (t, 0.5) of the 2D texture of height 1 that stands for it. */
static void coord_1d(gp *p, const ir_expr *t, const char *fill) {
    hfx_sb_put(p->out, "vec2(");
    hfx_glsl_expr(p, t, PREC_ASSIGN);
    hfx_sb_printf(p->out, ", %s)", fill);
}

/* tex*D(s, t) and tex*Dgrad(s, t, ddx, ddy) (no gradients in GLSL 110). */
static void tex_plain_args(gp *p, const ir_expr *e, bool one_d, bool grad) {
    if (one_d) coord_1d(p, e->a[1], "0.5");
    else hfx_glsl_expr(p, e->a[1], PREC_ASSIGN);
    for (int k = 2; grad && !p->legacy && k < 4; k++) {
        hfx_sb_put(p->out, ", ");
        if (one_d) coord_1d(p, e->a[k], "0.0");
        else hfx_glsl_expr(p, e->a[k], PREC_ASSIGN);
    }
}

/* tex*Dbias / tex*Dlod: the level (or bias) in .w. */
static void tex_level_args(gp *p, const ir_expr *t, bool one_d, unsigned dims) {
    if (one_d) { hfx_sb_put(p->out, "vec2("); coord_part(p, t, 1); hfx_sb_put(p->out, ", 0.5)"); }
    else coord_part(p, t, dims);
    hfx_sb_put(p->out, ", ");
    hfx_glsl_expr(p, t, PREC_POSTFIX);
    hfx_sb_put(p->out, ".w");
}

/* tex*Dproj: divided by .w (textureProj where GLSL has the form). */
static void tex_proj_args(gp *p, const ir_expr *t, hfx_dim dim) {
    if (dim == DIM_1D) {
        hfx_sb_put(p->out, "vec2(");
        coord_part(p, t, 1);
        hfx_sb_put(p->out, " / ");
        hfx_glsl_expr(p, t, PREC_POSTFIX);
        hfx_sb_put(p->out, ".w, 0.5)");
    } else if (dim == DIM_CUBE) {
        coord_part(p, t, 3);
        hfx_sb_put(p->out, " / ");
        hfx_glsl_expr(p, t, PREC_POSTFIX);
        hfx_sb_put(p->out, ".w");
    } else {
        hfx_glsl_expr(p, t, PREC_ASSIGN);
    }
}

/* Every tex* intrinsic: its dimension and form come from its row of intrinsics.def. */
static void emit_tex(gp *p, const ir_expr *e, int max) {
    (void)max;
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of((int)e->intrin);
    hfx_dim dim = info->dim;
    hfx_tex_form form = info->tex_form == TEXF_PLAIN && e->n == 4 ? TEXF_GRAD : info->tex_form;
    if (e->n < 2) { hfx_glsl_error(p, e->loc, "texture sampling needs coordinates"); return; }
    if (p->legacy && form == TEXF_LOD && p->stage == IR_PIXEL) { /* 110 has texture2DLod in vertex shaders only */
        hfx_glsl_error(p, e->loc, "tex*Dlod in a pixel shader needs GLSL 330 or ES 300");
        return;
    }
    hfx_sb_printf(p->out, "%s(", tex_function(p, dim, form));
    hfx_glsl_expr(p, e->a[0], PREC_ASSIGN);
    hfx_sb_put(p->out, ", ");
    if (form == TEXF_PLAIN || form == TEXF_GRAD) tex_plain_args(p, e, dim == DIM_1D, form == TEXF_GRAD);
    else if (form == TEXF_BIAS || form == TEXF_LOD) tex_level_args(p, e->a[1], dim == DIM_1D, dim == DIM_2D ? 2 : 3);
    else tex_proj_args(p, e->a[1], dim);
    hfx_sb_put(p->out, ")");
}

/* GLSL 110 lacks the hyperbolic functions, trunc-based helpers, isnan/isinf, modf and
 * transpose/determinant: helpers with the same meaning. Returns true when it printed e. */
static bool legacy_intrinsic(gp *p, const ir_expr *e) {
    const hfx_type *t = e->n ? e->a[0]->type : e->type;
    const char *name = NULL, *text = NULL;
    switch (e->intrin) {
    case HFX_INTR_COSH: name = "hfx_cosh"; text = "$T hfx_cosh($T x) { return (exp(x) + exp(-x)) * 0.5; }\n"; break;
    case HFX_INTR_SINH: name = "hfx_sinh"; text = "$T hfx_sinh($T x) { return (exp(x) - exp(-x)) * 0.5; }\n"; break;
    case HFX_INTR_TANH: name = "hfx_tanh"; text = "$T hfx_tanh($T x) { $T e = exp(2.0 * x); return (e - 1.0) / (e + 1.0); }\n"; break;
    case HFX_INTR_MODF: name = "hfx_modf"; text = "$T hfx_modf($T x, out $T i) { i = sign(x) * floor(abs(x)); return x - i; }\n"; break;
    case HFX_INTR_ISNAN: /* vectors found by fuzz/fuzz_diff.c: 110 has no isnan at all */
        name = "hfx_isnan";
        text = ncomp(t) == 1 ? "bool hfx_isnan($T x) { return !(x == x); }\n"
                             : "bvec$N hfx_isnan($T x) { return not(equal(x, x)); }\n";
        break;
    case HFX_INTR_ISINF: /* x == x, and x * 0 is NaN: the product of the two tests, per component */
        name = "hfx_isinf";
        text = ncomp(t) == 1 ? "bool hfx_isinf($T x) { return x == x && x * 0.0 != 0.0; }\n"
                             : "bvec$N hfx_isinf($T x) { return bvec$N(vec$N(equal(x, x)) * vec$N(notEqual(x * 0.0, $T(0.0)))); }\n";
        break;
    case HFX_INTR_DETERMINANT:
        if (t->rows == 2) { name = "hfx_determinant"; text = "float hfx_determinant($T m) { return m[0][0] * m[1][1] - m[0][1] * m[1][0]; }\n"; }
        else if (t->rows == 3) { name = "hfx_determinant"; text = "float hfx_determinant($T m) { return dot(m[0], cross(m[1], m[2])); }\n"; }
        else if (t->rows == 4) { /* along the first column, each minor as dot(u, cross(v, w)); found by fuzz/fuzz_diff.c */
            name = "hfx_determinant";
            text = "float hfx_determinant($T m) { return m[0].x * dot(m[1].yzw, cross(m[2].yzw, m[3].yzw)) - "
                   "m[0].y * dot(m[1].xzw, cross(m[2].xzw, m[3].xzw)) + m[0].z * dot(m[1].xyw, cross(m[2].xyw, m[3].xyw)) - "
                   "m[0].w * dot(m[1].xyz, cross(m[2].xyz, m[3].xyz)); }\n";
        } else return false;
        break;
    case HFX_INTR_TRANSPOSE:
        if (t->rows == 2) { name = "hfx_transpose"; text = "$T hfx_transpose($T m) { return $T(m[0][0], m[1][0], m[0][1], m[1][1]); }\n"; }
        else if (t->rows == 3) {
            name = "hfx_transpose";
            text = "$T hfx_transpose($T m) { return $T(m[0][0], m[1][0], m[2][0], m[0][1], m[1][1], m[2][1], m[0][2], m[1][2], m[2][2]); }\n";
        } else if (t->rows == 4) {
            name = "hfx_transpose";
            text = "$T hfx_transpose($T m) { return $T(m[0][0], m[1][0], m[2][0], m[3][0], m[0][1], m[1][1], m[2][1], m[3][1], "
                   "m[0][2], m[1][2], m[2][2], m[3][2], m[0][3], m[1][3], m[2][3], m[3][3]); }\n";
        } else return false;
        break;
    default: return false;
    }
    helper_typed(p, name + 4, t, text);
    if (e->intrin == HFX_INTR_MODF) args_out2(p, name, e->a);
    else args(p, name, e->a, e->n);
    return true;
}

/* An emitter: prints the call e as GLSL (max: the loosest precedence the context allows). */
typedef void emit_fn(gp *p, const ir_expr *e, int max);

/* The row's GLSL function: only the emitters that call it on the arguments as they are (call,
 * legacy, numeric, matrix, all_any, trunc, modf) read it; the others write their own text. */
static const char *glsl_name_of(ir_intrin i);

/* The GLSL function of the row, with the same arguments. */
static void emit_call(gp *p, const ir_expr *e, int max) {
    (void)max;
    args(p, glsl_name_of(e->intrin), e->a, e->n);
}

/* The GLSL function, or in GLSL 110 a helper with the same meaning where 110 lacks it. */
static void emit_legacy(gp *p, const ir_expr *e, int max) {
    if (!(p->legacy && legacy_intrinsic(p, e))) emit_call(p, e, max);
}

static void emit_modf(gp *p, const ir_expr *e, int max) {
    (void)max;
    if (!(p->legacy && legacy_intrinsic(p, e))) args_out2(p, glsl_name_of(e->intrin), e->a);
}

/* determinant / transpose: a 1x1 "matrix" is its one value. */
static void emit_matrix(gp *p, const ir_expr *e, int max) {
    if (p->legacy && legacy_intrinsic(p, e)) return;
    if (!hfx_glsl_is_matrix(e->a[0]->type)) hfx_glsl_expr(p, e->a[0], max);
    else emit_call(p, e, max);
}

/* GLSL 110 has abs, sign, min, max and clamp for floats only: integer forms go through
 * float, exact for every value a 110 shader's ints (at least 16 bits) can hold. */
static void emit_numeric(gp *p, const ir_expr *e, int max) {
    const hfx_type *t = e->type;
    bool vector_like = t->kind != TY_MATRIX || t->rows == 1 || t->cols == 1;
    if (!p->legacy || (t->base != B_INT && t->base != B_UINT) || !vector_like) {
        emit_call(p, e, max);
        return;
    }
    unsigned n = ncomp(t);
    const char *ft = n == 1 ? "float" : hfx_arena_printf(p->c->arena, "vec%u", n);
    hfx_sb_printf(p->out, "%s(%s(", ty(p, t), glsl_name_of(e->intrin));
    for (uint32_t i = 0; i < e->n; i++) {
        hfx_sb_printf(p->out, "%s%s(", i ? ", " : "", ft);
        hfx_glsl_expr(p, e->a[i], PREC_ASSIGN);
        hfx_sb_put(p->out, ")");
    }
    hfx_sb_put(p->out, "))");
}

/* GLSL 110 has no trunc: sign(x) * floor(abs(x)). */
static void emit_trunc(gp *p, const ir_expr *e, int max) {
    if (!p->legacy) { emit_call(p, e, max); return; }
    hfx_sb_put(p->out, "(sign(");
    hfx_glsl_expr(p, e->a[0], PREC_ASSIGN);
    hfx_sb_put(p->out, ") * floor(abs(");
    hfx_glsl_expr(p, e->a[0], PREC_ASSIGN);
    hfx_sb_put(p->out, ")))");
}

/* D3D9's pow instruction raises |x| (SM2/SM3 code from fxc computes pow(x, y) so): a
 * negative base gives |x|^y, where GLSL's pow is undefined. */
/* A constant whose every component is >= 0. */
static bool const_nonnegative(const ir_expr *x) {
    if (x->kind != IE_CONST || !hfx_type_is_numeric(x->type)) return false;
    for (unsigned i = 0; i < hfx_type_components(x->type); i++)
        if (!(x->cval[i] >= 0)) return false;
    return true;
}

/* x is >= 0 (or NaN) in every component whatever its operands: abs of it changes nothing.
 * The lit shaders' pow(saturate(dot(r, v)), n) and pow(max(dot(r, v), 0), n) so skip an abs
 * per pixel (0.3 % of directional_specular.fx's pixel-bound frame on llvmpipe). */
static bool nonnegative(const ir_expr *x) {
    if (const_nonnegative(x)) return true;
    if (x->kind == IE_CONVERT && is_float(x->type->base) && is_float(x->a[0]->type->base)) return nonnegative(x->a[0]);
    if (x->kind != IE_INTRIN) return false;
    switch (x->intrin) {
    case HFX_INTR_SATURATE: case HFX_INTR_ABS: case HFX_INTR_LENGTH: case HFX_INTR_DISTANCE: return true;
    case HFX_INTR_MAX: return const_nonnegative(x->a[0]) || const_nonnegative(x->a[1]);
    case HFX_INTR_CLAMP: return const_nonnegative(x->a[1]);
    default: return false;
    }
}

/* D3D9's log instruction: log2(|x|), and -FLT_MAX (not -inf) at 0. */
static void d3d_log2(gp *p, const ir_expr *x) {
    bool whole = nonnegative(x);
    hfx_sb_put(p->out, whole ? "max(log2(" : "max(log2(abs(");
    hfx_glsl_expr(p, x, PREC_ASSIGN);
    hfx_sb_put(p->out, whole ? "), -3.40282347e+38)" : ")), -3.40282347e+38)");
}

/* fxc's products for pow(x, n) (hfx_ir_pow_products' rule), as a helper taking x once:
 * hfx_pow3(x) is x * (x * x). lower/once.c expands the products inside functions; this is for
 * the places without a function to hold a local (static initialisers). */
static void power_by_helper(gp *p, const ir_expr *x, int n) {
    const char *name = hfx_arena_printf(p->c->arena, n < 0 ? "powm%d" : "pow%d", n < 0 ? -n : n);
    if (hfx_glsl_helper(p, hfx_arena_printf(p->c->arena, "%s %s", name, ty(p, x->type)))) {
        const char *tn = ty(p, x->type);
        uint32_t m = (uint32_t)(n < 0 ? -(int64_t)n : n);
        hfx_sb_printf(&p->helpers, "%s hfx_%s(%s x)\n{\n    %s r = %s(1.0);\n    %s s = x;\n", tn, name, tn, tn, tn, tn);
        bool first = true;
        for (int i = 0; i < 32 && m >> i; i++) {
            if (i) hfx_sb_put(&p->helpers, "    s = s * s;\n");
            if (!(m >> i & 1)) continue;
            hfx_sb_put(&p->helpers, first ? "    r = s;\n" : "    r = r * s;\n");
            first = false;
        }
        hfx_sb_put(&p->helpers, n < 0 ? "    return 1.0 / r;\n}\n" : "    return r;\n}\n");
    }
    hfx_sb_printf(p->out, "hfx_%s(", name);
    hfx_glsl_expr(p, x, PREC_ASSIGN);
    hfx_sb_put(p->out, ")");
}

/* pow(x, y) is exp(y * log(x)) with D3D9's log: |x|, and pow(0, 0) = 1, pow(0, y > 0) = 0;
 * fxc's products where it expands a constant exponent. */
static void emit_pow(gp *p, const ir_expr *e, int max) {
    (void)max;
    int n;
    if (is_float(e->type->base) && hfx_type_equal(e->a[0]->type, e->type) &&
        hfx_ir_pow_products(e->a[1], ncomp(e->type), &n)) {
        power_by_helper(p, e->a[0], n);
        return;
    }
    hfx_sb_put(p->out, "exp2(");
    hfx_glsl_expr(p, e->a[1], PREC_MUL);
    hfx_sb_put(p->out, " * ");
    d3d_log2(p, e->a[0]);
    hfx_sb_put(p->out, ")");
}

/* log2, log (x ln 2) and log10 (x log10(2)) as fxc builds them on the log instruction. */
static void emit_log(gp *p, const ir_expr *e, int max) {
    const char *scale = e->intrin == HFX_INTR_LOG ? " * 0.693147181" : e->intrin == HFX_INTR_LOG10 ? " * 0.301029996" : "";
    if (*scale) wrap_open(p, PREC_MUL, max);
    d3d_log2(p, e->a[0]);
    hfx_sb_put(p->out, scale);
    if (*scale) wrap_close(p, PREC_MUL, max);
}

/* D3D9's rsq: 1 / sqrt(|x|), FLT_MAX at 0; sqrt is compiled as rcp(rsq(x)), so it takes |x| too. */
static void emit_rsqrt(gp *p, const ir_expr *e, int max) {
    (void)max;
    hfx_sb_put(p->out, "min(inversesqrt(abs(");
    hfx_glsl_expr(p, e->a[0], PREC_ASSIGN);
    hfx_sb_put(p->out, ")), 3.40282347e+38)");
}

static void emit_sqrt(gp *p, const ir_expr *e, int max) {
    (void)max;
    hfx_sb_put(p->out, "sqrt(abs(");
    hfx_glsl_expr(p, e->a[0], PREC_ASSIGN);
    hfx_sb_put(p->out, "))");
}

static void emit_all_any(gp *p, const ir_expr *e, int max) {
    (void)max;
    all_any(p, e, glsl_name_of(e->intrin));
}

static void emit_saturate(gp *p, const ir_expr *e, int max) {
    (void)max;
    const char *z = is_float(e->type->base) ? "0.0" : "0", *o = is_float(e->type->base) ? "1.0" : "1";
    hfx_sb_put(p->out, "clamp(");
    hfx_glsl_expr(p, e->a[0], PREC_ASSIGN);
    hfx_sb_printf(p->out, ", %s, %s)", z, o);
}

/* D3D's screen y grows downwards, GL's window y upwards (unless flipped). */
static void emit_ddy(gp *p, const ir_expr *e, int max) {
    p->uses_fixup = true;
    wrap_open(p, PREC_MUL, max);
    args(p, "dFdy", e->a, 1);
    hfx_sb_put(p->out, " * (2.0 * hfx_pos_fixup.z - 1.0)");
    wrap_close(p, PREC_MUL, max);
}

/* floor(x + 0.5), as fxc's ps_2/3 code computes round. */
static void emit_round(gp *p, const ir_expr *e, int max) {
    (void)max;
    hfx_sb_put(p->out, "floor(");
    hfx_glsl_expr(p, e->a[0], PREC_ADD);
    hfx_sb_put(p->out, " + 0.5)");
}

/* HLSL's fmod truncates (GLSL's mod floors). */
static void emit_fmod(gp *p, const ir_expr *e, int max) {
    (void)max;
    helper_typed(p, "fmod", e->type, p->legacy ? "$T hfx_fmod($T x, $T y) { $T q = x / y; return x - y * sign(q) * floor(abs(q)); }\n"
                                                 : "$T hfx_fmod($T x, $T y) { return x - y * trunc(x / y); }\n");
    args(p, "hfx_fmod", e->a, 2);
}

static void emit_lit(gp *p, const ir_expr *e, int max) {
    (void)max;
    helper_lit(p);
    args(p, "hfx_lit", e->a, 3);
}

/* asin, acos, atan and atan2 as fxc expands them (Direct3D 9 has no instruction for them): a
 * fixed polynomial, so the values are Windows' to the last digits (asin(-0.5) = -0.523645,
 * asin(0) = 6.76e-5, atan(1) = 0.7854096, atan2(-0, -1) = +pi). The same arithmetic is
 * common/eval.c's (hfx_ev_fxc_acos...). A comparison gives 0 or 1 to multiply by, which GLSL
 * 110 has too. The scalar and vector forms differ only in how they compare. */
static const char *const acos_text[2] = {
    "float hfx_acos(float x)\n{\n    float a = abs(x);\n"
    "    float p = ((a * -0.0187292993 + 0.0742610022) * a - 0.212114394) * a + 1.57072878;\n"
    "    float r = p * sqrt(abs(1.0 - a));\n    return r + float(x < -x) * (r * -2.0 + 3.14159274);\n}\n",
    "$T hfx_acos($T x)\n{\n    $T a = abs(x);\n"
    "    $T p = ((a * -0.0187292993 + 0.0742610022) * a - 0.212114394) * a + 1.57072878;\n"
    "    $T r = p * sqrt(abs(1.0 - a));\n    return r + $T(lessThan(x, -x)) * (r * -2.0 + 3.14159274);\n}\n"};

/* p(a) * a, the odd polynomial of atan on 0..1 */
#define HFX_ATAN_POLY(T) \
    "    " T " s = a * a;\n    " T " p = (((s * 0.0208350997 - 0.0851330012) * s + 0.180141002) * s - 0.330299497) * s + 0.999866009;\n" \
    "    " T " r = a * p;\n"
static const char *const atan_text[2] = {
    "float hfx_atan(float x)\n{\n    float a = min(abs(x), 1.0) * (1.0 / max(abs(x), 1.0));\n" HFX_ATAN_POLY("float")
    "    r = a * p + float(1.0 < abs(x)) * (r * -2.0 + 1.57079637);\n    return r * (1.0 - 2.0 * float(x < -x));\n}\n",
    "$T hfx_atan($T x)\n{\n    $T a = min(abs(x), 1.0) * (1.0 / max(abs(x), 1.0));\n" HFX_ATAN_POLY("$T")
    "    r = a * p + $T(lessThan($T(1.0), abs(x))) * (r * -2.0 + 1.57079637);\n"
    "    return r * (1.0 - 2.0 * $T(lessThan(x, -x)));\n}\n"};
static const char *const atan2_text[2] = {
    "float hfx_atan2(float y, float x)\n{\n    float a = min(abs(x), abs(y)) * (1.0 / max(abs(x), abs(y)));\n" HFX_ATAN_POLY("float")
    "    r = a * p + float(abs(x) < abs(y)) * (r * -2.0 + 1.57079637);\n"
    "    r = r + float(x < -x) * -3.14159274;\n    float lo = min(x, y), hi = max(x, y);\n"
    "    return r * (1.0 - 2.0 * float(lo < -lo) * float(hi >= -hi));\n}\n",
    "$T hfx_atan2($T y, $T x)\n{\n    $T a = min(abs(x), abs(y)) * (1.0 / max(abs(x), abs(y)));\n" HFX_ATAN_POLY("$T")
    "    r = a * p + $T(lessThan(abs(x), abs(y))) * (r * -2.0 + 1.57079637);\n"
    "    r = r + $T(lessThan(x, -x)) * -3.14159274;\n    $T lo = min(x, y), hi = max(x, y);\n"
    "    return r * (1.0 - 2.0 * $T(lessThan(lo, -lo)) * $T(greaterThanEqual(hi, -hi)));\n}\n"};
#undef HFX_ATAN_POLY

static void emit_acos(gp *p, const ir_expr *e, int max) {
    (void)max;
    helper_typed(p, "acos", e->type, acos_text[ncomp(e->type) > 1]);
    args(p, "hfx_acos", e->a, 1);
}

/* asin(x) = pi/2 - acos(x), as fxc computes it. */
static void emit_asin(gp *p, const ir_expr *e, int max) {
    (void)max;
    helper_typed(p, "acos", e->type, acos_text[ncomp(e->type) > 1]);
    helper_typed(p, "asin", e->type, "$T hfx_asin($T x) { return 1.57079637 - hfx_acos(x); }\n");
    args(p, "hfx_asin", e->a, 1);
}

static void emit_atan(gp *p, const ir_expr *e, int max) {
    (void)max;
    helper_typed(p, "atan", e->type, atan_text[ncomp(e->type) > 1]);
    args(p, "hfx_atan", e->a, 1);
}

static void emit_atan2(gp *p, const ir_expr *e, int max) {
    (void)max;
    helper_typed(p, "atan2", e->type, atan2_text[ncomp(e->type) > 1]);
    args(p, "hfx_atan2", e->a, 2);
}

/* mad(a, b, c) = a * b + c (GLSL 330 has no fma; the driver fuses it when it can). */
static void emit_mad(gp *p, const ir_expr *e, int max) {
    wrap_open(p, PREC_ADD, max);
    hfx_glsl_expr(p, e->a[0], PREC_MUL);
    hfx_sb_put(p->out, " * ");
    hfx_glsl_expr(p, e->a[1], PREC_UNARY);
    hfx_sb_put(p->out, " + ");
    hfx_glsl_expr(p, e->a[2], PREC_MUL);
    wrap_close(p, PREC_ADD, max);
}

/* dst: the distance vector of D3D's dst instruction, (1, a.y * b.y, a.z, b.w). */
static void emit_dst(gp *p, const ir_expr *e, int max) {
    (void)max;
    helper_typed(p, "dst", e->type, "$T hfx_dst($T a, $T b) { return $T(1.0, a.y * b.y, a.z, b.w); }\n");
    args(p, "hfx_dst", e->a, 2);
}

static void emit_sincos(gp *p, const ir_expr *e, int max) {
    (void)max;
    const hfx_type *t = e->a[0]->type;
    if (hfx_glsl_is_matrix(t)) /* GLSL's sin takes no matrix: column by column (HLSL rows) */
        helper_typed(p, "sincos", t, hfx_arena_printf(p->c->arena, "void hfx_sincos($T x, out $T s, out $T c) {\n"
                                     "    for (int i = 0; i < %u; i++) { s[i] = sin(x[i]); c[i] = cos(x[i]); }\n}\n", t->rows));
    else
        helper_typed(p, "sincos", t, "void hfx_sincos($T x, out $T s, out $T c) { s = sin(x); c = cos(x); }\n");
    hfx_sb_put(p->out, "hfx_sincos(");
    hfx_glsl_expr(p, e->a[0], PREC_ASSIGN);
    hfx_sb_put(p->out, ", ");
    hfx_glsl_lvalue(p, e->a[1], PREC_ASSIGN);
    hfx_sb_put(p->out, ", ");
    hfx_glsl_lvalue(p, e->a[2], PREC_ASSIGN);
    hfx_sb_put(p->out, ")");
}

static void emit_clip(gp *p, const ir_expr *e, int max) {
    (void)max;
    helper_clip(p, e->a[0]->type);
    args(p, "hfx_clip", e->a, 1);
}

static void emit_d3dcolor(gp *p, const ir_expr *e, int max) {
    (void)max;
    hfx_sb_put(p->out, "ivec4(");
    hfx_glsl_expr(p, e->a[0], PREC_POSTFIX);
    hfx_sb_put(p->out, ".zyxw * 255.001953)");
}

/* GLSL's dot is float only: integer vectors go through float and back. */
static void emit_dot(gp *p, const ir_expr *e, int max) {
    (void)max;
    if (!is_float(e->type->base)) hfx_sb_printf(p->out, "%s(", ty(p, e->type));
    hfx_sb_put(p->out, "dot(");
    as_float(p, e->a[0]);
    hfx_sb_put(p->out, ", ");
    as_float(p, e->a[1]);
    hfx_sb_put(p->out, is_float(e->type->base) ? ")" : "))");
}

static void emit_mul(gp *p, const ir_expr *e, int max) { print_mul(p, e, max); }

static void emit_ldexp(gp *p, const ir_expr *e, int max) {
    wrap_open(p, PREC_MUL, max);
    hfx_glsl_expr(p, e->a[0], PREC_MUL);
    hfx_sb_put(p->out, " * ");
    args(p, "exp2", e->a + 1, 1);
    wrap_close(p, PREC_MUL, max);
}

static void emit_isfinite(gp *p, const ir_expr *e, int max) {
    (void)max;
    if (ncomp(e->a[0]->type) != 1 && !p->legacy) { /* a component is NaN, infinite, or neither */
        args(p, "equal(isnan", e->a, 1);
        hfx_sb_put(p->out, ", ");
        args(p, "isinf", e->a, 1);
        hfx_sb_put(p->out, ")");
        return;
    }
    /* GLSL 110 has neither isnan nor isinf (found by fuzz/fuzz_diff.c): there x == x rules out
     * NaN, and x * 0 is 0 only when x is finite, as hfx_isnan / hfx_isinf test them */
    if (ncomp(e->a[0]->type) == 1 && !p->legacy)
        helper_typed(p, "isfinite", e->a[0]->type, "bool hfx_isfinite($T x) { return !(isnan(x) || isinf(x)); }\n");
    else if (ncomp(e->a[0]->type) == 1)
        helper_typed(p, "isfinite", e->a[0]->type, "bool hfx_isfinite($T x) { return x == x && x * 0.0 == 0.0; }\n");
    else
        helper_typed(p, "isfinite", e->a[0]->type,
                     "bvec$N hfx_isfinite($T x) { return bvec$N(vec$N(equal(x, x)) * vec$N(equal(x * 0.0, $T(0.0)))); }\n");
    args(p, "hfx_isfinite", e->a, 1);
}

static void emit_frexp(gp *p, const ir_expr *e, int max) {
    (void)max;
    if (ncomp(e->a[0]->type) != 1 && !p->legacy) { /* per component; 0 has exponent 0 and mantissa 0 */
        helper_typed(p, "frexp", e->type,
                     "$T hfx_frexp($T x, out $T e)\n{\n    bvec$N zero = equal(x, $T(0.0));\n"
                     "    e = mix(floor(log2(abs(x))) + 1.0, $T(0.0), zero);\n    return mix(x * exp2(-e), $T(0.0), zero);\n}\n");
        args_out2(p, "hfx_frexp", e->a);
        return;
    }
    if (ncomp(e->a[0]->type) != 1) { hfx_glsl_error(p, e->loc, "'frexp' of a vector needs GLSL 330 or ES 300"); return; }
    helper_typed(p, "frexp", e->type,
                 "float hfx_frexp(float x, out float e)\n{\n    if (x == 0.0) { e = 0.0; return 0.0; }\n"
                 "    e = floor(log2(abs(x))) + 1.0;\n    return x * exp2(-e);\n}\n");
    args_out2(p, "hfx_frexp", e->a);
}

/* asfloat / asint / asuint: GLSL's bit casts; a same-type call is a constructor. */
static void emit_reinterpret(gp *p, const ir_expr *e, int max) {
    (void)max;
    hfx_base from = e->a[0]->type->base, to = e->type->base;
    const char *fn = NULL;
    if (is_float(from) && to == B_INT) fn = "floatBitsToInt";
    else if (is_float(from) && to == B_UINT) fn = "floatBitsToUint";
    else if (from == B_INT && is_float(to)) fn = "intBitsToFloat";
    else if (from == B_UINT && is_float(to)) fn = "uintBitsToFloat";
    else fn = ty(p, e->type);
    if (p->legacy) { hfx_glsl_error(p, e->loc, "bit casts need GLSL 330 or ES 300"); return; }
    args(p, fn, e->a, 1);
}

static void emit_unsupported(gp *p, const ir_expr *e, int max) {
    (void)max;
    hfx_glsl_error(p, e->loc, hfx_arena_printf(p->c->arena, "'%s': intrinsic is not supported", hfx_intrinsic_name((int)e->intrin)));
}

/* The GLSL columns of check/intrinsics.def: each row's emitter and GLSL function. */
static const struct glsl_row {
    emit_fn *emit;
    const char *fn;
} rows[HFX_INTR_COUNT] = {
#define HFX_INTRINSIC(id, name, mn, mx, sig, dim, texf, lower, ev, glsl_emit, glsl_fn) [HFX_INTR_##id] = {emit_##glsl_emit, glsl_fn},
#include "check/intrinsics.def"
#undef HFX_INTRINSIC
};

static const char *glsl_name_of(ir_intrin i) { return rows[i].fn; }

void hfx_glsl_intrinsic(gp *p, const ir_expr *e, int max) {
    if ((unsigned)e->intrin >= HFX_INTR_COUNT) { hfx_glsl_error(p, e->loc, "unknown intrinsic"); return; }
    rows[e->intrin].emit(p, e, max);
}
