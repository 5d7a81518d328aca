/* test_fx2.c (Vulkan): an effect compiled by fxc (fx_2_0) loads on a Vulkan device and draws. The
 * binary is hfx's own (`hfxc /T fx_2_0 /Fo`: the source below compiled with its D3D9 bytecode and
 * written by fx2_write.c), so hfx_effect_load_memory goes through the fx_2_0 reader, the bytecode
 * translator and the SPIR-V step compiled sources take (effect/build.c). The pixel shader comes
 * from an array picked by ShaderIndex, as FNA's stock effects pick theirs; the validation layer
 * must stay silent. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "hfx/hfxc.h"
#include "vk_draw.h"

static test_vk *V;
static const float CLEAR[4] = {0, 0, 0, 1};
static const vk_quad FULL = {-1, -1, 1, 1, 0.5f, 1, 1, 0};

static const char source[] =
    "float4 Tint = {0.4, 0.8, 0.2, 1};\n"
    "float Scale = 1;\n"
    "int ShaderIndex = 0;\n"
    "void VS(float4 p : POSITION, float2 uv : TEXCOORD0, out float4 o : POSITION, out float2 t : TEXCOORD0) {\n"
    "    o = p; t = uv; }\n"
    "float4 Scaled(float2 t : TEXCOORD0) : COLOR { return Tint * Scale; }\n"
    "float4 Ramp(float2 t : TEXCOORD0) : COLOR { return float4(t.x, 1 - Tint.g, 0.5, 1); }\n"
    "PixelShader Shaders[2] = { compile ps_2_0 Scaled(), compile ps_2_0 Ramp() };\n"
    "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = (Shaders[ShaderIndex]); } }\n";

/* `source` as fx_2_0 bytes (malloc'ed), *size of them; NULL when hfx could not write it. */
static void *fx2_of_source(size_t *size) {
    hfxc_options opt = {0};
    opt.targets = 1u << HFX_TARGET_GLSL330;
    opt.flags = HFXC_D3D9_BYTECODE; /* what hfxc /T fx_2_0 /Fo asks for */
    hfxc_result *r = hfxc_compile_memory(source, sizeof source - 1, "tint.fx", &opt);
    char *why = NULL;
    void *out = hfxc_result_fx2(r, 0, size, &why);
    if (!out) fprintf(stderr, "tint.fx as fx_2_0: %s\n", why ? why : "");
    free(why);
    hfxc_result_free(r);
    CHECK(out != NULL);
    return out;
}

static hfx_effect *load_fx2(void) {
    size_t size = 0;
    unsigned char *bytes = fx2_of_source(&size);
    if (!bytes) return NULL;
    /* fx_2_0's version token, 0xFEFF0901 little-endian: the loader sees fxc's container, not .hfxo */
    CHECK(size > 4 && bytes[0] == 0x01 && bytes[1] == 0x09 && bytes[2] == 0xff && bytes[3] == 0xfe);
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(test_vk_device(V), bytes, size, "tint.fxo", NULL, &errors);
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : hfx_device_last_error(test_vk_device(V)));
    hfx_free(errors);
    free(bytes);
    CHECK(fx != NULL);
    return fx;
}

/* ShaderIndex 0: Tint * Scale with Scale 0.5 = (0.2, 0.4, 0.1, 0.5), in bytes 51, 102, 25.5,
 * 127.5 (either rounding of the halves is within CHECK_PIXEL's 1/255). */
static void scaled_tint(void) {
    hfx_effect *fx = load_fx2();
    if (!fx) return;
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Scale"), 0.5f), HFX_OK);
    CHECK_INT(vk_draw(V, fx, "T", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 3, 3, 51, 102, 25.5, 127.5);
    CHECK_PIXEL(V, 12, 9, 51, 102, 25.5, 127.5);
    hfx_effect_destroy(fx);
}

/* ShaderIndex 1: (u, 1 - 0.8, 0.5, 1). The quad's u runs 0 to 1 across the 16 pixels and
 * Direct3D 9 puts pixel x's centre at window x (its half-pixel offset, which hfx keeps), so
 * column x samples u = x / 16: x = 2 gives 0.125 (31.875), x = 13 gives 0.8125 (207.19); green
 * 0.2 is 51, blue 127.5. */
static void ramp_by_shader_index(void) {
    hfx_effect *fx = load_fx2();
    if (!fx) return;
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "ShaderIndex"), 1), HFX_OK);
    CHECK_INT(vk_draw(V, fx, "T", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 2, 5, 31.875, 51, 127.5, 255);
    CHECK_PIXEL(V, 13, 5, 207.19, 51, 127.5, 255);
    hfx_effect_destroy(fx);
}

int main(void) {
    hfx_vertex_layout *layout;
    V = vk_suite_begin(16, 16, &layout);
    RUN(scaled_tint);
    RUN(ramp_by_shader_index);
    vk_suite_end(V, layout); /* zero validation messages */
    return test_summary();
}
