/* test_alpha_test.c: D3D9's alpha test costs nothing unless the effect uses it. A program
 * carries the test only when some pass of its effect turns AlphaTestEnable on (to anything
 * but a constant FALSE): render states stay set for the next pass, so every program of such
 * an effect that writes COLOR0 carries it. Probed: the pixel shader writes alpha 0.25 (rgb
 * 1); under AlphaFunc = Greater with AlphaRef 128 (0.502) the pixel is discarded and the
 * cleared black stays; without the test it is drawn white. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_context.h"
#include "hfx/hfxc.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static hfx_device *dev;

#define SHADERS \
    "float Alpha = 0.25;\n" \
    "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n" \
    "float4 PS() : COLOR0 { return float4(1, 1, 1, Alpha); }\n"
#define PROGRAM "VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS();"

/* Test turns the test on; Inherits names no alpha state (it runs after Test's pass 0 within
 * one technique); Plain starts from the defaults (off). */
static const char uses_it[] =
    SHADERS
    "technique Test { pass P0 { AlphaTestEnable = TRUE; AlphaFunc = Greater; AlphaRef = 128; " PROGRAM " }\n"
    "                 pass P1 { " PROGRAM " } }\n"
    "technique Plain { pass P0 { " PROGRAM " } }\n";

static const char never_on[] =
    SHADERS "technique T { pass P0 { AlphaTestEnable = FALSE; " PROGRAM " } }\n";

static const char by_parameter[] =
    SHADERS "bool UseAlpha = true;\n"
    "technique T { pass P0 { AlphaTestEnable = (UseAlpha); AlphaFunc = Greater; AlphaRef = 128; " PROGRAM " } }\n";

static hfx_effect *load(const char *src) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, strlen(src), "alpha.fx", NULL, &errors);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    return fx;
}

/* Applies passes [0, count) of the technique, drawing the full-screen quad after each, and
 * returns the centre pixel's red. */
static int draw(hfx_effect *fx, const char *technique, int count) {
    static const float xy[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    GLuint vbo, vao = tgl_triangles(&g, xy, 6, &vbo);
    hfx_technique *t = hfx_effect_technique(fx, technique);
    hfx_effect_begin(fx);
    for (int i = 0; i < count; i++) {
        CHECK_INT(hfx_pass_apply(hfx_technique_pass(t, (size_t)i)), HFX_OK);
        if (i == count - 1) g.DrawArrays(GL_TRIANGLES, 0, 6);
    }
    hfx_effect_end(fx);
    unsigned char px[4];
    test_gl_read(gl, W / 2, H / 2, px);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    return px[0];
}

/* The GLSL of the effect's first program's pixel stage, as the runtime compiled it. */
static int fragment_mentions_alpha(const char *src) {
    hfxc_options o = {0};
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "alpha.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    int found = fx && fx->program_count && strstr(fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data, "hfx_alpha");
    hfxc_result_free(r);
    return found;
}

static void an_effect_that_uses_it(void) {
    hfx_effect *fx = load(uses_it);
    CHECK(fx != NULL);
    if (!fx) return;
    CHECK_INT(draw(fx, "Test", 1), 0);     /* 0.25 > 0.502 fails: discarded */
    CHECK_INT(draw(fx, "Test", 2), 0);     /* P1 inherits the test */
    CHECK_INT(draw(fx, "Plain", 1), 255);  /* begin restores the defaults: off */
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Alpha"), 0.75f), HFX_OK);
    CHECK_INT(draw(fx, "Test", 1), 255);   /* 0.75 > 0.502 passes */
    hfx_effect_destroy(fx);
    CHECK(fragment_mentions_alpha(uses_it));
}

static void an_effect_that_never_turns_it_on(void) {
    CHECK(!fragment_mentions_alpha(never_on));
    hfx_effect *fx = load(never_on);
    CHECK(fx != NULL);
    if (fx) CHECK_INT(draw(fx, "T", 1), 255);
    hfx_effect_destroy(fx);
}

static void a_parameter_may_turn_it_on(void) {
    CHECK(fragment_mentions_alpha(by_parameter));
    hfx_effect *fx = load(by_parameter);
    CHECK(fx != NULL);
    if (!fx) return;
    CHECK_INT(draw(fx, "T", 1), 0);
    CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "UseAlpha"), 0), HFX_OK);
    CHECK_INT(draw(fx, "T", 1), 255);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    g.Viewport(0, 0, W, H);
    dev = hfx_device_create_gl(test_gl_loader);
    RUN(an_effect_that_uses_it);
    RUN(an_effect_that_never_turns_it_on);
    RUN(a_parameter_may_turn_it_on);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
