/* ambient.fx and ambient_textured.fx (003 Código 7-1, 7-2): the ambient colour alone, then
 * times a WRAP-addressed, LINEAR-filtered texture (technique Texturizado) or not (Material).
 * The pixel shader's `colorMaterialAmbiental *= texturaColor` writes a per-pixel copy of the
 * global: every pixel starts from the application's value and the parameter is unchanged. */
#include "run_twice.h"

static seed_scene *S;

static rgba flat_shade(const seed_surface *s, const void *user) {
    (void)s;
    return *(const rgba *)user;
}

typedef struct textured_ref {
    rgba ambient;
    const seed_texture *tex;
    int textured;
} textured_ref;

static rgba textured_shade(const seed_surface *s, const void *user) {
    const textured_ref *r = user;
    if (!r->textured) return r->ambient;
    return rgba_mul(r->ambient, seed_texture_sample(r->tex, s->u, s->v, SEED_WRAP));
}

/* A 2 x 2 quad in the middle of a 4 x 4 view: pixels 32..95 are the object, the rest the
 * clear colour. */
static seed_mesh *centre_quad(double u0, double u1) {
    return seed_mesh_quad(S, v3_make(-1, 0, -1), v3_make(2, 0, 0), v3_make(0, 0, 2), v3_make(0, 1, 0), u0, u0, u1, u1);
}

static const rgba CLEAR = {0.0, 0.5, 0.0, 1.0};

/* The initializer {0.05F, 0.05F, 0.05F, 1.0F}: 12.75 / 255 grey where the quad is. */
static void ambient_default_colour(void) {
    hfx_effect *fx = seed_load(S, "ambient.fx");
    CHECK(fx != NULL);
    seed_mesh *quad = centre_quad(0, 1);
    seed_object obj = seed_object_at(quad, NULL);
    seed_camera_top(S, 2);
    if (fx) {
        /* The matrices are found by their semantics too, as FX Composer binds them. */
        CHECK(hfx_effect_param_by_semantic(fx, "WORLD") == hfx_effect_param(fx, "world"));
        CHECK(hfx_effect_param_by_semantic(fx, "Projection") == hfx_effect_param(fx, "projection"));
        seed_set_transforms(S, fx, "world", "view", "projection", NULL);
        seed_clear(S, CLEAR);
        CHECK_INT(seed_draw(S, fx, "ModeloAmbiental", quad, SEED_BLEND_NONE), 1);
        rgba def = rgba_make(0.05, 0.05, 0.05, 1);
        for (int y = 36; y < 96; y += 14)
            for (int x = 34; x < 96; x += 15) CHECK_PROBE(seed_probe(S, "ambient.fx", "default colour", &obj, x, y, flat_shade, &def));
        CHECK_PROBE(seed_expect(S, "ambient.fx", "outside: clear colour", 10, 10, CLEAR));
        CHECK_PROBE(seed_expect(S, "ambient.fx", "outside: clear colour", 110, 64, CLEAR));
    }
    seed_mesh_free(S, quad);
    if (fx) hfx_effect_destroy(fx);
    CHECK_SCENE(S);
}

/* A colour set by the application, a World that moves and scales the quad. */
static void ambient_set_colour_and_world(void) {
    hfx_effect *fx = seed_load(S, "ambient.fx");
    CHECK(fx != NULL);
    seed_mesh *quad = centre_quad(0, 1);
    float world[16], scale[16], move[16];
    xm_scale(scale, 0.5, 1, 0.75);
    xm_translation(move, 1, 0, -0.5);
    xm_mul(world, scale, move);
    seed_object obj = seed_object_at(quad, world);
    seed_camera_top(S, 2);
    if (fx) {
        rgba c = rgba_make(0.9, 0.6, 0.3, 0.8);
        seed_set_transforms(S, fx, "world", "view", "projection", world);
        seed_set_rgba(S, fx, "colorMaterialAmbiental", c);
        seed_clear(S, CLEAR);
        CHECK_INT(seed_draw(S, fx, "ModeloAmbiental", quad, SEED_BLEND_NONE), 1);
        /* The moved quad covers x in [0.5, 1.5], z in [-1.25, 0.25]: pixels 80..111, 24..71. */
        CHECK_PROBE(seed_probe(S, "ambient.fx", "set colour, moved quad", &obj, 96, 48, flat_shade, &c));
        CHECK_PROBE(seed_probe(S, "ambient.fx", "set colour, moved quad", &obj, 84, 28, flat_shade, &c));
        CHECK_PROBE(seed_probe(S, "ambient.fx", "set colour, moved quad", &obj, 108, 68, flat_shade, &c));
        CHECK_PROBE(seed_expect(S, "ambient.fx", "where the quad was", 64, 64, CLEAR));
        CHECK_PROBE(seed_expect(S, "ambient.fx", "left of the moved quad", 76, 48, CLEAR));
        CHECK_PROBE(seed_expect(S, "ambient.fx", "below the moved quad", 96, 76, CLEAR));
    }
    seed_mesh_free(S, quad);
    if (fx) hfx_effect_destroy(fx);
    CHECK_SCENE(S);
}

/* Texturizado: ambient * tex, with texcoords -0.5 .. 1.5 so WRAP repeats the texture. */
static void textured_technique(void) {
    hfx_effect *fx = seed_load(S, "ambient_textured.fx");
    CHECK(fx != NULL);
    unsigned char texels[64];
    seed_smooth_texels(texels);
    seed_texture tex = seed_texture_make(S, 4, 4, texels);
    seed_mesh *quad = seed_mesh_quad(S, v3_make(-2, 0, -2), v3_make(4, 0, 0), v3_make(0, 0, 4), v3_make(0, 1, 0),
                                     -0.5, -0.5, 1.5, 1.5);
    seed_object obj = seed_object_at(quad, NULL);
    seed_camera_top(S, 2);
    if (fx) {
        textured_ref r = {rgba_make(0.8, 0.9, 0.7, 1), &tex, 1};
        seed_set_transforms(S, fx, "world", "view", "projection", NULL);
        seed_set_rgba(S, fx, "colorMaterialAmbiental", r.ambient);
        seed_set_texture(S, fx, "texturaModelo", &tex);
        for (int frame = 0; frame < 2; frame++) { /* the second frame must not compound the *= */
            seed_clear(S, CLEAR);
            CHECK_INT(seed_draw(S, fx, "Texturizado", quad, SEED_BLEND_NONE), 1);
            for (int y = 4; y < 128; y += 17)
                for (int x = 3; x < 128; x += 19)
                    CHECK_PROBE(seed_probe(S, "ambient_textured.fx", frame ? "Texturizado, frame 2" : "Texturizado",
                                           &obj, x, y, textured_shade, &r));
        }
        /* Texel (1, 2) = (160, 200, 110, 195) by hand at its centre u = 0.375, v = 0.625
         * (pixel 56, 72), and its repeat one texture to the right (u = 1.375: pixel 120). */
        rgba hand = rgba_make(0.8 * 160 / 255, 0.9 * 200 / 255, 0.7 * 110 / 255, 195 / 255.0);
        CHECK_PROBE(seed_expect(S, "ambient_textured.fx", "texel (1,2) by hand", 56, 72, hand));
        CHECK_PROBE(seed_expect(S, "ambient_textured.fx", "texel (1,2) wrapped", 120, 72, hand));
        float after[4] = {0};
        hfx_param *p = hfx_effect_param(fx, "colorMaterialAmbiental");
        CHECK(p && hfx_param_get_floats(p, after, 4) == HFX_OK);
        CHECK_NEAR(after[0], 0.8, 1e-6);
        CHECK_NEAR(after[1], 0.9, 1e-6);
        CHECK_NEAR(after[2], 0.7, 1e-6);
        CHECK_NEAR(after[3], 1.0, 1e-6);
    }
    seed_texture_free(S, &tex);
    seed_mesh_free(S, quad);
    if (fx) hfx_effect_destroy(fx);
    CHECK_SCENE(S);
}

/* Material: mainPS(false) never samples; the default colour, texture bound or not. */
static void material_technique(void) {
    hfx_effect *fx = seed_load(S, "ambient_textured.fx");
    CHECK(fx != NULL);
    unsigned char texels[64];
    seed_smooth_texels(texels);
    seed_texture tex = seed_texture_make(S, 4, 4, texels);
    seed_mesh *quad = centre_quad(0, 1);
    seed_object obj = seed_object_at(quad, NULL);
    seed_camera_top(S, 2);
    if (fx) {
        textured_ref r = {rgba_make(0.05, 0.05, 0.05, 1), &tex, 0};
        seed_set_transforms(S, fx, "world", "view", "projection", NULL);
        seed_set_texture(S, fx, "texturaModelo", &tex);
        seed_clear(S, CLEAR);
        CHECK_INT(seed_draw(S, fx, "Material", quad, SEED_BLEND_NONE), 1);
        for (int y = 36; y < 96; y += 19)
            for (int x = 34; x < 96; x += 19)
                CHECK_PROBE(seed_probe(S, "ambient_textured.fx", "Material", &obj, x, y, textured_shade, &r));
        CHECK_PROBE(seed_expect(S, "ambient_textured.fx", "Material: outside", 5, 5, CLEAR));
    }
    seed_texture_free(S, &tex);
    seed_mesh_free(S, quad);
    if (fx) hfx_effect_destroy(fx);
    CHECK_SCENE(S);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(ambient_default_colour);
    RUN(ambient_set_colour_and_world);
    RUN(textured_technique);
    RUN(material_technique);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
