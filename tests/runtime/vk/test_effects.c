/* The Effect object model on Vulkan: textures through each sampler state (filters, address
 * modes, border colour), clones with their own values, technique switches, state expressions,
 * runtime-indexed shader arrays, hot reload, and an Apply with nothing changed writing neither
 * uniforms nor descriptors. Colours are worked out by hand from the texels and the equations. */
#include <stdio.h>
#include <unistd.h>

#include "vk_draw.h"

static test_vk *V;

static const float CLEAR[4] = {0.2f, 0.4f, 0.6f, 1.0f};
/* uv (0, 0) .. (2, 2) over the 64 x 64 image: pixel x samples u = x / 32 (D3D9's pixel centres). */
static const vk_quad FULL2 = {-1, -1, 1, 1, 0.5f, 2, 2, 0};

/* 2 x 2 texels: red, green / blue, white. */
static const unsigned char TEXELS[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};

static const char *TEXTURED =
    "texture Tex;\n"
    "int Addr = 1;\n"
    "sampler PointWrap = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; AddressU = Wrap; AddressV = Wrap; };\n"
    "sampler PointClamp = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; AddressU = Clamp; AddressV = Clamp; };\n"
    "sampler PointMirror = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; AddressU = Mirror; AddressV = Wrap; };\n"
    "sampler PointBorder = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; AddressU = Border;\n"
    "  AddressV = Wrap; BorderColor = 0xFFFFFFFF; };\n"
    "sampler PointTeal = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; AddressU = Border;\n"
    "  AddressV = Wrap; BorderColor = 0x80336699; };\n"
    "sampler LinearWrap = sampler_state { Texture = <Tex>; MinFilter = Linear; MagFilter = Linear; AddressU = Wrap; AddressV = Wrap; };\n"
    "sampler ByParam = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; AddressU = <Addr>; AddressV = Wrap; };\n"
    "float4 VS(float4 p : POSITION, inout float2 uv : TEXCOORD0) : POSITION { return p; }\n"
    "#define T(name, s) float4 name(float2 uv : TEXCOORD0) : COLOR { return tex2D(s, uv); }\\\n"
    "  technique name##T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 name(); } }\n"
    "T(Wrap, PointWrap)\nT(Clamp, PointClamp)\nT(Mirror, PointMirror)\nT(Border, PointBorder)\nT(Teal, PointTeal)\nT(Linear, LinearWrap)\n"
    "T(Param, ByParam)\n";

static void draw_textured(hfx_effect *fx, const char *technique) {
    CHECK_INT(vk_draw(V, fx, technique, &FULL2, 1, CLEAR), 0);
}

/* Row y = 8 samples v = 0.25, the middle of texel row 0 (red, green). Pixel 8: u = 0.25 (texel 0),
 * 24: 0.75 (texel 1), 40: 1.25, 56: 1.75, where the address mode decides. */
static void sampler_states(void) {
    hfx_effect *fx = vk_load(V, TEXTURED);
    test_vk_texture tex;
    CHECK(test_vk_texture_make(V, 2, 2, TEXELS, &tex));
    if (!fx) return;
    CHECK_INT(hfx_param_set_texture_vk(hfx_effect_param(fx, "Tex"), tex.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), 0);
    draw_textured(fx, "WrapT");
    CHECK_PIXEL(V, 8, 8, 255, 0, 0, 255);
    CHECK_PIXEL(V, 24, 8, 0, 255, 0, 255);
    CHECK_PIXEL(V, 40, 8, 255, 0, 0, 255);  /* 1.25 wraps to 0.25 */
    CHECK_PIXEL(V, 8, 24, 0, 0, 255, 255);  /* v = 0.75: row 1 */
    draw_textured(fx, "ClampT");
    CHECK_PIXEL(V, 40, 8, 0, 255, 0, 255);  /* clamps to the last texel */
    CHECK_PIXEL(V, 56, 40, 255, 255, 255, 255);
    draw_textured(fx, "MirrorT");
    CHECK_PIXEL(V, 40, 8, 0, 255, 0, 255);  /* 1.25 mirrors to 0.75 */
    CHECK_PIXEL(V, 56, 8, 255, 0, 0, 255);  /* 1.75 mirrors to 0.25 */
    draw_textured(fx, "BorderT");
    CHECK_PIXEL(V, 24, 8, 0, 255, 0, 255);
    CHECK_PIXEL(V, 40, 8, 255, 255, 255, 255); /* outside 0..1: the border colour */
    /* D3DCOLOR 0x80336699 is A 0x80, R 0x33, G 0x66, B 0x99: exact with VK_EXT_custom_border_color
     * (lavapipe has it), else the nearest fixed colour, transparent black */
    draw_textured(fx, "TealT");
    CHECK_PIXEL(V, 24, 8, 0, 255, 0, 255);
    if (test_vk_custom_border(V)) CHECK_PIXEL(V, 40, 8, 0x33, 0x66, 0x99, 0x80);
    else CHECK_PIXEL(V, 40, 8, 0, 0, 0, 0);
    draw_textured(fx, "LinearT");
    CHECK_PIXEL(V, 16, 8, 127.5, 127.5, 0, 255); /* u = 0.5: half red, half green */
    CHECK_PIXEL(V, 8, 8, 255, 0, 0, 255);
    /* AddressU = <Addr>: Wrap (1), then Clamp (3) set by the application, read at Apply. */
    draw_textured(fx, "ParamT");
    CHECK_PIXEL(V, 40, 8, 255, 0, 0, 255);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "Addr"), 3), 0);
    draw_textured(fx, "ParamT");
    CHECK_PIXEL(V, 40, 8, 0, 255, 0, 255);
    hfx_effect_destroy(fx);
    test_vk_texture_free(V, &tex);
}

static const char *COLORED =
    "float4 Color = float4(1, 0, 0, 1);\n"
    "float Ref = 0.4;\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PS() : COLOR { return Color; }\n"
    "float4 Green() : COLOR { return float4(0, 1, 0, 1); }\n"
    "technique Plain { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"
    "technique Other { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Green(); } }\n"
    "technique AlphaRef { pass P { AlphaTestEnable = true; AlphaFunc = Greater; AlphaRef = (Ref * 255);\n"
    "  VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* A clone shares the code and keeps its own values: the left half with the original's red,
 * the right half with the clone's blue, in one frame. */
static void clone_and_technique(void) {
    hfx_effect *fx = vk_load(V, COLORED);
    if (!fx) return;
    hfx_effect *copy = hfx_effect_clone(fx);
    CHECK(copy != NULL);
    const float blue[4] = {0, 0, 1, 1};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(copy, "Color"), blue, 4), 0);
    const vk_quad left = {-1, -1, 0, 1, 0.5f, 1, 1, 0}, right = {0, -1, 1, 1, 0.5f, 1, 1, 0};
    CHECK_INT(vk_draw(V, fx, "Plain", &left, 1, CLEAR), 0);
    CHECK_PIXEL(V, 16, 32, 255, 0, 0, 255);
    CHECK_INT(vk_draw(V, copy, "Plain", &right, 1, CLEAR), 0);
    CHECK_PIXEL(V, 48, 32, 0, 0, 255, 255);
    CHECK_INT(vk_draw(V, fx, "Plain", &left, 1, CLEAR), 0); /* the original still red */
    CHECK_PIXEL(V, 16, 32, 255, 0, 0, 255);
    CHECK_INT(vk_draw(V, fx, "Other", &left, 1, CLEAR), 0); /* technique switch */
    CHECK_PIXEL(V, 16, 32, 0, 255, 0, 255);
    hfx_effect_destroy(copy);
    hfx_effect_destroy(fx);
}

/* AlphaRef = (Ref * 255) runs at Apply: alpha 0.5 passes Greater 0.4 * 255, not 0.6 * 255. */
static void state_expression(void) {
    hfx_effect *fx = vk_load(V, COLORED);
    if (!fx) return;
    const float half_red[4] = {1, 0, 0, 0.5f};
    const vk_quad full = {-1, -1, 1, 1, 0.5f, 1, 1, 0};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), half_red, 4), 0);
    CHECK_INT(vk_draw(V, fx, "AlphaRef", &full, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 255, 0, 0, 127.5);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Ref"), 0.6f), 0);
    CHECK_INT(vk_draw(V, fx, "AlphaRef", &full, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 51, 102, 153, 255);
    hfx_effect_destroy(fx);
}

static const char *ARRAYS =
    "int ShaderIndex = 0;\n"
    "static const int PSIndices[3] = {2, 0, 1};\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PSRed() : COLOR { return float4(1, 0, 0, 1); }\n"
    "float4 PSGreen() : COLOR { return float4(0, 1, 0, 1); }\n"
    "float4 PSBlue(uniform float b) : COLOR { return float4(0, 0, b, 1); }\n"
    "PixelShader PSArray[3] = { compile ps_2_0 PSRed(), compile ps_2_0 PSGreen(), compile ps_2_0 PSBlue(1) };\n"
    "technique ByTable { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = (PSArray[PSIndices[ShaderIndex]]); } }\n";

/* ShaderIndex 0, 1, 2 pick PSArray[2], [0], [1]: blue, red, green. */
static void shader_arrays(void) {
    hfx_effect *fx = vk_load(V, ARRAYS);
    if (!fx) return;
    const vk_quad full = {-1, -1, 1, 1, 0.5f, 1, 1, 0};
    static const int want[3][3] = {{0, 0, 255}, {255, 0, 0}, {0, 255, 0}};
    for (int i = 0; i < 3; i++) {
        CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "ShaderIndex"), i), 0);
        CHECK_INT(vk_draw(V, fx, "ByTable", &full, 1, CLEAR), 0);
        CHECK_PIXEL(V, 32, 32, want[i][0], want[i][1], want[i][2], 255);
    }
    hfx_effect_destroy(fx);
}

static int write_file(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fputs(text, f);
    return fclose(f) == 0;
}

/* The file changes from red to green; reload keeps the instance and its handles' effect. */
static void hot_reload(void) {
    char path[] = "/tmp/hfx_vk_reloadXXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd < 0) return;
    close(fd);
    const char *red = "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                      "float4 PS() : COLOR { return float4(1, 0, 0, 1); }\n"
                      "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
    CHECK(write_file(path, red));
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load(test_vk_device(V), path, NULL, &errors);
    hfx_free(errors);
    CHECK(fx != NULL);
    const vk_quad full = {-1, -1, 1, 1, 0.5f, 1, 1, 0};
    if (fx) {
        CHECK_INT(vk_draw(V, fx, "T", &full, 1, CLEAR), 0);
        CHECK_PIXEL(V, 32, 32, 255, 0, 0, 255);
        CHECK(write_file(path, "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                               "float4 PS() : COLOR { return float4(0, 1, 0, 1); }\n"
                               "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"));
        CHECK_INT(hfx_effect_reload(fx, NULL, NULL, &errors), HFX_OK);
        hfx_free(errors);
        CHECK_INT(vk_draw(V, fx, "T", &full, 1, CLEAR), 0);
        CHECK_PIXEL(V, 32, 32, 0, 255, 0, 255);
        hfx_effect_destroy(fx);
    }
    unlink(path);
}

/* Applying the same pass again with nothing changed writes no uniform slice and no descriptor
 * set; a changed value writes one slice and no set (the ring's buffer is the same). */
static void unchanged_apply_writes_nothing(void) {
    hfx_effect *fx = vk_load(V, COLORED);
    if (!fx) return;
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "Plain"), 0);
    VkCommandBuffer cmd = test_vk_begin(V, CLEAR);
    size_t slices0, sets0, slices1, sets1, slices2, sets2;
    CHECK_INT(hfx_pass_apply_vk(pass, cmd, test_vk_target(V)), 0);
    hfx_device_writes_vk(test_vk_device(V), &slices0, &sets0);
    CHECK_INT(hfx_pass_apply_vk(pass, cmd, test_vk_target(V)), 0);
    hfx_device_writes_vk(test_vk_device(V), &slices1, &sets1);
    CHECK_INT(slices1, slices0);
    CHECK_INT(sets1, sets0);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Ref"), 0.1f), 0); /* not read by Plain's program */
    CHECK_INT(hfx_pass_apply_vk(pass, cmd, test_vk_target(V)), 0);
    hfx_device_writes_vk(test_vk_device(V), &slices1, &sets1);
    CHECK_INT(slices1, slices0);
    const float c[4] = {0.5f, 0.5f, 0.5f, 1};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), c, 4), 0);
    CHECK_INT(hfx_pass_apply_vk(pass, cmd, test_vk_target(V)), 0);
    hfx_device_writes_vk(test_vk_device(V), &slices2, &sets2);
    CHECK_INT(slices2, slices0 + 1);
    CHECK_INT(sets2, sets0);
    CHECK_INT(test_vk_end(V), 0);
    hfx_effect_destroy(fx);
}

int main(void) {
    hfx_vertex_layout *layout;
    V = vk_suite_begin(64, 64, &layout);
    RUN(sampler_states);
    RUN(clone_and_technique);
    RUN(state_expression);
    RUN(shader_arrays);
    RUN(hot_reload);
    RUN(unchanged_apply_writes_nothing);
    int messages = vk_suite_end(V, layout);
    return test_summary() || messages;
}
