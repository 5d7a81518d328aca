/* test_fixed_vertex.c: on GL, what tests/runtime/vk/test_real_effects.c checks on Vulkan, with
 * the same hand-computed values: a pass with only a pixel shader draws its positions as clip
 * space within D3D9's depth range 0..1; vertex inputs the vertex data lacks read (0, 0, 0, 1),
 * as D3D9 gives an element its vertex declaration lacks; a sampler with no texture reads
 * (0, 0, 0, 1). */
#include <string.h>

#include "gl_context.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static hfx_device *dev;

static const char src[] =
    "sampler2D depthSampler : register(s0);\n"
    "float4 Add = float4(0.25, 0.5, 0.75, 0);\n"
    "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return float4(uv, 0.25, 1); }\n"
    "float4 ByRegister(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(depthSampler, uv) + Add; }\n"
    "struct VO { float4 p : POSITION; float4 c : COLOR0; float4 t : TEXCOORD1; float4 w : TEXCOORD2; };\n"
    "VO VS(float4 p : POSITION, float4 c : COLOR0, float4 t3 : TEXCOORD3, float4 bw : BLENDWEIGHT) {\n"
    "  VO o; o.p = p; o.c = c; o.t = t3; o.w = bw; return o; }\n"
    "float4 Color(float4 c : COLOR0) : COLOR0 { return c * 0.5 + 0.25; }\n"
    "float4 Tex(float4 t : TEXCOORD1) : COLOR0 { return t * 0.5 + 0.25; }\n"
    "float4 Weight(float4 w : TEXCOORD2) : COLOR0 { return w * 0.5 + 0.25; }\n"
    "technique Null { pass P { VertexShader = NULL; PixelShader = compile ps_2_0 PS(); } }\n"
    "technique Unset { pass P { PixelShader = compile ps_2_0 PS(); } }\n"
    "technique ByRegisterT { pass P { PixelShader = compile ps_2_0 ByRegister(); } }\n"
    "#define T(name) technique name##T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 name(); } }\n"
    "T(Color) T(Tex) T(Weight)\n";

/* The whole viewport at depth z, clockwise on screen: position (x, y, z) and uv, (0, 0) at the
 * top left; only POSITION0 and TEXCOORD0 are enabled arrays. */
static void draw(hfx_effect *fx, const char *tech, float z) {
    const float v[] = {-1, 1, z, 0, 0, 1, 1, z, 1, 0, 1, -1, z, 1, 1, -1, 1, z, 0, 0, 1, -1, z, 1, 1, -1, -1, z, 0, 1};
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, tech), 0);
    GLuint vao, buf;
    g.GenVertexArrays(1, &vao);
    g.BindVertexArray(vao);
    g.GenBuffers(1, &buf);
    g.BindBuffer(GL_ARRAY_BUFFER, buf);
    g.BufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW);
    int pos = hfx_pass_attribute_location(pass, "POSITION0"), uv = hfx_pass_attribute_location(pass, "TEXCOORD0");
    CHECK(pos >= 0);
    g.VertexAttribPointer((GLuint)pos, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void *)0);
    g.EnableVertexAttribArray((GLuint)pos);
    if (uv >= 0) {
        g.VertexAttribPointer((GLuint)uv, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void *)(3 * sizeof(float)));
        g.EnableVertexAttribArray((GLuint)uv);
    }
    g.ClearColor(0.2f, 0.4f, 0.6f, 1);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &buf);
    g.DeleteVertexArrays(1, &vao);
}

static hfx_effect *load(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "fixed.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    return fx;
}

/* Pixel (2, 6): uv (0.25, 0.75) at D3D9's pixel centres, so (0.25, 0.75, 0.25, 1) * 255; a
 * quad at depth -0.5 is outside D3D9's 0..1: clipped, the clear colour stays. */
static void pixel_shader_only(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    const char *techniques[2] = {"Null", "Unset"};
    for (int i = 0; i < 2; i++) {
        draw(fx, techniques[i], 0.5f);
        rt_check_pixel(gl, 2, 6, 64, 191, 64, 255);
        rt_check_pixel(gl, 6, 2, 191, 64, 64, 255);
        draw(fx, techniques[i], -0.5f);
        rt_check_pixel(gl, 2, 6, 51, 102, 153, 255);
    }
    hfx_effect_destroy(fx);
}

/* COLOR0, TEXCOORD3 and BLENDWEIGHT are not in the vertex data: (0, 0, 0, 1) each, so
 * (0.25, 0.25, 0.25, 0.75) * 255; the register-bound sampler with no texture: Add + (0, 0, 0, 1). */
static void missing_inputs_and_textures(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    const char *techniques[3] = {"ColorT", "TexT", "WeightT"};
    for (int i = 0; i < 3; i++) {
        draw(fx, techniques[i], 0.5f);
        rt_check_pixel(gl, 4, 4, 64, 64, 64, 191);
    }
    draw(fx, "ByRegisterT", 0.5f);
    rt_check_pixel(gl, 4, 4, 64, 128, 191, 255);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(pixel_shader_only);
    RUN(missing_inputs_and_textures);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
