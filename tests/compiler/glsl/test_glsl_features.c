/* test_glsl_features.c: a sweep of HLSL constructs (every intrinsic, matrix shapes, structs,
 * arrays, control flow) through hfx; glslang must accept the GLSL of every target. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "glsl_check.h"
#include "hfx/hfxc.h"
#include "test.h"

#define VS "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"
#define TECH "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n"

static int links(const char *body, unsigned targets) {
    size_t n = strlen(body) + 512;
    char *src = malloc(n);
    snprintf(src, n, "%s%s%s", VS, body, TECH);
    hfxc_options o = {0};
    o.targets = targets;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "f.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    int ok = fx && fx->program_count == 1;
    if (!fx) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "compile failed:\n%s%s\n", d, src);
        free(d);
    }
    for (int t = 0; ok && t < HFX_TARGET_COUNT; t++) {
        if (!(targets & (1u << t))) continue;
        char *log = NULL;
        const char *vs = fx->programs[0].code[0][t].data, *fs = fx->programs[0].code[1][t].data;
        if (!test_glsl_link(vs, fs, &log)) {
            fprintf(stderr, "target %d rejected:\n%s\n%s\n", t, log ? log : "", fs);
            ok = 0;
        }
        free(log);
    }
    hfxc_result_free(r);
    free(src);
    return ok;
}

static const unsigned ALL = (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300) | (1u << HFX_TARGET_GLSL110);
static const unsigned MODERN = (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300);

static void float_intrinsics(void) {
    CHECK(links("float4 v; float s;\n"
                "float4 ps() : COLOR {\n"
                "  float4 r = abs(v) + acos(v) + asin(v) + atan(v) + atan2(v, v) + ceil(v) + clamp(v, 0, 1);\n"
                "  r += cos(v) + cosh(v) + degrees(v) + exp(v) + exp2(v) + floor(v) + fmod(v, 2) + frac(v);\n"
                "  r += lerp(v, v, 0.5) + log(v) + log10(v) + log2(v) + max(v, s) + min(v, s) + pow(v, 2);\n"
                "  r += radians(v) + round(v) + rsqrt(v) + saturate(v) + sign(v) + sin(v) + sinh(v);\n"
                "  r += smoothstep(0, 1, v) + sqrt(v) + step(0.5, v) + tan(v) + tanh(v) + trunc(v);\n"
                "  r += ddx(v) + ddy(v) + fwidth(v) + ldexp(v, 2);\n"
                "  r.x += length(v) + distance(v, v) + dot(v, v) + determinant(float2x2(v));\n"
                "  r.xyz += cross(v.xyz, v.yzx) + normalize(v.xyz) + reflect(v.xyz, v.zyx) + refract(v.xyz, v.zyx, 0.5);\n"
                "  r.xyz += faceforward(v.xyz, v.xyz, v.xyz);\n"
                "  r += lit(v.x, v.y, v.z);\n"
                "  float sn, cs; sincos(s, sn, cs); r.x += sn * cs;\n"
                "  float4 ip; r += modf(v, ip) + ip;\n"
                "  if (any(v) && all(v.xy) && !isnan(s) && !isinf(s)) r.y += 1;\n"
                "  clip(v); clip(s);\n"
                "  return r; }\n", ALL));
}

/* The GLSL 330 pixel stage of VS + body + TECH (one program), or NULL; *r to free. */
static const char *fragment_330(const char *body, hfxc_result **r) {
    char src[2048];
    snprintf(src, sizeof src, "%s%s%s", VS, body, TECH);
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    *r = hfxc_compile_memory(src, strlen(src), "f.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(*r);
    CHECK(fx && fx->program_count == 1);
    return fx && fx->program_count == 1 ? fx->programs[0].code[1][HFX_TARGET_GLSL330].data : NULL;
}

/* pow(x, n), n a constant integer fxc expands (docs/conventions.md, "pow"): its products, the
 * sign kept, an operand with work in it computed once into a local; a scalar's 7 (four
 * multiplications, past three) stays exp2(7 * log2|x|); -2 is 1 / (x * x). Every target. */
static void pow_constant_integer_powers(void) {
    static const char body[] = "float4 v; float s;\n"
        "float4 ps() : COLOR { float4 r = pow(v + 1, 2) + pow(v - s, 3);\n"
        "  r.xyz += pow(v.xyz * s, 4); r.x += pow(s, 7) + pow(s, -2) + pow(s, 5); return r; }\n";
    CHECK(links(body, ALL));
    hfxc_result *r = NULL;
    const char *fs = fragment_330(body, &r);
    if (fs) {
        CHECK_CONTAINS(fs, "(hfx_once0 = v + vec4(1.0) , hfx_once0 * hfx_once0)");
        CHECK_CONTAINS(fs, "(hfx_once1 = v - s , hfx_once1 * (hfx_once1 * hfx_once1))");
        CHECK_CONTAINS(fs, "(hfx_once2 = v.xyz * s , hfx_once3 = hfx_once2 * hfx_once2 , hfx_once3 * hfx_once3)");
        CHECK_CONTAINS(fs, "exp2(7.0 * max(log2(abs(s)), -3.40282347e+38))");
        CHECK_CONTAINS(fs, "1.0 / (s * s)");
        CHECK_CONTAINS(fs, "(hfx_once4 = s * s , s * (hfx_once4 * hfx_once4))"); /* x * (x^2)^2 */
    }
    hfxc_result_free(r);
}

/* D3D9's pow takes |x|: the abs is left out where the base cannot be negative (saturate, max or
 * clamp with a non-negative bound, length), kept otherwise. */
static void pow_of_a_nonnegative_base(void) {
    static const char body[] = "float4 v; float s;\n"
        "float4 ps() : COLOR { return float4(pow(saturate(s), v.x), pow(max(s, 0), v.y), pow(clamp(s, 0.5, 2), v.z),\n"
        "  pow(length(v), v.w)) + pow(max(s, -1), v) + pow(s, v.x); }\n";
    CHECK(links(body, ALL));
    hfxc_result *r = NULL;
    const char *fs = fragment_330(body, &r);
    if (fs) {
        CHECK_CONTAINS(fs, "exp2(v.x * max(log2(clamp(s, 0.0, 1.0)), -3.40282347e+38))");
        CHECK_CONTAINS(fs, "exp2(v.y * max(log2(max(s, 0.0)), -3.40282347e+38))");
        CHECK_CONTAINS(fs, "exp2(v.z * max(log2(clamp(s, 0.5, 2.0)), -3.40282347e+38))");
        CHECK_CONTAINS(fs, "exp2(v.w * max(log2(length(v)), -3.40282347e+38))");
        CHECK_CONTAINS(fs, "max(log2(abs(vec4(max(s, -1.0)))), -3.40282347e+38)");
        CHECK_CONTAINS(fs, "exp2(v.x * max(log2(abs(s)), -3.40282347e+38))");
    }
    hfxc_result_free(r);
}

static void integer_and_bool_ops(void) {
    CHECK(links("int4 iv; int i; uint u; bool b; bool3 bv;\n"
                "float4 ps() : COLOR {\n"
                "  int4 q = iv / 3 + iv % 3 - abs(iv) * sign(iv) + max(iv, i) + min(iv, 2) + clamp(iv, 0, 4);\n"
                "  int k = (i << 2) >> 1 | (i & 3) ^ ~i; k++; --k; k += 2; k %= 3; k *= i;\n"
                "  bool3 c = bv && !bv || (iv.xyz > 2);\n"
                "  float3 sel = c ? float3(1, 2, 3) : float3(4, 5, 6);\n"
                "  int3 isel = c ? iv.xyz : int3(1, 2, 3);\n"
                "  float f = b ? 1.0 : 0.5;\n"
                "  return float4(sel + isel, f + k + q.x + dot(iv, iv)); }\n", MODERN));
}

/* Found by fuzz/fuzz_diff.c: GLSL 110 has abs, sign, min, max and clamp for floats only, and
 * the integer forms were printed as they are (glslang: "'abs' : no matching overloaded function"). */
static void integer_intrinsics_in_glsl110(void) {
    CHECK(links("int4 iv; int i;\n"
                "float4 ps() : COLOR {\n"
                "  int4 q = abs(iv) * sign(iv) + max(iv, i) + min(iv, 2) + clamp(iv, 0, 4);\n"
                "  return float4(q) + abs(i) + sign(i) + max(i, 2) + min(i, 1) + clamp(i, 0, 3); }\n", ALL));
}

/* Found by fuzz/fuzz_diff.c: isnan / isinf of a vector printed GLSL 110 has no function for. */
static void vector_isnan_isinf_in_glsl110(void) {
    CHECK(links("float4 v; float2 w;\n"
                "float4 ps() : COLOR {\n"
                "  bool4 n = isnan(v), i = isinf(v);\n"
                "  return float4(n) + float4(i) + float4(isnan(w), isinf(w)); }\n", ALL));
}

/* Found by fuzz/fuzz_diff.c: GLSL 110 lacks isnan / isinf (isfinite used them), determinant of
 * a 4x4, mat3(mat4), and array constructors (a local array was zeroed with one). */
static void more_glsl110_forms(void) {
    CHECK(links("float4 v; float s; float4x4 M;\n"
                "float4 ps() : COLOR {\n"
                "  float a[3]; a[0] = v.x; a[1] = v.y; a[2] = a[0] + a[1];\n"
                "  float3x3 n = (float3x3)M; float2x2 t = (float2x2)M;\n"
                "  return float4(isfinite(v)) + isfinite(s) + determinant(M) + n[1].x + t[1].y + a[2]; }\n", ALL));
}

static void matrices(void) {
    CHECK(links("float4x4 M; float3x3 N; float4x3 R; float3x4 C; float2x2 T;\n"
                "float4 ps(float4 v : TEXCOORD0) : COLOR {\n"
                "  float4 r = mul(v, M) + mul(M, v) + float4(mul(v.xyz, N), 1) + float4(mul(N, v.xyz), 0);\n"
                "  r.xyz += mul(v, R); r += mul(R, v.xyz).xyzz; r += mul(v.xyz, C); r.xyz += mul(C, v);\n"
                "  float4x4 P = mul(M, M) * 2 + M * M - M / 3; float3x3 Q = (float3x3)M; float4x3 S = mul(M, R);\n"
                "  float3x4 Ct = transpose(R);\n"
                "  r += P[2] + Q[1].xyzx + S._m00_m11_m22_m32 + Ct[0] + M._11_22_33_44 + T._m01;\n"
                "  P[1] = v; P._m23 = 2; P[2].x = 1;\n"
                "  float2x2 t2 = float2x2(v.xy, v.zw); t2 += T; t2 *= 2;\n"
                "  float2x2 z = 0; z = 1;\n"
                "  return r + P[1] + mul(v.xy, t2).xyxy + mul(z, v.xy).xyxy + determinant(M) + determinant(N); }\n", MODERN));
}

static void structs_arrays_functions(void) {
    CHECK(links("struct Light { float3 dir; float4 color; int on; };\n"
                "struct Pair { Light a; Light b[2]; };\n"
                "Light lights[3]; Pair pair; int count;\n"
                "static const float weights[3] = { 0.25, 0.5, 0.25 };\n"
                "static float2 offsets[2] = { float2(1, 2), float2(3, 4) };\n"
                "float4 shade(Light l, float3 n) { return l.color * max(dot(l.dir, n), 0); }\n"
                "void accumulate(inout float4 acc, in Light l, float3 n, out int used) { acc += shade(l, n); used = l.on; }\n"
                "Light pick(int i) { return lights[i]; }\n"
                "float4 ps(float3 n : TEXCOORD0, float4 c : COLOR0, float2 vp : VPOS, float face : VFACE) : COLOR {\n"
                "  float4 acc = 0; int used = 0; float local[4] = { 1, 2, 3, 4 };\n"
                "  [unroll] for (int i = 0; i < 3; i++) { accumulate(acc, lights[i], n, used); acc *= weights[i]; }\n"
                "  [loop] for (int j = 0; j < count; j++) { if (lights[j].on == 0) continue; acc += lights[j].color * local[j]; }\n"
                "  acc += shade(pair.a, n) + shade(pair.b[count], n) + pick(1).color;\n"
                "  Light copy = lights[count]; copy.color.rgb = 1; lights[0].color = copy.color;\n"
                "  int k = 0; while (k < 2) { k++; if (k > 5) break; } do { k--; } while (k > 0);\n"
                "  switch (count) { case 0: acc.x = 1; break; case 1: case 2: acc.y = 2; break; default: acc.z = 3; }\n"
                "  return acc + c + used + offsets[1].xyxy + vp.xyxy + face; }\n", MODERN));
}

static void texture_forms(void) {
    CHECK(links("texture t2; texture t3; texture tc;\n"
                "sampler2D s2 = sampler_state { Texture = <t2>; };\n"
                "sampler3D s3 = sampler_state { Texture = <t3>; };\n"
                "samplerCUBE sc = sampler_state { Texture = <tc>; };\n"
                "sampler gen;\n"
                "float4 ps(float4 uv : TEXCOORD0) : COLOR {\n"
                "  float4 r = tex2D(s2, uv.xy) + tex2Dlod(s2, uv) + tex2Dbias(s2, uv) + tex2Dproj(s2, uv)\n"
                "           + tex2Dgrad(s2, uv.xy, ddx(uv.xy), ddy(uv.xy)) + tex2D(s2, uv.xy, uv.zw, uv.wz);\n"
                "  r += tex3D(s3, uv.xyz) + tex3Dlod(s3, uv) + tex3Dbias(s3, uv) + tex3Dproj(s3, uv);\n"
                "  r += texCUBE(sc, uv.xyz) + texCUBElod(sc, uv) + texCUBEbias(sc, uv) + texCUBEproj(sc, uv);\n"
                "  r += tex2D(gen, uv.xy);\n"
                "  return r; }\n", MODERN));
}

static void sampler_parameters_and_odd_shapes(void) {
    CHECK(links("texture t; sampler2D s = sampler_state { Texture = <t>; }; uint u; float1 one;\n"
                "float4 fetch(sampler2D from, float2 uv) { return tex2D(from, uv); }\n"
                "float4 ps(float2 uv : TEXCOORD0) : COLOR {\n"
                "  float4 r = fetch(s, uv);\n"
                "  switch (u) { case 1u: r.x = one[0]; break; default: r.y = one.x; }\n"
                "  float1x4 row = float1x4(r); float4x1 col = float4x1(r);\n"
                "  r += row[0] + col._m10 + row._m03;\n"
                "  return r; }\n", MODERN));
}

static void vertex_texture_fetch_and_outputs(void) {
    const char *src =
        "texture h; sampler2D hs = sampler_state { Texture = <h>; };\n"
        "struct VOut { float4 pos : POSITION; float4 c : COLOR1; float psize : PSIZE; float fog : FOG; float2 uv : TEXCOORD3; };\n"
        "VOut vs(float3 p : POSITION, float4 bw : BLENDWEIGHT, int4 bi : BLENDINDICES, float3 t : TANGENT, float3 b : BINORMAL)\n"
        "{ VOut o; o.pos = float4(p, 1) + tex2Dlod(hs, float4(p.xy, 0, 0)) + bw + bi; o.c = float4(t + b, 1);\n"
        "  o.psize = 1; o.fog = 0; o.uv = p.xy; return o; }\n"
        "void ps(float4 c : COLOR1, float2 uv : TEXCOORD3, float4 unwritten : TEXCOORD5, out float4 o0 : COLOR0,\n"
        "        out float4 o1 : COLOR1, out float d : DEPTH) { o0 = c + unwritten; o1 = uv.xyxy; d = 0.5; }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n";
    hfxc_options o = {0};
    o.targets = ALL & ~(1u << HFX_TARGET_GLSL110);
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "v.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx && fx->program_count == 1);
    if (fx && fx->program_count == 1) {
        const hfx_fx_program *p = &fx->programs[0];
        char *log = NULL;
        int ok = test_glsl_link(p->code[0][HFX_TARGET_GLSL330].data, p->code[1][HFX_TARGET_GLSL330].data, &log);
        if (!ok) fprintf(stderr, "%s\n%s\n", log, p->code[0][HFX_TARGET_GLSL330].data);
        CHECK(ok);
        free(log);
        /* Cg locations: POSITION0 0, BLENDWEIGHT0 1, BLENDINDICES0 7, TANGENT0 14, BINORMAL0 15 */
        CHECK_INT(p->attribute_count, 5);
        static const char *const sem[] = { "POSITION0", "BLENDWEIGHT0", "BLENDINDICES0", "TANGENT0", "BINORMAL0" };
        static const int loc[] = { 0, 1, 7, 14, 15 };
        for (uint32_t i = 0; i < p->attribute_count && i < 5; i++) {
            CHECK_STR(p->attributes[i].semantic, sem[i]);
            CHECK_INT(p->attributes[i].location, loc[i]);
        }
        CHECK_CONTAINS(p->code[0][HFX_TARGET_GLSL330].data, "hfx_v_TEXCOORD5 = vec4(0.0);");
        CHECK_CONTAINS(p->code[0][HFX_TARGET_GLSL330].data, "gl_PointSize = float(hfx_ret.psize);");
        CHECK_CONTAINS(p->code[1][HFX_TARGET_GLSL330].data, "gl_FragDepth = float(hfx_arg5);");
        CHECK_INT(p->sampler_count, 1);
    }
    hfxc_result_free(r);
}

/* lower/flatten.c: an if / else that only picks a local's value is a select, as fxc flattens
 * it; not with [branch], a texture read, an integer division, two variables, or a big value. */
static void small_branches_flatten(void) {
    static const char body[] = "float4 v; int n, m; sampler2D S;\n"
        "float4 ps(float2 uv : TEXCOORD0) : COLOR { float a = 0, b = 1, c = 0, e = 0, f = 0; int d = 0;\n"
        "  if (v.x <= v.y) a = min(1 / (v.z + v.w * uv.x), 1); else a = 0;\n"
        "  if (uv.y > 0.5) b = v.x;\n"
        "  [branch] if (uv.x > 0.5) c = v.y; else c = v.z;\n"
        "  if (uv.x > 0.25) c = tex2D(S, uv).x;\n"
        "  if (m != 0) d = n / m;\n"
        "  if (uv.y > 0.25) e = 1; else f = 1;\n"
        "  if (uv.x > 0.75) e = sin(v.x) * cos(v.y) + sin(v.z) * cos(v.w) + sin(uv.x) * cos(uv.y) + v.x * v.y * v.z;\n"
        "  return float4(a, b, c, d) + e + f; }\n";
    CHECK(links(body, ALL));
    hfxc_result *r = NULL;
    const char *fs = fragment_330(body, &r);
    if (fs) {
        CHECK_CONTAINS(fs, "    a = v.x <= v.y ? min(1.0 / (v.z + v.w * uv.x), 1.0) : 0.0;\n");
        CHECK_CONTAINS(fs, "    b = uv.y > 0.5 ? v.x : b;\n");
        CHECK_CONTAINS(fs, "if (uv.x > 0.5)");
        CHECK_CONTAINS(fs, "if (uv.x > 0.25)");
        CHECK_CONTAINS(fs, "if (m != 0)");
        CHECK_CONTAINS(fs, "if (uv.y > 0.25)");
        CHECK_CONTAINS(fs, "if (uv.x > 0.75)");
    }
    hfxc_result_free(r);
}

/* lower/distances.c: distance(p, L) where the function also computes L - p is length(L - p),
 * which the driver shares with normalize(L - p); without L - q or with p - q nowhere it stays. */
static void distances_share_the_difference(void) {
    static const char body[] = "float3 L;\n"
        "float4 ps(float3 p : TEXCOORD0, float3 q : TEXCOORD1) : COLOR {\n"
        "  float3 d = normalize(L - p);\n"
        "  return float4(d, distance(p, L) + distance(q, L) + distance(p, q) + distance(q, p + 1)); }\n";
    CHECK(links(body, ALL));
    hfxc_result *r = NULL;
    const char *fs = fragment_330(body, &r);
    if (fs) {
        CHECK_CONTAINS(fs, "return vec4(d, length(L - p) + distance(q, L) + distance(p, q) + distance(q, p + vec3(1.0)));\n");
    }
    hfxc_result_free(r);
}

/* A generic sampler takes the dimension of the parameter it is passed to, and a call with
 * constant arguments compiles only the branch they select (fxc inlines calls): the tex2D
 * branch, which would make the same sampler 2D too, is gone from F(1)'s copy. DigitalRise's
 * VolumetricLight.fx and CubeMapShadowMask.fx. */
static void constant_arguments_select_the_code(void) {
    CHECK(links("texture t; sampler s = sampler_state { Texture = <t>; };\n"
                "float4 cube(samplerCUBE c, float3 d) { return texCUBE(c, d); }\n"
                "float4 F(float3 d, int mode) { if (mode == 1) return cube(s, d); return tex2D(s, d.xy); }\n"
                "float4 ps(float3 d : TEXCOORD0) : COLOR { return F(d, 1); }\n", MODERN));
    CHECK(links("texture t; sampler s = sampler_state { Texture = <t>; };\n"
                "static const int Mode = 2;\n"
                "float4 G(float2 uv, int mode, float k) { if (mode == 2) return tex2D(s, uv) * k; return texCUBE(s, uv.xyx); }\n"
                "float4 ps(float2 uv : TEXCOORD0) : COLOR { return G(uv, Mode, 2) + G(uv * 2, Mode, 2); }\n", MODERN));
}

int main(void) {
    RUN(float_intrinsics);
    RUN(pow_constant_integer_powers);
    RUN(pow_of_a_nonnegative_base);
    RUN(integer_and_bool_ops);
    RUN(integer_intrinsics_in_glsl110);
    RUN(vector_isnan_isinf_in_glsl110);
    RUN(more_glsl110_forms);
    RUN(matrices);
    RUN(structs_arrays_functions);
    RUN(texture_forms);
    RUN(sampler_parameters_and_odd_shapes);
    RUN(vertex_texture_fetch_and_outputs);
    RUN(constant_arguments_select_the_code);
    RUN(small_branches_flatten);
    RUN(distances_share_the_difference);
    return test_summary();
}
