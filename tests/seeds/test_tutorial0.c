/* tutorial0.fx (000 §5): tex2D through a sampler_state with CLAMP addressing and LINEAR
 * filtering. The top camera sees x, z in [-2, 2] on 128 pixels (32 per unit); the quad carries
 * texcoords -0.5 .. 1.5, so u = x / 2 + 0.5 and the 4x4 texture covers pixels 32 .. 96, 16
 * pixels per texel, with clamped edges all around. */
#include "run_twice.h"
#include "stripes.h"

#define FILE_ "tutorial0.fx"

static seed_scene *S;

typedef struct sample_ref {
    const seed_texture *tex;
    seed_address address;
} sample_ref;

/* The tutorial's pixel shader: return tex2D(diffuseSampler, input.TexCoord). */
static rgba tutorial0_shade(const seed_surface *s, const void *user) {
    const sample_ref *r = user;
    return seed_texture_sample(r->tex, s->u, s->v, r->address);
}

/* Neighbouring texels differ by at most 40 per channel so that a half-pixel shift moves a
 * probe by less than one step; the edges differ by 120 so CLAMP and WRAP disagree there. */
static void make_texels(unsigned char texels[4 * 4 * 4]) {
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            unsigned char *p = texels + (y * 4 + x) * 4;
            p[0] = (unsigned char)(40 + 40 * x);
            p[1] = (unsigned char)(40 + 40 * y);
            p[2] = (unsigned char)(200 - 20 * (x + y));
            p[3] = 255;
        }
}

typedef struct tut0 {
    hfx_effect *fx;
    seed_mesh *quad;
    seed_object obj;
    unsigned char texels[64];
    seed_texture tex;
} tut0;

static int tut0_render(tut0 *t) {
    seed_camera_top(S, 2);
    t->fx = seed_load(S, FILE_);
    if (!t->fx) return 0;
    make_texels(t->texels);
    t->tex = seed_texture_make(S, 4, 4, t->texels);
    t->quad = seed_mesh_quad(S, v3_make(-2, 0, -2), v3_make(4, 0, 0), v3_make(0, 0, 4), v3_make(0, 1, 0), -0.5,
                             -0.5, 1.5, 1.5);
    t->obj = seed_object_at(t->quad, NULL);
    seed_set_transforms(S, t->fx, "World", "View", "Projection", NULL);
    seed_set_texture(S, t->fx, "diffuseTexture", &t->tex);
    seed_clear(S, rgba_make(0, 0, 0, 0));
    return seed_draw(S, t->fx, "Tut0", t->quad, SEED_BLEND_NONE) == 1;
}

static void tut0_free(tut0 *t) {
    if (t->fx) hfx_effect_destroy(t->fx);
    seed_texture_free(S, &t->tex);
    seed_mesh_free(S, t->quad);
}

static rgba texel_colour(const tut0 *t, int x, int y) {
    const unsigned char *p = t->texels + (y * 4 + x) * 4;
    return rgba_make(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0, p[3] / 255.0);
}

/* A value worked out by hand: the reference gives it at the probe's Direct3D 9 sample point
 * (checking the reasoning), and the pixel matches the reference there. */
static void hand_probe(tut0 *t, const char *label, int x, int y, rgba hand) {
    sample_ref ref = {&t->tex, SEED_CLAMP};
    seed_surface s;
    CHECK(seed_pick(S, &t->obj, 1, x, y, &s) == 0);
    rgba r = tutorial0_shade(&s, &ref);
    CHECK_NEAR(r.r, hand.r, 1e-6);
    CHECK_NEAR(r.g, hand.g, 1e-6);
    CHECK_NEAR(r.b, hand.b, 1e-6);
    CHECK_NEAR(r.a, hand.a, 1e-6);
    CHECK_PROBE(seed_probe(S, FILE_, label, &t->obj, x, y, tutorial0_shade, &ref));
}

/* Texel (i, j)'s centre is u = (i + 0.5) / 4, i.e. x = -0.75 + 0.5 i: pixel 40 + 16 i. There
 * the filter returns the texel itself. */
static void texels_appear_at_their_centres(void) {
    tut0 t = {0};
    CHECK(tut0_render(&t));
    if (t.fx)
        for (int j = 0; j < 4; j++)
            for (int i = 0; i < 4; i++) {
                char label[40];
                snprintf(label, sizeof label, "texel (%d,%d) centre", i, j);
                hand_probe(&t, label, 40 + 16 * i, 40 + 16 * j, texel_colour(&t, i, j));
            }
    tut0_free(&t);
    CHECK_SCENE(S);
}

/* Halfway between two texel centres (pixel 48: u = 0.25) LINEAR gives their mean; a quarter of
 * the way (pixel 44) 3:1. */
static void linear_filter_blends_neighbours(void) {
    tut0 t = {0};
    CHECK(tut0_render(&t));
    if (t.fx) {
        rgba a = texel_colour(&t, 0, 1), b = texel_colour(&t, 1, 1);
        hand_probe(&t, "mean of texels (0,1),(1,1)", 48, 56, rgba_scale(rgba_add(a, b), 0.5));
        hand_probe(&t, "3:1 of texels (0,1),(1,1)", 44, 56,
                                rgba_add(rgba_scale(a, 0.75), rgba_scale(b, 0.25)));
        rgba c = texel_colour(&t, 2, 2), d = texel_colour(&t, 3, 2), e = texel_colour(&t, 2, 3), f = texel_colour(&t, 3, 3);
        hand_probe(&t, "mean of texels (2..3,2..3)", 80, 80,
                                rgba_scale(rgba_add(rgba_add(c, d), rgba_add(e, f)), 0.25));
        sample_ref ref = {&t.tex, SEED_CLAMP};
        for (int y = 36; y < 96; y += 11)
            for (int x = 35; x < 96; x += 13)
                CHECK_PROBE(seed_probe(S, FILE_, "bilinear", &t.obj, x, y, tutorial0_shade, &ref));
    }
    tut0_free(&t);
    CHECK_SCENE(S);
}

/* CLAMP: beyond the texel centres of the border and outside [0, 1] the border texel itself,
 * where WRAP would blend in the opposite border (120 steps away). */
static void clamp_holds_the_border_texels(void) {
    tut0 t = {0};
    CHECK(tut0_render(&t));
    if (t.fx) {
        hand_probe(&t, "u,v < 0: texel (0,0)", 8, 8, texel_colour(&t, 0, 0));
        hand_probe(&t, "u > 1, v < 0: texel (3,0)", 120, 8, texel_colour(&t, 3, 0));
        hand_probe(&t, "u < 0, v > 1: texel (0,3)", 8, 120, texel_colour(&t, 0, 3));
        hand_probe(&t, "u,v > 1: texel (3,3)", 120, 120, texel_colour(&t, 3, 3));
        hand_probe(&t, "u = 0 edge: texel (0,2)", 32, 72, texel_colour(&t, 0, 2));
        hand_probe(&t, "v = 1 edge: texel (1,3)", 56, 96, texel_colour(&t, 1, 3));
        rgba a = texel_colour(&t, 3, 1), b = texel_colour(&t, 3, 2);
        hand_probe(&t, "u > 1 between rows 1 and 2", 110, 64, rgba_scale(rgba_add(a, b), 0.5));
        sample_ref ref = {&t.tex, SEED_CLAMP};
        for (int y = 4; y < 128; y += 24)
            for (int x = 2; x < 128; x += 25)
                CHECK_PROBE(seed_probe(S, FILE_, "clamped", &t.obj, x, y, tutorial0_shade, &ref));
    }
    tut0_free(&t);
    CHECK_SCENE(S);
}

/* Direct3D 9 samples pixel (x, y) at screen point (x, y), GL at (x + 0.5, y + 0.5). With a
 * 128 x 128 texture mapped one texel per pixel, every Direct3D 9 pixel lands on the border
 * between two texels and LINEAR returns their mean (the blur every XNA developer met), where
 * GL returns the texel itself. Red repeats 0, 128, 255 along u and green along v, so the mean
 * of texels x - 1 and x tells Direct3D 9's centres from GL's (the texel) and from a shift the
 * wrong way (texels x and x + 1), in both directions. */
static void pixel_centres_follow_direct3d9(void) {
    hfx_effect *fx = seed_load(S, FILE_);
    CHECK(fx != NULL);
    if (!fx) {
        CHECK_SCENE(S);
        return;
    }
    static unsigned char texels[128 * 128 * 4];
    seed_period3_texels(texels, 128);
    seed_texture tex = seed_texture_make(S, 128, 128, texels);
    seed_mesh *floor = seed_mesh_floor(S, 2);
    seed_camera_top(S, 2);
    seed_set_transforms(S, fx, "World", "View", "Projection", NULL);
    seed_set_texture(S, fx, "diffuseTexture", &tex);
    seed_clear(S, rgba_make(0, 0, 0, 0));
    CHECK_INT(seed_draw(S, fx, "Tut0", floor, SEED_BLEND_NONE), 1);
    static const int xs[6] = {30, 31, 32, 70, 98, 121}, ys[3] = {40, 77, 102};
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 6; i++) {
            int x = xs[i], y = ys[j];
            rgba mean = rgba_make((seed_period3(x - 1) + seed_period3(x)) / 2 / 255,
                                  (seed_period3(y - 1) + seed_period3(y)) / 2 / 255, 0, 1);
            CHECK_PROBE(seed_expect(S, "tutorial0.fx (centres)", "d3d9 centre: mean of 2 texels", x, y, mean));
        }
    seed_texture_free(S, &tex);
    seed_mesh_free(S, floor);
    hfx_effect_destroy(fx);
    CHECK_SCENE(S);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(texels_appear_at_their_centres);
    RUN(linear_filter_blends_neighbours);
    RUN(clamp_holds_the_border_texels);
    RUN(pixel_centres_follow_direct3d9);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
