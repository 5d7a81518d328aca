/* test_apply.c: Apply against hand-built effects: uniform uploads (values read back from GL,
 * pixels of rendered frames), dirty tracking counted through the GL function table. */
#include <string.h>

#include "gl_context.h"
#include "internal.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 16
#define H 16

static test_gl *gl;
static tgl g;
static hfx_device *dev;
static GLuint vao, vbo;

/* Two triangles covering the whole target. */
static const float full[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};

static void draw_full(void) {
    g.BindVertexArray(vao);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
}

static void clear(float r, float gg, float b, float a) {
    g.ClearColor(r, gg, b, a);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

static hfx_effect *load(hfx_fx_effect *cfx) {
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, cfx, NULL, &errors);
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : "(no message)");
    CHECK(fx != NULL);
    hfx_free(errors);
    return fx;
}

static GLuint current_program(void) {
    GLint p = 0;
    g.GetIntegerv(GL_CURRENT_PROGRAM, &p);
    return (GLuint)p;
}

/* An effect whose pixel shader outputs the uniform Color. */
static hfx_fx_effect *color_effect(void) {
    hfx_fx_effect *fx = tb_new();
    uint32_t c = tb_param(fx, "Color", "Color", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 0, 4);
    uint32_t prog = tb_program(fx, tb_vs_pos, tb_fs_color);
    tb_attribute(fx, prog, "POSITION0", "POSITION0", 0);
    tb_uses(fx, prog, c);
    tb_technique(fx, "T");
    tb_pass(fx, "P", prog, 0, 0);
    return fx;
}

static void test_uniform_colour_pixels(void) {
    hfx_effect *fx = load(color_effect());
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), (float[4]){1, 0.5f, 0.25f, 1}, 4), HFX_OK);
    clear(0, 0, 0, 0);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    draw_full();
    rt_check_pixel(gl, 3, 4, 255, 128, 64, 255); /* 0.5 * 255 = 127.5 and 0.25 * 255 = 63.75 round up */
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), (float[4]){0, 1, 0, 1}, 4), HFX_OK);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    draw_full();
    rt_check_pixel(gl, 10, 12, 0, 255, 0, 255);
    CHECK_INT(hfx_pass_attribute_location(pass, "POSITION0"), 0);
    CHECK_INT(hfx_pass_attribute_location(pass, "position"), 0);
    CHECK_INT(hfx_pass_attribute_location(pass, "TEXCOORD0"), -1);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
}

static const char *const vs_matrix =
    "#version 330\n"
    "layout(location = 0) in vec2 POSITION0;\n"
    "uniform mat4 WorldViewProj;\n"
    "void main() { gl_Position = WorldViewProj * vec4(POSITION0, 0.5, 1.0); }\n";

/* XNA's matrices are row-major with row vectors: mul(v, M). Scale by 0.25 and translate
 * x by +0.5: the full-screen quad becomes x in [0.25, 0.75], y in [-0.25, 0.25] (NDC). */
static void test_matrix_upload(void) {
    hfx_fx_effect *cfx = tb_new();
    uint32_t m = tb_param(cfx, "WorldViewProj", "WorldViewProj", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 4, 4, 0, HFX_NONE, 0, 16);
    uint32_t c = tb_param(cfx, "Color", "Color", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 16, 4);
    uint32_t prog = tb_program(cfx, vs_matrix, tb_fs_color);
    tb_uses(cfx, prog, m);
    tb_uses(cfx, prog, c);
    tb_technique(cfx, "T");
    tb_pass(cfx, "P", prog, 0, 0);
    hfx_effect *fx = load(cfx);
    const float xform[16] = {0.25f, 0, 0, 0, 0, 0.25f, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "WorldViewProj"), xform), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), (float[4]){1, 1, 1, 1}, 4), HFX_OK);
    clear(0, 0, 0, 1);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(fx), 0)), HFX_OK);
    draw_full();
    /* NDC x 0.5 is column 12 of 16; y 0 is between rows 7 and 8 */
    rt_check_pixel(gl, 12, 8, 255, 255, 255, 255);
    rt_check_pixel(gl, 8, 8, 0, 0, 0, 255);   /* NDC x 0.06: left of the quad */
    rt_check_pixel(gl, 12, 2, 0, 0, 0, 255);  /* NDC y 0.69: above it */
    float got[16];
    g.GetUniformfv(current_program(), g.GetUniformLocation(current_program(), "WorldViewProj"), got);
    for (int k = 0; k < 16; k++) CHECK_NEAR(got[k], xform[k], 0); /* uploaded as given, transpose = GL_FALSE */
    hfx_effect_destroy(fx);
}

static const char *const fs_spots =
    "#version 330\n"
    "struct Spot { vec3 Posicion; vec4 Color; };\n"
    "uniform Spot spots[2];\n"
    "uniform float weights[3];\n"
    "uniform int count;\n"
    "uniform bool flag;\n"
    "out vec4 hfx_out0;\n"
    "void main() {\n"
    "    hfx_out0 = spots[1].Color * weights[2] + vec4(spots[0].Posicion, 0.0) * weights[0];\n"
    "    if (flag) hfx_out0.b = float(count) / 4.0;\n"
    "}\n";

static hfx_fx_effect *spots_effect(void) {
    hfx_fx_effect *fx = tb_new();
    uint32_t spots = tb_param(fx, "spots", "spots", HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 2, HFX_NONE, 0, 14);
    uint32_t w = tb_param(fx, "weights", "weights", HFX_CLASS_SCALAR, HFX_TYPE_FLOAT, 1, 1, 3, HFX_NONE, 14, 3);
    uint32_t count = tb_param(fx, "count", "count", HFX_CLASS_SCALAR, HFX_TYPE_INT, 1, 1, 0, HFX_NONE, 17, 1);
    uint32_t flag = tb_param(fx, "flag", "flag", HFX_CLASS_SCALAR, HFX_TYPE_BOOL, 1, 1, 0, HFX_NONE, 18, 1);
    uint32_t s0 = tb_param(fx, "", NULL, HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 0, spots, 0, 7);
    tb_param(fx, "", NULL, HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 0, spots, 7, 7);
    tb_children(fx, spots, s0, 2);
    for (uint32_t e = 0; e < 2; e++) {
        uint32_t a = tb_param(fx, "Posicion", "Posicion", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 3, 0, s0 + e, 7 * e, 3);
        tb_param(fx, "Color", "Color", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, s0 + e, 7 * e + 3, 4);
        tb_children(fx, s0 + e, a, 2);
    }
    uint32_t we = fx->param_count;
    for (uint32_t e = 0; e < 3; e++) tb_param(fx, "", NULL, HFX_CLASS_SCALAR, HFX_TYPE_FLOAT, 1, 1, 0, w, 14 + e, 1);
    tb_children(fx, w, we, 3);
    uint32_t prog = tb_program(fx, tb_vs_pos, fs_spots);
    tb_uses(fx, prog, spots);
    tb_uses(fx, prog, w);
    tb_uses(fx, prog, count);
    tb_uses(fx, prog, flag);
    tb_technique(fx, "T");
    tb_pass(fx, "P", prog, 0, 0);
    return fx;
}

static void test_struct_array_and_int_uniforms(void) {
    hfx_effect *fx = load(spots_effect());
    hfx_param *spots = hfx_effect_param(fx, "spots");
    CHECK_INT(hfx_param_set_floats(hfx_param_member(hfx_param_element(spots, 1), "Color"), (float[4]){0.5f, 1, 0, 1}, 4), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_param_member(hfx_param_element(spots, 0), "Posicion"), (float[3]){0.5f, 0, 0}, 3), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "weights"), (float[3]){1, 0, 0.5f}, 3), HFX_OK);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "count"), 3), HFX_OK);
    CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "flag"), 1), HFX_OK);
    clear(0, 0, 0, 0);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(fx), 0)), HFX_OK);
    draw_full();
    /* r = 0.5 * 0.5 + 0.5 * 1 = 0.75; g = 1 * 0.5; b = 3 / 4; a = 1 * 0.5 */
    rt_check_pixel(gl, 5, 5, 191, 128, 191, 128);
    GLuint prog = current_program();
    float pos[3] = {0};
    g.GetUniformfv(prog, g.GetUniformLocation(prog, "spots[0].Posicion"), pos);
    CHECK_NEAR(pos[0], 0.5, 0);
    float w2 = 0;
    g.GetUniformfv(prog, g.GetUniformLocation(prog, "weights[2]"), &w2);
    CHECK_NEAR(w2, 0.5, 0);
    GLint count = 0;
    g.GetUniformiv(prog, g.GetUniformLocation(prog, "count"), &count);
    CHECK_INT(count, 3);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
}

/* A device whose GL calls are counted. */
static void test_unchanged_apply_makes_no_gl_call(void) {
    hfx_device *cdev = hfx_device_create_gl(tc_loader);
    CHECK(cdev != NULL);
    hfx_fx_effect *cfx = color_effect();
    uint32_t tp = tb_param(cfx, "tex", NULL, HFX_CLASS_OBJECT, HFX_TYPE_TEXTURE2D, 0, 0, 0, HFX_NONE, 0, 0);
    uint32_t sp = tb_param(cfx, "samp", "samp", HFX_CLASS_OBJECT, HFX_TYPE_SAMPLER2D, 0, 0, 0, HFX_NONE, 0, 0);
    uint32_t s = tb_sampler(cfx, sp, tp, HFX_FX_DIM_2D);
    uint32_t first = cfx->state_count;
    tb_state_e(cfx, "MinFilter", 0, "Linear");
    tb_sampler_states(cfx, s, first, 1);
    tb_sampler_use(cfx, 0, "samp", s, 0);
    first = cfx->state_count;
    tb_state_e(cfx, "CullMode", 0, "None");
    tb_state_e(cfx, "ZEnable", 0, "False");
    tb_state_e(cfx, "AlphaBlendEnable", 0, "True");
    tb_state_e(cfx, "SrcBlend", 0, "SrcAlpha");
    tb_state_e(cfx, "DestBlend", 0, "InvSrcAlpha");
    tb_state_e(cfx, "StencilEnable", 0, "True");
    cfx->passes[0].first_state = first;
    cfx->passes[0].state_count = cfx->state_count - first;
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(cdev, cfx, NULL, &errors);
    CHECK(fx != NULL);
    hfx_free(errors);
    GLuint tex = 0;
    g.GenTextures(1, &tex);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "tex"), tex), HFX_OK);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    tc_reset();
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK(tc_calls() > 0);
    CHECK_INT(tc_count("glUseProgram"), 1);
    CHECK_INT(tc_count("glUniform4fv"), 1);
    CHECK_INT(tc_count("glBindTexture"), 1);
    CHECK_INT(tc_count("glBindSampler"), 1);
    tc_reset();
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 0);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), (float[4]){0, 0, 0, 0}, 4), HFX_OK); /* same value */
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 0);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), (float[4]){1, 0, 0, 0}, 4), HFX_OK);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 1);
    CHECK_INT(tc_count("glUniform4fv"), 1);
    g.DeleteTextures(1, &tex);
    hfx_effect_destroy(fx);
    hfx_device_destroy(cdev);
    g.UseProgram(0);
}

/* Fifty float parameters, all read by one program; changing one makes one upload. */
static void test_one_changed_float_of_fifty(void) {
    hfx_device *cdev = hfx_device_create_gl(tc_loader);
    hfx_fx_effect *cfx = tb_new();
    char fs[8192] = "#version 330\nout vec4 hfx_out0;\n", name[16];
    for (uint32_t i = 0; i < 50; i++) {
        snprintf(name, sizeof name, "p%u", (unsigned)i);
        tb_param(cfx, name, name, HFX_CLASS_SCALAR, HFX_TYPE_FLOAT, 1, 1, 0, HFX_NONE, i, 1);
        snprintf(fs + strlen(fs), sizeof fs - strlen(fs), "uniform float p%u;\n", (unsigned)i);
    }
    strcat(fs, "void main() { float s = 0.0;\n");
    for (uint32_t i = 0; i < 50; i++) snprintf(fs + strlen(fs), sizeof fs - strlen(fs), "s += p%u * %u.0;\n", (unsigned)i, (unsigned)(i + 1));
    strcat(fs, "hfx_out0 = vec4(s / 255.0, 0.0, 0.0, 1.0); }\n");
    uint32_t prog = tb_program(cfx, tb_vs_pos, fs);
    for (uint32_t i = 0; i < 50; i++) tb_uses(cfx, prog, i);
    tb_technique(cfx, "T");
    tb_pass(cfx, "P", prog, 0, 0);
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(cdev, cfx, NULL, &errors);
    CHECK(fx != NULL);
    hfx_free(errors);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    tc_reset();
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "p17"), 2.0f), HFX_OK);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 1);
    CHECK_INT(tc_count("glUniform1fv"), 1);
    clear(0, 0, 0, 0);
    draw_full();
    rt_check_pixel(gl, 1, 1, 36, 0, 0, 255); /* 2 * (17 + 1) = 36 */
    hfx_effect_destroy(fx);
    hfx_device_destroy(cdev);
    g.UseProgram(0);
}

/* Clones share the GL program; each Apply uploads that clone's values. */
static void test_clones_share_programs(void) {
    hfx_effect *a = load(color_effect());
    hfx_effect *b = hfx_effect_clone(a);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(a, "Color"), (float[4]){1, 0, 0, 1}, 4), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(b, "Color"), (float[4]){0, 0, 1, 1}, 4), HFX_OK);
    hfx_pass *pa = hfx_technique_pass(hfx_effect_current_technique(a), 0);
    hfx_pass *pb = hfx_technique_pass(hfx_effect_current_technique(b), 0);
    clear(0, 0, 0, 0);
    hfx_pass_apply(pa);
    draw_full();
    rt_check_pixel(gl, 0, 0, 255, 0, 0, 255);
    hfx_pass_apply(pb);
    draw_full();
    rt_check_pixel(gl, 0, 0, 0, 0, 255, 255);
    hfx_pass_apply(pa);
    draw_full();
    rt_check_pixel(gl, 0, 0, 255, 0, 0, 255);
    hfx_effect_destroy(a);
    hfx_pass_apply(pb);
    draw_full();
    rt_check_pixel(gl, 0, 0, 0, 0, 255, 255);
    hfx_effect_destroy(b);
}

static const char *const vs_fixup =
    "#version 330\n"
    "layout(location = 0) in vec2 POSITION0;\n"
    "uniform vec4 hfx_pos_fixup;\n"
    "void main() {\n"
    "    gl_Position = vec4(POSITION0, 0.5, 1.0);\n"
    "    gl_Position.y *= 1.0 - 2.0 * hfx_pos_fixup.z;\n"
    "    gl_Position.xy += hfx_pos_fixup.xy * gl_Position.w;\n"
    "}\n";

static void read_fixup(float out[4]) {
    GLuint prog = current_program();
    g.GetUniformfv(prog, g.GetUniformLocation(prog, "hfx_pos_fixup"), out);
}

/* docs/conventions.md: (1/W, -1/H, 0, H) on the default framebuffer, (1/W, 1/H, 1, H) with the
 * front face flipped in a framebuffer object. */
static void test_pos_fixup_follows_viewport_and_target(void) {
    hfx_fx_effect *cfx = tb_new();
    uint32_t c = tb_param(cfx, "Color", "Color", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 0, 4);
    uint32_t prog = tb_program(cfx, vs_fixup, tb_fs_color);
    tb_uses(cfx, prog, c);
    tb_technique(cfx, "T");
    tb_pass(cfx, "P", prog, 0, 0);
    hfx_effect *fx = load(cfx);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    float f[4];
    CHECK_INT(hfx_effect_begin(fx), HFX_OK);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    read_fixup(f);
    CHECK_NEAR(f[0], 1.0 / W, 0);
    CHECK_NEAR(f[1], -1.0 / H, 0);
    CHECK_NEAR(f[2], 0, 0);
    CHECK_NEAR(f[3], H, 0);
    GLint face = 0;
    g.GetIntegerv(GL_FRONT_FACE, &face);
    CHECK_INT(face, GL_CW);
    hfx_device_set_viewport(dev, 0, 0, 8, 4);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    read_fixup(f);
    CHECK_NEAR(f[0], 1.0 / 8, 0);
    CHECK_NEAR(f[3], 4, 0);
    GLint vp[4];
    g.GetIntegerv(GL_VIEWPORT, vp);
    CHECK_INT(vp[3], 4);
    CHECK_INT(hfx_effect_end(fx), HFX_OK);
    /* a framebuffer object: y flips to D3D9's row order, and the front face with it */
    GLuint tex, fbo;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    g.BindTexture(GL_TEXTURE_2D, 0);
    g.GenFramebuffers(1, &fbo);
    g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    g.Viewport(0, 0, 4, 2);
    CHECK_INT(hfx_effect_begin(fx), HFX_OK);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    read_fixup(f);
    CHECK_NEAR(f[0], 0.25, 0);
    CHECK_NEAR(f[1], 0.5, 0);
    CHECK_NEAR(f[2], 1, 0);
    CHECK_NEAR(f[3], 2, 0);
    g.GetIntegerv(GL_FRONT_FACE, &face);
    CHECK_INT(face, GL_CCW);
    CHECK_INT(hfx_effect_end(fx), HFX_OK);
    g.GetIntegerv(GL_FRONT_FACE, &face);
    CHECK_INT(face, GL_CW); /* what begin found */
    g.BindFramebuffer(GL_FRAMEBUFFER, 0);
    g.DeleteFramebuffers(1, &fbo);
    g.DeleteTextures(1, &tex);
    hfx_device_set_viewport(dev, 0, 0, W, H);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
}

/* Applying a pass again after another one rebinds its program; with nothing in between it
 * makes no call (the same-pass path), and the application's own glUseProgram is seen only
 * after hfx_device_sync. */
static void test_reapply_and_sync(void) {
    hfx_device *cdev = hfx_device_create_gl(tc_loader);
    hfx_effect *a = hfx_rt_effect_from_fx(cdev, color_effect(), NULL, NULL);
    hfx_effect *b = hfx_rt_effect_from_fx(cdev, color_effect(), NULL, NULL);
    CHECK(a && b);
    hfx_pass *pa = hfx_technique_pass(hfx_effect_current_technique(a), 0);
    hfx_pass *pb = hfx_technique_pass(hfx_effect_current_technique(b), 0);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(a, "Color"), (float[4]){1, 0, 0, 1}, 4), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(b, "Color"), (float[4]){0, 1, 0, 1}, 4), HFX_OK);
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    GLuint prog_a = current_program();
    tc_reset();
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    CHECK_INT(tc_calls(), 0);
    CHECK_INT(hfx_pass_apply(pb), HFX_OK);
    CHECK(current_program() != prog_a);
    tc_reset();
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    CHECK_INT(tc_count("glUseProgram"), 1);
    CHECK_INT(current_program(), prog_a);
    clear(0, 0, 0, 0);
    draw_full();
    rt_check_pixel(gl, 2, 2, 255, 0, 0, 255);
    g.UseProgram(0); /* behind hfx's back: trusted shadow, so not seen... */
    tc_reset();
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    CHECK_INT(tc_calls(), 0);
    hfx_device_sync(cdev); /* ...until the application says so */
    tc_reset();
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    CHECK_INT(tc_count("glUseProgram"), 1);
    CHECK_INT(current_program(), prog_a);
    hfx_device_sync(NULL);
    hfx_effect_destroy(a);
    hfx_effect_destroy(b);
    hfx_device_destroy(cdev);
    g.UseProgram(0);
}

/* A second begin is refused with HFX_ERR_STATE (a call out of order), so end restores what the
 * first begin saw; an end without begin gets the same code. */
static void test_begin_twice(void) {
    hfx_fx_effect *cfx = color_effect();
    uint32_t first = cfx->state_count;
    tb_state_e(cfx, "AlphaBlendEnable", 0, "True");
    cfx->passes[0].first_state = first;
    cfx->passes[0].state_count = cfx->state_count - first;
    hfx_effect *fx = load(cfx);
    CHECK(hfx_effect_device(fx) == dev);
    CHECK(hfx_effect_device(NULL) == NULL);
    g.Disable(GL_BLEND);
    CHECK_INT(hfx_effect_begin(fx), HFX_OK);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(fx), 0)), HFX_OK);
    CHECK_INT(g.IsEnabled(GL_BLEND), GL_TRUE);
    CHECK_INT(hfx_effect_begin(fx), HFX_ERR_STATE);
    CHECK(strstr(hfx_device_last_error(dev), "hfx_effect_begin twice") != NULL);
    CHECK_STR(hfx_result_string(HFX_ERR_STATE), "a call out of order");
    CHECK_INT(hfx_effect_end(fx), HFX_OK);
    CHECK_INT(g.IsEnabled(GL_BLEND), GL_FALSE);
    CHECK_INT(hfx_effect_end(fx), HFX_ERR_STATE);
    CHECK_STR(hfx_device_last_error(dev), "hfx_effect_end without hfx_effect_begin (a call out of order)");
    CHECK_INT(hfx_effect_begin(fx), HFX_OK); /* the pair works again after the refusals */
    CHECK_INT(hfx_effect_end(fx), HFX_OK);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    CHECK(dev != NULL);
    vao = tgl_triangles(&g, full, 6, &vbo);
    g.Viewport(0, 0, W, H);
    RUN(test_uniform_colour_pixels);
    RUN(test_matrix_upload);
    RUN(test_struct_array_and_int_uniforms);
    RUN(test_unchanged_apply_makes_no_gl_call);
    RUN(test_one_changed_float_of_fifty);
    RUN(test_clones_share_programs);
    RUN(test_pos_fixup_follows_viewport_and_target);
    RUN(test_reapply_and_sync);
    RUN(test_begin_twice);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
