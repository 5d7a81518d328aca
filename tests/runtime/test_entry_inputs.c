/* test_entry_inputs.c: an entry point's `in` parameters are its own copies. HLSL passes
 * parameters by value ("Function Parameters" in Microsoft's HLSL reference: `in` copies the
 * value in, the default), so fxc accepts writes to an entry point's inputs and the rest of the
 * function reads the written value; on D3D9 an input register (v#, t#) is read-only, so fxc reads
 * it into a temporary. GLSL's `in` globals are read-only too: hfx copies them into main's locals
 * before calling the entry. Drawn twice: hfx's own GLSL, and through fxc's format (the D3D9
 * bytecode writer, fx_2_0, its reader). */
#include <stdlib.h>
#include <string.h>

#include "gl_context.h"
#include "hfx/hfxc.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static hfx_device *dev;

/* Writes to a whole input, to components of one, and to a struct input's member. */
static const char src[] =
    "float4 K = {0.25, 0.5, 0.125, 1};\n"
    "struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; };\n"
    "struct PSIn { float2 uv : TEXCOORD0; };\n"
    "VSOut VS(float4 pos : POSITION0, float2 uv : TEXCOORD0) {\n"
    "  pos.xy *= 0.5;\n"
    "  uv = uv * 0.5 + 0.25;\n"
    "  VSOut o; o.pos = pos; o.uv = uv; return o;\n"
    "}\n"
    "float4 PS(PSIn i) : COLOR {\n"
    "  i.uv.y = 0.75;\n"
    "  i.uv.x += 0.125;\n"
    "  return float4(i.uv, K.z, 1);\n"
    "}\n"
    "technique T { pass P { CullMode = None; VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

static hfx_effect *load_glsl(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "inputs.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    return fx;
}

static hfx_effect *load_fx2(void) {
    hfxc_options co = {.flags = HFXC_PACK_UNIFORMS | HFXC_NO_PRESHADERS | HFXC_D3D9_BYTECODE};
    hfxc_result *r = hfxc_compile_memory(src, sizeof src - 1, "inputs.fx", &co);
    size_t size = 0;
    char *errors = NULL;
    void *data = hfxc_result_fx2(r, 0, &size, &errors);
    if (!data) printf("%s\n", errors ? errors : "");
    free(errors);
    hfx_effect *fx = NULL;
    if (data) {
        char *e = NULL;
        fx = hfx_effect_load_memory(dev, data, size, "inputs.fxo", NULL, &e);
        if (!fx) printf("%s\n", e ? e : "");
        hfx_free(e);
    }
    free(data);
    hfxc_result_free(r);
    return fx;
}

/* The full-screen quad with uv = (0.5, 0.5) everywhere. The vertex shader halves the position
 * (the quad covers pixels 2..5 only: pixel (0, 0) keeps the clear colour) and makes uv
 * 0.5 * 0.5 + 0.25 = 0.5; the pixel shader sets uv.y = 0.75 and adds 0.125 to uv.x: the colour
 * is (0.625, 0.75, K.z = 0.125, 1) = (159, 191, 32, 255). */
static void draw_and_probe(hfx_effect *fx) {
    CHECK(fx != NULL);
    if (!fx) return;
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "T"), 0);
    int uv = hfx_pass_attribute_location(pass, "TEXCOORD0");
    CHECK(uv > 0);
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    if (uv > 0) g.VertexAttrib4f((GLuint)uv, 0.5f, 0.5f, 0, 0);
    g.ClearColor(0, 0, 0, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    rt_check_pixel(gl, 4, 4, 159, 191, 32, 255);
    rt_check_pixel(gl, 0, 0, 0, 0, 0, 255);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
    hfx_effect_destroy(fx);
}

static void written_inputs_glsl(void) { draw_and_probe(load_glsl()); }
static void written_inputs_fx2(void) { draw_and_probe(load_fx2()); }

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(written_inputs_glsl);
    RUN(written_inputs_fx2);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
