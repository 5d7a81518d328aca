/* test_glsl_errors.c: what GLSL cannot express is a located error, never a crash; and the
 * entry point's interface rules (missing semantics) follow fxc. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "hfx/hfxc.h"
#include "test.h"

static char *diagnostics(const char *src) {
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "e.fx", NULL);
    char *d = hfxc_diagnostics_text(r);
    CHECK(!hfxc_result_ok(r));
    hfxc_result_free(r);
    return d;
}

#define VS "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"

static void noise_is_reported(void) {
    char *d = diagnostics(VS "float4 ps(float2 uv : TEXCOORD0) : COLOR { return noise(uv); }\n"
                          "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n");
    CHECK_CONTAINS(d, "e.fx(2,51): error X3094: 'noise': intrinsic is not supported in shaders");
    free(d);
}

static void asm_block_is_reported(void) {
    char *d = diagnostics(VS "float4 ps() : COLOR { asm { mov r0, c0 }; return 1; }\n"
                          "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n");
    CHECK_CONTAINS(d, "e.fx(2,23): error X3094: asm blocks are not supported");
    free(d);
}

static void missing_input_semantic(void) {
    char *d = diagnostics(VS "float4 ps(float2 uv) : COLOR { return uv.xyxy; }\n"
                          "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n");
    CHECK_CONTAINS(d, "e.fx(2,18): error X3502: 'ps': input parameter 'uv' missing semantics");
    free(d);
}

static void missing_return_semantic(void) {
    char *d = diagnostics(VS "float4 ps() { return 1; }\n"
                          "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n");
    CHECK_CONTAINS(d, "e.fx(2,8): error X3502: 'ps': function return value missing semantics");
    free(d);
}

/* Found by fuzz/fuzz_diff.c: "COLOR0x" was written as COLOR0 but never declared (X9000). */
static void odd_color_semantic_is_reported(void) {
    char *d = diagnostics(VS "float4 ps() : COLOR0x { return 1; }\n"
                          "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n");
    CHECK_STR(d, "e.fx(2,8): error X4502: invalid ps_3_0 output semantic 'COLOR0X0'\n"); /* fxc's number (ir/lower/model.c) */
    free(d);
}

/* A pass without a pixel shader (fixed function) still gets a program that links. */
static void fixed_function_pixel_stage(void) {
    const char *src = "struct V { float4 p : POSITION; float4 c : COLOR0; };\n"
                      "V vs(float4 p : POSITION) { V o; o.p = p; o.c = float4(1, 0, 0, 1); return o; }\n"
                      "technique T { pass P { VertexShader = compile vs_2_0 vs(); } }\n";
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "f.fx", NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx && fx->program_count == 1);
    if (fx && fx->program_count == 1) {
        const char *fs = fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data;
        const char *vs = fx->programs[0].code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data;
        CHECK_CONTAINS(fs, "hfx_o_COLOR0 = hfx_v_COLOR0;");
        /* vs_2_0 colour outputs saturate like oD0 */
        CHECK_CONTAINS(vs, "hfx_v_COLOR0 = clamp(hfx_ret.c, 0.0, 1.0);");
    }
    hfxc_result_free(r);
}

/* GLSL 110 has no non-square matrices and no integer bit operations: asked for that target,
 * such a shader is a located error instead of GLSL that does not compile. */
static void glsl110_limits_are_reported(void) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL110;
    const char *src = VS "float3x4 M; int k;\n"
                      "float4 ps(float3 v : TEXCOORD0) : COLOR { return mul(M, float4(v, 1)).xyzz + (k << 1); }\n"
                      "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n";
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "l.fx", &o);
    char *d = hfxc_diagnostics_text(r);
    CHECK(!hfxc_result_ok(r));
    CHECK_CONTAINS(d, "l.fx(3,81): error X3094: integer bit operations are not available in GLSL 110");
    CHECK_CONTAINS(d, "l.fx(3,8): error X3094: 'ps': non-square matrices are not available in GLSL 110");
    free(d);
    hfxc_result_free(r);
}

/* Found by fuzz/fuzz_diff.c (glslang refused what the 110 printer made): a switch, tex2Dlod in
 * a pixel shader and an array initializer are located errors for GLSL 110 now. */
static void glsl110_switch_lod_and_array_constructors(void) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL110;
    const char *src = VS "sampler S; int k;\n"
                      "float4 ps(float2 uv : TEXCOORD0) : COLOR { float w[2] = {1, 2}; float4 c = tex2Dlod(S, float4(uv, 0, 0));\n"
                      "  switch (k) { case 1: c *= 2; break; default: break; } return c * w[k]; }\n"
                      "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n";
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "l.fx", &o);
    char *d = hfxc_diagnostics_text(r);
    CHECK(!hfxc_result_ok(r));
    CHECK_CONTAINS(d, "l.fx(3,57): error X3094: array initializers and constructors need GLSL 330 or ES 300");
    CHECK_CONTAINS(d, "l.fx(3,76): error X3094: tex*Dlod in a pixel shader needs GLSL 330 or ES 300");
    CHECK_CONTAINS(d, "l.fx(4,3): error X3094: switch statements need GLSL 330 or ES 300");
    CHECK(!strstr(d, "X9000"));
    free(d);
    hfxc_result_free(r);
}

int main(void) {
    RUN(noise_is_reported);
    RUN(asm_block_is_reported);
    RUN(missing_input_semantic);
    RUN(missing_return_semantic);
    RUN(odd_color_semantic_is_reported);
    RUN(fixed_function_pixel_stage);
    RUN(glsl110_limits_are_reported);
    RUN(glsl110_switch_lod_and_array_constructors);
    return test_summary();
}
