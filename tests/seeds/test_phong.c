/* phong.fx (000 §6.0.6): ambient + diffuse + specular of one directional light,
 *   I = A * Ai + Lc * Di * tex * N.L + Si * Sc * (R.V)^n,  R = normalize(2 (N.L) N - L),
 * with L = -normalize(LightDirection), N the normalised interpolated world normal and V the
 * normalised interpolated camPosition - worldPosition. */
#include "scene.h"

#include "files.h"

#define FILE_ "phong.fx"

static seed_scene *S;

typedef struct phong_ref {
    v3 light_direction, cam;
    rgba light_colour, specular_colour, ambient_colour;
    double specular_power, specular_intensity, ambient_intensity, diffuse_intensity;
    const seed_texture *tex;
} phong_ref;

/* The tutorial's equations, term by term. */
static rgba phong_shade(const seed_surface *s, const void *user) {
    const phong_ref *p = user;
    v3 n = v3_normalize(s->normal);
    v3 l = v3_neg(v3_normalize(p->light_direction));
    v3 v = v3_normalize(v3_sub(p->cam, s->pos));
    rgba tex = seed_texture_sample(p->tex, s->u, s->v, SEED_CLAMP);
    double diff = saturate(v3_dot(n, l));
    v3 r = v3_normalize(v3_sub(v3_scale(n, 2 * diff), l));
    double spec = hlsl_pow(saturate(v3_dot(r, v)), p->specular_power);
    rgba ambient = rgba_scale(p->ambient_colour, p->ambient_intensity);
    rgba diffuse = rgba_scale(rgba_mul(p->light_colour, tex), p->diffuse_intensity * diff);
    rgba specular = rgba_scale(p->specular_colour, p->specular_intensity * spec);
    return rgba_add(rgba_add(ambient, diffuse), specular);
}

static const unsigned char TEXELS[2 * 2 * 4] = {200, 150, 100, 255, 200, 150, 100, 255,
                                                 200, 150, 100, 255, 200, 150, 100, 255};

static phong_ref default_ref(const seed_texture *tex) {
    phong_ref r;
    r.light_direction = v3_make(1, -1, 0);
    r.cam = v3_make(0.5, 1, 0);
    r.light_colour = rgba_make(1, 0.9, 0.8, 1);
    r.specular_colour = rgba_make(1, 1, 1, 1);
    r.ambient_colour = rgba_make(0.2, 0.3, 0.4, 1);
    r.specular_power = 20;
    r.specular_intensity = 0.4;
    r.ambient_intensity = 0.25;
    r.diffuse_intensity = 0.6;
    r.tex = tex;
    return r;
}

static void set_params(hfx_effect *fx, const phong_ref *r) {
    seed_set_v3(S, fx, "LightDirection", r->light_direction);
    seed_set_rgba(S, fx, "LightColor", r->light_colour);
    seed_set_v3(S, fx, "camPosition", r->cam);
    seed_set_rgba(S, fx, "SpecularColor", r->specular_colour);
    seed_set_float(S, fx, "SpecularPower", r->specular_power);
    seed_set_float(S, fx, "SpecularIntensity", r->specular_intensity);
    seed_set_rgba(S, fx, "AmbientColor", r->ambient_colour);
    seed_set_float(S, fx, "AmbientIntensity", r->ambient_intensity);
    seed_set_float(S, fx, "DiffuseIntensity", r->diffuse_intensity);
    seed_set_texture(S, fx, "DiffuseTexture", r->tex);
}

typedef struct floor_scene {
    hfx_effect *fx;
    seed_mesh *floor;
    seed_object obj;
    seed_texture tex;
} floor_scene;

static int floor_open(floor_scene *f) {
    f->fx = seed_load(S, FILE_);
    f->tex = seed_texture_make(S, 2, 2, TEXELS);
    f->floor = seed_mesh_floor(S, 2);
    f->obj = seed_object_at(f->floor, NULL);
    seed_camera_top(S, 2);
    return f->fx != NULL;
}

static void floor_draw(floor_scene *f, const phong_ref *r) {
    seed_set_transforms(S, f->fx, "World", "View", "Projection", NULL);
    set_params(f->fx, r);
    seed_clear(S, rgba_make(0, 0, 0, 0));
    CHECK_INT(seed_draw(S, f->fx, "Phong", f->floor, SEED_BLEND_NONE), 1);
}

static void floor_close(floor_scene *f) {
    if (f->fx) hfx_effect_destroy(f->fx);
    seed_texture_free(S, &f->tex);
    seed_mesh_free(S, f->floor);
    CHECK_SCENE(S);
}

static void probe_grid(floor_scene *f, const phong_ref *r, const char *label) {
    for (int y = 10; y < 128; y += 27)
        for (int x = 12; x < 128; x += 26) CHECK_PROBE(seed_probe(S, FILE_, label, &f->obj, x, y, phong_shade, r));
}

/* Diffuse and specular off: A * Ai = (0.05, 0.075, 0.1, 0.25) everywhere. */
static void ambient_term(void) {
    floor_scene f = {0};
    if (floor_open(&f)) {
        phong_ref r = default_ref(&f.tex);
        r.diffuse_intensity = r.specular_intensity = 0;
        floor_draw(&f, &r);
        CHECK_PROBE(seed_expect(S, FILE_, "ambient by hand", 64, 64, rgba_make(0.05, 0.075, 0.1, 0.25)));
        probe_grid(&f, &r, "ambient");
    }
    CHECK(f.fx != NULL);
    floor_close(&f);
}

/* Specular off, ambient off: Lc * Di * tex * N.L with N.L = cos 45 degrees everywhere on the
 * floor: (1, .9, .8) * .6 * (200, 150, 100)/255 * .7071. */
static void diffuse_term(void) {
    floor_scene f = {0};
    if (floor_open(&f)) {
        phong_ref r = default_ref(&f.tex);
        r.specular_intensity = r.ambient_intensity = 0;
        floor_draw(&f, &r);
        double k = 0.6 * sqrt(0.5);
        rgba hand = rgba_make(1 * 200 / 255.0 * k, 0.9 * 150 / 255.0 * k, 0.8 * 100 / 255.0 * k, 1 * k);
        CHECK_PROBE(seed_expect(S, FILE_, "diffuse by hand", 64, 64, hand));
        CHECK_PROBE(seed_expect(S, FILE_, "diffuse by hand", 5, 120, hand));
        probe_grid(&f, &r, "diffuse");
    }
    CHECK(f.fx != NULL);
    floor_close(&f);
}

static void all_three_terms(void) {
    floor_scene f = {0};
    if (floor_open(&f)) {
        phong_ref r = default_ref(&f.tex);
        floor_draw(&f, &r);
        probe_grid(&f, &r, "ambient+diffuse+specular");
        r.light_direction = v3_make(-0.3, -1, 0.6); /* not normalised: the shader does it */
        r.cam = v3_make(-1, 2, 1);
        floor_draw(&f, &r);
        probe_grid(&f, &r, "other light and camera");
    }
    CHECK(f.fx != NULL);
    floor_close(&f);
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
    floor_scene f = {0};
    if (floor_open(&f)) {
        phong_ref r = default_ref(&f.tex);
        r.specular_power = 40;
        floor_draw(&f, &r);
        int first = brightest_column();
        printf("  highlight with camPosition (0.5, 1, 0): column %d (expected 48)\n", first);
        CHECK(abs(first - 48) <= 1);
        CHECK_PROBE(seed_probe(S, FILE_, "highlight, camera 1", &f.obj, 48, 64, phong_shade, &r));
        CHECK_PROBE(seed_probe(S, FILE_, "beside highlight, camera 1", &f.obj, 56, 64, phong_shade, &r));
        r.cam = v3_make(1.5, 1, 0);
        floor_draw(&f, &r);
        int second = brightest_column();
        printf("  highlight with camPosition (1.5, 1, 0): column %d (expected 80)\n", second);
        CHECK(abs(second - 80) <= 1);
        CHECK_PROBE(seed_probe(S, FILE_, "highlight, camera 2", &f.obj, 80, 64, phong_shade, &r));
        CHECK_PROBE(seed_probe(S, FILE_, "old highlight, camera 2", &f.obj, 48, 64, phong_shade, &r));
    }
    CHECK(f.fx != NULL);
    floor_close(&f);
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
        r.cam = v3_make(0, 1, 4);
        seed_set_transforms(S, fx, "World", "View", "Projection", world);
        set_params(fx, &r);
        seed_clear(S, rgba_make(0, 0, 0, 0));
        CHECK_INT(seed_draw(S, fx, "Phong", sphere, SEED_BLEND_NONE), 1);
        int probes = 0;
        for (int y = 20; y < 110; y += 5)
            for (int x = 20; x < 110; x += 5) {
                seed_surface a, b;
                /* Stay off the silhouette: the surroundings must hit the sphere too. */
                if (seed_pick_offset(S, &obj, 1, x, y, -1.5, -1.5, &a) < 0 ||
                    seed_pick_offset(S, &obj, 1, x, y, 1.5, 1.5, &b) < 0 ||
                    seed_pick_offset(S, &obj, 1, x, y, -1.5, 1.5, &a) < 0 ||
                    seed_pick_offset(S, &obj, 1, x, y, 1.5, -1.5, &b) < 0)
                    continue;
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
    floor_scene f = {0};
    if (floor_open(&f)) {
        phong_ref a = default_ref(&f.tex), b = default_ref(&f.tex);
        seed_set_transforms(S, f.fx, "World", "View", "Projection", NULL);
        set_params(f.fx, &a);
        hfx_effect *clone = hfx_effect_clone(f.fx);
        CHECK(clone != NULL);
        if (clone) {
            b.light_colour = rgba_make(0.2, 0.9, 0.4, 1);
            b.cam = v3_make(-1, 1.5, 0.5);
            seed_set_rgba(S, clone, "LightColor", b.light_colour);
            seed_set_v3(S, clone, "camPosition", b.cam);
            seed_clear(S, rgba_make(0, 0, 0, 0));
            CHECK_INT(seed_draw(S, clone, "Phong", f.floor, SEED_BLEND_NONE), 1);
            probe_grid(&f, &b, "clone, own values");
            seed_clear(S, rgba_make(0, 0, 0, 0));
            CHECK_INT(seed_draw(S, f.fx, "Phong", f.floor, SEED_BLEND_NONE), 1);
            probe_grid(&f, &a, "original after the clone changed");
            hfx_effect_destroy(clone);
            seed_clear(S, rgba_make(0, 0, 0, 0));
            CHECK_INT(seed_draw(S, f.fx, "Phong", f.floor, SEED_BLEND_NONE), 1);
            probe_grid(&f, &a, "original after the clone is gone");
        }
    }
    CHECK(f.fx != NULL);
    floor_close(&f);
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
    test_require_seeds();
    S = seed_scene_create(128, 128);
    if (!S) {
        fprintf(stderr, "no OSMesa GL 3.3 context\n");
        return 1;
    }
    run_all();
    printf("== the same, loading the effects from .hfxo bytes (hfxc, then hfx_effect_load_memory)\n");
    seed_use_hfxo(S, 1);
    run_all();
    seed_report(S);
    seed_scene_destroy(S);
    return test_summary();
}
