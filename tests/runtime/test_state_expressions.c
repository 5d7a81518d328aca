/* test_state_expressions.c: pass states that are expressions of parameters (D3D9 evaluates
 * them when the pass is applied): `AlphaRef = (Ref * 255);` and `AlphaFunc = (Funcs[Which]);`
 * over a static const table, compiled to common/eval_code programs and run by Apply, from the
 * .fx and from its .hfxo bytes alike. A full-screen quad of alpha 0.5 (127.5 of 255) is drawn
 * red over a blue clear; the probe says whether the alpha test let it through.
 * D3DCMPFUNC: NEVER 1, GREATER 5, ALWAYS 8. */
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
    "float Ref = 0.4;\n"
    "int Which = 1;\n"
    "static const int Funcs[2] = {1, 8};\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PS() : COLOR { return float4(1, 0, 0, 0.5); }\n"
    "technique ByRef { pass P { AlphaTestEnable = true; AlphaFunc = Greater; AlphaRef = (Ref * 255);\n"
    "  VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n"
    "technique ByTable { pass P { AlphaTestEnable = true; AlphaFunc = (Funcs[Which]); AlphaRef = 0;\n"
    "  VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

/* 1 when the quad was drawn (red), 0 when the alpha test discarded it (blue stays). */
static int drawn(hfx_effect *fx, const char *technique) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    g.ClearColor(0, 0, 1, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    hfx_effect_begin(fx);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, technique), 0)), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    hfx_effect_end(fx);
    unsigned char px[4];
    test_gl_read(gl, W / 2, H / 2, px);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
    return px[0] > 200 && px[2] < 50;
}

/* Ref 0.4: AlphaRef 102 < 127.5, drawn; 0.6: 153, not drawn; back to 0.4: drawn again
 * (Apply computes the state anew each time). */
static void alpha_ref_follows_its_parameter(hfx_effect *fx) {
    hfx_param *ref = hfx_effect_param(fx, "Ref");
    CHECK_INT(drawn(fx, "ByRef"), 1);
    CHECK_INT(hfx_param_set_float(ref, 0.6f), HFX_OK);
    CHECK_INT(drawn(fx, "ByRef"), 0);
    CHECK_INT(hfx_param_set_float(ref, 0.4f), HFX_OK);
    CHECK_INT(drawn(fx, "ByRef"), 1);
}

/* Which 0: NEVER; 1: ALWAYS; 7 clamps to the last element (ALWAYS); -3 to the first (NEVER). */
static void table_index_clamps_as_d3d9(hfx_effect *fx) {
    hfx_param *which = hfx_effect_param(fx, "Which");
    const int cases[4][2] = {{0, 0}, {1, 1}, {7, 1}, {-3, 0}};
    for (int i = 0; i < 4; i++) {
        CHECK_INT(hfx_param_set_int(which, cases[i][0]), HFX_OK);
        CHECK_INT(drawn(fx, "ByTable"), cases[i][1]);
    }
}

static void from_fx(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "expr.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    CHECK_STR(hfx_effect_warnings(fx), "");
    alpha_ref_follows_its_parameter(fx);
    table_index_clamps_as_d3d9(fx);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
}

static void from_hfxo(void) {
    hfxc_result *r = hfxc_compile_memory(src, sizeof src - 1, "expr.fx", NULL);
    const hfx_fx_effect *e = hfxc_result_effect(r);
    CHECK(e != NULL);
    void *bytes = NULL;
    size_t size = 0;
    CHECK(e && hfx_fx_write_hfxo(e, &bytes, &size) == 0);
    uint32_t exprs = 0;
    for (uint32_t i = 0; e && i < e->state_count; i++) exprs += e->states[i].kind == HFX_FX_VALUE_EXPR;
    CHECK_INT(exprs, 2);
    hfx_effect *fx = bytes ? hfx_effect_load_memory(dev, bytes, size, "expr.hfxo", NULL, NULL) : NULL;
    CHECK(fx != NULL);
    if (fx) {
        alpha_ref_follows_its_parameter(fx);
        table_index_clamps_as_d3d9(fx);
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
