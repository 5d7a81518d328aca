/* The Vulkan SPIR-V target (HFX_TARGET_SPIRV_VK): every good seed compiles for it, each module is
 * valid for Vulkan 1.0 (spirv-tools, when present), and the rewritten GLSL has the layout the
 * runtime relies on: one std140 block at set 0 binding 0 shared by both stages, samplers from
 * binding 1 in the program's order, explicit varying locations, no GL depth remap. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "glsl/spirv.h"
#include "hfx/hfxc.h"
#include "test.h"

#if defined(__has_include)
#if __has_include(<spirv-tools/libspirv.h>)
#include <spirv-tools/libspirv.h>
#define HAVE_SPIRV_TOOLS 1
#endif
#endif

static const char *const good_seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
    "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
    "spot_specular.fx", "tutorial0.fx",
};

static int valid_for_vulkan(const hfx_fx_code *c, const char *what) {
#ifdef HAVE_SPIRV_TOOLS
    spv_context ctx = spvContextCreate(SPV_ENV_VULKAN_1_0);
    spv_const_binary_t bin = {(const uint32_t *)(const void *)c->data, c->size / 4};
    spv_diagnostic diag = NULL;
    spv_result_t rc = spvValidate(ctx, &bin, &diag);
    if (rc != SPV_SUCCESS) fprintf(stderr, "%s: %s\n", what, diag && diag->error ? diag->error : "invalid");
    spvDiagnosticDestroy(diag);
    spvContextDestroy(ctx);
    return rc == SPV_SUCCESS;
#else
    (void)what;
    return c->size >= 20 && ((const uint32_t *)(const void *)c->data)[0] == HFX_SPIRV_MAGIC;
#endif
}

static void every_seed_compiles_for_vulkan(void) {
    for (size_t i = 0; i < sizeof good_seeds / sizeof *good_seeds; i++) {
        char *path = test_seed_path(good_seeds[i]);
        hfxc_options o = {0};
        o.targets = 1u << HFX_TARGET_SPIRV_VK;
        hfxc_result *r = hfxc_compile_file(path, &o);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        for (uint32_t p = 0; fx && p < fx->program_count; p++)
            for (int s = 0; s < HFX_STAGE_COUNT; s++) {
                CHECK(fx->programs[p].code[s][HFX_TARGET_SPIRV_VK].data != NULL);
                CHECK(fx->programs[p].code[s][HFX_TARGET_GLSL330].data == NULL); /* not asked for */
                if (fx->programs[p].code[s][HFX_TARGET_SPIRV_VK].data)
                    CHECK(valid_for_vulkan(&fx->programs[p].code[s][HFX_TARGET_SPIRV_VK], good_seeds[i]));
            }
        hfxc_result_free(r);
        free(path);
    }
}

static const char *SRC =
    "float4x4 WVP; float4 Tint; int Count; float3 Lights[3];\n"
    "texture Tex; sampler S = sampler_state { Texture = <Tex>; };\n"
    "struct V { float4 p : POSITION; float2 uv : TEXCOORD0; };\n"
    "V VS(V v) { v.p = mul(v.p, WVP); return v; }\n"
    "float4 PS(float2 uv : TEXCOORD0) : COLOR { float4 c = tex2D(S, uv) * Tint;\n"
    "  for (int i = 0; i < Count; i++) c.rgb += Lights[i]; return c; }\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

static void rewritten_glsl_has_the_vulkan_layout(void) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    o.flags = HFXC_PACK_UNIFORMS;
    hfxc_result *r = hfxc_compile_memory(SRC, strlen(SRC), "vk.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        char *vs = hfx_spirv_vk_glsl(fx, &fx->programs[0], HFX_STAGE_VERTEX);
        char *ps = hfx_spirv_vk_glsl(fx, &fx->programs[0], HFX_STAGE_FRAGMENT);
        CHECK_CONTAINS(vs, "#version 450 core");
        CHECK_CONTAINS(vs, "layout(std140, set = 0, binding = 0) uniform hfx_block");
        CHECK_CONTAINS(ps, "layout(std140, set = 0, binding = 0) uniform hfx_block");
        CHECK_CONTAINS(ps, "layout(set = 0, binding = 1) uniform sampler2D");
        CHECK_CONTAINS(vs, "layout(location = 0) out vec4 hfx_v_TEXCOORD0;");
        CHECK_CONTAINS(ps, "layout(location = 0) in vec4 hfx_v_TEXCOORD0;");
        CHECK(vs && !strstr(vs, "gl_Position.z = gl_Position.z * 2.0"));
        /* both stages declare the same block: the pixel stage's Count and Lights are in the vertex one too */
        const char *b1 = vs ? strstr(vs, "uniform hfx_block") : NULL, *b2 = ps ? strstr(ps, "uniform hfx_block") : NULL;
        CHECK(b1 && b2 && strncmp(b1, b2, (size_t)(strchr(b1, '}') - b1)) == 0);
        free(vs);
        free(ps);
    }
    hfxc_result_free(r);
}

int main(void) {
    RUN(rewritten_glsl_has_the_vulkan_layout);
    test_require_seeds();
    RUN(every_seed_compiles_for_vulkan);
    return test_summary();
}
