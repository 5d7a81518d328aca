/* test_shader_arrays.c: passes whose shaders come from shader arrays indexed by parameters, as
 * XNA's stock effects choose among their shader pairs: `PixelShader = (PSArray[PSIndices[
 * ShaderIndex]]);` through a static const table, and through an int array parameter (FNA's
 * VSIndices). Apply evaluates the index as D3D9 does (clamped into the tables and the array)
 * and draws with the chosen entry's program; from the .fx and from its .hfxo. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "gl_context.h"
#include "hfx/hfxc.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 4
#define H 4

static test_gl *gl;
static tgl g;
static hfx_device *dev;

static const char src[] =
    "int ShaderIndex = 0;\n"
    "int Indices[3] = {1, 2, 0};\n"
    "static const int PSIndices[4] = {2, 0, 1, 1};\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 VSHalf(float4 p : POSITION) : POSITION { return float4(p.x * 0.5 + 0.5, p.y, 0, 1); }\n"
    "float4 PSRed() : COLOR { return float4(1, 0, 0, 1); }\n"
    "float4 PSGreen() : COLOR { return float4(0, 1, 0, 1); }\n"
    "float4 PSBlue(uniform float b) : COLOR { return float4(0, 0, b, 1); }\n"
    "VertexShader VSArray[2] = { compile vs_2_0 VS(), compile vs_2_0 VSHalf() };\n"
    "PixelShader PSArray[3] = { compile ps_2_0 PSRed(), compile ps_2_0 PSGreen(), compile ps_2_0 PSBlue(1) };\n"
    "technique ByTable { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = (PSArray[PSIndices[ShaderIndex]]); } }\n"
    "technique ByParam { pass P { VertexShader = (VSArray[ShaderIndex / 2]); PixelShader = (PSArray[Indices[ShaderIndex]]); } }\n";

/* The colour at the centre (r, g, b as 0/1) after drawing the technique over a black clear. */
static int draw(hfx_effect *fx, const char *technique, int index, int x, int y) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "ShaderIndex"), index), HFX_OK);
    g.ClearColor(0, 0, 0, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, technique), 0)), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    unsigned char px[4];
    test_gl_read(gl, x, y, px);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
    return (px[0] > 128) * 4 + (px[1] > 128) * 2 + (px[2] > 128);
}

enum { BLACK = 0, BLUE = 1, GREEN = 2, RED = 4 };

static void check_effect(hfx_effect *fx) {
    /* ShaderIndex 0..3 -> PSIndices 2, 0, 1, 1 -> blue, red, green, green; 7 and -5 clamp to
     * the table's last and first entries: green, blue */
    const int table[6][2] = {{0, BLUE}, {1, RED}, {2, GREEN}, {3, GREEN}, {7, GREEN}, {-5, BLUE}};
    for (int i = 0; i < 6; i++) CHECK_INT(draw(fx, "ByTable", table[i][0], 2, 2), table[i][1]);
    /* ByParam: PS from the parameter array Indices = {1, 2, 0}; VS 0 (full screen) for
     * ShaderIndex 0 and 1, VSHalf (the right half only) for 2:
     * 0 -> green everywhere; 1 -> blue; 2 -> red on the right, black on the left */
    CHECK_INT(draw(fx, "ByParam", 0, 0, H - 1), GREEN);
    CHECK_INT(draw(fx, "ByParam", 1, 0, H - 1), BLUE);
    CHECK_INT(draw(fx, "ByParam", 2, W - 1, H - 1), RED); /* the bottom row: D3D9's pixel centres */
    CHECK_INT(draw(fx, "ByParam", 2, 0, H - 1), BLACK);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
}

static void from_fx(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "arrays.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    CHECK_STR(hfx_effect_warnings(fx), "");
    check_effect(fx);
    hfx_effect_destroy(fx);
}

static void from_hfxo(void) {
    hfxc_result *r = hfxc_compile_memory(src, sizeof src - 1, "arrays.fx", NULL);
    const hfx_fx_effect *e = hfxc_result_effect(r);
    CHECK(e != NULL);
    /* ByTable reaches PS 0, 1, 2 (3 variants); ByParam (VS, PS) = (0, 1), (0, 2), (1, 0) */
    CHECK_INT(e ? e->variant_count : 0, 6);
    void *bytes = NULL;
    size_t size = 0;
    CHECK(e && hfx_fx_write_hfxo(e, &bytes, &size) == 0);
    hfx_effect *fx = bytes ? hfx_effect_load_memory(dev, bytes, size, "arrays.hfxo", NULL, NULL) : NULL;
    CHECK(fx != NULL);
    if (fx) {
        check_effect(fx);
        hfx_effect_destroy(fx);
    }
    free(bytes);
    hfxc_result_free(r);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(from_fx);
    RUN(from_hfxo);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
