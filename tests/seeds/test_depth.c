/* Depth with Direct3D projections (XNA's CreatePerspectiveFieldOfView: depth 0 at the near
 * plane, 1 at the far plane), drawn with ambient.fx. Overlapping objects occlude by distance
 * whatever the drawing order; what lies nearer than the near plane or beyond the far plane is
 * clipped, as Direct3D clips 0 <= z <= w (a port that kept GL's -w <= z <= w would still show
 * what lies between half the near distance and the near plane). */
#include "run_twice.h"

#define FILE_ "ambient.fx"

static seed_scene *S;

static const rgba CLEAR = {0, 0, 0, 1};
static const rgba RED = {0.9, 0.1, 0.1, 1}, GREEN = {0.1, 0.8, 0.2, 1}, BLUE = {0.1, 0.2, 0.9, 1},
                  YELLOW = {0.9, 0.9, 0.1, 1}, GREY = {0.5, 0.5, 0.5, 1};

typedef struct depth_scene {
    hfx_effect *fx;
    seed_mesh *far_quad, *near_quad, *too_near, *too_far, *floor;
} depth_scene;

/* A quad in the plane z = z0 facing +z (towards the camera). */
static seed_mesh *facing_quad(double x0, double y0, double size, double z0) {
    return seed_mesh_quad(S, v3_make(x0, y0, z0), v3_make(size, 0, 0), v3_make(0, size, 0), v3_make(0, 0, 1), 0, 0, 1, 1);
}

/* The camera at (0, 0, 5) looking down -z, 45 degrees, near 1, far 50. */
static int open_scene(depth_scene *d) {
    d->fx = seed_load(S, FILE_);
    d->far_quad = facing_quad(-1, -1, 2, 0);
    d->near_quad = facing_quad(-0.5, -0.5, 2, 1);
    d->too_near = facing_quad(-3, -3, 6, 4.25);    /* 0.75 from the camera */
    d->too_far = facing_quad(-40, -40, 80, -55);   /* 60 from the camera */
    d->floor = seed_mesh_quad(S, v3_make(-3, -0.3, 6), v3_make(6, 0, 0), v3_make(0, 0, -8), v3_make(0, 1, 0), 0, 0, 1, 1);
    float view[16], proj[16];
    xm_look_at(view, v3_make(0, 0, 5), v3_make(0, 0, 0), v3_make(0, 1, 0));
    xm_perspective_fov(proj, SEED_PI / 4, 1, 1, 50);
    seed_camera(S, view, proj);
    return d->fx != NULL;
}

static void close_scene(depth_scene *d) {
    CHECK(d->fx != NULL);
    if (d->fx) hfx_effect_destroy(d->fx);
    seed_mesh_free(S, d->far_quad);
    seed_mesh_free(S, d->near_quad);
    seed_mesh_free(S, d->too_near);
    seed_mesh_free(S, d->too_far);
    seed_mesh_free(S, d->floor);
    CHECK_SCENE(S);
}

static void draw(depth_scene *d, const seed_mesh *m, rgba colour) {
    seed_set_transforms(S, d->fx, "world", "view", "projection", NULL);
    seed_set_rgba(S, d->fx, "colorMaterialAmbiental", colour);
    CHECK_INT(seed_draw(S, d->fx, "ModeloAmbiental", m, SEED_BLEND_NONE), 1);
}

/* Every pixel that shows one object (or none) wherever in it one looks must show that
 * object's colour (the clear colour when none). */
static void compare_image(const char *label, const seed_object *objs, const rgba *colours, int n) {
    int wrong = 0, checked = 0;
    int seen[8] = {0};
    for (int y = 0; y < seed_height(S); y += 2)
        for (int x = 0; x < seed_width(S); x += 2) {
            seed_surface s;
            int hit = seed_pick_certain(S, objs, n, x, y, &s);
            if (hit == -2) continue;
            rgba want = hit >= 0 ? colours[hit] : CLEAR, got = seed_pixel(S, x, y);
            double d = 255 * maxd(maxd(fabs(want.r - got.r), fabs(want.g - got.g)), fabs(want.b - got.b));
            if (d > SEED_TOLERANCE) {
                if (wrong < 5)
                    printf("  %s: pixel (%d,%d) got %.0f %.0f %.0f, expected object %d\n", label, x, y, got.r * 255,
                           got.g * 255, got.b * 255, hit);
                wrong++;
            }
            if (hit >= 0) seen[hit] = 1;
            checked++;
        }
    printf("  %s: %d pixels compared, %d wrong\n", label, checked, wrong);
    CHECK_INT(wrong, 0);
    for (int i = 0; i < n; i++) CHECK(seen[i]);
}

/* The nearer green quad hides part of the red one, drawn before or after it. */
static void nearer_object_wins_in_either_order(void) {
    depth_scene d = {0};
    if (open_scene(&d)) {
        seed_object objs[2] = {seed_object_at(d.far_quad, NULL), seed_object_at(d.near_quad, NULL)};
        rgba colours[2] = {RED, GREEN};
        seed_clear(S, CLEAR);
        draw(&d, d.far_quad, RED);
        draw(&d, d.near_quad, GREEN);
        compare_image("far then near", objs, colours, 2);
        seed_clear(S, CLEAR);
        draw(&d, d.near_quad, GREEN);
        draw(&d, d.far_quad, RED);
        compare_image("near then far", objs, colours, 2);
        /* By hand: (0.25, 0.25, 1) lies on the green quad in front of the red one; (-0.75,
         * -0.75, 0) on the red quad only. */
        int x, y;
        seed_pixel_of(S, v3_make(0.25, 0.25, 1), &x, &y);
        CHECK_PROBE(seed_expect(S, "depth (ambient.fx)", "overlap: the nearer quad", x, y, GREEN));
        seed_pixel_of(S, v3_make(-0.75, -0.75, 0), &x, &y);
        CHECK_PROBE(seed_expect(S, "depth (ambient.fx)", "far quad alone", x, y, RED));
    }
    close_scene(&d);
}

/* A quad 0.75 from the camera covers the whole view, one 60 away fills the background: both
 * lie outside Direct3D's 0..1 depth range and must leave the picture as it was. */
static void near_and_far_planes_clip(void) {
    depth_scene d = {0};
    if (open_scene(&d)) {
        seed_object objs[2] = {seed_object_at(d.far_quad, NULL), seed_object_at(d.near_quad, NULL)};
        rgba colours[2] = {RED, GREEN};
        seed_clear(S, CLEAR);
        draw(&d, d.far_quad, RED);
        draw(&d, d.near_quad, GREEN);
        draw(&d, d.too_near, BLUE);
        draw(&d, d.too_far, YELLOW);
        compare_image("too near and too far", objs, colours, 2);
        CHECK_PROBE(seed_expect(S, "depth (ambient.fx)", "in front of the near plane: clipped", 64, 64, GREEN));
        CHECK_PROBE(seed_expect(S, "depth (ambient.fx)", "beyond the far plane: clipped", 3, 3, CLEAR));
    }
    close_scene(&d);
}

/* A floor running from behind the camera into the distance: its part nearer than the near
 * plane (the bottom rows) is cut away, the rest drawn. */
static void near_plane_cuts_a_crossing_object(void) {
    depth_scene d = {0};
    if (open_scene(&d)) {
        seed_object obj = seed_object_at(d.floor, NULL);
        rgba colours[1] = {GREY};
        seed_clear(S, CLEAR);
        draw(&d, d.floor, GREY);
        compare_image("floor across the near plane", &obj, colours, 1);
        /* Row 127 looks down at 22 degrees (tan = 0.984 tan 22.5): it meets the floor 0.74
         * ahead, inside the near plane. Row 100 (0.5625 tan 22.5) meets it 1.29 ahead. */
        seed_surface s;
        CHECK(seed_pick(S, &obj, 1, 64, 127, &s) < 0);
        CHECK(seed_pick(S, &obj, 1, 64, 100, &s) == 0);
        CHECK_PROBE(seed_expect(S, "depth (ambient.fx)", "floor nearer than the near plane", 64, 127, CLEAR));
        CHECK_PROBE(seed_expect(S, "depth (ambient.fx)", "floor beyond the near plane", 64, 100, GREY));
    }
    close_scene(&d);
}

/* A sphere sunk into a floor, seen from above at an angle: where they cross, the per-pixel
 * depths decide, not the drawing order. */
static void interpenetrating_sphere_and_floor(void) {
    depth_scene d = {0};
    if (open_scene(&d)) {
        seed_mesh *sphere = seed_mesh_sphere(S, 1, 24, 16), *floor = seed_mesh_floor(S, 2);
        float view[16], proj[16], world[16];
        xm_look_at(view, v3_make(0.5, 2.5, 3.5), v3_make(0, 0, 0), v3_make(0, 1, 0));
        xm_perspective_fov(proj, SEED_PI / 3, 1, 1, 50);
        seed_camera(S, view, proj);
        xm_translation(world, 0.2, 0.3, -0.1);
        seed_object objs[2] = {seed_object_at(floor, NULL), seed_object_at(sphere, world)};
        rgba colours[2] = {GREY, RED};
        seed_set_rgba(S, d.fx, "colorMaterialAmbiental", RED);
        seed_clear(S, CLEAR);
        seed_set_transforms(S, d.fx, "world", "view", "projection", world);
        CHECK_INT(seed_draw(S, d.fx, "ModeloAmbiental", sphere, SEED_BLEND_NONE), 1);
        seed_set_transforms(S, d.fx, "world", "view", "projection", NULL);
        seed_set_rgba(S, d.fx, "colorMaterialAmbiental", GREY);
        CHECK_INT(seed_draw(S, d.fx, "ModeloAmbiental", floor, SEED_BLEND_NONE), 1);
        compare_image("sphere sunk into the floor", objs, colours, 2);
        seed_mesh_free(S, sphere);
        seed_mesh_free(S, floor);
    }
    close_scene(&d);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(nearer_object_wins_in_either_order);
    RUN(near_and_far_planes_clip);
    RUN(near_plane_cuts_a_crossing_object);
    RUN(interpenetrating_sphere_and_floor);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
