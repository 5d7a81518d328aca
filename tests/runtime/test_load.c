/* test_load.c: loads that fail (GL compile and link errors, effects without code for the
 * target, corrupt indices, missing files) leave the device unchanged and usable. */
#include "files.h"
#include "gl_context.h"
#include "internal.h"
#include "rt_support.h"
#include "test.h"

static test_gl *gl;
static tgl g;
static hfx_device *dev;

static hfx_fx_effect *one_pass(const char *vs, const char *fs) {
    hfx_fx_effect *fx = tb_new();
    uint32_t c = tb_param(fx, "Color", "Color", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 0, 4);
    uint32_t prog = tb_program(fx, vs, fs);
    tb_uses(fx, prog, c);
    tb_technique(fx, "T");
    tb_pass(fx, "P", prog, 0, 0);
    return fx;
}

static GLint current_program(void) {
    GLint p = 0;
    g.GetIntegerv(GL_CURRENT_PROGRAM, &p);
    return p;
}

static void test_glsl_compile_error(void) {
    hfx_effect *good = hfx_rt_effect_from_fx(dev, one_pass(tb_vs_pos, tb_fs_color), NULL, NULL);
    CHECK(good != NULL);
    hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(good), 0));
    GLint before = current_program();
    char *errors = NULL;
    hfx_effect *bad = hfx_rt_effect_from_fx(dev, one_pass(tb_vs_pos, "#version 330\nvoid main() { oops }\n"), NULL, &errors);
    CHECK(bad == NULL);
    CHECK_CONTAINS(errors, "test.fx: GL refused the fragment shader: ");
    CHECK_STR(hfx_device_last_error(dev), errors);
    CHECK_INT(current_program(), before);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_free(errors);
    /* the device still works */
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(good, "Color"), (float[4]){1, 0, 0, 1}, 4), HFX_OK);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(good), 0)), HFX_OK);
    hfx_effect_destroy(good);
}

static void test_glsl_link_error(void) {
    char *errors = NULL;
    hfx_effect *bad = hfx_rt_effect_from_fx(
        dev, one_pass("#version 330\nlayout(location = 0) in vec2 p;\nout vec2 v;\n"
                      "void main() { v = p; gl_Position = vec4(p, 0.0, 1.0); }\n",
                      "#version 330\nin vec3 v;\nout vec4 o;\nvoid main() { o = vec4(v, 1.0); }\n"),
        NULL, &errors);
    CHECK(bad == NULL);
    CHECK_CONTAINS(errors, "test.fx: GL refused to link a program: ");
    hfx_free(errors);
}

static void test_missing_target(void) {
    hfx_fx_effect *fx = one_pass(tb_vs_pos, tb_fs_color);
    fx->targets = 1u << HFX_TARGET_GLSL110;
    char *errors = NULL;
    CHECK(hfx_rt_effect_from_fx(dev, fx, NULL, &errors) == NULL);
    CHECK_STR(errors, "test.fx: the effect carries no code for the requested shader target");
    hfx_free(errors);
    hfx_load_options opt = {0};
    opt.target = HFX_TARGET_GLSL110;
    fx = one_pass(tb_vs_pos, tb_fs_color);
    fx->targets |= 1u << HFX_TARGET_GLSL110; /* claims it, has none */
    CHECK(hfx_rt_effect_from_fx(dev, fx, &opt, &errors) == NULL);
    CHECK_STR(errors, "test.fx: program 0 has no code for the requested GLSL target");
    hfx_free(errors);
}

static void test_corrupt_effect(void) {
    hfx_fx_effect *fx = one_pass(tb_vs_pos, tb_fs_color);
    fx->params[0].words = 400;
    char *errors = NULL;
    CHECK(hfx_rt_effect_from_fx(dev, fx, NULL, &errors) == NULL);
    CHECK_STR(errors, "test.fx: parameter 0 lies outside the effect's data");
    hfx_free(errors);
    fx = one_pass(tb_vs_pos, tb_fs_color);
    fx->passes[0].state_count = 3;
    CHECK(hfx_rt_effect_from_fx(dev, fx, NULL, &errors) == NULL);
    CHECK_STR(errors, "test.fx: pass 0 lies outside the effect's data");
    hfx_free(errors);
    fx = one_pass(tb_vs_pos, tb_fs_color);
    tb_state_p(fx, "Texture", 0, 99);
    fx->passes[0].state_count = 1;
    CHECK(hfx_rt_effect_from_fx(dev, fx, NULL, &errors) == NULL);
    CHECK_STR(errors, "test.fx: state 0 names no parameter");
    hfx_free(errors);
    fx = one_pass(tb_vs_pos, tb_fs_color);
    fx->techniques[0].pass_count = 2;
    CHECK(hfx_rt_effect_from_fx(dev, fx, NULL, &errors) == NULL);
    CHECK_STR(errors, "test.fx: technique 0 lies outside the effect's data");
    hfx_free(errors);
}

static void test_bad_files_and_arguments(void) {
    char *errors = NULL;
    CHECK(hfx_effect_load(dev, "/nonexistent/x.fx", NULL, &errors) == NULL);
    CHECK_STR(errors, "/nonexistent/x.fx: cannot read the file");
    hfx_free(errors);
    CHECK(hfx_effect_load(dev, NULL, NULL, &errors) == NULL);
    CHECK_STR(errors, "hfx_effect_load: NULL path");
    hfx_free(errors);
    CHECK(hfx_effect_load(NULL, "x.fx", NULL, &errors) == NULL);
    CHECK(errors == NULL);
    CHECK(hfx_effect_load_memory(dev, NULL, 0, "m.fx", NULL, &errors) == NULL);
    CHECK_STR(errors, "hfx_effect_load_memory: NULL data");
    hfx_free(errors);
    const char junk[] = "this is not an effect {{{";
    CHECK(hfx_effect_load_memory(dev, junk, sizeof junk - 1, "junk.fx", NULL, &errors) == NULL);
    CHECK(errors != NULL && strstr(errors, "junk.fx") != NULL);
    CHECK(strstr(hfx_device_last_error(dev), "junk.fx") != NULL);
    hfx_free(errors);
    CHECK(hfx_effect_load_memory(dev, junk, sizeof junk - 1, "junk.fx", NULL, NULL) == NULL); /* errors optional */
    hfx_effect_destroy(NULL);
    CHECK_STR(hfx_effect_warnings(NULL), "");
    CHECK_INT(hfx_effect_begin(NULL), HFX_ERR_NULL);
    CHECK_INT(hfx_effect_end(NULL), HFX_ERR_NULL);
    CHECK(hfx_device_create_gl(NULL) == NULL);
}

/* A compiled effect saved as .hfxo loads from memory and from a file, without the compiler. */
static void test_hfxo_round_trip(void) {
    hfx_fx_effect *cfx = one_pass(tb_vs_pos, tb_fs_color);
    tb_set_float(cfx, 1, 0.5f); /* Color defaults to (0, 0.5, 0, 0) */
    void *data = NULL;
    size_t size = 0;
    CHECK_INT(hfx_fx_write_hfxo(cfx, &data, &size), 0);
    hfx_fx_effect_free(cfx);
    if (!data) return;
    CHECK(hfx_fx_is_hfxo(data, size));
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, data, size, "saved.hfxo", NULL, &errors);
    CHECK(fx != NULL);
    CHECK(errors == NULL);
    float c[4] = {0};
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "Color"), c, 4), HFX_OK);
    CHECK_NEAR(c[1], 0.5, 0);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(fx), 0)), HFX_OK);
    hfx_effect_destroy(fx);
    char *dir = test_temp_dir();
    char path[512];
    snprintf(path, sizeof path, "%s/saved.hfxo", dir);
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (f) {
        fwrite(data, 1, size, f);
        fclose(f);
        fx = hfx_effect_load(dev, path, NULL, &errors);
        CHECK(fx != NULL);
        CHECK_STR(hfx_technique_name(hfx_effect_current_technique(fx)), "T");
        hfx_effect_destroy(fx);
        /* a truncated file is refused with the reader's reason */
        f = fopen(path, "wb");
        fwrite(data, 1, size / 2, f);
        fclose(f);
        CHECK(hfx_effect_load(dev, path, NULL, &errors) == NULL);
        CHECK(errors != NULL && strstr(errors, path) == errors);
        if (errors) printf("truncated: %s\n", errors);
        hfx_free(errors);
        remove(path);
    }
    remove(dir);
    free(dir);
    free(data);
}

static void *no_gl(const char *name) { (void)name; return NULL; }

static void test_device_without_gl(void) {
    CHECK(hfx_device_create_gl(no_gl) == NULL);
    hfx_device_destroy(NULL);
    CHECK_STR(hfx_device_last_error(NULL), "no device");
}

int main(void) {
    gl = test_gl_create(8, 8);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    CHECK(dev != NULL);
    RUN(test_glsl_compile_error);
    RUN(test_glsl_link_error);
    RUN(test_missing_target);
    RUN(test_corrupt_effect);
    RUN(test_bad_files_and_arguments);
    RUN(test_hfxo_round_trip);
    RUN(test_device_without_gl);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
