/* test_bc_intrin.c: the intrinsics D3D9 has no instruction for (compiler/bytecode/bc_intrin_math.c),
 * run. Each shader is compiled through the fxc path (/T, /E), decoded by d3d9/ and executed here
 * by a small interpreter of the instructions as Direct3D 9's reference defines them (rcp of 0 is
 * +inf, rsq and log read |x|, exp is 2^x, cmp is src0 >= 0 ? src1 : src2, slt / sge give 0 / 1,
 * sincos writes cos to x and sin to y, lit and dst as their pages say). The input is v0 (COLOR0
 * in pixel shaders, POSITION in vertex shaders); the output oC0 / oPos. Expected values are the
 * documented functions worked out by hand, and for fxc's polynomials the polynomial's value,
 * checked against the exact function within the polynomial's documented error. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "d3d9/d3d9.h"
#include "hfx/hfxc.h"
#include "test.h"

typedef struct machine { float r[32][4], c[256][4], v[16][4], out[4]; bool killed; } machine;

static float *reg(machine *m, uint8_t type, uint16_t num) {
    switch (type) {
    case D3D9_REG_TEMP: return m->r[num & 31];
    case D3D9_REG_CONST: return m->c[num & 255];
    case D3D9_REG_INPUT: return m->v[num & 15];
    default: return m->out; /* oC0, oPos: the one output these shaders write */
    }
}

static void read_src(machine *m, const d3d9_src *s, float out[4]) {
    const float *r = reg(m, s->type, s->num);
    for (unsigned c = 0; c < 4; c++) {
        float x = r[s->swizzle >> (2 * c) & 3];
        if (s->mod == D3D9_SMOD_ABS || s->mod == D3D9_SMOD_ABSNEG) x = fabsf(x);
        if (s->mod == D3D9_SMOD_NEG || s->mod == D3D9_SMOD_ABSNEG) x = -x;
        out[c] = x;
    }
}

static float d3d_rcp(float x) { return x == 0 ? INFINITY : 1.0f / x; }

/* One arithmetic instruction: its four results before the write mask. */
static void execute(machine *m, const d3d9_inst *in) {
    float a[4] = {0}, b[4] = {0}, c[4] = {0}, d[4] = {0};
    if (in->src_count > 0) read_src(m, &in->src[0], a);
    if (in->src_count > 1) read_src(m, &in->src[1], b);
    if (in->src_count > 2) read_src(m, &in->src[2], c);
    switch (in->op) {
    case D3D9_TEXKILL: {
        float x[4];
        memcpy(x, reg(m, in->dst.type, in->dst.num), sizeof x);
        for (unsigned k = 0; k < 3; k++) m->killed |= x[k] < 0; /* texkill tests x, y and z */
        return;
    }
    case D3D9_DP3: d[0] = a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; break;
    case D3D9_DP4: d[0] = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; break;
    case D3D9_DP2ADD: d[0] = a[0] * b[0] + a[1] * b[1] + c[0]; break;
    case D3D9_RCP: d[0] = d3d_rcp(a[0]); break;
    case D3D9_RSQ: d[0] = d3d_rcp(sqrtf(fabsf(a[0]))); break;
    case D3D9_EXP: d[0] = exp2f(a[0]); break;
    case D3D9_LOG: d[0] = a[0] == 0 ? -INFINITY : log2f(fabsf(a[0])); break;
    case D3D9_POW: d[0] = powf(fabsf(a[0]), b[0]); break;
    case D3D9_SINCOS: d[0] = cosf(a[0]); d[1] = sinf(a[0]); break;
    case D3D9_LIT: /* (1, max(x, 0), x > 0 and y > 0 ? y^w : 0, 1) */
        d[0] = d[3] = 1;
        d[1] = a[0] > 0 ? a[0] : 0;
        d[2] = a[0] > 0 && a[1] > 0 ? powf(a[1], a[3]) : 0;
        break;
    case D3D9_DST: d[0] = 1; d[1] = a[1] * b[1]; d[2] = a[2]; d[3] = b[3]; break;
    default:
        for (unsigned k = 0; k < 4; k++) {
            switch (in->op) {
            case D3D9_MOV: d[k] = a[k]; break;
            case D3D9_ADD: d[k] = a[k] + b[k]; break;
            case D3D9_MUL: d[k] = a[k] * b[k]; break;
            case D3D9_MAD: d[k] = a[k] * b[k] + c[k]; break;
            case D3D9_MIN: d[k] = a[k] < b[k] ? a[k] : b[k]; break;
            case D3D9_MAX: d[k] = a[k] > b[k] ? a[k] : b[k]; break;
            case D3D9_ABS: d[k] = fabsf(a[k]); break;
            case D3D9_FRC: d[k] = a[k] - floorf(a[k]); break;
            case D3D9_SLT: d[k] = a[k] < b[k]; break;
            case D3D9_SGE: d[k] = a[k] >= b[k]; break;
            case D3D9_CMP: d[k] = a[k] >= 0 ? b[k] : c[k]; break;
            case D3D9_LRP: d[k] = a[k] * b[k] + (1 - a[k]) * c[k]; break;
            case D3D9_DSX: case D3D9_DSY: d[k] = 0; break; /* one pixel: no neighbour */
            default: fprintf(stderr, "interpreter: %s not handled\n", hfx_d3d9_op_find(in->op)->name); m->killed = true; return;
            }
        }
    }
    bool scalar = in->op == D3D9_DP3 || in->op == D3D9_DP4 || in->op == D3D9_DP2ADD ||
                  ((hfx_d3d9_op_find(in->op)->flags & D3D9_OPF_SCALAR) && in->op != D3D9_SINCOS);
    float *dst = reg(m, in->dst.type, in->dst.num);
    for (unsigned k = 0; k < 4; k++) {
        if (!(in->dst.mask & (1u << k))) continue;
        float x = scalar ? d[0] : d[k];
        if (in->dst.mods & D3D9_DMOD_SAT) x = x < 0 ? 0 : x > 1 ? 1 : x;
        dst[k] = x;
    }
}

/* Compiles src's main for profile and runs it on v0 = in; false when it does not compile. */
static bool run(const char *src, const char *profile, const float in[4], float out[4], bool *killed) {
    hfxc_options o = {.entry = "main", .profile = profile};
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "t.fx", &o);
    size_t size = 0;
    const void *code = hfxc_result_bytecode(r, &size);
    bool ok = hfxc_result_ok(r) && code;
    if (!ok) {
        char *text = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s", text ? text : "");
        free(text);
    }
    hfx_arena arena;
    hfx_diags diags;
    hfx_arena_init(&arena);
    hfx_diags_init(&diags, &arena, 0);
    d3d9_input din = {code, (uint32_t)size, hfx_diags_add_file(&diags, "t.pso", NULL, "", 0), 0};
    d3d9_shader *s = ok ? hfx_d3d9_decode(&arena, &diags, &din) : NULL;
    machine *m = calloc(1, sizeof *m);
    memcpy(m->v[0], in, sizeof m->v[0]);
    for (uint32_t i = 0; s && i < s->inst_count; i++) {
        const d3d9_inst *x = &s->insts[i];
        if (x->op == D3D9_DEF) memcpy(m->c[x->dst.num], x->value.f, sizeof m->c[0]);
        else if (!(hfx_d3d9_op_find(x->op)->flags & D3D9_OPF_DECL)) execute(m, x);
    }
    ok = s != NULL;
    memcpy(out, m->out, sizeof m->out);
    if (killed) *killed = m->killed;
    free(m);
    hfx_arena_free(&arena);
    hfxc_result_free(r);
    return ok;
}

/* f(x) in a pixel shader (ps_3_0), its float4 result. */
static void ps(const char *body, const float in[4], float out[4]) {
    char src[1024];
    snprintf(src, sizeof src, "float4 main(float4 x : COLOR0) : COLOR0 { %s }\n", body);
    CHECK(run(src, "ps_3_0", in, out, NULL));
}
static void vs(const char *body, const float in[4], float out[4]) {
    char src[1024];
    snprintf(src, sizeof src, "float4 main(float4 x : POSITION) : POSITION { %s }\n", body);
    CHECK(run(src, "vs_2_0", in, out, NULL));
}

#define NEAR4(o, a, b, c, d, tol) do { CHECK_NEAR((o)[0], a, tol); CHECK_NEAR((o)[1], b, tol); \
                                       CHECK_NEAR((o)[2], c, tol); CHECK_NEAR((o)[3], d, tol); } while (0)

/* acos(0.5) = p(0.5) sqrt(0.5), p(a) = ((-0.0187293 a + 0.0742610) a - 0.2121144) a + 1.5707288:
 * p(0.5) = 1.4808957, times 0.70710678 = 1.0471513 (exact 1.0471976: 4.6e-5 off, inside the
 * polynomial's 6.7e-5). acos(-0.5) = pi - 1.0471513 = 2.0944414; asin = pi/2 - acos:
 * asin(0.5) = 0.5236451, asin(0) = pi/2 - 1.5707288 = 6.76e-5 (Windows' value, not 0). Both
 * stages: the sign by cmp (pixel) and by slt (vertex). */
static void inverse_sine_cosine(void) {
    float o[4];
    const float x[4] = {0.5f, -0.5f, 0, 1};
    for (int stage = 0; stage < 2; stage++) {
        (stage ? vs : ps)("return acos(x);", x, o);
        NEAR4(o, 1.0471513, 2.0944414, 1.5707288, 0, 1e-6);
        CHECK_NEAR(o[0], acos(0.5), 6.7e-5);
        (stage ? vs : ps)("return asin(x);", x, o);
        NEAR4(o, 0.5236451, -0.5236451, 6.76e-5, 1.5707964, 1e-6);
    }
}

/* atan's polynomial on 0..1: a (((((0.0208351 s - 0.085133) s + 0.180141) s - 0.3302995) s
 * + 0.999866), s = a^2. At a = 1: 0.0208351 - 0.085133 + 0.180141 - 0.3302995 + 0.999866 =
 * 0.7854096 (pi/4 = 0.7853982: 1.1e-5 off). atan(2) = pi/2 - r(0.5): s = 0.25, p = 0.9273011,
 * r(0.5) = 0.4636506 (atan(0.5) = 0.4636476), so 1.1071457; atan(-2) its negation.
 * atan2(y, x) folds the quadrant: (1, -1) pi - 0.7854096 = 2.3561830, (-1, -1) its negation,
 * (0, -1) pi (min(x, y) < 0 <= max: negated from -pi), (-1, 0) -pi/2. */
static void inverse_tangent(void) {
    float o[4];
    const float x[4] = {1, 2, -2, 0};
    for (int stage = 0; stage < 2; stage++) {
        (stage ? vs : ps)("return atan(x);", x, o);
        NEAR4(o, 0.7854096, 1.1071457, -1.1071457, 0, 2e-6);
        CHECK_NEAR(o[1], atan(2.0), 1e-5);
        const float yx[4] = {1, -1, 0, -1};
        (stage ? vs : ps)("return float4(atan2(x.x, x.y), atan2(x.y, x.y), atan2(x.z, x.y), atan2(x.y, x.z));", yx, o);
        NEAR4(o, 2.3561830, -2.3561830, 3.1415927, -1.5707964, 2e-6);
    }
}

/* sinh(1) = (e - 1/e) / 2 = 1.1752012, cosh(1) = 1.5430806, tanh(0.5) = 0.46211716,
 * tan(0.5) = 0.54630249; ldexp(0.5, 3) = 4; mad(2, 3, 1) = 7. */
static void exponentials(void) {
    float o[4];
    const float x[4] = {1, 0.5f, 3, 2};
    ps("return float4(sinh(x.x), cosh(x.x), tanh(x.y), tan(x.y));", x, o);
    NEAR4(o, 1.1752012, 1.5430806, 0.46211716, 0.54630249, 1e-6);
    ps("return float4(ldexp(x.y, x.z), mad(x.w, x.z, x.x), tanh(-x.z * 40), tanh(x.z * 40));", x, o);
    NEAR4(o, 4, 7, -1, 1, 1e-6); /* e^240 overflows: 1 - 2 / (inf + 1) is still 1 */
}

/* pow over a vector is written as a log per component, one mul, an exp per component (fxc's
 * shorter form; bc_intrin.c): |x|^y in each lane. (2, -3, 0.5, 0) ^ (3, 2, 2, 2) = (8, 9, 0.25, 0):
 * -3 as |-3| (D3D9's pow and log read |x|), 0 as 2^(2 * -inf) = 0. Both stages. */
static void vector_powers(void) {
    float o[4];
    const float x[4] = {2, -3, 0.5f, 0};
    for (int stage = 0; stage < 2; stage++) {
        (stage ? vs : ps)("return pow(x, float4(3, 2, 2, 2));", x, o);
        NEAR4(o, 8, 9, 0.25, 0, 1e-5);
    }
}

/* trunc toward zero; modf keeps the sign in both parts (-2.5: -0.5 and -2); frexp: 6 = 0.75 *
 * 2^3, 4 = 0.5 * 2^3, -0.25 = -0.5 * 2^-1, 0 gives 0 and 0. */
static void parts_of_numbers(void) {
    float o[4];
    const float x[4] = {-2.5f, 2.75f, -1.25f, 0};
    ps("return trunc(x);", x, o);
    NEAR4(o, -2, 2, -1, 0, 0);
    ps("float2 i; float2 f = modf(x.xy, i); return float4(f, i);", x, o);
    NEAR4(o, -0.5, 0.75, -2, 2, 0);
    const float y[4] = {6, 4, -0.25f, 0};
    for (int stage = 0; stage < 2; stage++) {
        (stage ? vs : ps)("float2 e; float2 m = frexp(x.xy, e); return float4(m, e);", y, o);
        NEAR4(o, 0.75, 0.5, 3, 3, 0);
        (stage ? vs : ps)("float2 e; float2 m = frexp(x.zw, e); return float4(m, e);", y, o);
        NEAR4(o, -0.5, 0, -1, 0, 0);
    }
}

/* lit(l, h, m) = (1, max(l, 0), l < 0 or h < 0 ? 0 : h^m, 1): (0.5, 0.5, 2) gives (1, 0.5,
 * 0.25, 1), (-0.5, 0.5, 2) (1, 0, 0, 1). dst(a, b) = (1, a.y b.y, a.z, b.w). The vertex shader
 * uses the instructions, the pixel shader their parts. */
static void lighting_helpers(void) {
    float o[4];
    const float x[4] = {0.5f, 0.5f, 2, -0.5f};
    for (int stage = 0; stage < 2; stage++) {
        (stage ? vs : ps)("return lit(x.x, x.y, x.z);", x, o);
        NEAR4(o, 1, 0.5, 0.25, 1, 1e-6);
        (stage ? vs : ps)("return lit(x.w, x.y, x.z);", x, o);
        NEAR4(o, 1, 0, 0, 1, 0);
        (stage ? vs : ps)("return dst(x, x.wzyx);", x, o);
        NEAR4(o, 1, 1, 2, 0.5, 0);
    }
}

/* Determinants by cofactors: a 2x2 (0.5 * 3 - (-1.5) * 0.25 = 1.875), a 3x3 with one
 * off-diagonal term (2 * 3 * 4 = 24), a triangular 4x4 (2 * 3 * 4 * 5 = 120), a 4x4 permutation
 * (a 4-cycle, odd: -(2 * 3 * 4 * 5) = -120) and a column_major parameter (its registers hold
 * columns: the same determinant). */
static void determinants(void) {
    float o[4];
    const float x[4] = {0.5f, -1.5f, 0.25f, 3};
    ps("float2x2 m = {x.x, x.y, x.z, x.w}; float3x3 n = {2, 0, 0, 0, 3, 0, 1, 0, 4};\n"
       "float4x4 t = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 1, 2, 3, 5}, p = {0, 2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 5, 0, 0, 0};\n"
       "return float4(determinant(m), determinant(n), determinant(t), determinant(p) * x.w);", x, o);
    NEAR4(o, 1.875, 24, 120, -360, 0);
    ps("float4x4 m = {x.w, 0, 0, 0, 0, x.w, 0, 0, 0, 0, x.w, 0, x.x, x.y, x.z, x.w}; return determinant(m);", x, o);
    CHECK_NEAR(o[0], 81, 0);
}

/* refract(i, n, eta): i = (0.6, -0.8, 0), n = (0, 1, 0): dot = -0.8, k = 1 - 0.25 * 0.36 = 0.91,
 * eta 0.5 gives (0.3, -0.4 - (-0.4 + 0.9539392) ... = (0.3, -0.9539392, 0); eta 2: k = 1 - 4 *
 * 0.36 < 0, total internal reflection, 0. faceforward(n, i, ng) = dot(ng, i) < 0 ? n : -n. */
static void geometry(void) {
    float o[4];
    const float x[4] = {0.5f, 2, -1, 1};
    for (int stage = 0; stage < 2; stage++) {
        (stage ? vs : ps)("return float4(refract(float3(0.6, -0.8, 0), float3(0, 1, 0), x.x), 1);", x, o);
        NEAR4(o, 0.3, -0.9539392, 0, 1, 1e-6);
        (stage ? vs : ps)("return float4(refract(float3(0.6, -0.8, 0), float3(0, 1, 0), x.y), 1);", x, o);
        NEAR4(o, 0, 0, 0, 1, 0);
        (stage ? vs : ps)("return float4(faceforward(float2(3, 4), float2(0, x.z), float2(0, 1)),"
                          " faceforward(float2(3, 4), float2(0, x.w), float2(0, 1)));", x, o);
        NEAR4(o, 3, 4, -3, -4, 0);
    }
}

/* The classifications as compares (a NaN takes every cmp's and slt's else side): inputs 1,
 * +inf, -inf, NaN. all() is the smallest magnitude's test against 0. */
static void classification(void) {
    float o[4];
    const float x[4] = {1, INFINITY, -INFINITY, NAN};
    for (int stage = 0; stage < 2; stage++) {
        (stage ? vs : ps)("return isnan(x);", x, o);
        NEAR4(o, 0, 0, 0, 1, 0);
        (stage ? vs : ps)("return isinf(x);", x, o);
        NEAR4(o, 0, 1, 1, 0, 0);
        (stage ? vs : ps)("return isfinite(x);", x, o);
        NEAR4(o, 1, 0, 0, 0, 0);
        const float y[4] = {1, -2, 0.5f, 0};
        (stage ? vs : ps)("return float4(all(x), all(x.xyz), all(x.yw), all(x.x));", y, o);
        NEAR4(o, 0, 1, 0, 1, 0);
    }
}

/* D3DCOLORtoUBYTE4(c) = int4(c.zyxw * 255.001953): (0.1, 0.2, 0.3, 0.4) gives 76.5 -> 76, 51.0 ->
 * 51, 25.5 -> 25, 102.0 -> 102. Bit casts: a constant's bits (0x3F800000 is 1.0), a cast back
 * to the argument's own type the value; a computed value's bits are refused at its position. */
static void casts(void) {
    float o[4];
    const float x[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    ps("return D3DCOLORtoUBYTE4(x);", x, o);
    NEAR4(o, 76, 51, 25, 102, 0);
    ps("return float4(asfloat(0x3F800000), asfloat(asint(x.y)), asfloat(x.z), asuint(1.0) / 1065353216.0);", x, o);
    NEAR4(o, 1, 0.2f, 0.3f, 1, 0);
    const char *src = "float4 main(float4 x : COLOR0) : COLOR0 { return asint(x.x); }\n";
    hfxc_options opt = {.entry = "main", .profile = "ps_3_0"};
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "t.fx", &opt);
    char *text = hfxc_diagnostics_text(r);
    CHECK(!hfxc_result_ok(r));
    CHECK_STR(text, "t.fx(1,50): error X5006: asint of a computed value reinterprets bits, which D3D9's float registers "
                    "do not hold\n");
    free(text);
    hfxc_result_free(r);
}

/* clip of a float4: texkill tests three components, so two of them (xyz, then w). */
static void clip_four(void) {
    const char *src = "float4 main(float4 x : COLOR0) : COLOR0 { clip(x); return 1; }\n";
    float o[4];
    bool killed = true;
    CHECK(run(src, "ps_2_0", (const float[4]){1, 2, 3, 4}, o, &killed));
    CHECK(!killed);
    CHECK(run(src, "ps_2_0", (const float[4]){1, 2, 3, -4}, o, &killed));
    CHECK(killed);
    CHECK(run(src, "ps_2_0", (const float[4]){1, -2, 3, 4}, o, &killed));
    CHECK(killed);
}

/* sincos's out arguments into fresh locals (written as assignments, never into the zero
 * constant an unwritten local reads as), a matrix componentwise; conversions that regroup: a
 * vector as a float2x2 (rows xy, zw), a matrix as a vector, an array from a matrix. */
static void out_arguments_and_shapes(void) {
    float o[4];
    const float x[4] = {0, 1.5707964f, 3.1415927f, 0.5f};
    ps("float4 s, c; sincos(x, s, c); return float4(s.y, c.x, c.z, s.w);", x, o);
    NEAR4(o, 1, 1, -1, sinf(0.5f), 1e-6);
    ps("float2x2 s, c; sincos(float2x2(x), s, c); return float4(c[0], c[1]);", x, o);
    NEAR4(o, 1, cosf(1.5707964f), -1, cosf(0.5f), 1e-6);
    const float y[4] = {1, 2, 3, 4};
    ps("float2x2 m = (float2x2)x; return float4(m[1], m[0]);", y, o);
    NEAR4(o, 3, 4, 1, 2, 0);
    ps("float2x2 m = {x.w, x.z, x.y, x.x}; return (float4)m;", y, o);
    NEAR4(o, 4, 3, 2, 1, 0);
    ps("float2x2 m = {x.y, x.x, x.w, x.z}; float a[4] = (float[4])m; return float4(a[3], a[2], a[1], a[0]);", y, o);
    NEAR4(o, 3, 4, 1, 2, 0);
}

/* m = transpose(m) in place: the transposed view reads the registers the copy writes, so they are
 * read first (a parallel copy). m's rows 2 (1, 2, 3), 2 (4, 1, 2), 2 (3, 4, 1) for x = (1, 2, 3, 4),
 * transposed: (2, 8, 6), (4, 2, 8), (6, 4, 2) (DigitalRise-style tangent frames and the Apress
 * terrain's `tangentSpace = transpose(tangentSpace)` lost their third row to the overwrite). */
static void transpose_in_place(void) {
    float o[4];
    const float x[4] = {1, 2, 3, 4};
    for (int stage = 0; stage < 2; stage++) {
        const char *body = "float3x3 m = float3x3(x.xyz, x.wxy, x.zwx) * 2; m = transpose(m); return float4(m[0], m[1].x);";
        (stage ? vs : ps)(body, x, o);
        NEAR4(o, 2, 8, 6, 4, 0);
        (stage ? vs : ps)("float3x3 m = float3x3(x.xyz, x.wxy, x.zwx) * 2; m = transpose(m); return float4(m[2], m[1].z);",
                          x, o);
        NEAR4(o, 6, 4, 2, 8, 0);
    }
}

int main(void) {
    RUN(inverse_sine_cosine);
    RUN(inverse_tangent);
    RUN(exponentials);
    RUN(vector_powers);
    RUN(parts_of_numbers);
    RUN(lighting_helpers);
    RUN(determinants);
    RUN(geometry);
    RUN(classification);
    RUN(casts);
    RUN(clip_four);
    RUN(out_arguments_and_shapes);
    RUN(transpose_in_place);
    return test_summary();
}
