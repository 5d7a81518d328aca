/* The Vulkan SPIR-V target (HFX_TARGET_SPIRV_VK): every good seed compiles for it, each module is
 * valid for Vulkan 1.0 (spirv-tools, when present), and the modules have the layout the runtime
 * relies on: one std140 block shared by both stages, samplers from binding 1 in the program's
 * order, explicit varying locations (tests/runtime/vk draw with Vulkan's depth, no GL remap). */
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

enum { OP_NAME = 5, OP_MEMBER_NAME = 6 };

/* The member names of the struct type OpName'd `type` in a module, ", "-separated into out. */
static void member_names(const hfx_fx_code *c, const char *type, char *out, size_t size) {
    const uint32_t *w = (const uint32_t *)(const void *)c->data;
    size_t n = c->size / 4, used = 0;
    uint32_t id = 0;
    out[0] = 0;
    for (size_t i = 5; i < n && (w[i] >> 16);) {
        uint32_t len = w[i] >> 16, op = w[i] & 0xffffu;
        if (i + len > n) break;
        if (op == OP_NAME && len >= 3 && strcmp((const char *)&w[i + 2], type) == 0) id = w[i + 1];
        if (op == OP_MEMBER_NAME && len >= 4 && id && w[i + 1] == id && used + 1 < size)
            used += (size_t)snprintf(out + used, size - used, "%s%s", used ? ", " : "", (const char *)&w[i + 3]);
        i += len;
    }
}

/* The printer's Vulkan mode, read back from the modules: one block of both stages' loose
 * uniforms, the sampler at binding 1, the varyings at matching locations. */
static void modules_have_the_vulkan_layout(void) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_SPIRV_VK;
    o.flags = HFXC_PACK_UNIFORMS;
    hfxc_result *r = hfxc_compile_memory(SRC, strlen(SRC), "vk.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_code *vs = &fx->programs[0].code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV_VK];
        const hfx_fx_code *ps = &fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV_VK];
        const uint32_t *vw = (const uint32_t *)(const void *)vs->data, *pw = (const uint32_t *)(const void *)ps->data;
        int32_t loc, binding;
        CHECK_INT(hfx_spirv_find(pw, ps->size / 4, "S", &loc, &binding), 1);
        CHECK_INT(binding, 1);
        CHECK_INT(hfx_spirv_find(vw, vs->size / 4, "hfx_v_TEXCOORD0", &loc, NULL), 1);
        CHECK_INT(loc, 0);
        CHECK_INT(hfx_spirv_find(pw, ps->size / 4, "hfx_v_TEXCOORD0", &loc, NULL), 1);
        CHECK_INT(loc, 0);
        /* both stages declare the same block: the pixel stage's Count and Lights are in the vertex
         * one too; WVP and Tint are packed (hfx_c), Count and Lights are not (an int, a dynamic index) */
        char vm[256], pm[256];
        member_names(vs, "hfx_block", vm, sizeof vm);
        member_names(ps, "hfx_block", pm, sizeof pm);
        CHECK_STR(vm, "hfx_c, hfx_pos_fixup, Count, Lights");
        CHECK_STR(pm, vm);
    }
    hfxc_result_free(r);
}

int main(void) {
    RUN(modules_have_the_vulkan_layout);
    test_require_seeds();
    RUN(every_seed_compiles_for_vulkan);
    return test_summary();
}
