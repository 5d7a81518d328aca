/* test_model.c: what a shader model refuses (compiler/ir/lower/model.c), with fxc's numbers and
 * the HLSL positions: semantics the model has no register for (X4502, from D3D9's register
 * pages: ps_2_0 reads v0-v1 / t0-t7 only), and [unroll] loops fxc cannot unroll (X3511). */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hfx/hfxc.h"
#include "test.h"

/* The diagnostics of compiling src; ok says whether the compile must succeed. */
static char *compile(const char *src, bool ok) {
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "m.fx", NULL);
    char *d = hfxc_diagnostics_text(r);
    CHECK(hfxc_result_ok(r) == ok);
    if (hfxc_result_ok(r) != ok) fprintf(stderr, "%s", d);
    hfxc_result_free(r);
    return d;
}

static void expect_error(const char *src, const char *line) {
    char *d = compile(src, false);
    CHECK_CONTAINS(d, line);
    free(d);
}

static void expect_ok(const char *src) { free(compile(src, true)); }

#define VS "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"
#define PASS(vsp, psp) "technique T { pass P { VertexShader = compile " vsp " vs(); PixelShader = compile " psp " ps(); } }\n"

/* ps_2_0's inputs are the colour and texture coordinate registers: a FOG input it reads has none. */
static void ps2_reads_fog(void) {
    expect_error(VS "float4 ps(float f : FOG) : COLOR { return f; }\n" PASS("vs_2_0", "ps_2_0"),
                 "m.fx(2,17): error X4502: invalid ps_2_0 input semantic 'FOG0'");
    expect_error(VS "float4 ps(float s : PSIZE) : COLOR { return s; }\n" PASS("vs_2_0", "ps_2_0"),
                 "m.fx(2,17): error X4502: invalid ps_2_0 input semantic 'PSIZE0'");
    expect_error(VS "float4 ps(float2 v : VPOS) : COLOR { return v.xyxy; }\n" PASS("vs_2_0", "ps_2_0"),
                 "m.fx(2,18): error X4502: invalid ps_2_0 input semantic 'VPOS0'"); /* VPOS is ps_3_0's */
    expect_error(VS "float4 ps(float4 c : COLOR2) : COLOR { return c; }\n" PASS("vs_2_0", "ps_2_0"),
                 "m.fx(2,18): error X4502: invalid input semantic 'COLOR2': Legal indices are in [0,1]");
    expect_error(VS "float4 ps(float4 t : TEXCOORD8) : COLOR { return t; }\n" PASS("vs_2_0", "ps_2_0"),
                 "m.fx(2,18): error X4502: invalid input semantic 'TEXCOORD8': Legal indices are in [0,7]");
}

/* The vertex shader's output struct as the pixel input: its POSITION is fine while unread. */
static void ps2_position_only_when_read(void) {
    const char *decl = "struct V { float4 p : POSITION; float2 uv : TEXCOORD0; };\n"
                       "V vs(float4 p : POSITION) { V o; o.p = p; o.uv = p.xy; return o; }\n";
    char src[1024];
    snprintf(src, sizeof src, "%sfloat4 ps(V i) : COLOR { return i.uv.xyxy; }\n%s", decl, PASS("vs_2_0", "ps_2_0"));
    expect_ok(src);
    snprintf(src, sizeof src, "%sfloat4 ps(V i) : COLOR { return i.p; }\n%s", decl, PASS("vs_2_0", "ps_2_0"));
    expect_error(src, "m.fx(1,19): error X4502: invalid ps_2_0 input semantic 'POSITION0'");
    /* the struct handed to a function: the members it reads (fxc inlines the call) */
    snprintf(src, sizeof src, "%sfloat4 f(V v) { return v.uv.xyxy; }\nfloat4 ps(V i) : COLOR { return f(i); }\n%s", decl,
             PASS("vs_2_0", "ps_2_0"));
    expect_ok(src);
    snprintf(src, sizeof src, "%sfloat4 g(V v) { return v.p; }\nfloat4 f(V v) { return g(v) + v.uv.x; }\n"
             "float4 ps(V i) : COLOR { return f(i); }\n%s", decl, PASS("vs_2_0", "ps_2_0"));
    expect_error(src, "m.fx(1,19): error X4502: invalid ps_2_0 input semantic 'POSITION0'");
}

/* ps_3_0 declares its inputs with any usage (dcl_usage), except the position's POSITION0. */
static void ps3_inputs(void) {
    expect_ok("struct V { float4 p : POSITION; float f : FOG; float3 n : NORMAL; };\n"
              "V vs(float4 p : POSITION) { V o; o.p = p; o.f = p.x; o.n = p.xyz; return o; }\n"
              "float4 ps(float f : FOG, float3 n : NORMAL) : COLOR { return float4(n, f); }\n" PASS("vs_3_0", "ps_3_0"));
    expect_error(VS "float4 ps(float4 p : POSITION) : COLOR { return p; }\n" PASS("vs_3_0", "ps_3_0"),
                 "m.fx(2,18): error X4502: invalid input semantic 'POSITION0': Legal indices are in [1,15]");
}

/* Pixel outputs are oC0-oC3 and oDepth; vs_2_0's outputs oPos, oPts, oFog, oD0-1, oT0-7. */
static void outputs(void) {
    expect_error(VS "float4 ps() : TEXCOORD0 { return 1; }\n" PASS("vs_3_0", "ps_3_0"),
                 "m.fx(2,8): error X4502: invalid ps_3_0 output semantic 'TEXCOORD0'");
    expect_error(VS "float4 ps() : COLOR4 { return 1; }\n" PASS("vs_3_0", "ps_3_0"),
                 "m.fx(2,8): error X4502: invalid output semantic 'COLOR4': Legal indices are in [0,3]");
    const char *vs_normal = "struct V { float4 p : POSITION; float3 n : NORMAL; };\n"
                            "V vs(float4 p : POSITION) { V o; o.p = p; o.n = p.xyz; return o; }\n"
                            "float4 ps() : COLOR { return 1; }\n";
    char src[1024];
    snprintf(src, sizeof src, "%s%s", vs_normal, PASS("vs_2_0", "ps_2_0"));
    expect_error(src, "m.fx(1,40): error X4502: invalid vs_2_0 output semantic 'NORMAL0'");
    snprintf(src, sizeof src, "%s%s", vs_normal, PASS("vs_3_0", "ps_3_0"));
    expect_ok(src); /* vs_3_0's output registers take any usage */
    expect_ok("struct V { float4 p : POSITION; float s : PSIZE; float f : FOG; float4 c : COLOR1; float4 t : TEXCOORD7; };\n"
              "V vs(float4 p : POSITION) { V o = (V)0; o.p = p; return o; }\n"
              "float4 ps() : COLOR3 { return 1; }\n" PASS("vs_2_0", "ps_2_0"));
}

#define LOOP_PS(attr, bound, body) \
    "int N; float4 ps() : COLOR {\n float s = 0;\n " attr " for (int i = 0; i < " bound "; i++) { " body " }\n return s;\n}\n"

/* [unroll] needs a count fxc can find: a constant bound within 1024 iterations, or [unroll(n)]. */
static void unroll_needs_a_count(void) {
    expect_error(VS LOOP_PS("[unroll]", "N", "s += 1;") PASS("vs_3_0", "ps_3_0"),
                 "m.fx(4,11): error X3511: unable to unroll loop, loop does not appear to terminate in a timely manner (1024 iterations)");
    expect_error(VS LOOP_PS("[unroll]", "2000", "s += i;") PASS("vs_3_0", "ps_3_0"), "m.fx(4,11): error X3511:");
    expect_ok(VS LOOP_PS("[unroll(4)]", "N", "s += 1;") PASS("vs_3_0", "ps_3_0"));
    expect_ok(VS LOOP_PS("[unroll]", "8", "s += 1;") PASS("vs_3_0", "ps_3_0"));
    expect_ok(VS LOOP_PS("[loop]", "N", "s += 1;") PASS("vs_3_0", "ps_3_0"));
    expect_ok(VS LOOP_PS("", "N", "s += 1;") PASS("vs_3_0", "ps_3_0"));
    /* a break could end it at a constant count: left to fxc's judgement, accepted */
    expect_ok(VS LOOP_PS("[unroll]", "N", "if (i > 4) break; s += 1;") PASS("vs_3_0", "ps_3_0"));
}

/* A local sampler names a sampler register: declared without one and read, it is fxc's X4000
 * (Microsoft's list of HLSL errors and warnings: "the specified variable is used without having
 * been completely initialized"), at the read; one set where it is declared reads as its value. */
static void local_samplers(void) {
    const char *g = "texture T; sampler2D G = sampler_state { Texture = <T>; };\n";
    char src[1024];
    snprintf(src, sizeof src, "%s" VS "float4 ps(float2 uv : TEXCOORD0) : COLOR { sampler2D s; return tex2D(s, uv); }\n%s", g,
             PASS("vs_2_0", "ps_2_0"));
    expect_error(src, "m.fx(3,70): error X4000: variable 's' used without having been completely initialized");
    snprintf(src, sizeof src, "%s" VS "float4 ps(float2 uv : TEXCOORD0) : COLOR { sampler2D s = G; sampler2D u; return tex2D(s, uv); }\n%s",
             g, PASS("vs_2_0", "ps_2_0"));
    expect_ok(src); /* s reads as G; u, never read, is nothing */
}

int main(void) {
    RUN(ps2_reads_fog);
    RUN(ps2_position_only_when_read);
    RUN(ps3_inputs);
    RUN(outputs);
    RUN(unroll_needs_a_count);
    RUN(local_samplers);
    return test_summary();
}
