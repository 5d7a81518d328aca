/* test_texture.c: runtime/texture.c. A texture is sampled with the mip levels it has, as in
 * D3D9, whatever MipFilter the sampler asks for: one level, a short chain, a full chain, 2D and
 * cube, under MipFilter None, Point and Linear. Every level is one solid colour, so a probe
 * says which level (or which blend of two) the sampler read; GL alone would read the short
 * chains as incomplete textures, black.
 * D3D9's rules (IDirect3DDevice9::SetSamplerState, D3DSAMP_MIPFILTER): None samples the top
 * level; Point the level nearest the LOD; Linear blends the two around it; a LOD past the
 * last level the texture has reads the last level. */
#include <string.h>

#include "gl_context.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 4
#define H 4

static test_gl *gl;
static tgl g;
static hfx_device *dev;

/* Level colours: red, green, blue, yellow, magenta (levels 0..4). */
static const unsigned char level_rgb[5][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}, {255, 0, 255}};

static const char effect_src[] =
    "texture Tex; textureCUBE Cube; float Lod;\n"
    "sampler2D S0 = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; MipFilter = None; };\n"
    "sampler2D S1 = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; MipFilter = Point; };\n"
    "sampler2D S2 = sampler_state { Texture = <Tex>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; };\n"
    "samplerCUBE C0 = sampler_state { Texture = <Cube>; MinFilter = Point; MipFilter = None; };\n"
    "samplerCUBE C1 = sampler_state { Texture = <Cube>; MinFilter = Point; MipFilter = Point; };\n"
    "samplerCUBE C2 = sampler_state { Texture = <Cube>; MinFilter = Linear; MipFilter = Linear; };\n"
    "samplerCUBE C3 = sampler_state { Texture = <Cube>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; };\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 P0() : COLOR { return tex2Dlod(S0, float4(0.5, 0.5, 0, Lod)); }\n"
    "float4 P1() : COLOR { return tex2Dlod(S1, float4(0.5, 0.5, 0, Lod)); }\n"
    "float4 P2() : COLOR { return tex2Dlod(S2, float4(0.5, 0.5, 0, Lod)); }\n"
    "float4 Q0() : COLOR { return texCUBElod(C0, float4(1, 0, 0, Lod)); }\n"
    "float4 Q1() : COLOR { return texCUBElod(C1, float4(1, 0, 0, Lod)); }\n"
    "float4 Q2() : COLOR { return texCUBElod(C2, float4(1, 0, 0, Lod)); }\n"
    "float4 Seam() : COLOR { return texCUBElod(C3, float4(1, 0.8, 0, 0)); }\n"
    "float4 Implicit() : COLOR { return tex2D(S2, float2(0.25, 0.25)); }\n"
    "technique Flat { pass None { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 P0(); }\n"
    "  pass Point { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 P1(); }\n"
    "  pass Linear { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 P2(); } }\n"
    "technique Cubes { pass None { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Q0(); }\n"
    "  pass Point { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Q1(); }\n"
    "  pass Linear { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Q2(); } }\n"
    "technique Seams { pass Linear { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Seam(); } }\n"
    "technique Magnified { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Implicit(); } }\n";

static void fill_level(GLenum target, int level, int size) {
    unsigned char texels[16 * 16 * 4];
    for (int i = 0; i < size * size; i++) {
        memcpy(texels + 4 * i, level_rgb[level], 3);
        texels[4 * i + 3] = 255;
    }
    g.TexImage2D(target, level, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

/* A 16x16 2D texture (or an 8x8 cube) holding levels 0 .. levels-1, nothing else set. */
static GLuint make_texture(GLenum target, int levels) {
    GLuint tex;
    g.GenTextures(1, &tex);
    g.BindTexture(target, tex);
    g.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    int size = target == GL_TEXTURE_CUBE_MAP ? 8 : 16;
    for (int l = 0; l < levels; l++, size /= 2) {
        if (target != GL_TEXTURE_CUBE_MAP) fill_level(target, l, size);
        for (int f = 0; target == GL_TEXTURE_CUBE_MAP && f < 6; f++) fill_level(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, l, size);
    }
    g.BindTexture(target, 0);
    return tex;
}

/* Draws pass p of technique tech over the target with Lod and returns the centre pixel. */
static void draw(hfx_effect *fx, const char *tech, const char *pass, float lod, unsigned char out[4]) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Lod"), lod), HFX_OK);
    g.ClearColor(0.5f, 0.5f, 0.5f, 0.5f);
    g.Clear(GL_COLOR_BUFFER_BIT);
    hfx_technique *t = hfx_effect_technique(fx, tech);
    hfx_pass *p = NULL;
    for (size_t i = 0; t && i < hfx_technique_pass_count(t); i++)
        if (strcmp(hfx_pass_name(hfx_technique_pass(t, i)), pass) == 0) p = hfx_technique_pass(t, i);
    CHECK(p != NULL);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    test_gl_read(gl, W / 2, H / 2, out);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
}

/* The pixel is level l's colour, or (l2 >= 0) (1 - t) of level l and t of level l2. */
static void check_blend(const unsigned char px[4], int l, int l2, double t) {
    for (int c = 0; c < 3; c++) {
        double want = l2 < 0 ? level_rgb[l][c] : (1 - t) * level_rgb[l][c] + t * level_rgb[l2][c];
        CHECK_NEAR(px[c], want, 1);
    }
    CHECK_INT(px[3], 255);
}

static void check_level(const unsigned char px[4], int l) { check_blend(px, l, -1, 0); }

static hfx_effect *load(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, effect_src, sizeof effect_src - 1, "mips.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    return fx;
}

/* One case: a texture with `levels` levels read at lod under each MipFilter; want[i] is the
 * level None, Point and Linear read, blended with want2[i] (-1: none) by lod's fraction. */
static void check_filters(hfx_effect *fx, GLenum target, int levels, float lod, const int want[3], const int want2[3]) {
    static const char *const passes[3] = {"None", "Point", "Linear"};
    GLuint tex = make_texture(target, levels);
    int cube = target == GL_TEXTURE_CUBE_MAP;
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, cube ? "Cube" : "Tex"), tex), HFX_OK);
    for (int i = 0; i < 3; i++) {
        unsigned char px[4];
        draw(fx, cube ? "Cubes" : "Flat", passes[i], lod, px);
        check_blend(px, want[i], want2[i], lod - (int)lod);
    }
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteTextures(1, &tex);
    hfx_device_texture_changed(dev, tex); /* the name may come back for the next texture */
}

static const int no_blend[3] = {-1, -1, -1};

/* 16x16 with 5 levels is whole: LOD 3 reads level 3 under Point and Linear. */
static void test_full_chain_2d(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    check_filters(fx, GL_TEXTURE_2D, 5, 3.0f, (const int[3]){0, 3, 3}, no_blend);
    /* LOD 1.25: Point reads the nearer level, 1; Linear 3/4 of level 1 and 1/4 of level 2 */
    check_filters(fx, GL_TEXTURE_2D, 5, 1.25f, (const int[3]){0, 1, 1}, (const int[3]){-1, -1, 2});
    hfx_effect_destroy(fx);
}

/* Three levels of five: LOD 3 is past the last, so Point and Linear read level 2. */
static void test_partial_chain_2d(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    check_filters(fx, GL_TEXTURE_2D, 3, 3.0f, (const int[3]){0, 2, 2}, no_blend);
    check_filters(fx, GL_TEXTURE_2D, 3, 0.0f, (const int[3]){0, 0, 0}, no_blend);
    hfx_effect_destroy(fx);
}

/* One level: every filter reads it at every LOD. */
static void test_one_level_2d(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    check_filters(fx, GL_TEXTURE_2D, 1, 3.0f, (const int[3]){0, 0, 0}, no_blend);
    hfx_effect_destroy(fx);
}

/* Cubes: 8x8 is whole with 4 levels; 2 levels stop at 4x4; 1 level. */
static void test_cube_chains(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    check_filters(fx, GL_TEXTURE_CUBE_MAP, 4, 3.0f, (const int[3]){0, 3, 3}, no_blend);
    check_filters(fx, GL_TEXTURE_CUBE_MAP, 2, 3.0f, (const int[3]){0, 1, 1}, no_blend);
    check_filters(fx, GL_TEXTURE_CUBE_MAP, 1, 3.0f, (const int[3]){0, 0, 0}, no_blend);
    hfx_effect_destroy(fx);
}

/* The seeds' case: a one-level texture magnified under MinFilter, MagFilter, MipFilter =
 * Linear (directional.fx's sampler) is drawn textured, not black; and the texture is
 * checked once: later Applies query nothing. */
static void test_magnified_one_level_and_checked_once(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    GLuint tex = make_texture(GL_TEXTURE_2D, 1);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), tex), HFX_OK);
    unsigned char px[4];
    draw(fx, "Magnified", "P", 0, px);
    check_level(px, 0);
    GLint max = 0;
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &max);
    CHECK_INT(max, 0);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
}

/* glGenerateMipmap after hfx lowered MAX_LEVEL: hfx_device_texture_changed raises it again,
 * and the new levels are read. */
static void test_levels_added_later(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    GLuint tex = make_texture(GL_TEXTURE_2D, 3);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), tex), HFX_OK);
    unsigned char px[4];
    draw(fx, "Flat", "Point", 4.0f, px);
    check_level(px, 2);
    g.BindTexture(GL_TEXTURE_2D, tex);
    fill_level(GL_TEXTURE_2D, 3, 2);
    fill_level(GL_TEXTURE_2D, 4, 1);
    g.BindTexture(GL_TEXTURE_2D, 0);
    hfx_device_texture_changed(dev, tex);
    draw(fx, "Flat", "Point", 4.0f, px);
    check_level(px, 4);
    GLint max = 0;
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &max);
    CHECK_INT(max, 1000); /* GL's default, as the application left it */
    g.BindTexture(GL_TEXTURE_2D, 0);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
}

/* A MAX_LEVEL the application set below the last level stays. */
static void test_application_max_level_kept(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    GLuint tex = make_texture(GL_TEXTURE_2D, 3);
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
    g.BindTexture(GL_TEXTURE_2D, 0);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), tex), HFX_OK);
    unsigned char px[4];
    draw(fx, "Flat", "Point", 3.0f, px);
    check_level(px, 1);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
}

/* Cube maps filter across face edges on every back end (Vulkan and WebGL 2 cannot do otherwise).
 * Faces 1x1: +X red, +Y green, the rest blue. Direction (1, 0.8, 0) is on +X (major axis x) at
 * s = (-z/|x| + 1) / 2 = 0.5, t = (-y/|x| + 1) / 2 = 0.1 (the GL / D3D cube face tables); in
 * texels t * 1 - 0.5 = -0.4, so bilinear filtering takes 0.6 of +X's texel and 0.4 of the texel
 * past the edge at t = 0, the +Y face's: (153, 102, 0). Filtering inside the face alone (clamped
 * to its edge) would give pure red. */
static void test_seamless_cube(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    GLuint tex;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_CUBE_MAP, tex);
    for (int f = 0; f < 6; f++) {
        unsigned char texel[4] = {f == 0 ? 255 : 0, f == 2 ? 255 : 0, f == 0 || f == 2 ? 0 : 255, 255};
        g.TexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    }
    g.BindTexture(GL_TEXTURE_CUBE_MAP, 0);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Cube"), tex), HFX_OK);
    unsigned char px[4];
    draw(fx, "Seams", "Linear", 0, px);
    CHECK_NEAR(px[0], 153, 2);
    CHECK_NEAR(px[1], 102, 2);
    CHECK_NEAR(px[2], 0, 1);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
    hfx_device_texture_changed(dev, tex);
}

/* Where the passes bind each texture: declared type, or (plain `texture`) the samplers' kind. */
static void test_texture_targets(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    CHECK_INT(hfx_param_texture_target(hfx_effect_param(fx, "Tex")), GL_TEXTURE_2D);
    CHECK_INT(hfx_param_texture_target(hfx_effect_param(fx, "Cube")), GL_TEXTURE_CUBE_MAP);
    CHECK_INT(hfx_param_texture_target(hfx_effect_param(fx, "C1")), GL_TEXTURE_CUBE_MAP);
    CHECK_INT(hfx_param_texture_target(hfx_effect_param(fx, "Lod")), 0);
    CHECK_INT(hfx_param_texture_target(NULL), 0);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(test_full_chain_2d);
    RUN(test_partial_chain_2d);
    RUN(test_one_level_2d);
    RUN(test_cube_chains);
    RUN(test_magnified_one_level_and_checked_once);
    RUN(test_levels_added_later);
    RUN(test_application_max_level_kept);
    RUN(test_texture_targets);
    RUN(test_seamless_cube);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
