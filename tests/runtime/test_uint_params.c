/* test_uint_params.c: a `uint` parameter reaches the shader. D3D9 has no integer registers
 * for uint; hfx keeps the value as the int the application sets (hfx_param_set_int) and
 * uploads its bits to the GLSL uint with glUniform1uiv, so a switch or a comparison on it
 * sees the value (before, the int upload failed on the uint uniform and the shader read 0). */
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
    "uint Mode;\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PS() : COLOR { return Mode == 3u ? float4(0, 1, 0, 1) : Mode > 3u ? float4(0, 0, 1, 1) : float4(1, 0, 0, 1); }\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

static void check_mode(hfx_effect *fx, int mode, int r, int gr, int b) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "Mode"), mode), HFX_OK);
    int back = -1;
    CHECK_INT(hfx_param_get_int(hfx_effect_param(fx, "Mode"), &back), HFX_OK);
    CHECK_INT(back, mode);
    g.ClearColor(0, 0, 0, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, "T"), 0)), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    rt_check_pixel(gl, 2, 2, r, gr, b, 255);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
}

/* 3: green; 7: blue (7 > 3); 0: red; -1 is 0xFFFFFFFF as a uint: blue. */
static void uint_parameter_reaches_the_shader(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "uint.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    check_mode(fx, 3, 0, 255, 0);
    check_mode(fx, 7, 0, 0, 255);
    check_mode(fx, 0, 255, 0, 0);
    check_mode(fx, -1, 0, 0, 255);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(uint_parameter_reaches_the_shader);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
