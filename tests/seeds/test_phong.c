/* phong.fx (000 §6.0.6): ambient + diffuse + specular of one directional light,
 *   I = A * Ai + Lc * Di * tex * N.L + Si * Sc * (R.V)^n,  R = normalize(2 (N.L) N - L),
 * with L = -normalize(LightDirection), N the normalised interpolated world normal and V the
 * normalised interpolated camPosition - worldPosition. */
#include "floor.h"
#include "lighting.h"
#include "run_twice.h"

#define FILE_ "phong.fx"

static seed_scene *S;

typedef struct phong_ref {
    v3 light_direction;
    rgba light_colour;
    seed_tutorial_material m;
} phong_ref;

/* The tutorial's equations, term by term. */
static rgba phong_shade(const seed_surface *s, const void *user) {
    const phong_ref *p = user;
    const seed_tutorial_material *m = &p->m;
    v3 n = v3_normalize(s->normal);
    v3 l = v3_neg(v3_normalize(p->light_direction));
    v3 v = v3_normalize(v3_sub(m->cam, s->pos));
    rgba tex = seed_texture_sample(m->tex, s->u, s->v, SEED_CLAMP);
    double diff = saturate(v3_dot(n, l));
    double spec = seed_tutorial_specular(n, l, v, m->specular_power);
    rgba ambient = rgba_scale(m->ambient_colour, m->ambient_intensity);
    rgba diffuse = rgba_scale(rgba_mul(p->light_colour, tex), m->diffuse_intensity * diff);
    rgba specular = rgba_scale(m->specular_colour, m->specular_intensity * spec);
    return rgba_add(rgba_add(ambient, diffuse), specular);
}

static const unsigned char TEXELS[2 * 2 * 4] = {200, 150, 100, 255, 200, 150, 100, 255,
                                                 200, 150, 100, 255, 200, 150, 100, 255};

static phong_ref default_ref(const seed_texture *tex) {
    phong_ref r;
    r.light_direction = v3_make(1, -1, 0);
    r.m.cam = v3_make(0.5, 1, 0);
    r.light_colour = rgba_make(1, 0.9, 0.8, 1);
    r.m.specular_colour = rgba_make(1, 1, 1, 1);
    r.m.ambient_colour = rgba_make(0.2, 0.3, 0.4, 1);
    r.m.specular_power = 20;
    r.m.specular_intensity = 0.4;
    r.m.ambient_intensity = 0.25;
    r.m.diffuse_intensity = 0.6;
    r.m.tex = tex;
    return r;
}

static void set_params(hfx_effect *fx, const phong_ref *r) {
    seed_set_v3(S, fx, "LightDirection", r->light_direction);
    seed_set_rgba(S, fx, "LightColor", r->light_colour);
    seed_set_tutorial_material(S, fx, &r->m);
}

/* The floor from -2 to 2 fills the view: 32 pixels per unit. */
static const seed_floor_setup FLOOR = {.half = 2, .view_half = 2, .tex_width = 2, .tex_height = 2, .texels = TEXELS};

static void floor_draw(seed_floor *f, const phong_ref *r) {
    seed_set_transforms(S, f->fx, "World", "View", "Projection", NULL);
    set_params(f->fx, r);
    seed_floor_draw(S, f, f->fx, "Phong", SEED_BLEND_NONE, 1);
}

static void probe_grid(seed_floor *f, const phong_ref *r, const char *label) {
    seed_grid grid = {.x0 = 12, .step_x = 26, .y0 = 10, .step_y = 27};
    seed_floor_probe_grid(S, f, label, grid, phong_shade, r);
}

/* Diffuse and specular off: A * Ai = (0.05, 0.075, 0.1, 0.25) everywhere. */
static void ambient_term(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        phong_ref r = default_ref(&f.tex);
        r.m.diffuse_intensity = r.m.specular_intensity = 0;
        floor_draw(&f, &r);
        CHECK_PROBE(seed_expect(S, FILE_, "ambient by hand", 64, 64, rgba_make(0.05, 0.075, 0.1, 0.25)));
        probe_grid(&f, &r, "ambient");
    }
    seed_floor_close(S, &f);
}

/* Specular off, ambient off: Lc * Di * tex * N.L with N.L = cos 45 degrees everywhere on the
 * floor: (1, .9, .8) * .6 * (200, 150, 100)/255 * .7071. */
static void diffuse_term(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        phong_ref r = default_ref(&f.tex);
        r.m.specular_intensity = r.m.ambient_intensity = 0;
        floor_draw(&f, &r);
        double k = 0.6 * sqrt(0.5);
        rgba hand = rgba_make(1 * 200 / 255.0 * k, 0.9 * 150 / 255.0 * k, 0.8 * 100 / 255.0 * k, 1 * k);
        CHECK_PROBE(seed_expect(S, FILE_, "diffuse by hand", 64, 64, hand));
        CHECK_PROBE(seed_expect(S, FILE_, "diffuse by hand", 5, 120, hand));
        probe_grid(&f, &r, "diffuse");
    }
    seed_floor_close(S, &f);
}

static void all_three_terms(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        phong_ref r = default_ref(&f.tex);
        floor_draw(&f, &r);
        probe_grid(&f, &r, "ambient+diffuse+specular");
        r.light_direction = v3_make(-0.3, -1, 0.6); /* not normalised: the shader does it */
        r.m.cam = v3_make(-1, 2, 1);
        floor_draw(&f, &r);
        probe_grid(&f, &r, "other light and camera");
    }
    seed_floor_close(S, &f);
}

/* Brightest pixel of row z = 0 (pixel row 64). */
static int brightest_column(void) {
    int best = -1;
    double best_sum = -1;
    for (int x = 0; x < 128; x++) {
        rgba c = seed_pixel(S, x, 64);
        double sum = c.r + c.g + c.b;
        if (sum > best_sum) {
            best_sum = sum;
            best = x;
        }
    }
    return best;
}

/* With LightDirection (1, -1, 0) the floor reflects light along R = (1, 1, 0) / sqrt 2, so the
 * highlight sits where camPosition - P is parallel to R: P = (cam.x - cam.y, 0, cam.z). The
 * camera at (0.5, 1, 0) puts it at x = -0.5 (pixel 48), at (1.5, 1, 0) at x = 0.5 (pixel 80). */
static void highlight_follows_the_camera(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        phong_ref r = default_ref(&f.tex);
        r.m.specular_power = 40;
        floor_draw(&f, &r);
        int first = brightest_column();
        printf("  highlight with camPosition (0.5, 1, 0): column %d (expected 48)\n", first);
        CHECK(abs(first - 48) <= 1);
        CHECK_PROBE(seed_probe(S, FILE_, "highlight, camera 1", &f.obj, 48, 64, phong_shade, &r));
        CHECK_PROBE(seed_probe(S, FILE_, "beside highlight, camera 1", &f.obj, 56, 64, phong_shade, &r));
        r.m.cam = v3_make(1.5, 1, 0);
        floor_draw(&f, &r);
        int second = brightest_column();
        printf("  highlight with camPosition (1.5, 1, 0): column %d (expected 80)\n", second);
        CHECK(abs(second - 80) <= 1);
        CHECK_PROBE(seed_probe(S, FILE_, "highlight, camera 2", &f.obj, 80, 64, phong_shade, &r));
        CHECK_PROBE(seed_probe(S, FILE_, "old highlight, camera 2", &f.obj, 48, 64, phong_shade, &r));
    }
    seed_floor_close(S, &f);
}

/* A sphere in perspective, rotated and moved by World: N and V interpolate across its
 * triangles (N shrinks between vertices; the shader renormalises it). */
static void sphere_in_perspective(void) {
    hfx_effect *fx = seed_load(S, FILE_);
    CHECK(fx != NULL);
    seed_texture tex = seed_texture_make(S, 2, 2, TEXELS);
    seed_mesh *sphere = seed_mesh_sphere(S, 1, 24, 16);
    float view[16], proj[16], rot[16], move[16], world[16];
    xm_look_at(view, v3_make(0, 1, 4), v3_make(0, 0, 0), v3_make(0, 1, 0));
    xm_perspective_fov(proj, SEED_PI / 3, 1, 0.5, 30);
    seed_camera(S, view, proj);
    xm_rotation_y(rot, 0.4);
    xm_translation(move, 0.2, 0, 0);
    xm_mul(world, rot, move);
    seed_object obj = seed_object_at(sphere, world);
    if (fx) {
        phong_ref r = default_ref(&tex);
        r.light_direction = v3_make(-1, -1, -1);
        r.m.cam = v3_make(0, 1, 4);
        seed_set_transforms(S, fx, "World", "View", "Projection", world);
        set_params(fx, &r);
        seed_clear(S, rgba_make(0, 0, 0, 0));
        CHECK_INT(seed_draw(S, fx, "Phong", sphere, SEED_BLEND_NONE), 1);
        int probes = 0;
        for (int y = 20; y < 110; y += 5)
            for (int x = 20; x < 110; x += 5) {
                /* Stay off the silhouette: the surroundings must hit the sphere too. */
                if (!seed_well_inside(S, &obj, x, y, 1.5)) continue;
                CHECK_PROBE(seed_probe(S, FILE_, "sphere", &obj, x, y, phong_shade, &r));
                probes++;
            }
        CHECK(probes > 40);
        seed_save_png(S, "phong_sphere");
    }
    seed_texture_free(S, &tex);
    seed_mesh_free(S, sphere);
    if (fx) hfx_effect_destroy(fx);
    CHECK_SCENE(S);
}

/* Effect.Clone(): the clone shares the code and starts from the original's values, and from
 * then on each keeps its own (XNA's semantics). */
static void clones_keep_their_own_values(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        phong_ref a = default_ref(&f.tex), b = default_ref(&f.tex);
        seed_set_transforms(S, f.fx, "World", "View", "Projection", NULL);
        set_params(f.fx, &a);
        hfx_effect *clone = hfx_effect_clone(f.fx);
        CHECK(clone != NULL);
        if (clone) {
            b.light_colour = rgba_make(0.2, 0.9, 0.4, 1);
            b.m.cam = v3_make(-1, 1.5, 0.5);
            seed_set_rgba(S, clone, "LightColor", b.light_colour);
            seed_set_v3(S, clone, "camPosition", b.m.cam);
            seed_floor_draw(S, &f, clone, "Phong", SEED_BLEND_NONE, 1);
            probe_grid(&f, &b, "clone, own values");
            seed_floor_draw(S, &f, f.fx, "Phong", SEED_BLEND_NONE, 1);
            probe_grid(&f, &a, "original after the clone changed");
            hfx_effect_destroy(clone);
            seed_floor_draw(S, &f, f.fx, "Phong", SEED_BLEND_NONE, 1);
            probe_grid(&f, &a, "original after the clone is gone");
        }
    }
    seed_floor_close(S, &f);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(ambient_term);
    RUN(diffuse_term);
    RUN(all_three_terms);
    RUN(highlight_follows_the_camera);
    RUN(sphere_in_perspective);
    RUN(clones_keep_their_own_values);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
