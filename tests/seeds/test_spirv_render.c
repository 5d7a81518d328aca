/* The SPIR-V target loaded by the runtime (runtime/spirv_load.c) against the GLSL 330 one: on an
 * OpenGL 4.5 core context (ARB_gl_spirv on llvmpipe), every case renders a seed once loaded with
 * HFX_TARGET_GLSL330 and once with HFX_TARGET_SPIRV, with the same parameters, and the two images
 * must agree within 1/255 per channel over the whole image (and light some pixels). Then a
 * colour changes after the first frame, both re-render, and the SPIR-V image must follow
 * (differ from its first frame) and still match the GLSL one. Without ARB_gl_spirv, loading
 * with the SPIR-V target fails with a message that says so (HFX_ERR_GL inside the runtime). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "scene.h"

#define W 128
#define H 128

static seed_scene *S;

typedef struct spv_case {
    const char *file, *technique;
    int passes;
    seed_blend blend;
    int sphere;                                /* else the floor, seen from the top */
    void (*set)(hfx_effect *fx, const seed_texture *tex);
    void (*update)(hfx_effect *fx);            /* after the first frame: a colour changes */
} spv_case;

/* --- the seeds' parameters -------------------------------------------------------------------- */

static void phong_set(hfx_effect *fx, const seed_texture *tex) {
    seed_set_transforms(S, fx, "World", "View", "Projection", NULL);
    seed_set_v3(S, fx, "LightDirection", v3_make(1, -1, 0.3));
    seed_set_rgba(S, fx, "LightColor", rgba_make(1, 0.9, 0.8, 1));
    seed_set_v3(S, fx, "camPosition", v3_make(0.5, 1, 0));
    seed_set_rgba(S, fx, "SpecularColor", rgba_make(1, 1, 1, 1));
    seed_set_float(S, fx, "SpecularPower", 20);
    seed_set_float(S, fx, "SpecularIntensity", 0.4);
    seed_set_rgba(S, fx, "AmbientColor", rgba_make(0.2, 0.3, 0.4, 1));
    seed_set_float(S, fx, "AmbientIntensity", 0.25);
    seed_set_float(S, fx, "DiffuseIntensity", 0.6);
    seed_set_texture(S, fx, "DiffuseTexture", tex);
}
static void phong_update(hfx_effect *fx) { seed_set_rgba(S, fx, "LightColor", rgba_make(0.3, 1, 0.2, 1)); }

static void spot_set(hfx_effect *fx, const seed_texture *tex) {
    seed_set_transforms(S, fx, "world", "view", "projection", NULL);
    seed_set_v3(S, fx, "posicionLuz", v3_make(0.2, 2, -0.2));
    seed_set_v3(S, fx, "blancoLuz", v3_make(0, 0, 0));
    seed_set_float(S, fx, "anguloInterno", 0.3);
    seed_set_float(S, fx, "anguloExterno", 0.6);
    seed_set_float(S, fx, "falloff", 1.5);
    seed_set_bool(S, fx, "atenuado", 1);
    seed_set_float(S, fx, "c1", 1);
    seed_set_float(S, fx, "c2", 0);
    seed_set_float(S, fx, "c3", 0.001);
    seed_set_float(S, fx, "rango", 20);
    seed_set_texture(S, fx, "texturaModelo", tex);
    seed_set_v3(S, fx, "posicionCamara", v3_make(0.3, 3, 0.4));
    seed_set_bool(S, fx, "modIluEsp", 1);
    seed_set_float(S, fx, "ks", 1);
    seed_set_float(S, fx, "n", 8);
}
static void spot_update(hfx_effect *fx) { seed_set_float(S, fx, "ks", 0.2); }

static void multi_set(hfx_effect *fx, const seed_texture *tex) {
    seed_set_transforms(S, fx, "world", "view", "projection", NULL);
    seed_set_bool(S, fx, "habiEspec", 1);
    seed_set_float(S, fx, "ks", 0.05);
    seed_set_float(S, fx, "n", 5);
    seed_set_v3(S, fx, "posicionCamara", v3_make(0.4, 2.5, 1.2));
    seed_set_texture(S, fx, "texturaModelo", tex);
    seed_param_v3(S, seed_member(S, fx, "direccionales", 0, "Direccion"), "Direccion", v3_make(0.5, -1, 0.2));
    seed_param_rgba(S, seed_member(S, fx, "direccionales", 0, "Color"), "Color", rgba_make(0.8, 0.7, 0.6, 1));
    seed_param_int(S, seed_member(S, fx, "direccionales", 0, "Encender"), "Encender", 1);
    seed_param_v3(S, seed_member(S, fx, "direccionales", 1, "Direccion"), "Direccion", v3_make(-1, -0.7, -0.4));
    seed_param_rgba(S, seed_member(S, fx, "direccionales", 1, "Color"), "Color", rgba_make(0.3, 0.5, 0.9, 1));
    seed_param_int(S, seed_member(S, fx, "direccionales", 1, "Encender"), "Encender", 1);
    seed_param_v3(S, seed_member(S, fx, "puntuales", 1, "Posicion"), "Posicion", v3_make(1.2, 0.5, 0.8));
    seed_param_rgba(S, seed_member(S, fx, "puntuales", 1, "Color"), "Color", rgba_make(0.5, 0.9, 0.5, 1));
    seed_param_float(S, seed_member(S, fx, "puntuales", 1, "Rango"), "Rango", 1.6);
    seed_param_float(S, seed_member(S, fx, "puntuales", 1, "C1"), "C1", 1);
    seed_param_float(S, seed_member(S, fx, "puntuales", 1, "C2"), "C2", 0.5);
    seed_param_float(S, seed_member(S, fx, "puntuales", 1, "C3"), "C3", 1.5);
    seed_param_int(S, seed_member(S, fx, "puntuales", 1, "Atenuar"), "Atenuar", 1);
    seed_param_int(S, seed_member(S, fx, "puntuales", 1, "Encender"), "Encender", 1);
    seed_param_v3(S, seed_member(S, fx, "spots", 1, "Posicion"), "Posicion", v3_make(-0.8, 1.5, 1));
    seed_param_v3(S, seed_member(S, fx, "spots", 1, "Blanco"), "Blanco", v3_make(-1, 0, 1.2));
    seed_param_rgba(S, seed_member(S, fx, "spots", 1, "Color"), "Color", rgba_make(0.6, 0.6, 1, 1));
    seed_param_float(S, seed_member(S, fx, "spots", 1, "AnguloInterno"), "AnguloInterno", 0.2);
    seed_param_float(S, seed_member(S, fx, "spots", 1, "AnguloExterno"), "AnguloExterno", 0.5);
    seed_param_float(S, seed_member(S, fx, "spots", 1, "Falloff"), "Falloff", 0.8);
    seed_param_float(S, seed_member(S, fx, "spots", 1, "Rango"), "Rango", 5);
    seed_param_float(S, seed_member(S, fx, "spots", 1, "C1"), "C1", 1);
    seed_param_float(S, seed_member(S, fx, "spots", 1, "C2"), "C2", 0.1);
    seed_param_float(S, seed_member(S, fx, "spots", 1, "C3"), "C3", 0.1);
    seed_param_int(S, seed_member(S, fx, "spots", 1, "Atenuar"), "Atenuar", 1);
    seed_param_int(S, seed_member(S, fx, "spots", 1, "Encender"), "Encender", 1);
}
static void multi_update(hfx_effect *fx) {
    seed_param_rgba(S, seed_member(S, fx, "spots", 1, "Color"), "Color", rgba_make(1, 0.2, 0.1, 1));
}

enum { LIGHTS = 10 };
static void point_set(hfx_effect *fx, const seed_texture *tex) {
    seed_set_transforms(S, fx, "World", "View", "Projection", NULL);
    seed_set_v3(S, fx, "camPosition", v3_make(0.5, 2, 0.5));
    seed_set_rgba(S, fx, "SpecularColor", rgba_make(1, 1, 1, 1));
    seed_set_float(S, fx, "SpecularPower", 16);
    seed_set_float(S, fx, "SpecularIntensity", 0.3);
    seed_set_rgba(S, fx, "AmbientColor", rgba_make(0.1, 0.1, 0.15, 1));
    seed_set_float(S, fx, "AmbientIntensity", 0.5);
    seed_set_float(S, fx, "DiffuseIntensity", 0.8);
    seed_set_texture(S, fx, "DiffuseTexture", tex);
    float pos[LIGHTS * 3], col[LIGHTS * 4], rad[LIGHTS];
    for (int i = 0; i < LIGHTS; i++) {
        double a = 2 * SEED_PI * i / LIGHTS;
        pos[i * 3] = (float)(1.4 * cos(a)), pos[i * 3 + 1] = 0.4f, pos[i * 3 + 2] = (float)(1.4 * sin(a));
        col[i * 4] = (float)(0.3 + 0.07 * i), col[i * 4 + 1] = (float)(1 - 0.08 * i);
        col[i * 4 + 2] = (float)(0.2 + 0.05 * (i % 3)), col[i * 4 + 3] = 1;
        rad[i] = 0.8f + 0.05f * (float)i;
    }
    seed_set_int(S, fx, "activeLights", LIGHTS);
    hfx_param *p = hfx_effect_param(fx, "LightPosition");
    CHECK(p && hfx_param_set_floats(p, pos, LIGHTS * 3) == HFX_OK);
    p = hfx_effect_param(fx, "LightColor");
    CHECK(p && hfx_param_set_floats(p, col, LIGHTS * 4) == HFX_OK);
    p = hfx_effect_param(fx, "LightRadius");
    CHECK(p && hfx_param_set_floats(p, rad, LIGHTS) == HFX_OK);
}
static void point_update(hfx_effect *fx) {
    hfx_param *p = hfx_effect_param(fx, "LightColor");
    seed_param_rgba(S, p ? hfx_param_element(p, 9) : NULL, "LightColor[9]", rgba_make(1, 0, 1, 1));
}

static void empty_set(hfx_effect *fx, const seed_texture *tex) {
    (void)tex;
    float view[16], proj[16], world[16], wv[16], wvp[16];
    xm_look_at(view, v3_make(1, 1.5, 4), v3_make(0, 0, 0), v3_make(0, 1, 0));
    xm_perspective_fov(proj, SEED_PI / 4, 1, 1, 20);
    seed_camera(S, view, proj);
    xm_translation(world, 0.3, -0.2, 0);
    xm_mul(wv, world, view);
    xm_mul(wvp, wv, proj);
    hfx_param *p = hfx_effect_param(fx, "WorldViewProj");
    CHECK(p && hfx_param_set_matrix(p, wvp) == HFX_OK);
}
static void empty_update(hfx_effect *fx) {
    float view[16], proj[16], world[16], wv[16], wvp[16];
    xm_look_at(view, v3_make(1, 1.5, 4), v3_make(0, 0, 0), v3_make(0, 1, 0));
    xm_perspective_fov(proj, SEED_PI / 4, 1, 1, 20);
    xm_translation(world, -0.4, 0.3, 0);
    xm_mul(wv, world, view);
    xm_mul(wvp, wv, proj);
    hfx_param *p = hfx_effect_param(fx, "WorldViewProj");
    CHECK(p && hfx_param_set_matrix(p, wvp) == HFX_OK);
}

static const spv_case CASES[] = {
    {"phong.fx", "Phong", 1, SEED_BLEND_NONE, 0, phong_set, phong_update},
    {"spot_specular.fx", "Texturizado", 1, SEED_BLEND_NONE, 0, spot_set, spot_update},
    {"multilights_repaired.fx", "Texturizado", 2, SEED_BLEND_ADD_AFTER_FIRST, 0, multi_set, multi_update},
    {"pointlights.fx", "PointLights", 1, SEED_BLEND_NONE, 0, point_set, point_update},
    {"fxcomposer_empty.fx", "technique0", 1, SEED_BLEND_NONE, 1, empty_set, empty_update},
};

/* --- rendering and comparing -------------------------------------------------------------------- */

static void grab(unsigned char *img) {
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            rgba c = seed_pixel(S, x, y);
            unsigned char *p = img + ((size_t)y * W + x) * 4;
            p[0] = (unsigned char)lround(c.r * 255), p[1] = (unsigned char)lround(c.g * 255);
            p[2] = (unsigned char)lround(c.b * 255), p[3] = (unsigned char)lround(c.a * 255);
        }
}

/* The largest channel difference over the image, and how many pixels differ at all. */
static int image_diff(const unsigned char *a, const unsigned char *b, int *differing) {
    int worst = 0;
    *differing = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        int d = 0;
        for (int c = 0; c < 4; c++) {
            int e = abs((int)a[i * 4 + c] - (int)b[i * 4 + c]);
            if (e > d) d = e;
        }
        if (d) (*differing)++;
        if (d > worst) worst = d;
    }
    return worst;
}

/* Pixels with some colour over the clear colour (black). */
static int lit_pixels(const unsigned char *img) {
    int n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        if (img[i * 4] > 8 || img[i * 4 + 1] > 8 || img[i * 4 + 2] > 8) n++;
    return n;
}

static void draw(hfx_effect *fx, const spv_case *c, const seed_mesh *mesh) {
    seed_clear(S, rgba_make(0, 0, 0, 0));
    CHECK_INT(seed_draw(S, fx, c->technique, mesh, c->blend), c->passes);
}

static void compare(const char *file, const char *when, const unsigned char *glsl, const unsigned char *spv) {
    int differing, worst = image_diff(glsl, spv, &differing);
    printf("  %s %s: GLSL vs SPIR-V max %d/255, %d pixels differ, %d lit\n", file, when, worst, differing,
           lit_pixels(spv));
    CHECK(worst <= 1);
    CHECK(lit_pixels(glsl) > 500);
    CHECK(lit_pixels(spv) > 500);
}

static void run_case(const spv_case *c) {
    printf("== %s (%s)\n", c->file, c->technique);
    unsigned char texels[64];
    seed_smooth_texels(texels);
    seed_texture tex = seed_texture_make(S, 4, 4, texels);
    seed_mesh *mesh = c->sphere ? seed_mesh_sphere(S, 1, 20, 14) : seed_mesh_floor(S, 2);
    if (!c->sphere) seed_camera_top(S, 2);
    seed_use_target(S, HFX_TARGET_GLSL330);
    hfx_effect *glsl = seed_load(S, c->file);
    seed_use_target(S, HFX_TARGET_SPIRV);
    hfx_effect *spv = seed_load(S, c->file);
    seed_use_target(S, HFX_TARGET_GLSL330);
    CHECK(glsl != NULL);
    CHECK(spv != NULL);
    size_t bytes = (size_t)W * H * 4;
    unsigned char *a = malloc(bytes), *b = malloc(bytes), *b0 = malloc(bytes);
    if (glsl && spv && a && b && b0) {
        c->set(glsl, &tex);
        c->set(spv, &tex);
        draw(glsl, c, mesh);
        grab(a);
        draw(spv, c, mesh);
        grab(b);
        compare(c->file, "first frame", a, b);
        if (test_current_failed_) {
            seed_save_png(S, c->file);
        }
        memcpy(b0, b, bytes);
        /* After the first frame: the new value must reach the SPIR-V program. */
        c->update(glsl);
        c->update(spv);
        draw(glsl, c, mesh);
        grab(a);
        draw(spv, c, mesh);
        grab(b);
        compare(c->file, "after an update", a, b);
        int changed;
        image_diff(b0, b, &changed);
        printf("  %s: the update changed %d pixels of the SPIR-V image\n", c->file, changed);
        CHECK(changed > 100);
    }
    free(a), free(b), free(b0);
    if (glsl) hfx_effect_destroy(glsl);
    if (spv) hfx_effect_destroy(spv);
    seed_texture_free(S, &tex);
    seed_mesh_free(S, mesh);
    CHECK_SCENE(S);
}

static void render_both_targets(void) {
    for (size_t i = 0; i < sizeof CASES / sizeof *CASES; i++) run_case(&CASES[i]);
}

/* Beyond the seeds: a struct, a bool, an array element, a sampler and the alpha test's uniforms
 * (hfx_alpha_func / hfx_alpha_ref), all by location in the SPIR-V. */
static const char ALPHA_FX[] =
    "float4x4 World, View, Projection;\n"
    "struct Mat { float4 colour; float k; };\n"
    "Mat mat;\n"
    "bool invert;\n"
    "float4 tint[3];\n"
    "texture tex;\n"
    "sampler smp = sampler_state { Texture = <tex>; MinFilter = Point; MagFilter = Point; };\n"
    "void vs(float4 p : POSITION0, float2 uv : TEXCOORD0, out float4 o : POSITION0, out float2 ouv : TEXCOORD0) {\n"
    "    o = mul(mul(mul(p, World), View), Projection); ouv = uv; }\n"
    "float4 ps(float2 uv : TEXCOORD0) : COLOR0 {\n"
    "    float4 c = mat.colour * mat.k + tint[2] * tex2D(smp, uv);\n"
    "    if (invert) c.rgb = 1 - c.rgb;\n"
    "    c.a = uv.x; return c; }\n"
    "technique T { pass P { AlphaTestEnable = true; AlphaFunc = Greater; AlphaRef = 100;\n"
    "    VertexShader = compile vs_2_0 vs(); PixelShader = compile ps_2_0 ps(); } }\n";

static hfx_effect *load_alpha(hfx_target target) {
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    opt.target = target;
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(seed_device(S), ALPHA_FX, sizeof ALPHA_FX - 1, "alpha.fx", &opt, &errors);
    if (!fx) printf("  alpha.fx: %s%s\n", errors ? errors : "", hfx_device_last_error(seed_device(S)));
    hfx_free(errors);
    return fx;
}

static void alpha_set(hfx_effect *fx, const seed_texture *tex) {
    seed_set_transforms(S, fx, "World", "View", "Projection", NULL);
    hfx_param *mat = hfx_effect_param(fx, "mat");
    seed_param_rgba(S, hfx_param_member(mat, "colour"), "mat.colour", rgba_make(0.2, 0.1, 0.4, 1));
    seed_param_float(S, hfx_param_member(mat, "k"), "mat.k", 0.5);
    hfx_param *t = hfx_effect_param(fx, "tint");
    seed_param_rgba(S, t ? hfx_param_element(t, 2) : NULL, "tint[2]", rgba_make(0.9, 0.8, 0.3, 1));
    seed_set_texture(S, fx, "tex", tex);
}
static void alpha_update(hfx_effect *fx) {
    seed_set_bool(S, fx, "invert", 1);
    hfx_param *t = hfx_effect_param(fx, "tint");
    seed_param_rgba(S, t ? hfx_param_element(t, 2) : NULL, "tint[2]", rgba_make(0.1, 0.5, 0.9, 1));
}

static void struct_bool_alpha_test(void) {
    spv_case c = {"alpha.fx", "T", 1, SEED_BLEND_NONE, 0, alpha_set, alpha_update};
    unsigned char texels[64];
    seed_smooth_texels(texels);
    seed_texture tex = seed_texture_make(S, 4, 4, texels);
    seed_mesh *mesh = seed_mesh_floor(S, 2);
    seed_camera_top(S, 2);
    hfx_effect *glsl = load_alpha(HFX_TARGET_GLSL330), *spv = load_alpha(HFX_TARGET_SPIRV);
    CHECK(glsl != NULL);
    CHECK(spv != NULL);
    size_t bytes = (size_t)W * H * 4;
    unsigned char *a = malloc(bytes), *b = malloc(bytes), *b0 = malloc(bytes);
    if (glsl && spv && a && b && b0) {
        for (int round = 0; round < 2; round++) {
            if (round) {
                memcpy(b0, b, bytes);
                alpha_update(glsl);
                alpha_update(spv);
            } else {
                alpha_set(glsl, &tex);
                alpha_set(spv, &tex);
            }
            draw(glsl, &c, mesh);
            grab(a);
            draw(spv, &c, mesh);
            grab(b);
            compare(c.file, round ? "after an update" : "first frame", a, b);
            /* The alpha test keeps u > 100/255: the left part of the floor stays clear. */
            CHECK(b[(64 * W + 5) * 4 + 0] == 0 && b[(64 * W + 5) * 4 + 3] == 0);
            CHECK(b[(64 * W + 120) * 4 + 3] > 200);
        }
        int changed;
        image_diff(b0, b, &changed);
        CHECK(changed > 100);
    }
    free(a), free(b), free(b0);
    if (glsl) hfx_effect_destroy(glsl);
    if (spv) hfx_effect_destroy(spv);
    seed_texture_free(S, &tex);
    seed_mesh_free(S, mesh);
    CHECK_SCENE(S);
}

/* A GL without ARB_gl_spirv, as a device sees it: the loader has no glSpecializeShader. (OSMesa
 * gives llvmpipe's 4.5 core context even when asked for 3.3, so the lack is made here.) */
static void *loader_without_spirv(const char *name) {
    if (strncmp(name, "glSpecializeShader", 18) == 0) return NULL;
    return test_gl_loader(name);
}

/* Loading with the SPIR-V target fails cleanly, and the device still loads and draws GLSL. */
static void refused_without_gl_spirv(void) {
    hfx_device *dev = hfx_device_create_gl(loader_without_spirv);
    CHECK(dev != NULL);
    if (!dev) return;
    char *path = test_seed_path("phong.fx"), *errors = NULL;
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    opt.target = HFX_TARGET_SPIRV;
    hfx_effect *fx = path ? hfx_effect_load(dev, path, &opt, &errors) : NULL;
    CHECK(fx == NULL);
    const char *msg = hfx_device_last_error(dev);
    printf("  without ARB_gl_spirv: %s\n", msg);
    CHECK(strstr(msg, "SPIR-V") != NULL && strstr(msg, "ARB_gl_spirv") != NULL);
    /* *errors holds the compiler's warnings here (load.c adds the load error only when it is
     * empty): hfx_device_last_error is where the reason is. */
    hfx_free(errors);
    if (fx) hfx_effect_destroy(fx);
    /* The device is still usable: the same file with GLSL 330 loads and draws. */
    unsigned char texels[64];
    seed_smooth_texels(texels);
    seed_texture tex = seed_texture_make(S, 4, 4, texels);
    seed_mesh *floor = seed_mesh_floor(S, 2);
    seed_camera_top(S, 2);
    opt.target = HFX_TARGET_GLSL330;
    hfx_effect *g = path ? hfx_effect_load(dev, path, &opt, NULL) : NULL;
    CHECK(g != NULL);
    if (g) {
        phong_set(g, &tex);
        draw(g, &CASES[0], floor);
        unsigned char *img = malloc((size_t)W * H * 4);
        if (img) {
            grab(img);
            CHECK(lit_pixels(img) > 500);
        }
        free(img);
        hfx_effect_destroy(g);
    }
    free(path);
    seed_texture_free(S, &tex);
    seed_mesh_free(S, floor);
    hfx_device_destroy(dev);
    CHECK_SCENE(S);
}

int main(void) {
    test_require_seeds();
    S = seed_scene_create_version(W, H, 4, 5);
    if (!S) {
        fprintf(stderr, "no OSMesa GL 4.5 core context\n");
        return 1;
    }
    RUN(render_both_targets);
    printf("== the same, loading the effects from .hfxo bytes (hfxc, then hfx_effect_load_memory)\n");
    seed_use_hfxo(S, 1);
    RUN(render_both_targets);
    seed_use_hfxo(S, 0);
    RUN(struct_bool_alpha_test);
    RUN(refused_without_gl_spirv);
    seed_scene_destroy(S);
    return test_summary();
}
