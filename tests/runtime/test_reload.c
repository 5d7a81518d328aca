/* test_reload.c: hfx_effect_reload on a .fx rewritten between loads: values whose parameter kept
 * its shape and was set by the application survive and reach GL under the new code, the rest
 * take the new defaults (an edited initializer shows), the
 * technique is kept by name, a failed compile changes nothing, clones keep the old code, and a
 * reload between begin and end leaves end restoring what begin saw. Every expected colour is
 * worked out by hand from the shaders below (GL rounds x * 255 to the nearest byte). */
#define _DEFAULT_SOURCE /* mkstemp */
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "gl_context.h"
#include "internal.h"
#include "rt_support.h"
#include "test.h"

#define W 16
#define H 16

static test_gl *gl;
static tgl g;
static hfx_device *dev;

/* The vertex shader and parameters both versions share. The texture is 1x1 (100, 50, 150). */
#define COMMON \
    "float4x4 WorldViewProj;\n" \
    "float4 Tint = float4(1, 1, 1, 1);\n" \
    "struct Light { float3 Color; float Scale; };\n" \
    "Light light;\n" \
    "texture Tex;\n" \
    "sampler2D Samp = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; MipFilter = None; };\n" \
    "float4 VS(float4 pos : POSITION0) : POSITION0 { return mul(pos, WorldViewProj); }\n"

/* v1: rgb = Tint * light.Color * light.Scale + tex * Gone + (0, Changes, 0). */
static const char v1[] =
    COMMON
    "float Gone = 0.5;\n"
    "float Changes = 0.25;\n"
    "float4 PS() : COLOR0 {\n"
    "    float3 t = tex2D(Samp, float2(0.5, 0.5)).rgb;\n"
    "    return float4(Tint.rgb * light.Color * light.Scale + t * Gone + float3(0, Changes, 0), 1);\n"
    "}\n"
    "float4 Flat() : COLOR0 { return Tint; }\n"
    "technique Main { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"
    "technique Flat { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Flat(); } }\n";

/* v2: Gone removed, Added new, Changes now a float2, the formula changed, the techniques swapped
 * round and Main's pass turns the depth test on (ZFunc Always draws everything anyway):
 * rgb = Tint * light.Color * light.Scale * Added + tex + (Changes.x, 0, Changes.y) * 0.25. */
static const char v2[] =
    COMMON
    "float Added = 0.5;\n"
    "float2 Changes = float2(0.5, 0.75);\n"
    "float4 PS() : COLOR0 {\n"
    "    float3 t = tex2D(Samp, float2(0.5, 0.5)).rgb;\n"
    "    return float4(Tint.rgb * light.Color * light.Scale * Added + t + float3(Changes.x, 0, Changes.y) * 0.25, 1);\n"
    "}\n"
    "float4 Flat() : COLOR0 { return Tint; }\n"
    "technique Flat { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Flat(); } }\n"
    "technique Main { pass P0 { ZEnable = TRUE; ZFunc = Always;\n"
    "    VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* v3: only a technique of another name: the current one falls back to the first. */
static const char v3[] =
    COMMON
    "float4 Other() : COLOR0 { return Tint; }\n"
    "technique Other { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Other(); } }\n";

/* A missing ';' after the return on line 9: the error is at the '}' on line 10. */
static const char bad[] =
    COMMON
    "float4 PS() : COLOR0 {\n"
    "    return Tint\n"
    "}\n"
    "technique Main { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* Scale 0.5 in x and y: the quad covers the middle of the target only, so a corner pixel shows
 * whether the matrix reached GL. */
static const float half[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static const float tint[4] = {0.5f, 1, 0.25f, 1};
static const float light_color[3] = {1, 0.5f, 1};
static const float light_scale = 0.8f;

/* v1 with the values above and Changes = 0.2:
 *   Tint * Color * Scale = (0.5 * 1, 1 * 0.5, 0.25 * 1) * 0.8 = (0.4, 0.4, 0.2)
 *   tex * Gone = (100, 50, 150) / 255 * 0.5 = (0.196078, 0.098039, 0.294118)
 *   + (0, 0.2, 0): (0.596078, 0.698039, 0.494118) * 255 = (152.0, 178.0, 126.0) */
static const int v1_rgb[3] = {152, 178, 126};
/* v2 with the kept values, Added = 0.5 and Changes = its new default (0.5, 0.75):
 *   (0.4, 0.4, 0.2) * 0.5 = (0.2, 0.2, 0.1); tex = (0.392157, 0.196078, 0.588235);
 *   (0.5, 0, 0.75) * 0.25 = (0.125, 0, 0.1875)
 *   sum (0.717157, 0.396078, 0.875735) * 255 = (182.9, 101.0, 223.3) */
static const int v2_rgb[3] = {183, 101, 223};

static char path[] = "/tmp/hfx_reload_XXXXXX";

static void write_file(const char *text) {
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* A full-screen quad of float3 positions on the attribute the pass reads POSITION from. */
static void draw_quad(hfx_pass *pass) {
    static const float xyz[18] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1, 0};
    GLuint vao, vbo;
    g.GenVertexArrays(1, &vao);
    g.BindVertexArray(vao);
    g.GenBuffers(1, &vbo);
    g.BindBuffer(GL_ARRAY_BUFFER, vbo);
    g.BufferData(GL_ARRAY_BUFFER, sizeof xyz, xyz, GL_STATIC_DRAW);
    int loc = hfx_pass_attribute_location(pass, "POSITION");
    CHECK(loc >= 0);
    if (loc >= 0) {
        g.VertexAttribPointer((GLuint)loc, 3, GL_FLOAT, GL_FALSE, 0, NULL);
        g.EnableVertexAttribArray((GLuint)loc);
        g.DrawArrays(GL_TRIANGLES, 0, 6);
    }
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
}

static void check_pixel(int x, int y, const int rgb[3]) {
    unsigned char px[4];
    test_gl_read(gl, x, y, px);
    CHECK_NEAR(px[0], rgb[0], 1);
    CHECK_NEAR(px[1], rgb[1], 1);
    CHECK_NEAR(px[2], rgb[2], 1);
}

/* Clears to black and draws the current technique's first pass between begin and end. */
static void render(hfx_effect *fx) {
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    CHECK(pass != NULL);
    if (!pass) return;
    hfx_effect_begin(fx);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    draw_quad(pass);
    hfx_effect_end(fx);
}

static GLuint make_texture(void) {
    static const unsigned char texel[4] = {100, 50, 150, 255};
    GLuint t;
    g.GenTextures(1, &t);
    g.BindTexture(GL_TEXTURE_2D, t);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    g.BindTexture(GL_TEXTURE_2D, 0);
    return t;
}

static hfx_effect *load_v1(GLuint tex) {
    write_file(v1);
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load(dev, path, NULL, &errors);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return NULL;
    hfx_param *light = hfx_effect_param(fx, "light");
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "WorldViewProj"), half), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Tint"), tint, 4), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_param_member(light, "Color"), light_color, 3), HFX_OK);
    CHECK_INT(hfx_param_set_float(hfx_param_member(light, "Scale"), light_scale), HFX_OK);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Changes"), 0.2f), HFX_OK);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), tex), HFX_OK);
    hfx_effect_set_current_technique(fx, hfx_effect_technique(fx, "Main"));
    return fx;
}

static void check_kept_values(hfx_effect *fx, GLuint tex) {
    float m[16], v[4];
    CHECK_INT(hfx_param_get_matrix(hfx_effect_param(fx, "WorldViewProj"), m), HFX_OK);
    for (int i = 0; i < 16; i++) CHECK_NEAR(m[i], half[i], 0);
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "Tint"), v, 4), HFX_OK);
    for (int i = 0; i < 4; i++) CHECK_NEAR(v[i], tint[i], 0);
    hfx_param *light = hfx_effect_param(fx, "light");
    CHECK_INT(hfx_param_get_floats(hfx_param_member(light, "Color"), v, 3), HFX_OK);
    for (int i = 0; i < 3; i++) CHECK_NEAR(v[i], light_color[i], 0);
    CHECK_INT(hfx_param_get_float(hfx_param_member(light, "Scale"), v), HFX_OK);
    CHECK_NEAR(v[0], light_scale, 0);
    unsigned int t = 0;
    CHECK_INT(hfx_param_get_texture(hfx_effect_param(fx, "Tex"), &t), HFX_OK);
    CHECK_INT(t, tex);
}

static void test_reload_keeps_values(void) {
    static const int black[3] = {0, 0, 0};
    GLuint tex = make_texture();
    hfx_effect *fx = load_v1(tex);
    if (!fx) return;
    render(fx);
    check_pixel(8, 8, v1_rgb);
    check_pixel(1, 1, black);
    hfx_effect *clone = hfx_effect_clone(fx);
    CHECK(clone != NULL);
    /* Flat's pass is program-only, so the device remembers it for Apply's short way; that
     * pointer must not outlive the passes the reload replaces */
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, "Flat"), 0)), HFX_OK);
    CHECK(dev->applied != NULL && dev->applied->fx == fx);

    write_file(v2);
    hfx_effect *same = fx;
    char *errors = NULL;
    int rc = hfx_effect_reload(fx, NULL, NULL, &errors);
    if (rc) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK_INT(rc, HFX_OK);
    CHECK(fx == same);
    CHECK(dev->applied == NULL);
    check_kept_values(fx, tex);
    float v[4] = {0};
    hfx_param *changes = hfx_effect_param(fx, "Changes");
    CHECK_INT(hfx_param_columns(changes), 2);
    CHECK_INT(hfx_param_get_floats(changes, v, 2), HFX_OK);
    CHECK_NEAR(v[0], 0.5, 0);
    CHECK_NEAR(v[1], 0.75, 0);
    CHECK_INT(hfx_param_get_float(hfx_effect_param(fx, "Added"), v), HFX_OK);
    CHECK_NEAR(v[0], 0.5, 0);
    CHECK(hfx_effect_param(fx, "Gone") == NULL);
    CHECK_STR(hfx_technique_name(hfx_effect_current_technique(fx)), "Main");
    CHECK(hfx_effect_current_technique(fx) == hfx_effect_technique_at(fx, 1));
    render(fx);
    check_pixel(8, 8, v2_rgb);
    check_pixel(1, 1, black); /* the matrix reached the new program */

    /* the clone keeps v1's code and its own copy of the values */
    render(clone);
    check_pixel(8, 8, v1_rgb);
    CHECK(hfx_effect_param(clone, "Gone") != NULL);

    /* a compile error changes nothing */
    write_file(bad);
    rc = hfx_effect_reload(fx, NULL, NULL, &errors);
    CHECK_INT(rc, HFX_ERR_LOAD);
    char want[256];
    snprintf(want, sizeof want, "%s(10,1): error X3000: syntax error: unexpected token '}'", path);
    CHECK_CONTAINS(errors, want);
    hfx_free(errors);
    CHECK_STR(hfx_technique_name(hfx_effect_current_technique(fx)), "Main");
    CHECK(hfx_effect_param(fx, "Added") != NULL);
    check_kept_values(fx, tex);
    render(fx);
    check_pixel(8, 8, v2_rgb);

    /* the technique's name is gone: the first one */
    write_file(v3);
    CHECK_INT(hfx_effect_reload(fx, NULL, NULL, NULL), HFX_OK);
    CHECK_STR(hfx_technique_name(hfx_effect_current_technique(fx)), "Other");
    check_kept_values(fx, tex);
    render(fx); /* returns Tint: (0.5, 1, 0.25) * 255 = (127.5, 255, 63.75) */
    check_pixel(8, 8, (const int[3]){128, 255, 64});

    hfx_effect_destroy(clone);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
}

static void test_reload_from_memory_needs_a_path(void) {
    hfx_effect *fx = hfx_effect_load_memory(dev, v1, sizeof v1 - 1, "mem.fx", NULL, NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Tint"), tint, 4), HFX_OK);
    char *errors = NULL;
    CHECK_INT(hfx_effect_reload(fx, NULL, NULL, &errors), HFX_ERR_NOT_FOUND);
    CHECK_CONTAINS(errors, "loaded from memory");
    CHECK_STR(hfx_device_last_error(dev), errors);
    hfx_free(errors);
    float v[4];
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "Tint"), v, 4), HFX_OK);
    CHECK_NEAR(v[1], tint[1], 0);
    /* with a path it reloads, and remembers the path for the next time */
    write_file(v3);
    CHECK_INT(hfx_effect_reload(fx, path, NULL, NULL), HFX_OK);
    CHECK_INT(hfx_effect_reload(fx, NULL, NULL, NULL), HFX_OK);
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "Tint"), v, 4), HFX_OK);
    CHECK_NEAR(v[1], tint[1], 0);
    hfx_effect_destroy(fx);
}

/* A .hfxo path reloads like a .fx one: v2 written out as .hfxo, then read back over v1. */
static void test_reload_from_hfxo(void) {
    GLuint tex = make_texture();
    write_file(v2);
    hfx_effect *compiled = hfx_effect_load(dev, path, NULL, NULL);
    hfx_effect *fx = load_v1(tex);
    CHECK(compiled != NULL);
    void *data = NULL;
    size_t size = 0;
    char hfxo[] = "/tmp/hfx_reload_hfxo_XXXXXX";
    int fd = mkstemp(hfxo);
    CHECK(fd >= 0);
    if (compiled && fx && fd >= 0 && hfx_fx_write_hfxo(compiled->sh->fx, &data, &size) == 0) {
        CHECK_INT(write(fd, data, size), size);
        CHECK_INT(hfx_effect_reload(fx, hfxo, NULL, NULL), HFX_OK);
        check_kept_values(fx, tex);
        CHECK(hfx_effect_param(fx, "Added") != NULL);
        CHECK_STR(hfx_technique_name(hfx_effect_current_technique(fx)), "Main");
        render(fx);
        check_pixel(8, 8, v2_rgb);
    }
    if (fd >= 0) close(fd), remove(hfxo);
    free(data);
    hfx_effect_destroy(compiled);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
}

static GLint get_int(GLenum what) {
    GLint v = 0;
    g.GetIntegerv(what, &v);
    return v;
}

/* begin saved program 0, no depth test and `prior` on unit 0; v1 binds the effect's texture
 * there, v2 also turns the depth test on: end puts all three back. */
static void test_reload_between_begin_and_end(void) {
    GLuint tex = make_texture(), prior = make_texture();
    hfx_effect *fx = load_v1(tex);
    if (!fx) return;
    g.UseProgram(0);
    g.Disable(GL_DEPTH_TEST);
    g.ActiveTexture(GL_TEXTURE0);
    g.BindTexture(GL_TEXTURE_2D, prior);
    CHECK_INT(hfx_effect_begin(fx), HFX_OK);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(fx), 0)), HFX_OK);
    write_file(v2);
    CHECK_INT(hfx_effect_reload(fx, NULL, NULL, NULL), HFX_OK);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(g.IsEnabled(GL_DEPTH_TEST), GL_TRUE);
    draw_quad(pass);
    check_pixel(8, 8, v2_rgb);
    CHECK_INT(hfx_effect_end(fx), HFX_OK);
    CHECK_INT(get_int(GL_CURRENT_PROGRAM), 0);
    CHECK_INT(g.IsEnabled(GL_DEPTH_TEST), GL_FALSE);
    CHECK_INT(get_int(GL_ACTIVE_TEXTURE), GL_TEXTURE0);
    CHECK_INT(get_int(GL_TEXTURE_BINDING_2D), prior);
    hfx_effect_destroy(fx);
    g.BindTexture(GL_TEXTURE_2D, 0);
    g.DeleteTextures(1, &tex);
    g.DeleteTextures(1, &prior);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
}

/* An edited initializer shows after a reload unless the application set that parameter:
 * Base's default goes from red to green and nobody set it, so the new green is drawn; Add was
 * set to (0, 0, 0.5, 0), so its new default (0.25, 0, 0, 0) does not replace it. The pixel is
 * Base + Add = (0, 1, 0.5) -> (0, 255, 127.5). The file grows by a character, so
 * hfx_effect_reload_if_changed sees the change whatever the clock's resolution. */
static void test_reload_takes_new_defaults(void) {
    static const char red[] =
        "float4 Base = float4(1, 0, 0, 1);\n"
        "float4 Add = float4(0, 0, 0, 0);\n"
        "float4 VS(float4 pos : POSITION0) : POSITION0 { return pos; }\n"
        "float4 PS() : COLOR0 { return Base + Add; }\n"
        "technique Main { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
    static const char green[] =
        "float4 Base = float4(0, 1, 0, 1);\n"
        "float4 Add = float4(0.25, 0, 0, 0);\n"
        "float4 VS(float4 pos : POSITION0) : POSITION0 { return pos; }\n"
        "float4 PS() : COLOR0 { return Base + Add; }\n"
        "technique Main { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
    static const float add[4] = {0, 0, 0.5f, 0};
    write_file(red);
    hfx_effect *fx = hfx_effect_load(dev, path, NULL, NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Add"), add, 4), HFX_OK);
    render(fx);
    check_pixel(8, 8, (const int[3]){255, 0, 128});
    write_file(green);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 1);
    float v[4];
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "Base"), v, 4), HFX_OK);
    CHECK(v[0] == 0 && v[1] == 1 && v[2] == 0 && v[3] == 1);
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "Add"), v, 4), HFX_OK);
    CHECK(v[0] == 0 && v[1] == 0 && v[2] == 0.5f && v[3] == 0);
    render(fx);
    check_pixel(8, 8, (const int[3]){0, 255, 128});
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    int fd = mkstemp(path);
    if (fd < 0) test_skip("mkstemp failed");
    close(fd);
    RUN(test_reload_keeps_values);
    RUN(test_reload_from_memory_needs_a_path);
    RUN(test_reload_from_hfxo);
    RUN(test_reload_between_begin_and_end);
    RUN(test_reload_takes_new_defaults);
    remove(path);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
