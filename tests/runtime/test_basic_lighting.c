/* test_basic_lighting.c: fx/basic_lighting.fx, an effect in the style of XNA's BasicEffect
 * (ShaderIndex picks one of 14 shader pairs through static const tables), drawn with every
 * ShaderIndex and probed against colours computed here from XNA's lighting equations: three
 * directional lights, Blinn's half vector, DiffuseColor / EmissiveColor / SpecularColor, vertex
 * colour, texture, fog, and two-bone skinning.
 *
 * The scene: a full-screen quad in the z = 0 plane (World identity), normal
 * (0, 0, 1), the eye far up the z axis, so N and E = (0, 0, 1) at every pixel and vertex and
 * Gouraud and per-pixel lighting give the same colour. Worked example, ShaderIndex 4 (vertex
 * lighting, no texture, no vertex colour), lights as set below:
 *   light 0: L = (0, 0, 1): N.L = 1, H = (0, 0, 1), N.H = 1
 *   light 1: L = (-0.7071, 0, 0.7071): N.L = 0.7071, H = normalize(-0.7071, 0, 1.7071) =
 *            (-0.3827, 0, 0.9239), (N.H)^16 = 0.28173
 *   light 2: L = (0, 0, -1): N.L = -1, no diffuse, no specular
 *   diffuse  = (0.5, 0.25, 0.125) + 0.7071 (0.2, 0.4, 0.6) = (0.64142, 0.53284, 0.54926)
 *              * DiffuseColor (0.8, 0.6, 0.4) + Emissive (0.05, 0.1, 0) = (0.56314, 0.41971, 0.21971)
 *   specular = (0.25, 0.25, 0.25) + 0.28173 (0.5, 0.5, 0) = (0.39087, 0.39087, 0.25) * 0.5
 *   colour   = diffuse + specular * alpha 0.75 = (0.70972, 0.56628, 0.31346), then fog 0.25 towards
 *              FogColor (0, 0, 1) * 0.75: (0.53229, 0.42471, 0.42260), alpha 0.75. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "gl_context.h"
#include "hfx/hfxc.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static hfx_device *dev;
static GLuint texture;

typedef struct vec { double x, y, z; } vec;

static const double diffuse_color[4] = {0.8, 0.6, 0.4, 0.75}, emissive[3] = {0.05, 0.1, 0}, specular_color[3] = {0.5, 0.5, 0.5};
static const double power = 16, fog = 0.25, fog_color[3] = {0, 0, 1};
static const double vertex_color[4] = {0.5, 1, 1, 1}, texel[4] = {128 / 255.0, 128 / 255.0, 1, 1};
static const vec light_dir[3] = {{0, 0, -1}, {0.70710678, 0, -0.70710678}, {0, 0, 1}};
static const vec light_diffuse[3] = {{0.5, 0.25, 0.125}, {0.2, 0.4, 0.6}, {1, 1, 1}};
static const vec light_specular[3] = {{0.25, 0.25, 0.25}, {0.5, 0.5, 0}, {1, 1, 1}};
static const double bone_angle = 60 * 3.14159265358979 / 180; /* bone 1 turns about y */

static double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec unit(vec a) { double l = sqrt(dot(a, a)); return (vec){a.x / l, a.y / l, a.z / l}; }

/* XNA's per-light terms, summed, tinted: out[0..2] diffuse, out[3..5] specular. */
static void lights(vec n, vec e, double out[6]) {
    double d[3] = {0}, s[3] = {0};
    for (int i = 0; i < 3; i++) {
        vec l = {-light_dir[i].x, -light_dir[i].y, -light_dir[i].z};
        double dot_l = dot(l, n), dot_h = dot(unit((vec){e.x + l.x, e.y + l.y, e.z + l.z}), n);
        double zero_l = dot_l >= 0 ? 1 : 0, spec = pow(fmax(dot_h, 0.000001) * zero_l, power);
        const double *ld = &light_diffuse[i].x, *ls = &light_specular[i].x;
        for (int c = 0; c < 3; c++) d[c] += zero_l * dot_l * ld[c], s[c] += spec * ls[c];
    }
    for (int c = 0; c < 3; c++) out[c] = d[c] * diffuse_color[c] + emissive[c], out[3 + c] = s[c] * specular_color[c];
}

/* The colour ShaderIndex `index` must draw (see the table in fx/basic_lighting.fx). */
static void expected(int index, double rgba[4]) {
    bool lit = index >= 4, skinned = index >= 12, vc = !skinned && (index & 1), tx = !skinned && (index & 2);
    vec n = skinned ? (vec){sin(bone_angle), 0, cos(bone_angle)} : (vec){0, 0, 1};
    double l[6] = {1, 1, 1, 0, 0, 0};
    if (lit) lights(n, (vec){0, 0, 1}, l);
    for (int c = 0; c < 4; c++) {
        double base = lit ? (c < 3 ? l[c] : diffuse_color[3]) : diffuse_color[c];
        rgba[c] = base * (vc ? vertex_color[c] : 1) * (tx ? texel[c] : 1);
    }
    for (int c = 0; c < 3; c++) {
        rgba[c] += l[3 + c] * rgba[3];
        rgba[c] += (fog_color[c] * rgba[3] - rgba[c]) * fog;
    }
}

static void set3(hfx_effect *fx, const char *name, vec v) {
    float f[3] = {(float)v.x, (float)v.y, (float)v.z};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, name), f, 3), HFX_OK);
}

static void set_scene(hfx_effect *fx) {
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    float c = (float)cos(bone_angle), s = (float)sin(bone_angle);
    const float turn[16] = {c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1}; /* XNA's CreateRotationY */
    /* the quad half way into D3D's 0..1 depth range, so that the skinned (turned) quad stays
     * unclipped around the centre */
    static const float to_middle[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0.5f, 1};
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "World"), identity), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "WorldInverseTranspose"), identity), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "WorldViewProj"), to_middle), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_param_element(hfx_effect_param(fx, "Bones"), 0), identity), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_param_element(hfx_effect_param(fx, "Bones"), 1), turn), HFX_OK);
    set3(fx, "EyePosition", (vec){0, 0, 1e6});
    float dc[4] = {0.8f, 0.6f, 0.4f, 0.75f}, fv[4] = {0, 0, 0, (float)fog};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "DiffuseColor"), dc, 4), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "FogVector"), fv, 4), HFX_OK);
    set3(fx, "EmissiveColor", (vec){emissive[0], emissive[1], emissive[2]});
    set3(fx, "SpecularColor", (vec){specular_color[0], specular_color[1], specular_color[2]});
    set3(fx, "FogColor", (vec){fog_color[0], fog_color[1], fog_color[2]});
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "SpecularPower"), (float)power), HFX_OK);
    for (int i = 0; i < 3; i++) {
        char name[64];
        snprintf(name, sizeof name, "DirLight%dDirection", i), set3(fx, name, light_dir[i]);
        snprintf(name, sizeof name, "DirLight%dDiffuseColor", i), set3(fx, name, light_diffuse[i]);
        snprintf(name, sizeof name, "DirLight%dSpecularColor", i), set3(fx, name, light_specular[i]);
    }
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Texture"), texture), HFX_OK);
}

/* Constant attributes (normal, colour, uv, bone indices and weights) as generic values. */
static void set_attributes(hfx_pass *pass) {
    static const struct { const char *semantic; float v[4]; } attrs[] = {
        {"NORMAL0", {0, 0, 1, 0}}, {"COLOR0", {0.5f, 1, 1, 1}}, {"TEXCOORD0", {0.5f, 0.5f, 0, 0}},
        {"BLENDINDICES0", {0, 1, 0, 0}}, {"BLENDWEIGHT0", {0, 1, 0, 0}}};
    for (size_t i = 0; i < sizeof attrs / sizeof attrs[0]; i++) {
        int loc = hfx_pass_attribute_location(pass, attrs[i].semantic);
        if (loc < 0) continue;
        g.DisableVertexAttribArray((GLuint)loc);
        g.VertexAttrib4f((GLuint)loc, attrs[i].v[0], attrs[i].v[1], attrs[i].v[2], attrs[i].v[3]);
    }
}

static void draw_index(hfx_effect *fx, int index) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "ShaderIndex"), index), HFX_OK);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "BasicEffect"), 0);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    set_attributes(pass);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
}

static void check_index(hfx_effect *fx, int index) {
    double want[4];
    unsigned char px[4];
    expected(index, want);
    draw_index(fx, index);
    test_gl_read(gl, W / 2, H / 2, px);
    for (int c = 0; c < 4; c++)
        if (fabs(px[c] - want[c] * 255) > 1.5) {
            fprintf(stderr, "ShaderIndex %d: pixel (%d, %d, %d, %d), expected (%.1f, %.1f, %.1f, %.1f)\n", index, px[0],
                    px[1], px[2], px[3], want[0] * 255, want[1] * 255, want[2] * 255, want[3] * 255);
            CHECK(0);
            return;
        }
}

/* The worked example of the header, by hand: guards the reference itself. */
static void reference_matches_the_worked_example(void) {
    double c[4];
    expected(4, c);
    CHECK_NEAR(c[0], 0.53229, 2e-4);
    CHECK_NEAR(c[1], 0.42471, 2e-4);
    CHECK_NEAR(c[2], 0.42260, 2e-4);
    CHECK_NEAR(c[3], 0.75, 1e-9);
}

static void every_shader_index(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load(dev, HFX_SOURCE_DIR "/fx/basic_lighting.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    set_scene(fx);
    for (int index = 0; index < 14; index++) check_index(fx, index);
    hfx_effect_destroy(fx);
}

/* The same probes with every shader sent through the D3D9 bytecode back end and read back
 * (source -> vs_2_0 / ps_2_0 bytecode -> hfx's reader -> GLSL): its register allocation (values
 * packed into shared registers' components), its skinning by columns, its folds. */
static void every_shader_index_through_d3d9(void) {
    hfxc_options co;
    memset(&co, 0, sizeof co);
    co.targets = 1u << HFX_TARGET_GLSL330;
    co.flags = HFXC_VIA_D3D9 | HFXC_PACK_UNIFORMS;
    hfxc_result *r = hfxc_compile_file(HFX_SOURCE_DIR "/fx/basic_lighting.fx", &co);
    const hfx_fx_effect *compiled = r ? hfxc_result_effect(r) : NULL;
    if (!compiled) {
        char *text = r ? hfxc_diagnostics_text(r) : NULL;
        printf("%s\n", text ? text : "");
        free(text);
    }
    CHECK(compiled != NULL);
    void *data = NULL;
    size_t size = 0;
    hfx_effect *fx = NULL;
    char *errors = NULL;
    if (compiled && hfx_fx_write_hfxo(compiled, &data, &size) == 0)
        fx = hfx_effect_load_memory(dev, data, size, "basic_lighting.fx", NULL, &errors);
    if (compiled && !fx) printf("%s\n", errors ? errors : "");
    CHECK(fx != NULL);
    if (fx) {
        set_scene(fx);
        for (int index = 0; index < 14; index++) check_index(fx, index);
        hfx_effect_destroy(fx);
    }
    hfx_free(errors);
    free(data);
    hfxc_result_free(r);
}

static void make_texture(void) {
    static const unsigned char rgba[4] = {128, 128, 255, 255};
    g.GenTextures(1, &texture);
    g.BindTexture(GL_TEXTURE_2D, texture);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    hfx_device_texture_changed(dev, texture);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    make_texture();
    RUN(reference_matches_the_worked_example);
    RUN(every_shader_index);
    RUN(every_shader_index_through_d3d9);
    g.DeleteTextures(1, &texture);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
