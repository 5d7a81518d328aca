/* What real-world effects need of the Vulkan back end, each as the GL one draws it: passes with
 * only a pixel shader (the fixed-function stand-in: positions as clip space, D3D9's depth range),
 * samplers the application gave no texture (bound only by register, or with no `Texture =`:
 * the default (0, 0, 0, 1) of their dimension), cube and volume textures through cube and 3D
 * views, and vertex inputs the layout lacks ((0, 0, 0, 1), as D3D9 gives an element its vertex
 * declaration lacks), and colours written past the target's attachments (dropped). The
 * validation layer must stay silent through all of it. */
#include <stdio.h>

#include "vk_draw.h"

static test_vk *V;

static const float CLEAR[4] = {0.2f, 0.4f, 0.6f, 1.0f};
/* uv (0, 0) .. (1, 1) over the 64 x 64 image: pixel (x, y) samples (x / 64, y / 64). */
static const vk_quad FULL = {-1, -1, 1, 1, 0.5f, 1, 1, 0};

static const char *PIXEL_ONLY =
    "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return float4(uv, 0.25, 1); }\n"
    "technique Null { pass P { VertexShader = NULL; PixelShader = compile ps_2_0 PS(); } }\n"
    "technique Unset { pass P { PixelShader = compile ps_2_0 PS(); } }\n";

/* No vertex shader: D3D9's vertex processing with identity transforms, the position is clip
 * space. Pixel (16, 48): uv (0.25, 0.75), so (0.25, 0.75, 0.25, 1) * 255. A quad at depth -0.5
 * is outside D3D9's 0..1 and clipped: the clear colour stays. */
static void pixel_shader_only(void) {
    hfx_effect *fx = vk_load(V, PIXEL_ONLY);
    if (!fx) return;
    const char *techniques[2] = {"Null", "Unset"};
    for (int i = 0; i < 2; i++) {
        CHECK_INT(vk_draw(V, fx, techniques[i], &FULL, 1, CLEAR), 0);
        CHECK_PIXEL(V, 16, 48, 63.75, 191.25, 63.75, 255);
        CHECK_PIXEL(V, 48, 16, 191.25, 63.75, 63.75, 255);
        const vk_quad behind = {-1, -1, 1, 1, -0.5f, 1, 1, 0};
        CHECK_INT(vk_draw(V, fx, techniques[i], &behind, 1, CLEAR), 0);
        CHECK_PIXEL(V, 16, 48, 51, 102, 153, 255);
    }
    hfx_effect_destroy(fx);
}

static const char *SAMPLERS =
    "sampler2D depthSampler : register(s0);\n"
    "sampler TextureSampler;\n"
    "samplerCUBE Env;\n"
    "sampler3D Vol;\n"
    "float4 Add = float4(0.25, 0.5, 0.75, 0);\n"
    "float3 Dir = float3(1, 0, 0);\n"
    "float W = 0.25;\n"
    "float4 ByRegister(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(depthSampler, uv) + Add; }\n"
    "float4 Plain(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(TextureSampler, uv) + Add; }\n"
    "float4 Cube(float2 uv : TEXCOORD0) : COLOR0 { return texCUBE(Env, Dir) + Add; }\n"
    "float4 Volume(float2 uv : TEXCOORD0) : COLOR0 { return tex3D(Vol, float3(uv, W)) + Add; }\n"
    "textureCUBE EnvT;\n"
    "samplerCUBE EnvLinear = sampler_state { Texture = <EnvT>; MinFilter = Linear; MagFilter = Linear; };\n"
    "float4 Seam(float2 uv : TEXCOORD0) : COLOR0 { return texCUBE(EnvLinear, Dir) + Add; }\n"
    "#define T(name) technique name##T { pass P { PixelShader = compile ps_2_0 name(); } }\n"
    "T(ByRegister) T(Plain) T(Cube) T(Volume) T(Seam)\n";

/* No texture set: every sampler, whatever its dimension, reads (0, 0, 0, 1) as in D3D9 (and on
 * GL, texture object 0), so each technique draws Add + (0, 0, 0, 1). */
static void samplers_without_textures(void) {
    hfx_effect *fx = vk_load(V, SAMPLERS);
    if (!fx) return;
    const char *techniques[4] = {"ByRegisterT", "PlainT", "CubeT", "VolumeT"};
    for (int i = 0; i < 4; i++) {
        CHECK_INT(vk_draw(V, fx, techniques[i], &FULL, 1, CLEAR), 0);
        CHECK_PIXEL(V, 32, 32, 63.75, 127.5, 191.25, 255);
    }
    /* a texture set on the register-bound sampler itself is what it samples */
    static const unsigned char red[4] = {255, 0, 0, 255};
    test_vk_texture tex;
    CHECK(test_vk_texture_make(V, 1, 1, red, &tex));
    CHECK_INT(hfx_param_set_texture_vk(hfx_effect_param(fx, "depthSampler"), tex.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), 0);
    CHECK_INT(vk_draw(V, fx, "ByRegisterT", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 255, 127.5, 191.25, 255);
    hfx_effect_destroy(fx);
    test_vk_texture_free(V, &tex);
}

/* A cube of one texel per face, +X red, -X green, +Y blue, -Y yellow, +Z magenta, -Z cyan: each
 * axis direction reads its face. A volume of two slices, red then green: w = 0.25 and 0.75 are
 * the slices' centres. */
static void cube_and_volume(void) {
    static const unsigned char faces[24] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255,
                                            255, 255, 0, 255, 255, 0, 255, 255, 0, 255, 255, 255};
    static const float dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const float zero[4] = {0, 0, 0, 0};
    hfx_effect *fx = vk_load(V, SAMPLERS);
    if (!fx) return;
    test_vk_texture cube, vol;
    CHECK(test_vk_texture_make_kind(V, TEST_VK_CUBE, 1, 1, 1, 0, faces, &cube));
    CHECK(test_vk_texture_make_kind(V, TEST_VK_3D, 1, 1, 2, 0, faces, &vol)); /* slices red, green */
    CHECK_INT(hfx_param_set_texture_vk(hfx_effect_param(fx, "Env"), cube.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), 0);
    CHECK_INT(hfx_param_set_texture_vk(hfx_effect_param(fx, "Vol"), vol.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), 0);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Add"), zero, 4), 0);
    for (int f = 0; f < 6; f++) {
        CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Dir"), dirs[f], 3), 0);
        CHECK_INT(vk_draw(V, fx, "CubeT", &FULL, 1, CLEAR), 0);
        CHECK_PIXEL(V, 32, 32, faces[4 * f], faces[4 * f + 1], faces[4 * f + 2], 255);
    }
    /* filtered across the face edge, as GL does (tests/runtime/test_texture.c, test_seamless_cube):
     * (1, 0.8, 0) is on +X at t = 0.1, 0.6 of +X's texel and 0.4 of +Y's: (153, 0, 102) */
    static const float seam[3] = {1, 0.8f, 0};
    CHECK_INT(hfx_param_set_texture_vk(hfx_effect_param(fx, "EnvT"), cube.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), 0);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Dir"), seam, 3), 0);
    CHECK_INT(vk_draw(V, fx, "SeamT", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 153, 0, 102, 255);
    CHECK_INT(vk_draw(V, fx, "VolumeT", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 255, 0, 0, 255);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "W"), 0.75f), 0);
    CHECK_INT(vk_draw(V, fx, "VolumeT", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 0, 255, 0, 255);
    hfx_effect_destroy(fx);
    test_vk_texture_free(V, &cube);
    test_vk_texture_free(V, &vol);
}

static const char *MISSING_INPUTS =
    "struct VO { float4 p : POSITION; float4 c : COLOR0; float4 t : TEXCOORD1; float4 w : TEXCOORD2; };\n"
    "VO VS(float4 p : POSITION, float4 c : COLOR0, float4 t3 : TEXCOORD3, float4 bw : BLENDWEIGHT) {\n"
    "  VO o; o.p = p; o.c = c; o.t = t3; o.w = bw; return o; }\n"
    "float4 Color(float4 c : COLOR0) : COLOR0 { return c * 0.5 + 0.25; }\n"
    "float4 Tex(float4 t : TEXCOORD1) : COLOR0 { return t * 0.5 + 0.25; }\n"
    "float4 Weight(float4 w : TEXCOORD2) : COLOR0 { return w * 0.5 + 0.25; }\n"
    "#define T(name) technique name##T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 name(); } }\n"
    "T(Color) T(Tex) T(Weight)\n";

/* The layout has POSITION and TEXCOORD0 only: COLOR0, TEXCOORD3 and BLENDWEIGHT read
 * (0, 0, 0, 1), so each pass draws (0.25, 0.25, 0.25, 0.75). */
static void missing_inputs(void) {
    hfx_effect *fx = vk_load(V, MISSING_INPUTS);
    if (!fx) return;
    const char *techniques[3] = {"ColorT", "TexT", "WeightT"};
    for (int i = 0; i < 3; i++) {
        CHECK_INT(vk_draw(V, fx, techniques[i], &FULL, 1, CLEAR), 0);
        CHECK_PIXEL(V, 32, 32, 63.75, 63.75, 63.75, 191.25);
    }
    hfx_effect_destroy(fx);
}

static const char *MORE_TARGETS =
    "struct PO { float4 c0 : COLOR0; float4 c1 : COLOR1; float4 c3 : COLOR3; };\n"
    "PO PS() { PO o; o.c0 = float4(0, 1, 0, 1); o.c1 = float4(1, 0, 0, 1); o.c3 = float4(0, 0, 1, 1); return o; }\n"
    "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n";

/* COLOR1 and COLOR3 written with one colour attachment: dropped, as D3D9 drops what goes to a
 * render target that is not set; COLOR0 lands, and the validation layer says nothing (each
 * message fails the test in main). */
static void more_outputs_than_targets(void) {
    hfx_effect *fx = vk_load(V, MORE_TARGETS);
    if (!fx) return;
    CHECK_INT(vk_draw(V, fx, "T", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 0, 255, 0, 255);
    CHECK_INT(vk_draw(V, fx, "T", &FULL, 1, CLEAR), 0); /* the same pipeline again */
    CHECK_PIXEL(V, 10, 50, 0, 255, 0, 255);
    hfx_effect_destroy(fx);
}

static const char *SECOND_PASS_NO_SHADERS =
    "float4 PS() : COLOR0 { return float4(0, 1, 0, 1); }\n"
    "technique T { pass P { PixelShader = compile ps_2_0 PS(); } pass Q { ZEnable = false; } }\n";

/* A pass that sets no shaders keeps the ones set before it, as in D3D9 (and GL's bound
 * program): the right half, drawn by pass Q, is green too. */
static void pass_without_shaders(void) {
    hfx_effect *fx = vk_load(V, SECOND_PASS_NO_SHADERS);
    if (!fx) return;
    const vk_quad halves[2] = {{-1, -1, 0, 1, 0.5f, 1, 1, 0}, {0, -1, 1, 1, 0.5f, 1, 1, 0}};
    CHECK_INT(vk_draw(V, fx, "T", halves, 2, CLEAR), 0);
    CHECK_PIXEL(V, 16, 32, 0, 255, 0, 255);
    CHECK_PIXEL(V, 48, 32, 0, 255, 0, 255);
    hfx_effect_destroy(fx);
}

/* One untyped texture and sampler, sampled as 2D by one technique and as a cube by another
 * (DigitalRise's VolumetricLight: tex2Dlod for spotlights, texCUBElod for point lights). The
 * effect's sampler record has one dimension, which hfx_param_texture_target tells the
 * application; it sets a view of that kind. The program sampling the other kind reads what GL's
 * empty target of that kind gives, (0, 0, 0, 1), not that view (the validation layer's
 * viewType-07752): red + Add saturates to (255, 127.5, 191.25), (0, 0, 0, 1) + Add is Add. */
static const char *TWO_KINDS =
    "texture Light;\n"
    "sampler LightSampler = sampler_state { Texture = <Light>; };\n"
    "float4 Add = float4(0.25, 0.5, 0.75, 0);\n"
    "float4 Flat(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(LightSampler, uv) + Add; }\n"
    "float4 Round(float2 uv : TEXCOORD0) : COLOR0 { return texCUBE(LightSampler, float3(1, 0, 0)) + Add; }\n"
    "technique FlatT { pass P { PixelShader = compile ps_2_0 Flat(); } }\n"
    "technique RoundT { pass P { PixelShader = compile ps_2_0 Round(); } }\n";

static void one_sampler_two_kinds(void) {
    hfx_effect *fx = vk_load(V, TWO_KINDS);
    if (!fx) return;
    hfx_param *light = hfx_effect_param(fx, "Light");
    unsigned target = hfx_param_texture_target(light);
    int cube = target == 0x8513; /* GL_TEXTURE_CUBE_MAP; else GL_TEXTURE_2D */
    CHECK(cube || target == 0x0DE1);
    static const unsigned char red[6 * 4] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255,
                                             255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
    test_vk_texture tex;
    CHECK(test_vk_texture_make_kind(V, cube ? TEST_VK_CUBE : TEST_VK_2D, 1, 1, 1, 0, red, &tex));
    CHECK_INT(hfx_param_set_texture_vk(light, tex.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), 0);
    CHECK_INT(vk_draw(V, fx, "FlatT", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, cube ? 63.75 : 255, 127.5, 191.25, 255);
    CHECK_INT(vk_draw(V, fx, "RoundT", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, cube ? 255 : 63.75, 127.5, 191.25, 255);
    hfx_effect_destroy(fx);
    test_vk_texture_free(V, &tex);
}

int main(void) {
    hfx_vertex_layout *layout;
    V = vk_suite_begin(64, 64, &layout);
    RUN(pixel_shader_only);
    RUN(samplers_without_textures);
    RUN(cube_and_volume);
    RUN(missing_inputs);
    RUN(more_outputs_than_targets);
    RUN(pass_without_shaders);
    RUN(one_sampler_two_kinds);
    int messages = vk_suite_end(V, layout);
    return test_summary() || messages;
}
