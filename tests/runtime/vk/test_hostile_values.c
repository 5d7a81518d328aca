/* test_hostile_values.c (Vulkan): the shader-array selector of a hostile .hfxo and a state bound
 * to a parameter set to NaN / infinities, on the Vulkan runtime, with the values Direct3D's rule
 * gives (common/eval.h: truncate, NaN 0, out of range clamps), as tests/runtime/
 * test_hostile_values.c checks them on GL. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "eval_code.h"
#include "hfx/hfxc.h"
#include "states.h"
#include "vk_draw.h"

static test_vk *V;
static const float CLEAR[4] = {0, 0, 0, 1};
static const vk_quad FULL = {-1, -1, 1, 1, 0.5f, 1, 1, 0};

static const char arrays[] =
    "int ShaderIndex = 0;\n"
    "float Sel = 0;\n"
    "static const int PSIndices[4] = {2, 0, 1, 1};\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PSRed() : COLOR { return float4(1, 0, 0, 1); }\n"
    "float4 PSGreen() : COLOR { return float4(0, 1, 0, 1); }\n"
    "float4 PSBlue() : COLOR { return float4(0, 0, 1, 1); }\n"
    "PixelShader PSArray[3] = { compile ps_2_0 PSRed(), compile ps_2_0 PSGreen(), compile ps_2_0 PSBlue() };\n"
    "technique ByTable { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = (PSArray[PSIndices[ShaderIndex]]); } }\n";

/* The .hfxo (SPIR-V for Vulkan) of `arrays` whose PixelShader selector reads the float Sel
 * straight, with no table to clamp it: what a hostile file can hold. */
static void *hostile_hfxo(size_t *size) {
    hfxc_options opt = {0};
    opt.targets = 1u << HFX_TARGET_SPIRV_VK;
    hfxc_result *r = hfxc_compile_memory(arrays, sizeof arrays - 1, "arrays.fx", &opt);
    hfx_fx_effect *fx = hfxc_result_take_effect(r);
    hfxc_result_free(r);
    CHECK(fx != NULL);
    if (!fx) return NULL;
    uint32_t sel = HFX_NONE, patched = 0;
    for (uint32_t i = 0; i < fx->param_count; i++)
        if (!strcmp(fx->params[i].name, "Sel")) sel = fx->params[i].offset;
    uint32_t *exprs = realloc(fx->exprs, (fx->expr_words + 2) * sizeof *exprs);
    if (exprs && sel != HFX_NONE) {
        fx->exprs = exprs;
        exprs[fx->expr_words] = hfx_evc_word(HFX_EVC_PARAM, HFX_EV_FLOAT, 1);
        exprs[fx->expr_words + 1] = sel;
        for (uint32_t i = 0; i < fx->state_count; i++)
            if (fx->states[i].id == HFX_ST_PIXELSHADER && fx->states[i].kind == HFX_FX_VALUE_EXPR) {
                fx->states[i].ref = fx->expr_words;
                fx->states[i].count = 2;
                patched++;
            }
        fx->expr_words += 2;
    }
    CHECK_INT(patched, 1);
    void *out = NULL;
    CHECK(hfx_fx_write_hfxo(fx, &out, size) == 0);
    hfx_fx_effect_free(fx);
    return out;
}

/* Sel truncated by the rule and clamped into the pass's entries 0..2, as D3D9 clamps
 * PSArray[i]: 1e30 and +inf blue (the last), NaN, -inf and -5 red (the first), 1.9 green. */
static void selector_clamped_at_apply(void) {
    size_t size = 0;
    void *bytes = hostile_hfxo(&size);
    char *errors = NULL;
    hfx_effect *fx = bytes ? hfx_effect_load_memory(test_vk_device(V), bytes, size, "hostile.hfxo", NULL, &errors) : NULL;
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : "");
    hfx_free(errors);
    free(bytes);
    CHECK(fx != NULL);
    if (!fx) return;
    static const struct { float sel; unsigned char rgb[3]; } rows[] = {
        {0, {255, 0, 0}}, {1e30f, {0, 0, 255}}, {NAN, {255, 0, 0}}, {INFINITY, {0, 0, 255}},
        {-INFINITY, {255, 0, 0}}, {-5, {255, 0, 0}}, {1.9f, {0, 255, 0}}};
    for (size_t k = 0; k < sizeof rows / sizeof *rows; k++) {
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Sel"), rows[k].sel), HFX_OK);
        CHECK_INT(vk_draw(V, fx, "ByTable", &FULL, 1, CLEAR), 0);
        CHECK_PIXEL(V, 8, 8, rows[k].rgb[0], rows[k].rgb[1], rows[k].rgb[2], 255);
    }
    hfx_effect_destroy(fx);
}

/* `AlphaRef = Ref;` with Ref = NaN is 0, +inf 2147483647 (reference 255 / 255: nothing passes
 * Greater), -inf INT_MIN (reference 0: alpha 0.5 passes), 127.9 is 127 (0.498: passes). */
static void bound_states_at_apply(void) {
    hfx_effect *fx = vk_load(V, "float Ref;\n"
                                "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                                "float4 PS() : COLOR { return float4(1, 1, 1, 0.5); }\n"
                                "technique T { pass P { ZEnable = false; AlphaRef = Ref; AlphaTestEnable = true;"
                                " AlphaFunc = Greater; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n");
    if (!fx) return;
    static const struct { float v; int drawn; } rows[] = { /* the reference is (int & 255) / 255 */
        {NAN, 1}, {INFINITY, 0}, {-INFINITY, 1}, {1e10f, 0}, {127.9f, 1}};
    for (size_t k = 0; k < sizeof rows / sizeof *rows; k++) {
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Ref"), rows[k].v), HFX_OK);
        CHECK_INT(vk_draw(V, fx, "T", &FULL, 1, CLEAR), 0);
        CHECK_PIXEL(V, 8, 8, rows[k].drawn ? 255 : 0, rows[k].drawn ? 255 : 0, rows[k].drawn ? 255 : 0, rows[k].drawn ? 128 : 255);
    }
    hfx_effect_destroy(fx);
}

int main(void) {
    hfx_vertex_layout *layout;
    V = vk_suite_begin(16, 16, &layout);
    RUN(selector_clamped_at_apply);
    RUN(bound_states_at_apply);
    vk_suite_end(V, layout);
    return test_summary();
}
