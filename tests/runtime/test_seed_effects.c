/* test_seed_effects.c: the runtime on the seed corpus, compiled by hfx's compiler: every
 * seed loads and every pass applies without a GL error; a few render known colours. Skips
 * while the compiler cannot yet produce the simplest seed. */
#include "files.h"
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

static const char *const seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
    "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
    "spot_specular.fx", "tutorial0.fx"};

static hfx_effect *load_seed(const char *name, char **errors) {
    char *path = test_seed_path(name);
    hfx_effect *fx = hfx_effect_load(dev, path, NULL, errors);
    free(path);
    return fx;
}

static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/* A full-screen quad of float3 positions on the attribute the pass reads POSITION from. */
static void draw_quad(hfx_pass *pass) {
    static const float xyz[18] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1, 0};
    void(APIENTRYP attrib)(GLuint, GLint, GLenum, GLboolean, GLsizei, const void *) = g.VertexAttribPointer;
    GLuint vao, vbo;
    g.GenVertexArrays(1, &vao);
    g.BindVertexArray(vao);
    g.GenBuffers(1, &vbo);
    g.BindBuffer(GL_ARRAY_BUFFER, vbo);
    g.BufferData(GL_ARRAY_BUFFER, sizeof xyz, xyz, GL_STATIC_DRAW);
    int loc = hfx_pass_attribute_location(pass, "POSITION");
    CHECK(loc >= 0);
    if (loc >= 0) {
        attrib((GLuint)loc, 3, GL_FLOAT, GL_FALSE, 0, NULL);
        g.EnableVertexAttribArray((GLuint)loc);
        g.DrawArrays(GL_TRIANGLES, 0, 6);
    }
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
}

static void test_every_seed_loads_and_applies(void) {
    for (size_t i = 0; i < sizeof seeds / sizeof *seeds; i++) {
        char *errors = NULL;
        hfx_effect *fx = load_seed(seeds[i], &errors);
        if (!fx) fprintf(stderr, "%s: %s\n", seeds[i], errors ? errors : "");
        CHECK(fx != NULL);
        hfx_free(errors);
        if (!fx) continue;
        hfx_effect_begin(fx);
        for (size_t t = 0; t < hfx_effect_technique_count(fx); t++) {
            hfx_technique *tech = hfx_effect_technique_at(fx, t);
            CHECK(hfx_technique_pass_count(tech) > 0);
            for (size_t p = 0; p < hfx_technique_pass_count(tech); p++) CHECK_INT(hfx_pass_apply(hfx_technique_pass(tech, p)), HFX_OK);
        }
        hfx_effect_end(fx);
        GLenum err = g.GetError();
        if (err) fprintf(stderr, "%s: GL error 0x%x\n", seeds[i], err);
        CHECK_INT(err, GL_NO_ERROR);
        hfx_effect_destroy(fx);
    }
}

static void test_fxcomposer_empty_renders_white(void) {
    hfx_effect *fx = load_seed("fxcomposer_empty.fx", NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_param *wvp = hfx_effect_param_by_semantic(fx, "WorldViewProjection");
    CHECK(wvp == hfx_effect_param(fx, "WorldViewProj"));
    CHECK_INT(hfx_param_set_matrix(wvp, identity), HFX_OK);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "technique0"), 0);
    CHECK(pass != NULL);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    hfx_effect_begin(fx);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_FALSE); /* CullMode = None */
    draw_quad(pass);
    hfx_effect_end(fx);
    rt_check_pixel(gl, 8, 8, 255, 255, 255, 255);
    rt_check_pixel(gl, 0, 15, 255, 255, 255, 255);
    hfx_effect_destroy(fx);
}

static void test_ambient_annotations_and_colour(void) {
    hfx_effect *fx = load_seed("ambient.fx", NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_param *color = hfx_effect_param(fx, "colorMaterialAmbiental");
    CHECK_STR(hfx_annotation_string(hfx_param_annotation(color, "UIName")), "Color Ambiental");
    CHECK_STR(hfx_annotation_string(hfx_param_annotation(color, "UIWidget")), "Color");
    float c[4];
    CHECK_INT(hfx_param_get_floats(color, c, 4), HFX_OK);
    CHECK_NEAR(c[0], 0.05, 1e-7);
    CHECK_NEAR(c[3], 1.0, 0);
    CHECK(hfx_effect_param_by_semantic(fx, "world") == hfx_effect_param(fx, "world"));
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "world"), identity), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "view"), identity), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "projection"), identity), HFX_OK);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "ModeloAmbiental"), 0);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    hfx_effect_begin(fx);
    hfx_pass_apply(pass);
    draw_quad(pass);
    rt_check_pixel(gl, 8, 8, 13, 13, 13, 255); /* 0.05 * 255 = 12.75 */
    CHECK_INT(hfx_param_set_floats(color, (float[4]){1, 0.5f, 0, 1}, 4), HFX_OK);
    hfx_pass_apply(pass);
    draw_quad(pass);
    rt_check_pixel(gl, 8, 8, 255, 128, 0, 255);
    hfx_effect_end(fx);
    hfx_effect_destroy(fx);
}

/* The runtime packs float parameters into registers (hfx_c) unless asked not to; both render
 * the hand-computed colour: 0.2, 0.4, 0.6 * 255 = 51, 102, 153. */
static void test_packed_and_separate_render_alike(void) {
    hfx_load_options separate = {0};
    separate.separate_uniforms = 1;
    char *path = test_seed_path("ambient.fx");
    hfx_effect *fx[2] = {hfx_effect_load(dev, path, NULL, NULL), hfx_effect_load(dev, path, &separate, NULL)};
    free(path);
    CHECK(fx[0] && fx[1]);
    for (int k = 0; k < 2 && fx[0] && fx[1]; k++) {
        uint32_t prog = fx[k]->sh->fx->passes[0].program;
        if (k == 0) CHECK(fx[k]->sh->fx->programs[prog].reg_count > 0);
        else CHECK_INT(fx[k]->sh->fx->programs[prog].reg_count, 0);
        CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx[k], "world"), identity), HFX_OK);
        CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx[k], "view"), identity), HFX_OK);
        CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx[k], "projection"), identity), HFX_OK);
        CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx[k], "colorMaterialAmbiental"), (float[4]){0.2f, 0.4f, 0.6f, 1}, 4), HFX_OK);
        hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx[k], "ModeloAmbiental"), 0);
        g.ClearColor(0, 0, 0, 0);
        g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        hfx_effect_begin(fx[k]);
        CHECK_INT(hfx_pass_apply(pass), HFX_OK);
        draw_quad(pass);
        hfx_effect_end(fx[k]);
        rt_check_pixel(gl, 8, 8, 51, 102, 153, 255);
    }
    hfx_effect_destroy(fx[0]);
    hfx_effect_destroy(fx[1]);
}

static void test_multilights_bug_is_reported(void) {
    char *errors = NULL;
    hfx_effect *fx = load_seed("multilights.fx", &errors);
    CHECK(fx == NULL);
    CHECK_CONTAINS(errors, "multilights.fx(204,20): error X3013: 'Phong': no matching 4 parameter function");
    CHECK_CONTAINS(hfx_device_last_error(dev), "error X3013");
    hfx_free(errors);
    hfx_effect_destroy(fx);
}

static void test_multilights_struct_array(void) {
    hfx_effect *fx = load_seed("multilights_repaired.fx", NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_param *spots = hfx_effect_param(fx, "spots");
    CHECK_INT(hfx_param_get_class(spots), HFX_CLASS_STRUCT);
    CHECK_INT(hfx_param_elements(spots), 2);
    hfx_param *pos = hfx_param_member(hfx_param_element(spots, 1), "Posicion");
    CHECK(pos != NULL);
    CHECK_INT(hfx_param_get_class(pos), HFX_CLASS_VECTOR);
    CHECK_INT(hfx_param_columns(pos), 3);
    CHECK_INT(hfx_param_set_floats(pos, (float[3]){1, 2, 3}, 3), HFX_OK);
    CHECK_INT(hfx_param_set_int(hfx_param_member(hfx_param_element(spots, 1), "Encender"), 1), HFX_OK);
    int n = 0;
    CHECK_INT(hfx_param_get_int(hfx_effect_param(fx, "numLuces"), &n), HFX_OK);
    CHECK_INT(n, 4);
    hfx_technique *t = hfx_effect_technique(fx, "Texturizado");
    CHECK_INT(hfx_technique_pass_count(t), 2);
    CHECK(hfx_technique_pass_by_name(t, "MultiLuces") != NULL);
    hfx_effect_begin(fx);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass_by_name(t, "MultiLuces")), HFX_OK);
    hfx_effect_end(fx);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
}

static GLuint bound_program(void) {
    GLint p = 0;
    g.GetIntegerv(GL_CURRENT_PROGRAM, &p);
    return (GLuint)p;
}

/* tutorial0: World * View * Projection, then tex2D with Clamp / Linear on a 2x2 texture. */
static void test_tutorial0_samples_its_texture(void) {
    hfx_effect *fx = load_seed("tutorial0.fx", NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    const char *names[3] = {"World", "View", "Projection"};
    for (int i = 0; i < 3; i++) CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, names[i]), identity), HFX_OK);
    GLuint tex;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_2D, tex);
    /* memory row 0 (v = 0 in D3D and GL alike): red, green; row 1: blue, white */
    const unsigned char texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    g.BindTexture(GL_TEXTURE_2D, 0);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "diffuseTexture"), tex), HFX_OK);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "Tut0"), 0);
    int pos = hfx_pass_attribute_location(pass, "POSITION0"), uv = hfx_pass_attribute_location(pass, "TEXCOORD0");
    CHECK(pos >= 0 && uv >= 0 && pos != uv);
    /* x, y, z, w, u, v: texture coordinates follow the position, (-1, -1) -> (0, 0) */
    static const float verts[36] = {-1, -1, 0, 1, 0, 0, 1, -1, 0, 1, 1, 0, 1, 1, 0, 1, 1, 1,
                                    -1, -1, 0, 1, 0, 0, 1, 1, 0, 1, 1, 1, -1, 1, 0, 1, 0, 1};
    GLuint vao, vbo;
    g.GenVertexArrays(1, &vao);
    g.BindVertexArray(vao);
    g.GenBuffers(1, &vbo);
    g.BindBuffer(GL_ARRAY_BUFFER, vbo);
    g.BufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
    if (pos >= 0 && uv >= 0) {
        g.VertexAttribPointer((GLuint)pos, 4, GL_FLOAT, GL_FALSE, 6 * sizeof(float), NULL);
        g.EnableVertexAttribArray((GLuint)pos);
        g.VertexAttribPointer((GLuint)uv, 2, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void *)(4 * sizeof(float)));
        g.EnableVertexAttribArray((GLuint)uv);
    }
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    hfx_effect_begin(fx);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    GLint sampler = 0;
    g.GetIntegerv(GL_SAMPLER_BINDING, &sampler); /* unit 0 is active after the bind */
    GLint v = 0;
    g.GetSamplerParameteriv((GLuint)sampler, GL_TEXTURE_MIN_FILTER, &v);
    CHECK_INT(v, GL_LINEAR_MIPMAP_LINEAR);
    g.GetSamplerParameteriv((GLuint)sampler, GL_TEXTURE_WRAP_S, &v);
    CHECK_INT(v, GL_CLAMP_TO_EDGE);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    hfx_effect_end(fx);
    rt_check_pixel(gl, 0, H - 1, 255, 0, 0, 255);  /* bottom-left: u, v near 0 */
    rt_check_pixel(gl, W - 2, 1, 255, 255, 255, 255); /* near the top-right: u, v > 0.75 */
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    g.DeleteTextures(1, &tex);
    hfx_effect_destroy(fx);
}

/* pointlights: arrays of 50 uploaded in one call; multilights: struct array members. */
static void test_seed_arrays_reach_gl(void) {
    hfx_effect *fx = load_seed("pointlights.fx", NULL);
    CHECK(fx != NULL);
    if (fx) {
        float colors[200];
        for (int i = 0; i < 200; i++) colors[i] = (float)i / 200.0f;
        CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "LightColor"), colors, 200), HFX_OK);
        CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "activeLights"), 50), HFX_OK);
        hfx_effect_begin(fx);
        CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique_at(fx, 0), 0)), HFX_OK);
        GLuint prog = bound_program();
        float c[4] = {0};
        GLint loc = g.GetUniformLocation(prog, "LightColor[49]");
        CHECK(loc >= 0);
        g.GetUniformfv(prog, loc, c);
        CHECK_NEAR(c[0], 196 / 200.0, 1e-6);
        CHECK_NEAR(c[3], 199 / 200.0, 1e-6);
        hfx_effect_end(fx);
        hfx_effect_destroy(fx);
    }
    fx = load_seed("multilights_repaired.fx", NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_param *s1 = hfx_param_element(hfx_effect_param(fx, "spots"), 1);
    CHECK_INT(hfx_param_set_floats(hfx_param_member(s1, "Posicion"), (float[3]){1, 2, 3}, 3), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_param_member(s1, "Color"), (float[4]){0.5f, 0.25f, 1, 1}, 4), HFX_OK);
    hfx_effect_begin(fx);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass_by_name(hfx_effect_technique(fx, "Texturizado"), "MultiLuces")), HFX_OK);
    GLuint prog = bound_program();
    float p[4] = {0};
    GLint loc = g.GetUniformLocation(prog, "spots[1].Posicion");
    CHECK(loc >= 0);
    g.GetUniformfv(prog, loc, p);
    CHECK_NEAR(p[1], 2, 0);
    loc = g.GetUniformLocation(prog, "spots[1].Color");
    CHECK(loc >= 0);
    g.GetUniformfv(prog, loc, p);
    CHECK_NEAR(p[1], 0.25, 0);
    hfx_effect_end(fx);
    CHECK_STR(hfx_effect_warnings(fx), "");
    hfx_effect_destroy(fx);
}

int main(void) {
    test_require_seeds();
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    char *errors = NULL;
    hfx_effect *probe = load_seed("fxcomposer_empty.fx", &errors);
    if (!probe) {
        printf("fxcomposer_empty.fx: %s\n", errors ? errors : "");
        hfx_free(errors);
        hfx_device_destroy(dev);
        test_gl_destroy(gl);
        test_skip("the compiler does not produce effects yet");
    }
    hfx_free(errors);
    hfx_effect_destroy(probe);
    RUN(test_every_seed_loads_and_applies);
    RUN(test_fxcomposer_empty_renders_white);
    RUN(test_ambient_annotations_and_colour);
    RUN(test_packed_and_separate_render_alike);
    RUN(test_multilights_bug_is_reported);
    RUN(test_multilights_struct_array);
    RUN(test_tutorial0_samples_its_texture);
    RUN(test_seed_arrays_reach_gl);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
