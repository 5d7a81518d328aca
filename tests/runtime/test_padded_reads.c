/* test_padded_reads.c: a uniform array read at an index the compiler cannot bound (GLSL 330) is
 * declared one element longer and read at min(uint(i), len) (compiler/glsl: the padding); the
 * element past the end is never uploaded, so GL's zero from link time stays there, and a read
 * past either end gives D3D9's zero (0, 0, 0, 0): Colors = red, green, blue; the shader returns
 * Colors[Index + column] + (0, 0, 0, 1) (alpha 0 in the colours, so a wrong element shows; the
 * column, VPOS.x, keeps the read in the shader, where Colors[Index] would be a preshader) and
 * the probe is column 2. */
#include <string.h>

#include "gl_context.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 4
#define H 4

static test_gl *gl;
static tgl g;
static hfx_device *dev;

static const char src[] =
    "float4 Colors[3]; int Index;\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PS(float2 pos : VPOS) : COLOR { return Colors[Index + (int)pos.x] + float4(0, 0, 0, 1); }\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

/* Index set, the quad drawn with technique T, pixel (2, 2) probed. */
static void draw_with_index(hfx_effect *fx, int index, int r, int gr, int b) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "Index"), index), HFX_OK);
    g.ClearColor(1, 1, 1, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, "T"), 0)), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    rt_check_pixel(gl, 2, 2, r, gr, b, 255);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
}

/* The element read at `index` in column 2 (the shader adds the column to Index). */
static void check_index(hfx_effect *fx, int index, int r, int gr, int b) { draw_with_index(fx, index - 2, r, gr, b); }

/* 0..2: the colours; 3, 100, -1, INT_MIN + 3 (Index INT_MIN + 1): black (the padding's zero, and a negative index is a
 * large uint). The program has Colors[3], and it holds zero after the uploads of Colors. */
static void reads_past_either_end_are_zero(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "padded.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    static const float colors[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Colors"), colors, 12), HFX_OK);
    check_index(fx, 0, 255, 0, 0);
    check_index(fx, 1, 0, 255, 0);
    check_index(fx, 2, 0, 0, 255);
    check_index(fx, 3, 0, 0, 0);
    check_index(fx, 100, 0, 0, 0);
    check_index(fx, -1, 0, 0, 0);
    check_index(fx, -2147483647 + 2, 0, 0, 0); /* Index INT_MIN + 1 */
    GLint program = 0;
    g.GetIntegerv(GL_CURRENT_PROGRAM, &program);
    GLint pad = g.GetUniformLocation((GLuint)program, "Colors[3]");
    CHECK(pad >= 0);
    float v[4] = {-1, -1, -1, -1};
    if (pad >= 0) g.GetUniformfv((GLuint)program, pad, v);
    CHECK(v[0] == 0 && v[1] == 0 && v[2] == 0 && v[3] == 0);
    hfx_effect_destroy(fx);
}

/* Both stages read Colors, the vertex stage at an index it cannot bound: GL links a uniform only
 * when both stages declare it alike, so neither pads it (the vertex stage keeps its guarded read;
 * before, it declared Colors[4] against the pixel stage's Colors[3] and the link failed). The
 * vertex colour is Colors[Index + p.z] (z = 0 on the quad), the pixel adds Colors[2] times the
 * colour's green (a product with the varying, so Colors stays a pixel uniform, not a
 * preshader): Index 1 gives green + blue (0, 255, 255); Index 5, past the end, zero (black). */
static const char both_src[] =
    "float4 Colors[3]; int Index;\n"
    "float4 VS(float4 p : POSITION, out float4 c : COLOR0) : POSITION { c = Colors[Index + (int)p.z]; return p; }\n"
    "float4 PS(float4 c : COLOR0) : COLOR { return c + Colors[2] * c.g + float4(0, 0, 0, 1); }\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

static void an_array_both_stages_read_links(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, both_src, sizeof both_src - 1, "both.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    static const float colors[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Colors"), colors, 12), HFX_OK);
    draw_with_index(fx, 1, 0, 255, 255);
    draw_with_index(fx, 5, 0, 0, 0);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(reads_past_either_end_are_zero);
    RUN(an_array_both_stages_read_links);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
