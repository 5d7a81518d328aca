/* fxcomposer_empty.fx (003 §7.2.2, FX Composer's "Empty" template): WorldViewProj bound by its
 * WorldViewProjection semantic, a white pixel shader, and `CullMode = None` in the pass. */
#include "run_twice.h"

#define FILE_ "fxcomposer_empty.fx"

static seed_scene *S;

static const rgba CLEAR = {0.2, 0.1, 0.3, 1.0};
static const rgba WHITE = {1, 1, 1, 1};

static void set_wvp(hfx_effect *fx, const float world[16]) {
    float wv[16], wvp[16];
    xm_mul(wv, world, seed_view(S));
    xm_mul(wvp, wv, seed_projection(S));
    hfx_param *p = hfx_effect_param_by_semantic(fx, "WorldViewProjection");
    CHECK(p != NULL && p == hfx_effect_param(fx, "WorldViewProj"));
    CHECK(p && hfx_param_set_matrix(p, wvp) == HFX_OK);
}

/* Every pixel of a sphere in perspective: white inside its silhouette, the clear colour out
 * (pixels whose sample point lies within a tenth of a pixel of the silhouette are left out). */
static void white_silhouette(void) {
    hfx_effect *fx = seed_load(S, FILE_);
    CHECK(fx != NULL);
    seed_mesh *sphere = seed_mesh_sphere(S, 1, 20, 14);
    float view[16], proj[16], world[16];
    xm_look_at(view, v3_make(1, 1.5, 4), v3_make(0, 0, 0), v3_make(0, 1, 0));
    xm_perspective_fov(proj, SEED_PI / 4, 1, 1, 20);
    seed_camera(S, view, proj);
    xm_translation(world, 0.3, -0.2, 0);
    seed_object obj = seed_object_at(sphere, world);
    if (fx) {
        set_wvp(fx, world);
        seed_clear(S, CLEAR);
        CHECK_INT(seed_draw(S, fx, "technique0", sphere, SEED_BLEND_NONE), 1);
        int wrong = 0, inside = 0, outside = 0;
        double worst = 0;
        for (int y = 0; y < seed_height(S); y += 2)
            for (int x = 0; x < seed_width(S); x += 2) {
                seed_surface surf;
                int c = seed_pick_certain(S, &obj, 1, x, y, &surf);
                if (c == -2) continue;
                c = c == 0;
                rgba want = c ? WHITE : CLEAR, got = seed_pixel(S, x, y);
                double d = 255 * maxd(maxd(fabs(want.r - got.r), fabs(want.g - got.g)),
                                      maxd(fabs(want.b - got.b), fabs(want.a - got.a)));
                if (d > SEED_TOLERANCE) {
                    if (wrong < 5) printf("  pixel (%d,%d) should be %s\n", x, y, c ? "white" : "clear");
                    wrong++;
                }
                worst = maxd(worst, d);
                c ? inside++ : outside++;
            }
        printf("  %d pixels inside, %d outside, %d wrong\n", inside, outside, wrong);
        CHECK(inside > 250 && outside > 250);
        CHECK_INT(wrong, 0);
        CHECK_PROBE(seed_expect(S, FILE_, "centre of the sphere", 70, 70, WHITE));
        CHECK_PROBE(seed_expect(S, FILE_, "corner", 2, 2, CLEAR));
        if (worst > SEED_TOLERANCE) seed_save_png(S, "fxcomposer_empty_silhouette");
    }
    seed_mesh_free(S, sphere);
    if (fx) hfx_effect_destroy(fx);
    CHECK_SCENE(S);
}

/* The template and ambient.fx, a 2 x 2 floor, and the camera 10 below it looking up
 * (orthographic, 4 x 4 wide, screen up = +z), World the identity. */
typedef struct below_scene {
    hfx_effect *fx, *amb;
    seed_mesh *floor;
    float id[16];
} below_scene;

static int open_below(below_scene *b) {
    b->fx = seed_load(S, FILE_);
    b->amb = seed_load(S, "ambient.fx");
    CHECK(b->fx != NULL && b->amb != NULL);
    b->floor = seed_mesh_floor(S, 1);
    float view[16], proj[16];
    xm_look_at(view, v3_make(0, -10, 0), v3_make(0, 0, 0), v3_make(0, 0, 1));
    xm_orthographic(proj, 4, 4, 1, 20);
    seed_camera(S, view, proj);
    xm_identity(b->id);
    return b->fx && b->amb;
}

static void close_below(below_scene *b) {
    seed_mesh_free(S, b->floor);
    if (b->fx) hfx_effect_destroy(b->fx);
    if (b->amb) hfx_effect_destroy(b->amb);
    CHECK_SCENE(S);
}

/* The floor seen from below shows its back to the camera. The application culls
 * counter-clockwise faces (XNA's default); ambient.fx, whose pass says nothing about culling,
 * leaves that alone and draws nothing; the template's `CullMode = None` draws it. */
static void cull_mode_none_draws_back_faces(void) {
    below_scene b;
    int loaded = open_below(&b);
    hfx_effect *fx = b.fx, *amb = b.amb;
    seed_mesh *floor = b.floor;
    const float *id = b.id;
    seed_object obj = seed_object_at(floor, id);
    seed_surface s;
    CHECK(seed_pick(S, &obj, 1, 64, 64, &s) == 0 && !s.front);
    if (loaded) {
        seed_set_transforms(S, amb, "world", "view", "projection", id);
        seed_clear(S, CLEAR);
        CHECK_INT(seed_draw(S, amb, NULL, floor, SEED_BLEND_NONE), 1);
        CHECK_PROBE(seed_expect(S, "ambient.fx", "back face culled", 64, 64, CLEAR));
        set_wvp(fx, id);
        seed_clear(S, CLEAR);
        CHECK_INT(seed_draw(S, fx, "technique0", floor, SEED_BLEND_NONE), 1);
        CHECK_PROBE(seed_expect(S, FILE_, "back face drawn", 64, 64, WHITE));
        CHECK_PROBE(seed_expect(S, FILE_, "back face drawn", 40, 80, WHITE));
        CHECK_PROBE(seed_expect(S, FILE_, "beside the floor", 10, 64, CLEAR));
        /* And from above, the front. */
        float view[16], proj[16];
        xm_look_at(view, v3_make(0, 10, 0), v3_make(0, 0, 0), v3_make(0, 0, -1));
        xm_orthographic(proj, 4, 4, 1, 20);
        seed_camera(S, view, proj);
        set_wvp(fx, id);
        seed_clear(S, CLEAR);
        CHECK_INT(seed_draw(S, fx, "technique0", floor, SEED_BLEND_NONE), 1);
        CHECK_PROBE(seed_expect(S, FILE_, "front face drawn", 64, 64, WHITE));
    }
    close_below(&b);
}

/* hfx_effect_end puts the application's culling back: after the template, ambient.fx culls the
 * back face again without the application touching GL. */
static void culling_is_restored_after_the_effect(void) {
    below_scene b;
    if (open_below(&b)) {
        hfx_effect *fx = b.fx, *amb = b.amb;
        seed_mesh *floor = b.floor;
        const float *id = b.id;
        seed_clear(S, CLEAR);
        set_wvp(fx, id);
        CHECK_INT(seed_draw(S, fx, "technique0", floor, SEED_BLEND_NONE), 1);
        CHECK_PROBE(seed_expect(S, FILE_, "back face drawn", 64, 64, WHITE));
        seed_set_transforms(S, amb, "world", "view", "projection", id);
        seed_set_rgba(S, amb, "colorMaterialAmbiental", rgba_make(1, 0, 0, 1));
        CHECK_INT(seed_draw(S, amb, NULL, floor, SEED_BLEND_NONE), 1);
        CHECK_PROBE(seed_expect(S, "ambient.fx", "culled again after the template", 64, 64, WHITE));
    }
    close_below(&b);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(white_silhouette);
    RUN(cull_mode_none_draws_back_faces);
    RUN(culling_is_restored_after_the_effect);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
