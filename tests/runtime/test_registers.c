/* test_registers.c: packed parameters (hfxc --pack-uniforms): one `uniform vec4 hfx_c[N]` per
 * program, as D3D9's constant registers. Checks the register image GL holds (read back element
 * by element), that Apply sends all the changed registers in one call (one changed float4 or
 * matrix alone in its own, the image kept whole), that GL trimming the
 * array's unread tail costs no error, clones, and a rendered pixel. */
#include "gl_context.h"
#include "internal.h"
#include "rt_support.h"
#include "test.h"

#define W 16
#define H 16

static test_gl *gl;
static tgl g;
static GLuint vao, vbo;

/* Parameters: A float4 (reg 0), B float (reg 1), M float3x3 (regs 2..4), World float4x4
 * (regs 5..8), C float4 as its own uniform. Words: A 0..3, B 4, M 5..13, World 14..29, C 30..33. */
static const char *const fs_all =
    "#version 330\n"
    "out vec4 hfx_out0;\n"
    "uniform vec4 hfx_c[9];\n"
    "uniform vec4 C;\n"
    "void main() {\n"
    "    vec4 A = hfx_c[0];\n"
    "    float B = hfx_c[1].x;\n"
    "    mat3 M = mat3(hfx_c[2].xyz, hfx_c[3].xyz, hfx_c[4].xyz);\n"
    "    mat4 World = mat4(hfx_c[5], hfx_c[6], hfx_c[7], hfx_c[8]);\n"
    "    hfx_out0 = vec4(A.x * B, (M * vec3(1.0, 0.0, 0.0)).y, (World * vec4(0.0, 0.0, 0.0, 1.0)).z, 1.0) + C;\n"
    "}\n";

/* Reads only hfx_c[0]: GL keeps one element of nine. */
static const char *const fs_first =
    "#version 330\n"
    "out vec4 hfx_out0;\n"
    "uniform vec4 hfx_c[9];\n"
    "void main() { hfx_out0 = hfx_c[0]; }\n";

static void uses_reg(hfx_fx_effect *fx, uint32_t prog, uint32_t param, uint32_t reg) {
    tb_uses(fx, prog, param);
    fx->programs[prog].uniforms[fx->programs[prog].uniform_count - 1].reg = reg;
}

static hfx_fx_effect *packed_effect(const char *fs) {
    hfx_fx_effect *fx = tb_new();
    uint32_t a = tb_param(fx, "A", "A", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 0, 4);
    uint32_t b = tb_param(fx, "B", "B", HFX_CLASS_SCALAR, HFX_TYPE_FLOAT, 1, 1, 0, HFX_NONE, 4, 1);
    uint32_t m = tb_param(fx, "M", "M", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 3, 3, 0, HFX_NONE, 5, 9);
    uint32_t w = tb_param(fx, "World", "World", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 4, 4, 0, HFX_NONE, 14, 16);
    uint32_t c = tb_param(fx, "C", "C", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 30, 4);
    uint32_t prog = tb_program(fx, tb_vs_pos, fs);
    tb_attribute(fx, prog, "POSITION0", "POSITION0", 0);
    uses_reg(fx, prog, a, 0);
    uses_reg(fx, prog, b, 1);
    uses_reg(fx, prog, m, 2);
    uses_reg(fx, prog, w, 5);
    tb_uses(fx, prog, c);
    fx->programs[prog].reg_count = 9;
    tb_technique(fx, "T");
    tb_pass(fx, "P", prog, 0, 0);
    return fx;
}

static hfx_effect *load(hfx_device *dev, hfx_fx_effect *cfx) {
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, cfx, NULL, &errors);
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : "(no message)");
    CHECK(fx != NULL);
    hfx_free(errors);
    return fx;
}

static hfx_pass *first_pass(hfx_effect *fx) { return hfx_technique_pass(hfx_effect_current_technique(fx), 0); }

/* Register i of the bound program, as GL holds it. */
static void read_reg(uint32_t i, float out[4]) {
    GLint prog = 0;
    g.GetIntegerv(GL_CURRENT_PROGRAM, &prog);
    char name[16];
    snprintf(name, sizeof name, "hfx_c[%u]", (unsigned)i);
    GLint loc = g.GetUniformLocation((GLuint)prog, name);
    CHECK(loc >= 0);
    out[0] = out[1] = out[2] = out[3] = -1;
    if (loc >= 0) g.GetUniformfv((GLuint)prog, loc, out);
}

static void check_reg(uint32_t i, int comps, float x, float y, float z, float w) {
    float r[4];
    read_reg(i, r);
    const float want[4] = {x, y, z, w};
    for (int k = 0; k < comps; k++) CHECK_NEAR(r[k], want[k], 0);
}

static void set(hfx_effect *fx, const char *name, const float *v, size_t n) {
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, name), v, n), HFX_OK);
}

/* Rows padded to four components: a float3x3's rows in .xyz of three registers, a float4x4's
 * rows in four, XNA's translation (words 12..14) in the last. */
static void test_register_layout(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *fx = load(dev, packed_effect(fs_all));
    float m[9], w[16];
    for (int i = 0; i < 9; i++) m[i] = (float)(10 + i);
    for (int i = 0; i < 16; i++) w[i] = (float)(20 + i);
    set(fx, "A", (float[4]){1, 2, 3, 4}, 4);
    set(fx, "B", (float[1]){5}, 1);
    set(fx, "M", m, 9);
    set(fx, "World", w, 16);
    CHECK_INT(hfx_pass_apply(first_pass(fx)), HFX_OK);
    check_reg(0, 4, 1, 2, 3, 4);
    check_reg(1, 1, 5, 0, 0, 0);
    check_reg(2, 3, 10, 11, 12, 0);
    check_reg(3, 3, 13, 14, 15, 0);
    check_reg(4, 3, 16, 17, 18, 0);
    check_reg(5, 4, 20, 21, 22, 23);
    check_reg(8, 4, 32, 33, 34, 35);
    /* a later change reaches GL too, and leaves its neighbours as they were */
    set(fx, "B", (float[1]){-2.5f}, 1);
    CHECK_INT(hfx_pass_apply(first_pass(fx)), HFX_OK);
    check_reg(1, 1, -2.5f, 0, 0, 0);
    check_reg(0, 4, 1, 2, 3, 4);
    check_reg(2, 3, 10, 11, 12, 0);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* Everything changed in the registers goes up in one glUniform4fv; the unpacked C has its own. */
static void test_one_call_for_the_changed_range(void) {
    hfx_device *dev = hfx_device_create_gl(tc_loader);
    hfx_effect *fx = load(dev, packed_effect(fs_all));
    hfx_pass *pass = first_pass(fx);
    tc_reset();
    CHECK_INT(hfx_pass_apply(pass), HFX_OK); /* first: every register, and C */
    CHECK_INT(tc_count("glUniform4fv"), 2);
    tc_reset();
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 0);
    float w[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 7, 8, 9, 1};
    set(fx, "A", (float[4]){0.5f, 0, 0, 0}, 4);
    set(fx, "World", w, 16);
    set(fx, "B", (float[1]){3}, 1);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 1);
    CHECK_INT(tc_count("glUniform4fv"), 1);
    check_reg(8, 4, 7, 8, 9, 1);
    check_reg(1, 1, 3, 0, 0, 0);
    tc_reset();
    set(fx, "C", (float[4]){0, 0, 0, 1}, 4);
    set(fx, "B", (float[1]){4}, 1);
    set(fx, "B", (float[1]){4}, 1); /* the same value: no second entry, no second send */
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 2);
    tc_reset();
    set(fx, "B", (float[1]){6}, 1); /* one change since the last Apply: Apply's shortest way */
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 1);
    check_reg(1, 1, 6, 0, 0, 0);
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* A float4 (reg 0), a float4x4 (regs 1..4) and a float4 (reg 5): rows of four, whose registers
 * are their words as they are. */
static hfx_fx_effect *rows_of_four_effect(void) {
    static const char *const fs =
        "#version 330\n"
        "out vec4 hfx_out0;\n"
        "uniform vec4 hfx_c[6];\n"
        "void main() { hfx_out0 = hfx_c[0] + hfx_c[1] + hfx_c[2] + hfx_c[3] + hfx_c[4] + hfx_c[5]; }\n";
    hfx_fx_effect *fx = tb_new();
    uint32_t a = tb_param(fx, "A", "A", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 0, 4);
    uint32_t w = tb_param(fx, "World", "World", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 4, 4, 0, HFX_NONE, 4, 16);
    uint32_t e = tb_param(fx, "E", "E", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 20, 4);
    uint32_t prog = tb_program(fx, tb_vs_pos, fs);
    tb_attribute(fx, prog, "POSITION0", "POSITION0", 0);
    uses_reg(fx, prog, a, 0);
    uses_reg(fx, prog, w, 1);
    uses_reg(fx, prog, e, 5);
    fx->programs[prog].reg_count = 6;
    tb_technique(fx, "T");
    tb_pass(fx, "P", prog, 0, 0);
    return fx;
}

/* One changed float4 or matrix is one glUniform4fv over its own registers, and it also lands in
 * the register image: a later range over those registers (A and E changed, World not) sends
 * World's latest value, not the one before the single change. */
static void test_one_change_keeps_the_image(void) {
    hfx_device *dev = hfx_device_create_gl(tc_loader);
    hfx_effect *fx = load(dev, rows_of_four_effect());
    hfx_pass *pass = first_pass(fx);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    float w[16];
    for (int i = 0; i < 16; i++) w[i] = (float)(40 + i);
    tc_reset();
    set(fx, "World", w, 16);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 1);
    CHECK_INT(tc_count("glUniform4fv"), 1);
    check_reg(1, 4, 40, 41, 42, 43);
    check_reg(4, 4, 52, 53, 54, 55);
    tc_reset();
    set(fx, "A", (float[4]){1, 2, 3, 4}, 4);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 1);
    check_reg(0, 4, 1, 2, 3, 4);
    tc_reset();
    set(fx, "A", (float[4]){5, 6, 7, 8}, 4);
    set(fx, "E", (float[4]){9, 10, 11, 12}, 4);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 1); /* registers 0..5 in one call, World's from the image */
    check_reg(0, 4, 5, 6, 7, 8);
    check_reg(1, 4, 40, 41, 42, 43);
    check_reg(3, 4, 48, 49, 50, 51);
    check_reg(4, 4, 52, 53, 54, 55);
    check_reg(5, 4, 9, 10, 11, 12);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* GL keeps hfx_c[0] only: registers past it are kept on the CPU and never sent. */
static void test_unread_tail(void) {
    hfx_device *dev = hfx_device_create_gl(tc_loader);
    hfx_effect *fx = load(dev, packed_effect(fs_first));
    hfx_pass *pass = first_pass(fx);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    tc_reset();
    float w[16] = {0};
    w[14] = 2;
    set(fx, "World", w, 16);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_calls(), 0);
    set(fx, "A", (float[4]){0.25f, 0.5f, 0.75f, 1}, 4);
    set(fx, "World", (float[16]){0}, 16);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(tc_count("glUniform4fv"), 1);
    check_reg(0, 4, 0.25f, 0.5f, 0.75f, 1);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* Clones share the program and its register image; each Apply sends that clone's values. */
static void test_clones(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *a = load(dev, packed_effect(fs_all));
    hfx_effect *b = hfx_effect_clone(a);
    set(a, "A", (float[4]){1, 1, 1, 1}, 4);
    set(b, "A", (float[4]){2, 2, 2, 2}, 4);
    set(b, "B", (float[1]){9}, 1);
    CHECK_INT(hfx_pass_apply(first_pass(a)), HFX_OK);
    check_reg(0, 4, 1, 1, 1, 1);
    check_reg(1, 1, 0, 0, 0, 0);
    CHECK_INT(hfx_pass_apply(first_pass(b)), HFX_OK);
    check_reg(0, 4, 2, 2, 2, 2);
    check_reg(1, 1, 9, 0, 0, 0);
    set(a, "B", (float[1]){3}, 1);
    CHECK_INT(hfx_pass_apply(first_pass(a)), HFX_OK);
    check_reg(0, 4, 1, 1, 1, 1);
    check_reg(1, 1, 3, 0, 0, 0);
    hfx_effect_destroy(b);
    hfx_effect_destroy(a);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* The shader sees the values: A.x * B = 0.25 (63.75 -> 64), M's row 0 .y = 0.5 (127.5 -> 128),
 * World's translation z (word 14) = 0.75 (191.25 -> 191). */
static void test_pixel(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *fx = load(dev, packed_effect(fs_all));
    float m[9] = {0, 0.5f, 0, 0, 0, 0, 0, 0, 0}, w[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0.75f, 1};
    set(fx, "A", (float[4]){0.5f, 0, 0, 0}, 4);
    set(fx, "B", (float[1]){0.5f}, 1);
    set(fx, "M", m, 9);
    set(fx, "World", w, 16);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(first_pass(fx)), HFX_OK);
    g.BindVertexArray(vao);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    unsigned char px[4];
    test_gl_read(gl, 5, 5, px);
    CHECK_NEAR(px[0], 64, 1);
    CHECK_NEAR(px[1], 128, 1);
    CHECK_NEAR(px[2], 191, 1);
    CHECK_NEAR(px[3], 255, 0);
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    g.Viewport(0, 0, W, H);
    static const float full[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    vao = tgl_triangles(&g, full, 6, &vbo);
    RUN(test_register_layout);
    RUN(test_one_call_for_the_changed_range);
    RUN(test_one_change_keeps_the_image);
    RUN(test_unread_tail);
    RUN(test_clones);
    RUN(test_pixel);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    test_gl_destroy(gl);
    return test_summary();
}
