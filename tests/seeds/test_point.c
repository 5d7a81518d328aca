/* point.fx and point_specular.fx (003 Código 7-4, with 7-6 / 7-7): a point light,
 *   L = normalize(posicionLuz - P); rd = max(dot(L, N), 0); color = difuso * rd
 *   [modIluEsp]  R = normalize(2 N max(dot(L, N), 0) - L); V = normalize(cam - P)
 *                color += ks * max(dot(R, V), 0)^n * especular * rd
 *   [atenuado]   d = |P - posicionLuz|; color *= d <= rango ? min(1 / (c1 + c2 d + c3 d^2), 1) : 0
 *   color += ambient; [Texturizado] color *= tex;  color.a = 1 */
#include "floor.h"
#include "lighting.h"
#include "run_twice.h"

static seed_scene *S;

typedef struct point_ref {
    v3 light, cam;
    rgba ambient, diffuse, specular;
    double ks, n, c1, c2, c3, range;
    int textured, spec_on, attenuated;
    const seed_texture *tex;
} point_ref;

static rgba point_shade(const seed_surface *s, const void *user) {
    const point_ref *r = user;
    v3 n = s->normal, l = v3_normalize(v3_sub(r->light, s->pos));
    double rd = maxd(v3_dot(l, n), 0);
    rgba c = rgba_scale(r->diffuse, rd);
    if (r->spec_on)
        c = rgba_add(c, rgba_scale(r->specular, r->ks * seed_book_specular(n, l, s->pos, r->cam, r->n) * rd));
    if (r->attenuated)
        c = rgba_scale(c, seed_book_attenuation(v3_distance(s->pos, r->light), r->range, r->c1, r->c2, r->c3));
    c = rgba_add(c, r->ambient);
    if (r->textured) c = rgba_mul(c, seed_texture_sample(r->tex, s->u, s->v, SEED_WRAP));
    c.a = 1;
    return c;
}

static point_ref defaults(const seed_texture *tex) {
    point_ref r;
    r.light = v3_make(0.3, 1, -0.2);
    r.cam = v3_make(-0.5, 2, 1);
    r.ambient = rgba_make(0.05, 0.05, 0.05, 1);
    r.diffuse = rgba_make(0.24, 0.34, 0.39, 1);
    r.specular = rgba_make(1, 1, 1, 1);
    r.ks = 0.05;
    r.n = 5;
    r.c1 = r.c2 = r.c3 = r.range = 0; /* no initializers */
    r.textured = r.spec_on = r.attenuated = 0;
    r.tex = tex;
    return r;
}

/* The floor from -2 to 2 fills the view: 32 pixels per unit. */
static const seed_floor_setup FLOOR = {.half = 2, .view_half = 2, SEED_FLOOR_LOWER_NAMES};

static void set_light(seed_floor *p, const point_ref *r) {
    seed_set_v3(S, p->fx, "posicionLuz", r->light);
    seed_set_texture(S, p->fx, "texturaModelo", r->tex);
    if (r->attenuated) {
        seed_set_bool(S, p->fx, "atenuado", 1);
        seed_set_float(S, p->fx, "c1", r->c1);
        seed_set_float(S, p->fx, "c2", r->c2);
        seed_set_float(S, p->fx, "c3", r->c3);
        seed_set_float(S, p->fx, "rango", r->range);
    }
}

static void draw_and_probe(seed_floor *p, const point_ref *r, const char *technique, const char *label) {
    set_light(p, r);
    seed_floor_draw(S, p, p->fx, technique, SEED_BLEND_NONE, 1);
    seed_grid grid = {.x0 = 4, .step_x = 21, .y0 = 6, .step_y = 20};
    seed_floor_probe_grid(S, p, label, grid, point_shade, r);
}

/* atenuado's initializer is false: diffuse + ambient only. Under the light (0.3, 0, -0.2) the
 * floor faces it: rd = 1, so .05 + (.24, .34, .39). */
static void unattenuated_by_default(void) {
    seed_floor p = {0};
    if (seed_floor_open(S, &p, "point.fx", &FLOOR)) {
        point_ref r = defaults(&p.tex);
        draw_and_probe(&p, &r, "Material", "atenuado false");
        int x, y;
        seed_pixel_of(S, v3_make(0.3, 0, -0.2), &x, &y);
        CHECK_PROBE(seed_expect(S, p.file, "under the light, by hand", x, y, rgba_make(0.29, 0.39, 0.44, 1)));
    }
    seed_floor_close(S, &p);
}

/* c1 1, c2 .2, c3 .3, rango 2 with the light 1 above the floor: the light reaches a disc of
 * radius sqrt(3) around (0.3, -0.2); outside it only the ambient is left. */
static void attenuation_and_range_cut_off(void) {
    seed_floor p = {0};
    if (seed_floor_open(S, &p, "point.fx", &FLOOR)) {
        point_ref r = defaults(&p.tex);
        r.attenuated = 1;
        r.c1 = 1, r.c2 = 0.2, r.c3 = 0.3, r.range = 2;
        draw_and_probe(&p, &r, "Material", "attenuated");
        int x, y;
        /* Under the light d = 1: 1 / 1.5 of the diffuse. */
        seed_pixel_of(S, v3_make(0.3, 0, -0.2), &x, &y);
        CHECK_PROBE(seed_expect(S, p.file, "under the light, by hand", x, y,
                                rgba_make(0.05 + 0.24 / 1.5, 0.05 + 0.34 / 1.5, 0.05 + 0.39 / 1.5, 1)));
        /* 1.65 and 1.82 from the light's foot: d = 1.929 (inside the range) and 2.077 (outside). */
        const double radii[2] = {1.65, 1.82};
        const v3 dirs[3] = {{-1, 0, 0}, {0, 0, 1}, {0.6, 0, 0.8}};
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 2; i++) {
                v3 at = v3_add(v3_make(0.3, 0, -0.2), v3_scale(dirs[k], radii[i]));
                seed_pixel_of(S, at, &x, &y);
                double d = v3_distance(at, r.light);
                CHECK(i == 0 ? d < 2 : d > 2);
                if (i == 1) CHECK_PROBE(seed_expect(S, p.file, "beyond rango: ambient", x, y, rgba_make(0.05, 0.05, 0.05, 1)));
                else CHECK_PROBE(seed_probe(S, p.file, "just inside rango", &p.obj, x, y, point_shade, &r));
            }
        /* Attenuation off again: the whole floor lit. */
        seed_set_bool(S, p.fx, "atenuado", 0);
        r.attenuated = 0;
        draw_and_probe(&p, &r, "Material", "attenuation switched off");
    }
    seed_floor_close(S, &p);
}

static void textured_technique(void) {
    seed_floor p = {0};
    if (seed_floor_open(S, &p, "point.fx", &FLOOR)) {
        point_ref r = defaults(&p.tex);
        r.textured = 1;
        r.light = v3_make(-0.6, 0.8, 0.9);
        seed_set_rgba(S, p.fx, "colorMaterialDifuso", r.diffuse = rgba_make(0.7, 0.6, 0.5, 1));
        seed_set_rgba(S, p.fx, "colorMaterialAmbiental", r.ambient = rgba_make(0.1, 0.05, 0.15, 1));
        draw_and_probe(&p, &r, "Texturizado", "Texturizado");
        r.attenuated = 1;
        r.c1 = 0.5, r.c2 = 0, r.c3 = 0.5, r.range = 2.5;
        draw_and_probe(&p, &r, "Texturizado", "Texturizado, attenuated");
    }
    seed_floor_close(S, &p);
}

static void specular_off_and_on(void) {
    seed_floor p = {0};
    if (seed_floor_open(S, &p, "point_specular.fx", &FLOOR)) {
        point_ref r = defaults(&p.tex);
        seed_set_v3(S, p.fx, "posicionCamara", r.cam);
        draw_and_probe(&p, &r, "Material", "modIluEsp false");
        r.spec_on = 1;
        seed_set_bool(S, p.fx, "modIluEsp", 1);
        draw_and_probe(&p, &r, "Material", "modIluEsp, default ks 0.05");
        r.ks = 0.8;
        r.n = 20;
        seed_set_float(S, p.fx, "ks", r.ks);
        seed_set_float(S, p.fx, "n", r.n);
        draw_and_probe(&p, &r, "Material", "modIluEsp, ks .8, n 20");
        /* The highlight: where the line from the light to the camera's mirror image
         * (-0.5, -2, 1) meets the floor, a third of the way: (0.0333, 0, 0.1333). */
        int x, y;
        seed_pixel_of(S, v3_make(0.3 - 0.8 / 3, 0, -0.2 + 1.2 / 3), &x, &y);
        CHECK_PROBE(seed_probe(S, p.file, "highlight", &p.obj, x, y, point_shade, &r));
        r.attenuated = 1;
        r.c1 = 1, r.c2 = 0.2, r.c3 = 0.3, r.range = 2;
        r.textured = 1;
        draw_and_probe(&p, &r, "Texturizado", "modIluEsp, attenuated, Texturizado");
    }
    seed_floor_close(S, &p);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(unattenuated_by_default);
    RUN(attenuation_and_range_cut_off);
    RUN(textured_technique);
    RUN(specular_off_and_on);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
