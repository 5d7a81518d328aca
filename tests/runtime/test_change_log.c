/* test_change_log.c: the set + Apply fast path (runtime/params.c, program.c): what each Apply
 * uploads, counted through the GL function table, when the change log is walked, overflows,
 * is shared by two programs, or is left for a clone; and the set functions' fast checks
 * against their long way (array prefixes, refusals). */
#include "gl_context.h"
#include "internal.h"
#include "rt_support.h"
#include "test.h"

static test_gl *gl;
static tgl g;
static hfx_device *dev; /* counted */

#define N 8

/* N float4 parameters p0..p7 and a float4x4 M; pass 0 reads all, pass 1 reads p0 and M. */
static hfx_effect *load(void) {
    hfx_fx_effect *cfx = tb_new();
    char name[16], fs[4096] = "#version 330\nout vec4 hfx_out0;\nuniform mat4 M;\n";
    for (uint32_t i = 0; i < N; i++) {
        snprintf(name, sizeof name, "p%u", (unsigned)i);
        tb_param(cfx, name, name, HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, i * 4, 4);
        snprintf(fs + strlen(fs), sizeof fs - strlen(fs), "uniform vec4 p%u;\n", (unsigned)i);
    }
    uint32_t m = tb_param(cfx, "M", "M", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 4, 4, 0, HFX_NONE, N * 4, 16);
    char fs1[4096];
    strcpy(fs1, fs);
    strcat(fs, "void main() { vec4 s = M[0];\n");
    for (uint32_t i = 0; i < N; i++) snprintf(fs + strlen(fs), sizeof fs - strlen(fs), "s += p%u;\n", (unsigned)i);
    strcat(fs, "hfx_out0 = s; }\n");
    strcat(fs1, "void main() { hfx_out0 = p0 + M[1]; }\n");
    uint32_t a = tb_program(cfx, tb_vs_pos, fs), b = tb_program(cfx, tb_vs_pos, fs1);
    for (uint32_t i = 0; i < N; i++) tb_uses(cfx, a, i);
    tb_uses(cfx, a, m);
    tb_uses(cfx, b, 0);
    tb_uses(cfx, b, m);
    tb_technique(cfx, "T");
    tb_pass(cfx, "A", a, 0, 0);
    tb_pass(cfx, "B", b, 0, 0);
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, cfx, NULL, &errors);
    CHECK(fx != NULL);
    hfx_free(errors);
    return fx;
}

static hfx_pass *pass(hfx_effect *fx, int i) { return hfx_technique_pass(hfx_effect_current_technique(fx), (size_t)i); }

static int set(hfx_effect *fx, int i, float v) {
    char name[16];
    snprintf(name, sizeof name, "p%d", i);
    return hfx_param_set_floats(hfx_effect_param(fx, name), (float[4]){v, 0, 0, 0}, 4);
}

/* Reads p<i>.x back from the program GL has bound. */
static float gl_value(int i) {
    GLint prog = 0;
    g.GetIntegerv(GL_CURRENT_PROGRAM, &prog);
    char name[16];
    snprintf(name, sizeof name, "p%d", i);
    float v[4] = {-1, -1, -1, -1};
    g.GetUniformfv((GLuint)prog, g.GetUniformLocation((GLuint)prog, name), v);
    return v[0];
}

static void test_each_change_uploaded_once(void) {
    hfx_effect *fx = load();
    hfx_pass_apply(pass(fx, 0));
    tc_reset();
    CHECK_INT(set(fx, 3, 1), HFX_OK);
    CHECK_INT(set(fx, 3, 2), HFX_OK); /* twice before Apply: one upload of the last value */
    CHECK_INT(set(fx, 5, 7), HFX_OK);
    CHECK_INT(set(fx, 5, 0), HFX_OK); /* back to the value GL holds: still uploaded once, harmless */
    hfx_pass_apply(pass(fx, 0));
    CHECK_INT(tc_count("glUniform4fv"), 2);
    CHECK_NEAR(gl_value(3), 2, 0);
    tc_reset();
    hfx_pass_apply(pass(fx, 0));
    CHECK_INT(tc_calls(), 0);
    hfx_effect_destroy(fx);
}

/* Both passes follow the same log: each uploads what it reads, once. */
static void test_two_programs_share_the_log(void) {
    hfx_effect *fx = load();
    hfx_pass_apply(pass(fx, 0));
    hfx_pass_apply(pass(fx, 1));
    tc_reset();
    float m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "M"), m), HFX_OK);
    CHECK_INT(set(fx, 0, 4), HFX_OK);
    CHECK_INT(set(fx, 6, 4), HFX_OK);
    hfx_pass_apply(pass(fx, 0));
    CHECK_INT(tc_count("glUniform4fv"), 2);
    CHECK_INT(tc_count("glUniformMatrix4fv"), 1);
    tc_reset();
    hfx_pass_apply(pass(fx, 1));
    CHECK_INT(tc_count("glUniform4fv"), 1); /* p0; p6 is not read by B */
    CHECK_INT(tc_count("glUniformMatrix4fv"), 1);
    CHECK_NEAR(gl_value(0), 4, 0);
    tc_reset();
    hfx_pass_apply(pass(fx, 0));
    hfx_pass_apply(pass(fx, 1));
    CHECK_INT(tc_count("glUniform4fv") + tc_count("glUniformMatrix4fv"), 0);
    float back[16];
    CHECK_INT(hfx_param_get_matrix(hfx_effect_param(fx, "M"), back), HFX_OK);
    CHECK_NEAR(back[13], 14, 0);
    hfx_effect_destroy(fx);
}

/* Many more changes than the log holds between two looks: a full scan, still exact. */
static void test_log_overflow_falls_back_to_a_scan(void) {
    hfx_effect *fx = load();
    hfx_pass_apply(pass(fx, 0));
    hfx_pass_apply(pass(fx, 1));
    for (int k = 0; k < 5000; k++) {
        CHECK_INT(set(fx, k % 2 ? 2 : 7, (float)k), HFX_OK);
        if (k % 1000 == 0) hfx_pass_apply(pass(fx, 1)); /* B keeps looking, reads neither */
    }
    tc_reset();
    hfx_pass_apply(pass(fx, 0));
    CHECK_INT(tc_count("glUniform4fv"), 2);
    CHECK_NEAR(gl_value(2), 4999, 0);
    CHECK_NEAR(gl_value(7), 4998, 0);
    tc_reset();
    hfx_pass_apply(pass(fx, 1));
    CHECK_INT(tc_calls(), 1); /* glUseProgram only */
    hfx_effect_destroy(fx);
}

/* A clone's first Apply sends only the values that differ from what GL holds. */
static void test_clone_sends_only_differences(void) {
    hfx_effect *a = load();
    hfx_pass_apply(pass(a, 0));
    hfx_effect *b = hfx_effect_clone(a);
    CHECK_INT(set(b, 1, 9), HFX_OK);
    tc_reset();
    hfx_pass_apply(pass(b, 0));
    CHECK_INT(tc_count("glUniform4fv"), 1);
    CHECK_NEAR(gl_value(1), 9, 0);
    tc_reset();
    hfx_pass_apply(pass(a, 0));
    CHECK_INT(tc_count("glUniform4fv"), 1); /* p1 back to a's value */
    CHECK_NEAR(gl_value(1), 0, 0);
    CHECK_INT(set(a, 1, 3), HFX_OK);
    hfx_pass_apply(pass(a, 0));
    CHECK_NEAR(gl_value(1), 3, 0);
    hfx_effect_destroy(b);
    hfx_effect_destroy(a);
}

/* The set functions' one-compare checks agree with the long way. */
static void test_set_checks(void) {
    hfx_fx_effect *cfx = tb_new();
    uint32_t arr = tb_param(cfx, "arr", "arr", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 2, 3, HFX_NONE, 0, 6);
    tb_param(cfx, "iv", "iv", HFX_CLASS_VECTOR, HFX_TYPE_INT, 1, 3, 0, HFX_NONE, 6, 3);
    tb_param(cfx, "bv", "bv", HFX_CLASS_VECTOR, HFX_TYPE_BOOL, 1, 2, 0, HFX_NONE, 9, 2);
    tb_param(cfx, "m23", "m23", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 2, 3, 0, HFX_NONE, 11, 6);
    tb_top_count(cfx, 4);
    (void)arr;
    tb_technique(cfx, "T");
    tb_pass(cfx, "P", HFX_NONE, 0, 0);
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, cfx, NULL, &errors);
    CHECK(fx != NULL);
    hfx_free(errors);
    hfx_param *pa = hfx_effect_param(fx, "arr"), *pi = hfx_effect_param(fx, "iv"), *pb = hfx_effect_param(fx, "bv");
    hfx_param *pm = hfx_effect_param(fx, "m23");
    float f[6] = {1, 2, 3, 4, 5, 6}, out[6] = {0};
    uint64_t s0 = fx->stamps[0];
    CHECK_INT(hfx_param_set_floats(pa, f, 4), HFX_OK); /* a prefix of two elements */
    CHECK(fx->stamps[0] != s0);
    CHECK_INT(hfx_param_get_floats(pa, out, 6), HFX_OK);
    CHECK_NEAR(out[3], 4, 0);
    CHECK_NEAR(out[4], 0, 0);
    CHECK_INT(hfx_param_set_floats(pa, f, 3), HFX_ERR_COUNT);
    CHECK_INT(hfx_param_set_floats(pa, f, 8), HFX_ERR_COUNT);
    CHECK_INT(hfx_param_set_floats(pa, f, 6), HFX_OK);
    CHECK_INT(hfx_param_set_floats(pi, f, 3), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_set_ints(pi, (int[3]){1, 2, 3}, 3), HFX_OK);
    CHECK_INT(hfx_param_set_ints(pi, (int[2]){1, 2}, 2), HFX_ERR_COUNT);
    CHECK_INT(hfx_param_set_ints(pb, (int[2]){5, 0}, 2), HFX_OK);
    int iv[2] = {9, 9};
    CHECK_INT(hfx_param_get_ints(pb, iv, 2), HFX_OK);
    CHECK_INT(iv[0], 1); /* bools are 0/1 */
    CHECK_INT(iv[1], 0);
    uint64_t sb = fx->stamps[2];
    CHECK_INT(hfx_param_set_ints(pb, (int[2]){7, 0}, 2), HFX_OK); /* still true, false: no new version */
    CHECK(fx->stamps[2] == sb);
    float m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}, back[16];
    CHECK_INT(hfx_param_set_matrix(pm, m), HFX_OK);
    CHECK_INT(hfx_param_get_matrix(pm, back), HFX_OK);
    CHECK_NEAR(back[4], 5, 0);
    CHECK_NEAR(back[6], 7, 0);
    CHECK_NEAR(back[3], 0, 0);
    CHECK_INT(hfx_param_set_matrix_transpose(pm, m), HFX_OK);
    CHECK_INT(hfx_param_get_matrix(pm, back), HFX_OK);
    CHECK_NEAR(back[1], 5, 0);
    CHECK_INT(hfx_param_set_matrix(pa, m), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_set_floats(NULL, f, 6), HFX_ERR_NULL);
    CHECK_INT(hfx_param_set_floats(pa, NULL, 6), HFX_ERR_NULL);
    CHECK_INT(hfx_param_set_ints(NULL, iv, 2), HFX_ERR_NULL);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(16, 16);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(tc_loader);
    CHECK(dev != NULL);
    RUN(test_each_change_uploaded_once);
    RUN(test_two_programs_share_the_log);
    RUN(test_log_overflow_falls_back_to_a_scan);
    RUN(test_clone_sends_only_differences);
    RUN(test_set_checks);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
