/* spot.fx and spot_specular.fx (003 Código 7-5, with 7-6 / 7-7): a spot light,
 *   S = normalize(posicionLuz - blancoLuz); L = normalize(posicionLuz - P)
 *   rd = max(dot(L, N), 0); color = difuso * rd  [+ the specular of 7-7 when modIluEsp]
 *   cosA = max(dot(S, L), 0), cosT = cos(anguloInterno), cosF = cos(anguloExterno)
 *   angular factor: 1 when cosA >= cosT, ((cosA - cosF) / (cosT - cosF))^falloff between,
 *   0 when cosA <= cosF (the book's equation after Ilustración 7-25)
 *   [atenuado] times min(1 / (c1 + c2 d + c3 d^2), 1) within rango, 0 beyond
 *   color += ambient; [Texturizado] color *= tex; color.a = 1
 * The book's test values (§7.3.3): inner 0.01, outer 0.1, falloff 0.8, light at (0, 10, 0)
 * aimed at the origin, c1 1, c2 0, c3 0.001, rango 20, atenuado: a lit disc of radius
 * 10 tan 0.1 = 1.0033 on the floor, ambient elsewhere. */
#include "floor.h"
#include "lighting.h"
#include "run_twice.h"

static seed_scene *S;

typedef struct spot_ref {
    v3 light, target, cam;
    double inner, outer, falloff;
    rgba ambient, diffuse, specular;
    double ks, n, c1, c2, c3, range;
    int textured, spec_on, attenuated;
    const seed_texture *tex;
} spot_ref;

static rgba spot_shade(const seed_surface *s, const void *user) {
    const spot_ref *r = user;
    v3 n = s->normal;
    v3 spot = v3_normalize(v3_sub(r->light, r->target)), l = v3_normalize(v3_sub(r->light, s->pos));
    double rd = maxd(v3_dot(l, n), 0);
    rgba c = rgba_scale(r->diffuse, rd);
    if (r->spec_on)
        c = rgba_add(c, rgba_scale(r->specular, r->ks * seed_book_specular(n, l, s->pos, r->cam, r->n) * rd));
    double cos_a = maxd(v3_dot(spot, l), 0);
    c = rgba_scale(c, seed_book_spot_cone(cos_a, r->inner, r->outer, r->falloff));
    if (r->attenuated)
        c = rgba_scale(c, seed_book_attenuation(v3_distance(s->pos, r->light), r->range, r->c1, r->c2, r->c3));
    c = rgba_add(c, r->ambient);
    if (r->textured) c = rgba_mul(c, seed_texture_sample(r->tex, s->u, s->v, SEED_WRAP));
    c.a = 1;
    return c;
}

/* The book's values; the colours are the initializers of spot.fx (ambient .07). */
static spot_ref book_values(const seed_texture *tex) {
    spot_ref r;
    r.light = v3_make(0, 10, 0);
    r.target = v3_make(0, 0, 0);
    r.cam = v3_make(0.3, 3, 0.4);
    r.inner = 0.01, r.outer = 0.1, r.falloff = 0.8;
    r.ambient = rgba_make(0.07, 0.07, 0.07, 1);
    r.diffuse = rgba_make(0.24, 0.34, 0.39, 1);
    r.specular = rgba_make(1, 1, 1, 1);
    r.ks = 0.05, r.n = 5;
    r.c1 = 1, r.c2 = 0, r.c3 = 0.001, r.range = 20;
    r.textured = r.spec_on = 0;
    r.attenuated = 1;
    r.tex = tex;
    return r;
}

/* The floor from -1.5 to 1.5 fills the view: 128 / 3 pixels per unit. */
static const seed_floor_setup FLOOR = {.half = 1.5, .view_half = 1.5, SEED_FLOOR_LOWER_NAMES};

static void set_spot(seed_floor *p, const spot_ref *r) {
    seed_set_v3(S, p->fx, "posicionLuz", r->light);
    seed_set_v3(S, p->fx, "blancoLuz", r->target);
    seed_set_float(S, p->fx, "anguloInterno", r->inner);
    seed_set_float(S, p->fx, "anguloExterno", r->outer);
    seed_set_float(S, p->fx, "falloff", r->falloff);
    seed_set_bool(S, p->fx, "atenuado", r->attenuated);
    seed_set_float(S, p->fx, "c1", r->c1);
    seed_set_float(S, p->fx, "c2", r->c2);
    seed_set_float(S, p->fx, "c3", r->c3);
    seed_set_float(S, p->fx, "rango", r->range);
    seed_set_texture(S, p->fx, "texturaModelo", r->tex);
}

static void draw_and_probe(seed_floor *p, const spot_ref *r, const char *technique, const char *label) {
    set_spot(p, r);
    seed_floor_draw(S, p, p->fx, technique, SEED_BLEND_NONE, 1);
    seed_grid grid = {.x0 = 6, .step_x = 17, .y0 = 8, .step_y = 16};
    seed_floor_probe_grid(S, p, label, grid, spot_shade, r);
}

/* Along the centre row and column and a diagonal: inside the inner cone, in the falloff ring,
 * just inside and just outside the disc's rim (1.0033), and far outside. */
static void probe_the_disc(seed_floor *p, const spot_ref *r, const char *label) {
    static const double radii[] = {0, 0.05, 0.3, 0.6, 0.9, 0.97, 1.04, 1.3};
    static const v3 dirs[] = {{1, 0, 0}, {0, 0, -1}, {-0.6, 0, 0.8}};
    for (size_t k = 0; k < sizeof dirs / sizeof dirs[0]; k++)
        for (size_t i = 0; i < sizeof radii / sizeof radii[0]; i++) {
            int x, y;
            seed_pixel_of(S, v3_scale(dirs[k], radii[i]), &x, &y);
            char what[64];
            snprintf(what, sizeof what, "%s, r %.2f", label, radii[i]);
            CHECK_PROBE(seed_probe(S, p->file, what, &p->obj, x, y, spot_shade, r));
        }
}

/* The book's experiment with technique Material. At the centre the light is 10 away, straight
 * above: .07 + (.24, .34, .39) / 1.1; beyond the rim .07. */
static void book_test_values_light_a_disc(void) {
    seed_floor p = {0};
    if (seed_floor_open(S, &p, "spot.fx", &FLOOR)) {
        spot_ref r = book_values(&p.tex);
        draw_and_probe(&p, &r, "Material", "book values");
        probe_the_disc(&p, &r, "book values");
        int x, y;
        seed_pixel_of(S, v3_make(0, 0, 0), &x, &y);
        CHECK_PROBE(seed_expect(S, p.file, "centre by hand", x, y,
                                rgba_make(0.07 + 0.24 / 1.1, 0.07 + 0.34 / 1.1, 0.07 + 0.39 / 1.1, 1)));
        rgba ambient = rgba_make(0.07, 0.07, 0.07, 1);
        CHECK_PROBE(seed_expect(S, p.file, "corner: ambient", 2, 2, ambient));
        seed_pixel_of(S, v3_make(0, 0, 1.1), &x, &y);
        CHECK_PROBE(seed_expect(S, p.file, "just past the rim: ambient", x, y, ambient));
        /* The rim along the centre row: lit pixels (above ambient by 2 steps) end at 1.0033. */
        int first = -1, last = -1;
        for (int i = 0; i < 128; i++) {
            rgba c = seed_pixel(S, i, 64);
            if (c.b > 0.07 + 2.0 / 255) {
                if (first < 0) first = i;
                last = i;
            }
        }
        double unit = 128 / 3.0;
        printf("  lit span of row 64: %d..%d, %.3f..%.3f (expected about -1.003..1.003)\n", first, last,
               first / unit - 1.5, last / unit - 1.5);
        CHECK(first >= 0 && fabs(first / unit - 1.5 + 1.0033) < 0.08);
        CHECK(last >= 0 && fabs(last / unit - 1.5 - 1.0033) < 0.08);
        seed_save_png(S, "spot_book_values");
    }
    seed_floor_close(S, &p);
}

/* A wider cone aimed off centre, no distance attenuation, texture on. */
static void wide_cone_textured(void) {
    seed_floor p = {0};
    if (seed_floor_open(S, &p, "spot.fx", &FLOOR)) {
        spot_ref r = book_values(&p.tex);
        r.light = v3_make(-0.5, 2, 0.3);
        r.target = v3_make(0.2, 0, -0.1);
        r.inner = 0.2, r.outer = 0.5, r.falloff = 2;
        r.attenuated = 0;
        r.textured = 1;
        draw_and_probe(&p, &r, "Texturizado", "wide cone, Texturizado");
        r.attenuated = 1;
        r.c1 = 0.3, r.c2 = 0.1, r.c3 = 0.2, r.range = 2.4;
        draw_and_probe(&p, &r, "Texturizado", "wide cone, attenuated, Texturizado");
    }
    seed_floor_close(S, &p);
}

static void specular_off_and_on(void) {
    seed_floor p = {0};
    if (seed_floor_open(S, &p, "spot_specular.fx", &FLOOR)) {
        spot_ref r = book_values(&p.tex);
        r.light = v3_make(0.2, 2, -0.2);
        r.target = v3_make(0, 0, 0);
        r.inner = 0.3, r.outer = 0.6, r.falloff = 1.5;
        seed_set_v3(S, p.fx, "posicionCamara", r.cam);
        draw_and_probe(&p, &r, "Material", "modIluEsp false");
        r.spec_on = 1;
        seed_set_bool(S, p.fx, "modIluEsp", 1);
        draw_and_probe(&p, &r, "Material", "modIluEsp, default ks");
        r.ks = 1, r.n = 8;
        seed_set_float(S, p.fx, "ks", r.ks);
        seed_set_float(S, p.fx, "n", r.n);
        draw_and_probe(&p, &r, "Material", "modIluEsp, ks 1, n 8");
        r.textured = 1;
        draw_and_probe(&p, &r, "Texturizado", "modIluEsp, Texturizado");
        /* The book's values again with the specular on. */
        spot_ref b = book_values(&p.tex);
        b.spec_on = 1, b.ks = 1, b.n = 8;
        draw_and_probe(&p, &b, "Material", "book values, modIluEsp");
        probe_the_disc(&p, &b, "book values, modIluEsp");
    }
    seed_floor_close(S, &p);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(book_test_values_light_a_disc);
    RUN(wide_cone_textured);
    RUN(specular_off_and_on);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
