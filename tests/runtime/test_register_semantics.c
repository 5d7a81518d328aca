/* test_register_semantics.c: values that span several registers carry one semantic, as D3D9
 * numbers them: a `float4x4 world : TEXCOORD1` vertex input takes TEXCOORD1..4 (hardware
 * instancing sends an XNA Matrix as four Vector4s there; under D3D9's default column_major
 * packing each register is a column of `world`, so XNA's shaders multiply by
 * transpose(world)); a `float3x3 m : TEXCOORD4` output takes TEXCOORD4..6 and a
 * `float2 uv[2] : TEXCOORD0` output TEXCOORD0..1, read back the same way by the pixel shader. */
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
    "struct VSIn { float4 pos : POSITION0; float4x4 world : TEXCOORD1; };\n"
    "struct VSOut { float4 pos : POSITION; float3x3 m : TEXCOORD4; float2 uv[2] : TEXCOORD0; };\n"
    "VSOut VS(VSIn i) {\n"
    "  VSOut o;\n"
    "  o.pos = mul(i.pos, transpose(i.world));\n"
    "  o.m = (float3x3)i.world;\n"
    "  o.uv[0] = float2(0.25, 0.5); o.uv[1] = float2(0.75, 0);\n"
    "  return o;\n"
    "}\n"
    "float4 PS(float3x3 m : TEXCOORD4, float2 uv[2] : TEXCOORD0) : COLOR { return float4(m[0][1], uv[1].x, uv[0].y, 1); }\n"
    "technique T { pass P { CullMode = None; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

/* The instance's XNA matrix M, rows r0..r3 sent to TEXCOORD1..4 (locations 9..12):
 * r0 = (0.5, 0, 0, 0), r1 = (0.6, 0.5, 0, 0), r2 = (0, 0, 1, 0), r3 = (0.25, 0, 0, 1).
 * world = transpose(M), so world[0][1] = M[1][0] = 0.6 (read as M itself it would be 0), and
 * mul(p, transpose(world)) = p * M: x' = 0.5x + 0.6y... with the quad at pixel (4, 4) inside.
 * The probe: red 0.6 (153), green uv[1].x = 0.75 (191), blue uv[0].y = 0.5 (128). */
static void matrix_input_and_multi_register_outputs(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "regs.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "T"), 0);
    for (int k = 1; k <= 4; k++) {
        char sem[16];
        snprintf(sem, sizeof sem, "TEXCOORD%d", k);
        CHECK_INT(hfx_pass_attribute_location(pass, sem), 8 + k);
    }
    static const float rows[4][4] = {{0.5f, 0, 0, 0}, {0.6f, 0.5f, 0, 0}, {0, 0, 1, 0}, {0.25f, 0, 0, 1}};
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    for (int k = 0; k < 4; k++) g.VertexAttrib4f((GLuint)(9 + k), rows[k][0], rows[k][1], rows[k][2], rows[k][3]);
    g.ClearColor(0, 0, 0, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    rt_check_pixel(gl, 4, 4, 153, 191, 128, 255);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
    hfx_effect_destroy(fx);
}

/* ps_1_1..ps_1_3 read a texture coordinate register either as coordinates (`tex tN`, as they
 * are) or as a value (`texcoord tN`: "clamped to the range [0, 1]", Microsoft's reference page
 * of texcoord), as fxc picks by use; ps_2_0's t registers are not clamped. L = (-0.5, 0.25, 2):
 * - ps_1_1, L * 0.5 + 0.5 of the clamped (0, 0.25, 1): (0.5, 0.625, 1), probed (128, 159, 255);
 * - ps_2_0, of L itself: (0.25, 0.625, 1.5 -> 1 in the target), probed (64, 159, 255);
 * - ps_1_1 sampling a 2x1 texture (red, green; wrap, point) at uv = (-0.25, 0.5): wrapped to
 *   0.75, texel 1, green; clamped it would be u = 0, texel 0, red. */
static const char ps1_src[] =
    "texture Tex;\n"
    "sampler S = sampler_state { Texture = <Tex>; AddressU = Wrap; AddressV = Wrap; MinFilter = Point; MagFilter = Point;"
    " MipFilter = None; };\n"
    "struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; float3 L : TEXCOORD1; };\n"
    "VSOut VS(float4 pos : POSITION0) {\n"
    "  VSOut o; o.pos = pos; o.uv = float2(-0.25, 0.5); o.L = float3(-0.5, 0.25, 2.0); return o;\n"
    "}\n"
    "float4 Value(float3 L : TEXCOORD1) : COLOR { return float4(L * 0.5 + 0.5, 1); }\n"
    "float4 Sampled(VSOut i) : COLOR { return tex2D(S, i.uv); }\n"
    "technique PS11 { pass P { CullMode = None; VertexShader = compile vs_1_1 VS(); PixelShader = compile ps_1_1 Value(); } }\n"
    "technique PS20 { pass P { CullMode = None; VertexShader = compile vs_1_1 VS(); PixelShader = compile ps_2_0 Value(); } }\n"
    "technique Sample11 { pass P { CullMode = None; VertexShader = compile vs_1_1 VS(); PixelShader = compile ps_1_1 Sampled(); } }\n";

static void draw_technique(hfx_effect *fx, const char *name, int r, int gr, int b) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    g.ClearColor(0, 0, 0, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, name), 0)), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    rt_check_pixel(gl, 4, 4, r, gr, b, 255);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
}

static void ps_1_1_texcoords_read_as_values_clamp(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, ps1_src, sizeof ps1_src - 1, "ps11.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    static const unsigned char texels[8] = {255, 0, 0, 255, 0, 255, 0, 255};
    GLuint tex;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), tex), HFX_OK);
    draw_technique(fx, "PS11", 128, 159, 255);
    draw_technique(fx, "PS20", 64, 159, 255);
    draw_technique(fx, "Sample11", 0, 255, 0);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(matrix_input_and_multi_register_outputs);
    RUN(ps_1_1_texcoords_read_as_values_clamp);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
