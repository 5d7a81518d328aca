/* directional.fx and directional_specular.fx (003 Código 7-3, with 7-6 / 7-7): a directional
 * light, Lambert diffuse on the interpolated world normal, which the author does not
 * renormalise (a scaled World scales the light; a sphere's normals shrink between vertices):
 *   L = normalize(direccionLuz); rd = max(dot(-L, N), 0)
 *   color = ambient + difuso * rd
 *   [modIluEsp]  R = normalize(2 N max(dot(-L, N), 0) + L); V = normalize(cam - P)
 *                color += ks * max(dot(R, V), 0)^n * especular * rd
 *   [Texturizado] color *= tex (WRAP, LINEAR);  color.a = 1 */
#include "floor.h"
#include "lighting.h"
#include "run_twice.h"

static seed_scene *S;

typedef struct dir_ref {
    v3 dir, cam;
    rgba ambient, diffuse, specular;
    double ks, n;
    int textured, spec_on;
    const seed_texture *tex;
} dir_ref;

static rgba directional_shade(const seed_surface *s, const void *user) {
    const dir_ref *r = user;
    v3 l = v3_normalize(r->dir), n = s->normal;
    double rd = maxd(v3_dot(v3_neg(l), n), 0);
    rgba c = rgba_add(r->ambient, rgba_scale(r->diffuse, rd));
    /* The book's R = normalize(2 N max(dot(-L, N), 0) + L) is 7-7's with -L towards the light. */
    if (r->spec_on)
        c = rgba_add(c, rgba_scale(r->specular, r->ks * seed_book_specular(n, v3_neg(l), s->pos, r->cam, r->n) * rd));
    if (r->textured) c = rgba_mul(c, seed_texture_sample(r->tex, s->u, s->v, SEED_WRAP));
    c.a = 1;
    return c;
}

/* The initializers of both files: ambient {0.05...}, difuso {0.24, 0.34, 0.39, 1}; and of the
 * specular one: ks {0.05F}, n 5, especular white. */
static dir_ref defaults(const seed_texture *tex) {
    dir_ref r;
    r.dir = v3_make(1, -2, 0.5);
    r.cam = v3_make(0, 3, 1);
    r.ambient = rgba_make(0.05, 0.05, 0.05, 1);
    r.diffuse = rgba_make(0.24, 0.34, 0.39, 1);
    r.specular = rgba_make(1, 1, 1, 1);
    r.ks = 0.05;
    r.n = 5;
    r.textured = r.spec_on = 0;
    r.tex = tex;
    return r;
}

/* The floor from -half to half placed by `world` (NULL: identity) under the top camera
 * over -2..2. */
static int open_floor(seed_floor *d, const char *file, double half, const float *world) {
    const seed_floor_setup setup = {.half = half, .view_half = 2, .world = world, SEED_FLOOR_LOWER_NAMES};
    return seed_floor_open(S, d, file, &setup);
}

static void draw_and_probe(seed_floor *d, const dir_ref *r, const char *technique, const char *label) {
    seed_set_v3(S, d->fx, "direccionLuz", r->dir);
    seed_set_texture(S, d->fx, "texturaModelo", r->tex);
    seed_floor_draw(S, d, d->fx, technique, SEED_BLEND_NONE, 1);
    seed_grid grid = {.x0 = 5, .step_x = 21, .y0 = 7, .step_y = 20, .skip_misses = 1};
    seed_floor_probe_grid(S, d, label, grid, directional_shade, r);
}

static void material_with_default_colours(void) {
    seed_floor d = {0};
    if (open_floor(&d, "directional.fx", 2, NULL)) {
        dir_ref r = defaults(&d.tex);
        draw_and_probe(&d, &r, "Material", "Material");
        /* By hand: L = (1,-2,.5)/2.2913, rd = 2/2.2913 = .87287: .05 + (.24,.34,.39) rd. */
        double rd = 2 / sqrt(5.25);
        CHECK_PROBE(seed_expect(S, d.file, "Material by hand", 64, 64,
                                rgba_make(0.05 + 0.24 * rd, 0.05 + 0.34 * rd, 0.05 + 0.39 * rd, 1)));
        /* `direccionLuz = normalize(direccionLuz)` in the shader leaves the parameter alone. */
        float after[3] = {0};
        hfx_param *p = hfx_effect_param(d.fx, "direccionLuz");
        CHECK(p && hfx_param_get_floats(p, after, 3) == HFX_OK);
        CHECK_NEAR(after[0], 1, 1e-6);
        CHECK_NEAR(after[1], -2, 1e-6);
        CHECK_NEAR(after[2], 0.5, 1e-6);
    }
    seed_floor_close(S, &d);
}

static void textured_technique(void) {
    seed_floor d = {0};
    if (open_floor(&d, "directional.fx", 2, NULL)) {
        dir_ref r = defaults(&d.tex);
        r.textured = 1;
        r.dir = v3_make(-0.4, -1, -0.2);
        seed_set_rgba(S, d.fx, "colorMaterialDifuso", r.diffuse = rgba_make(0.6, 0.5, 0.3, 1));
        draw_and_probe(&d, &r, "Texturizado", "Texturizado");
    }
    seed_floor_close(S, &d);
}

/* World = scale 0.5: the world normal is (0, 0.5, 0) and nobody renormalises it, so the
 * diffuse term is half of what a unit normal gives. */
static void scaled_world_scales_the_light(void) {
    float world[16];
    xm_scale(world, 0.5, 0.5, 0.5);
    seed_floor d = {0};
    if (open_floor(&d, "directional.fx", 4, world)) {
        dir_ref r = defaults(&d.tex);
        r.dir = v3_make(0, -1, 0);
        draw_and_probe(&d, &r, "Material", "World scaled by 0.5");
        CHECK_PROBE(seed_expect(S, d.file, "half the diffuse, by hand", 64, 64,
                                rgba_make(0.05 + 0.12, 0.05 + 0.17, 0.05 + 0.195, 1)));
    }
    seed_floor_close(S, &d);
}

/* A sphere in perspective: the interpolated normals are shorter than 1 inside each triangle. */
static void sphere_normals_are_not_renormalised(void) {
    seed_floor d = {0};
    d.file = "directional.fx";
    d.fx = seed_load(S, d.file);
    seed_smooth_texels(d.texels);
    d.tex = seed_texture_make(S, 4, 4, d.texels);
    d.mesh = seed_mesh_sphere(S, 1, 12, 8); /* coarse: the normals shrink by up to 4% */
    d.obj = seed_object_at(d.mesh, NULL);
    float view[16], proj[16];
    xm_look_at(view, v3_make(0.5, 1.5, 3.5), v3_make(0, 0, 0), v3_make(0, 1, 0));
    xm_perspective_fov(proj, SEED_PI / 3, 1, 0.5, 30);
    seed_camera(S, view, proj);
    if (d.fx) {
        seed_set_transforms(S, d.fx, "world", "view", "projection", NULL);
        dir_ref r = defaults(&d.tex);
        r.dir = v3_make(-1, -1, -1);
        seed_set_rgba(S, d.fx, "colorMaterialDifuso", r.diffuse = rgba_make(0.9, 0.8, 0.7, 1));
        seed_set_v3(S, d.fx, "direccionLuz", r.dir);
        seed_floor_draw(S, &d, d.fx, "Material", SEED_BLEND_NONE, 1);
        for (int y = 16; y < 112; y += 8)
            for (int x = 16; x < 112; x += 8)
                if (seed_well_inside(S, &d.obj, x, y, 1.5))
                    CHECK_PROBE(seed_probe(S, d.file, "sphere, short normals", &d.obj, x, y, directional_shade, &r));
    }
    seed_floor_close(S, &d);
}

/* directional_specular.fx with modIluEsp false (its initializer): exactly directional.fx. */
static void specular_off_is_the_diffuse_model(void) {
    seed_floor d = {0};
    if (open_floor(&d, "directional_specular.fx", 2, NULL)) {
        dir_ref r = defaults(&d.tex);
        seed_set_v3(S, d.fx, "posicionCamara", r.cam);
        seed_set_float(S, d.fx, "ks", 1);
        draw_and_probe(&d, &r, "Material", "modIluEsp false");
        r.textured = 1;
        draw_and_probe(&d, &r, "Texturizado", "modIluEsp false, Texturizado");
    }
    seed_floor_close(S, &d);
}

static void specular_on(void) {
    seed_floor d = {0};
    if (open_floor(&d, "directional_specular.fx", 2, NULL)) {
        dir_ref r = defaults(&d.tex);
        r.spec_on = 1;
        seed_set_bool(S, d.fx, "modIluEsp", 1);
        seed_set_v3(S, d.fx, "posicionCamara", r.cam);
        draw_and_probe(&d, &r, "Material", "modIluEsp, default ks 0.05");
        r.ks = 1;
        r.n = 12;
        r.dir = v3_make(1, -1, 0);
        r.cam = v3_make(0.5, 1.5, 0.2);
        seed_set_float(S, d.fx, "ks", r.ks);
        seed_set_float(S, d.fx, "n", r.n);
        seed_set_v3(S, d.fx, "posicionCamara", r.cam);
        draw_and_probe(&d, &r, "Material", "modIluEsp, ks 1, n 12");
        /* The highlight: R = (1, 1, 0)/sqrt 2 from every point, so it sits at
         * P = (cam.x - cam.y, 0, cam.z) = (-1, 0, 0.2). */
        int x, y;
        seed_pixel_of(S, v3_make(-1, 0, 0.2), &x, &y);
        CHECK_PROBE(seed_probe(S, d.file, "highlight", &d.obj, x, y, directional_shade, &r));
        r.textured = 1;
        draw_and_probe(&d, &r, "Texturizado", "modIluEsp, Texturizado");
    }
    seed_floor_close(S, &d);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(material_with_default_colours);
    RUN(textured_technique);
    RUN(scaled_world_scales_the_light);
    RUN(sphere_normals_are_not_renormalised);
    RUN(specular_off_is_the_diffuse_model);
    RUN(specular_on);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
