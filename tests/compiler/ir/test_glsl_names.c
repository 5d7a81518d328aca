/* test_glsl_names.c: HLSL names are kept in the GLSL unless GLSL reserves them, and effects
 * using such names still give GLSL that glslang accepts. */
#include <stdlib.h>
#include <string.h>

#include "ir/ir.h"
#include "effect.h"
#include "glsl_check.h"
#include "hfx/hfxc.h"
#include "test.h"

static void reserved_names_are_prefixed(void) {
    hfx_arena a;
    hfx_arena_init(&a);
    CHECK_STR(hfx_glsl_name(&a, "colorMaterialAmbiental"), "colorMaterialAmbiental");
    CHECK_STR(hfx_glsl_name(&a, "input"), "hfx_input");
    CHECK_STR(hfx_glsl_name(&a, "texture"), "hfx_texture");
    CHECK_STR(hfx_glsl_name(&a, "mix"), "hfx_mix");
    CHECK_STR(hfx_glsl_name(&a, "dFdx"), "hfx_dFdx");
    CHECK_STR(hfx_glsl_name(&a, "sample"), "hfx_sample");
    CHECK_STR(hfx_glsl_name(&a, "main"), "hfx_main");
    CHECK_STR(hfx_glsl_name(&a, "gl_Thing"), "hfx_gl_Thing");
    CHECK_STR(hfx_glsl_name(&a, "a__b"), "hfx_a__b");
    CHECK_STR(hfx_glsl_name(&a, "hfx_x"), "hfx_hfx_x");
    CHECK_STR(hfx_glsl_name(&a, "Texture"), "Texture"); /* GLSL is case-sensitive */
    CHECK_STR(hfx_glsl_name(&a, "zzz"), "zzz");
    CHECK_STR(hfx_glsl_name(&a, "abs"), "hfx_abs");
    CHECK_STR(hfx_glsl_name(&a, "writeonly"), "hfx_writeonly");
    hfx_arena_free(&a);
}

static void effect_with_glsl_keywords_links(void) {
    const char *src =
        "float4 input; float mix = 0.5; struct S { float4 active; float smooth; };\n"
        "S flat;\n"
        "float4 fract(float4 layout) { float4 output = layout * mix; return output + flat.active; }\n"
        "float4 main(float4 p : POSITION) : POSITION { float precision = 1; return p * precision; }\n"
        "float4 ps(float2 uv : TEXCOORD0) : COLOR { float4 lowp = input; return fract(lowp) + flat.smooth; }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 main(); PixelShader = compile ps_3_0 ps(); } }\n";
    hfxc_options o = {0};
    o.targets = (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300);
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "k.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx && fx->program_count == 1);
    if (fx && fx->program_count == 1) {
        for (int t = 0; t < 2; t++) {
            int target = t ? HFX_TARGET_GLSLES300 : HFX_TARGET_GLSL330;
            char *log = NULL;
            int ok = test_glsl_link(fx->programs[0].code[0][target].data, fx->programs[0].code[1][target].data, &log);
            if (!ok) fprintf(stderr, "%s\n%s\n%s\n", log, fx->programs[0].code[0][target].data, fx->programs[0].code[1][target].data);
            CHECK(ok);
            free(log);
        }
        CHECK_CONTAINS(fx->programs[0].code[1][HFX_TARGET_GLSL330].data, "uniform vec4 hfx_input;");
        CHECK_CONTAINS(fx->programs[0].code[1][HFX_TARGET_GLSL330].data, "vec4 hfx_fract(vec4 hfx_layout)");
    }
    hfxc_result_free(r);
}

int main(void) {
    RUN(reserved_names_are_prefixed);
    RUN(effect_with_glsl_keywords_links);
    return test_summary();
}
