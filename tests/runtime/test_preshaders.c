/* test_preshaders.c: work on parameters alone runs on the CPU, once per change. The vertex
 * shader transforms by mul(World, ViewProj) (a preshader reading World and ViewProj), the pixel
 * shader returns Tint * cos(Angle) (one reading Tint and Angle). Probed against the equations,
 * with preshaders and without, from .fx, from .hfxo bytes and from SPIR-V; and counted: an
 * Apply with nothing changed runs no preshader, a changed parameter runs only those that read
 * it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compile.h"
#include "gl_context.h"
#include "gl/gl_int.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static hfx_device *dev;
static GLuint vao, vbo;

static const char effect_fx[] =
    "float4x4 World; float4x4 ViewProj; float4 Tint; float Angle;\n"
    "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, mul(World, ViewProj)); }\n"
    "float4 PS() : COLOR0 { return Tint * cos(Angle); }\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static const float half_size[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static const float tint[4] = {0.8f, 0.6f, 0.4f, 1.0f};

static hfx_effect *load(const hfx_load_options *opt) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, effect_fx, strlen(effect_fx), "pre.fx", opt, &errors);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    return fx;
}

static void set_all(hfx_effect *fx, const float *world, float angle) {
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "World"), world), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "ViewProj"), identity), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Tint"), tint, 4), HFX_OK);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Angle"), angle), HFX_OK);
}

/* Applies the pass, draws the full-screen quad, reads pixel (x, y). */
static void draw(hfx_effect *fx, int x, int y, unsigned char px[4]) {
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, "T"), 0)), HFX_OK);
    g.BindVertexArray(vao);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    test_gl_read(gl, x, y, px);
}

static void check_color(const unsigned char px[4], float scale) {
    for (int k = 0; k < 4; k++) CHECK_NEAR(px[k], tint[k] * scale * 255.0f, 1.01);
}

/* cos(pi / 3) = 0.5 (1.04719755 = pi / 3): the centre is Tint / 2. World halves x and y: the quad covers the middle
 * half of the target, so pixel (1, 1) keeps the clear colour (D3D9's half-pixel shift leaves row and column 0 on the quad's edge); with World the identity it is
 * drawn too. cos(0) = 1 gives Tint itself. */
static void pictures(hfx_effect *fx) {
    unsigned char px[4];
    set_all(fx, half_size, 1.04719755f);
    draw(fx, W / 2, H / 2, px);
    check_color(px, 0.5f);
    draw(fx, 1, 1, px);
    CHECK_INT(px[0], 0);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "World"), identity), HFX_OK);
    draw(fx, 1, 1, px);
    check_color(px, 0.5f);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Angle"), 0.0f), HFX_OK);
    draw(fx, W / 2, H / 2, px);
    check_color(px, 1.0f);
}

static void with_and_without(void) {
    hfx_load_options off = {0};
    off.no_preshaders = 1;
    hfx_effect *fx = load(NULL), *plain = load(&off);
    CHECK(fx && plain);
    if (fx && plain) {
        CHECK_INT(fx->sh->fx->programs[0].preshader_count, 2);
        CHECK_INT(plain->sh->fx->programs[0].preshader_count, 0);
        pictures(fx);
        pictures(plain);
    }
    hfx_effect_destroy(fx);
    hfx_effect_destroy(plain);
}

/* The counts: both run at the first Apply; nothing changed runs none; Angle runs the pixel
 * shader's alone, World the vertex shader's alone, and setting a value twice runs it once. */
static void only_what_changed_runs(void) {
    hfx_effect *fx = load(NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_rt_program *prog = &fx->sh->gl->programs[0];
    unsigned char px[4];
    set_all(fx, identity, 0.0f);
    draw(fx, W / 2, H / 2, px);
    CHECK_INT(prog->pre.runs, 2);
    draw(fx, W / 2, H / 2, px);
    CHECK_INT(prog->pre.runs, 2);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Angle"), 1.04719755f), HFX_OK);
    draw(fx, W / 2, H / 2, px);
    CHECK_INT(prog->pre.runs, 3);
    check_color(px, 0.5f);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "World"), half_size), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "World"), half_size), HFX_OK);
    draw(fx, 1, 1, px);
    CHECK_INT(prog->pre.runs, 4);
    CHECK_INT(px[0], 0);
    hfx_effect_destroy(fx);
}

/* The compiled effect's bytes carry the preshaders; the runtime alone runs them. */
static void from_compiled_bytes(hfx_target target) {
    hfx_load_options opt = {0};
    opt.target = target;
    char *diag = NULL;
    hfx_fx_effect *cfx = hfx_rt_compile_fx(NULL, effect_fx, strlen(effect_fx), "pre.fx", &opt, &diag);
    free(diag);
    void *bytes = NULL;
    size_t size = 0;
    CHECK(cfx && hfx_fx_write_hfxo(cfx, &bytes, &size) == 0);
    hfx_fx_effect_free(cfx);
    char *errors = NULL;
    hfx_effect *fx = bytes ? hfx_effect_load_memory(dev, bytes, size, "pre.hfxo", &opt, &errors) : NULL;
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    CHECK(fx != NULL);
    if (fx) {
        CHECK_INT(fx->sh->fx->programs[0].preshader_count, 2);
        pictures(fx);
    }
    hfx_effect_destroy(fx);
    hfx_free(errors);
    free(bytes);
}

static void hfxo_glsl(void) { from_compiled_bytes(HFX_TARGET_GLSL330); }

static void hfxo_spirv(void) {
    if (!dev->gl->spirv.ok) {
        printf("  no ARB_gl_spirv: SPIR-V not tested\n");
        return;
    }
    from_compiled_bytes(HFX_TARGET_SPIRV);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    g.Viewport(0, 0, W, H);
    static const float xy[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    vao = tgl_triangles(&g, xy, 6, &vbo);
    dev = hfx_device_create_gl(test_gl_loader);
    RUN(with_and_without);
    RUN(only_what_changed_runs);
    RUN(hfxo_glsl);
    RUN(hfxo_spirv);
    hfx_device_destroy(dev);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    test_gl_destroy(gl);
    return test_summary();
}
