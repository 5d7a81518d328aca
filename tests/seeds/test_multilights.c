/* multilights_repaired.fx (003 Código 7-8 with the missing argument restored) and the
 * unrepaired multilights.fx. Two passes: Ambiental draws the ambient colour (times the
 * texture in Texturizado), MultiLuces sums every switched-on light of three struct arrays of 2,
 * and the application adds the second pass to the first (BlendState.Additive: GL ONE, ONE):
 *   Phong(L, P, N, Lc, M) = rd (Lc M) [+ ks max(dot(R, V), 0)^n (Lc Esp) M rd when habiEspec],
 *     rd = max(dot(L, N), 0), R = normalize(2 N rd - L), V = normalize(cam - P)
 *   directional: Phong(-normalize(Dir)); point: Phong(normalize(Pos - P)) [* distance att.];
 *   spot: the angular factor of spot.fx times Phong [* distance att.];
 *   M = colorMaterialDifuso [* tex]. The loop runs to numLuces = 4 over arrays of 2: the
 * elements past the end read as zero constants, as D3D9's unused registers do, so they are off.
 * The framebuffer holds saturate(saturate(pass 1) + saturate(pass 2)). */
#include "files.h"
#include "floor.h"
#include "lighting.h"
#include "run_twice.h"

#define FILE_ "multilights_repaired.fx"

static seed_scene *S;

typedef struct dir_light { int on; v3 dir; rgba colour; } dir_light;
typedef struct point_light { int on, attenuate; v3 pos; rgba colour; double range, c1, c2, c3; } point_light;
typedef struct spot_light {
    int on, attenuate;
    v3 pos, target;
    rgba colour;
    double inner, outer, falloff, range, c1, c2, c3;
} spot_light;

typedef struct multi_ref {
    dir_light dirs[2];
    point_light points[2];
    spot_light spots[2];
    rgba ambient, diffuse, specular;
    double ks, n;
    int spec_on, textured;
    v3 cam;
    const seed_texture *tex;
} multi_ref;

static rgba phong(const multi_ref *r, v3 l, v3 p, v3 n, rgba lc, rgba m) {
    double rd = maxd(v3_dot(l, n), 0);
    rgba c = rgba_scale(rgba_mul(lc, m), rd);
    if (r->spec_on) {
        rgba spec = rgba_scale(rgba_mul(lc, r->specular), r->ks * seed_book_specular(n, l, p, r->cam, r->n));
        c = rgba_add(c, rgba_scale(rgba_mul(spec, m), rd));
    }
    return c;
}

static double distance_att(v3 p, v3 light, double range, double c1, double c2, double c3) {
    return seed_book_attenuation(v3_distance(p, light), range, c1, c2, c3);
}

static rgba spot(const multi_ref *r, const spot_light *s, v3 p, v3 n, rgba m) {
    v3 l = v3_normalize(v3_sub(s->pos, p)), axis = v3_normalize(v3_sub(s->pos, s->target));
    double k = seed_book_spot_cone(maxd(v3_dot(axis, l), 0), s->inner, s->outer, s->falloff);
    if (k == 0) return rgba_make(0, 0, 0, 0);
    rgba c = rgba_scale(phong(r, l, p, n, s->colour, m), k);
    if (s->attenuate) c = rgba_scale(c, distance_att(p, s->pos, s->range, s->c1, s->c2, s->c3));
    return c;
}

static rgba clamp01(rgba c) { return rgba_make(saturate(c.r), saturate(c.g), saturate(c.b), saturate(c.a)); }

static rgba multilights_shade(const seed_surface *s, const void *user) {
    const multi_ref *r = user;
    rgba tex = r->textured ? seed_texture_sample(r->tex, s->u, s->v, SEED_WRAP) : rgba_make(1, 1, 1, 1);
    rgba pass1 = rgba_mul(r->ambient, tex);
    rgba m = rgba_mul(r->diffuse, tex), sum = rgba_make(0, 0, 0, 0);
    for (int i = 0; i < 2; i++) {
        const dir_light *d = &r->dirs[i];
        const point_light *pt = &r->points[i];
        if (d->on) sum = rgba_add(sum, phong(r, v3_neg(v3_normalize(d->dir)), s->pos, s->normal, d->colour, m));
        if (pt->on) {
            rgba c = phong(r, v3_normalize(v3_sub(pt->pos, s->pos)), s->pos, s->normal, pt->colour, m);
            if (pt->attenuate) c = rgba_scale(c, distance_att(s->pos, pt->pos, pt->range, pt->c1, pt->c2, pt->c3));
            sum = rgba_add(sum, c);
        }
        if (r->spots[i].on) sum = rgba_add(sum, spot(r, &r->spots[i], s->pos, s->normal, m));
    }
    sum.a = 1;
    return clamp01(rgba_add(clamp01(pass1), clamp01(sum)));
}

/* The initializers: ambient .07, difuso (.24, .34, .39), especular white, ks .05, n 5. */
static void defaults(multi_ref *r, const seed_texture *tex) {
    memset(r, 0, sizeof *r);
    r->ambient = rgba_make(0.07, 0.07, 0.07, 1);
    r->diffuse = rgba_make(0.24, 0.34, 0.39, 1);
    r->specular = rgba_make(1, 1, 1, 1);
    r->ks = 0.05;
    r->n = 5;
    r->cam = v3_make(0.4, 2.5, 1.2);
    r->tex = tex;
}

/* Six lights that together light every part of the floor differently. */
static void six_lights(multi_ref *r) {
    r->dirs[0] = (dir_light){1, v3_make(0.5, -1, 0.2), rgba_make(0.8, 0.7, 0.6, 1)};
    r->dirs[1] = (dir_light){1, v3_make(-1, -0.7, -0.4), rgba_make(0.3, 0.5, 0.9, 1)};
    r->points[0] = (point_light){1, 0, v3_make(-1, 0.6, -1), rgba_make(0.9, 0.4, 0.2, 1), 0, 0, 0, 0};
    r->points[1] = (point_light){1, 1, v3_make(1.2, 0.5, 0.8), rgba_make(0.5, 0.9, 0.5, 1), 1.6, 1, 0.5, 1.5};
    r->spots[0] = (spot_light){1, 0, v3_make(0, 3, 0), v3_make(0, 0, 0), rgba_make(1, 1, 0.8, 1),
                               0.15, 0.35, 1.2, 0, 0, 0, 0};
    r->spots[1] = (spot_light){1, 1, v3_make(-0.8, 1.5, 1), v3_make(-1, 0, 1.2), rgba_make(0.6, 0.6, 1, 1),
                               0.2, 0.5, 0.8, 5, 1, 0.1, 0.1};
}

/* array[i].member = v, for the three light arrays. */
static void member_v3(hfx_effect *fx, const char *array, int i, const char *member, v3 v) {
    seed_param_v3(S, seed_member(S, fx, array, (size_t)i, member), member, v);
}
static void member_rgba(hfx_effect *fx, const char *array, int i, const char *member, rgba c) {
    seed_param_rgba(S, seed_member(S, fx, array, (size_t)i, member), member, c);
}
static void member_float(hfx_effect *fx, const char *array, int i, const char *member, double v) {
    seed_param_float(S, seed_member(S, fx, array, (size_t)i, member), member, v);
}
static void member_int(hfx_effect *fx, const char *array, int i, const char *member, int v) {
    seed_param_int(S, seed_member(S, fx, array, (size_t)i, member), member, v);
}

static void set_dir(hfx_effect *fx, int i, const dir_light *d) {
    member_v3(fx, "direccionales", i, "Direccion", d->dir);
    member_rgba(fx, "direccionales", i, "Color", d->colour);
    member_int(fx, "direccionales", i, "Encender", d->on);
}

/* Rango, C1, C2, C3, Atenuar and Encender, which puntuales and spots share. */
static void set_reach(hfx_effect *fx, const char *array, int i, const double range_c1_c2_c3[4], int attenuate,
                      int on) {
    static const char *const names[4] = {"Rango", "C1", "C2", "C3"};
    for (int k = 0; k < 4; k++) member_float(fx, array, i, names[k], range_c1_c2_c3[k]);
    member_int(fx, array, i, "Atenuar", attenuate);
    member_int(fx, array, i, "Encender", on);
}

static void set_point(hfx_effect *fx, int i, const point_light *p) {
    member_v3(fx, "puntuales", i, "Posicion", p->pos);
    member_rgba(fx, "puntuales", i, "Color", p->colour);
    set_reach(fx, "puntuales", i, (const double[4]){p->range, p->c1, p->c2, p->c3}, p->attenuate, p->on);
}

static void set_spot(hfx_effect *fx, int i, const spot_light *s) {
    member_v3(fx, "spots", i, "Posicion", s->pos);
    member_v3(fx, "spots", i, "Blanco", s->target);
    member_rgba(fx, "spots", i, "Color", s->colour);
    member_float(fx, "spots", i, "AnguloInterno", s->inner);
    member_float(fx, "spots", i, "AnguloExterno", s->outer);
    member_float(fx, "spots", i, "Falloff", s->falloff);
    set_reach(fx, "spots", i, (const double[4]){s->range, s->c1, s->c2, s->c3}, s->attenuate, s->on);
}

static void set_all(hfx_effect *fx, const multi_ref *r) {
    for (int i = 0; i < 2; i++) {
        set_dir(fx, i, &r->dirs[i]);
        set_point(fx, i, &r->points[i]);
        set_spot(fx, i, &r->spots[i]);
    }
    seed_set_bool(S, fx, "habiEspec", r->spec_on);
    seed_set_float(S, fx, "ks", r->ks);
    seed_set_float(S, fx, "n", r->n);
    seed_set_v3(S, fx, "posicionCamara", r->cam);
    seed_set_texture(S, fx, "texturaModelo", r->tex);
}

/* The floor from -2 to 2 fills the view: 32 pixels per unit. */
static const seed_floor_setup FLOOR = {.half = 2, .view_half = 2, SEED_FLOOR_LOWER_NAMES};

/* Pass 1 then pass 2 added to it, as the application draws the two passes. */
static void draw_two_passes(seed_floor *m, const char *technique) {
    seed_floor_draw(S, m, m->fx, technique, SEED_BLEND_ADD_AFTER_FIRST, 2);
}

static void draw_and_probe(seed_floor *m, const multi_ref *r, const char *label) {
    set_all(m->fx, r);
    draw_two_passes(m, r->textured ? "Texturizado" : "Material");
    seed_grid grid = {.x0 = 7, .step_x = 20, .y0 = 5, .step_y = 19};
    seed_floor_probe_grid(S, m, label, grid, multilights_shade, r);
}

/* Every light off (their fields start at zero): pass 1's .07 plus pass 2's black, alpha 1. */
static void lights_off_leave_the_ambient_pass(void) {
    seed_floor m = {0};
    if (seed_floor_open(S, &m, FILE_, &FLOOR)) {
        multi_ref r;
        defaults(&r, &m.tex);
        draw_two_passes(&m, "Material");
        CHECK_PROBE(seed_expect(S, FILE_, "no lights, by hand", 64, 64, rgba_make(0.07, 0.07, 0.07, 1)));
        CHECK_PROBE(seed_expect(S, FILE_, "no lights, by hand", 10, 100, rgba_make(0.07, 0.07, 0.07, 1)));
        draw_and_probe(&m, &r, "no lights");
    }
    seed_floor_close(S, &m);
}

/* Each light alone, through element 0 and element 1 of its array. */
static void each_light_alone(void) {
    seed_floor m = {0};
    if (seed_floor_open(S, &m, FILE_, &FLOOR)) {
        multi_ref all, r;
        defaults(&all, &m.tex);
        six_lights(&all);
        static const char *names[6] = {"direccionales[0] alone", "direccionales[1] alone", "puntuales[0] alone",
                                       "puntuales[1] alone", "spots[0] alone", "spots[1] alone"};
        for (int k = 0; k < 6; k++) {
            r = all;
            for (int i = 0; i < 2; i++) r.dirs[i].on = r.points[i].on = r.spots[i].on = 0;
            if (k < 2) r.dirs[k].on = 1;
            else if (k < 4) r.points[k - 2].on = 1;
            else r.spots[k - 4].on = 1;
            draw_and_probe(&m, &r, names[k]);
        }
        /* By hand: direccionales[0] alone with N = (0, 1, 0): rd = 1 / |(.5, -1, .2)| = .8704;
         * .07 + rd (.8, .7, .6) (.24, .34, .39). */
        r = all;
        for (int i = 0; i < 2; i++) r.dirs[i].on = r.points[i].on = r.spots[i].on = 0;
        r.dirs[0].on = 1;
        set_all(m.fx, &r);
        draw_two_passes(&m, "Material");
        double rd = 1 / sqrt(1.29);
        CHECK_PROBE(seed_expect(S, FILE_, "direccionales[0] by hand", 40, 90,
                                rgba_make(0.07 + rd * 0.8 * 0.24, 0.07 + rd * 0.7 * 0.34, 0.07 + rd * 0.6 * 0.39, 1)));
    }
    seed_floor_close(S, &m);
}

/* All six, then the specular, then the texture; then lights switched off one by one. */
static void six_lights_and_switching(void) {
    seed_floor m = {0};
    if (seed_floor_open(S, &m, FILE_, &FLOOR)) {
        multi_ref r;
        defaults(&r, &m.tex);
        six_lights(&r);
        draw_and_probe(&m, &r, "six lights");
        r.spec_on = 1;
        r.ks = 0.6;
        r.n = 10;
        draw_and_probe(&m, &r, "six lights, habiEspec");
        r.textured = 1;
        draw_and_probe(&m, &r, "six lights, habiEspec, Texturizado");
        r.dirs[0].on = 0;
        r.spots[1].on = 0;
        draw_and_probe(&m, &r, "direccionales[0], spots[1] off");
        r.points[0].on = r.points[1].on = 0;
        r.dirs[0].on = 1;
        draw_and_probe(&m, &r, "points off, direccionales[0] on");
    }
    seed_floor_close(S, &m);
}

/* numLuces = 2 stays inside the arrays: the same picture as the default 4, whose extra
 * iterations read elements that do not exist. */
static void loop_bound_past_the_arrays(void) {
    seed_floor m = {0};
    if (seed_floor_open(S, &m, FILE_, &FLOOR)) {
        int n = -1;
        hfx_param *p = hfx_effect_param(m.fx, "numLuces");
        CHECK(p && hfx_param_get_int(p, &n) == HFX_OK);
        CHECK_INT(n, 4);
        multi_ref r;
        defaults(&r, &m.tex);
        six_lights(&r);
        draw_and_probe(&m, &r, "numLuces 4 (default)");
        seed_set_int(S, m.fx, "numLuces", 2);
        draw_and_probe(&m, &r, "numLuces 2");
        seed_set_int(S, m.fx, "numLuces", 1); /* only element 0 of each array */
        multi_ref first = r;
        first.dirs[1].on = first.points[1].on = first.spots[1].on = 0;
        set_all(m.fx, &r);
        draw_two_passes(&m, "Material");
        seed_grid grid = {.x0 = 9, .step_x = 29, .y0 = 9, .step_y = 29};
        seed_floor_probe_grid(S, &m, "numLuces 1: elements 0 only", grid, multilights_shade, &first);
    }
    seed_floor_close(S, &m);
}

/* The unrepaired listing: Phong called with 4 arguments on line 204. The load fails with
 * fxc's message, nothing crashes, and the device goes on loading and drawing. */
static void broken_listing_fails_and_device_survives(void) {
    hfx_device *dev = seed_device(S);
    CHECK(dev != NULL);
    if (!dev) return;
    char *path = test_seed_path("multilights.fx");
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load(dev, path, NULL, &errors);
    CHECK(fx == NULL);
    CHECK_CONTAINS(errors, "multilights.fx(204,20): error X3013: 'Phong': no matching 4 parameter function");
    CHECK_CONTAINS(hfx_device_last_error(dev), "multilights.fx(204,20): error X3013");
    printf("  errors: %s\n", errors ? errors : "(null)");
    if (fx) hfx_effect_destroy(fx);
    hfx_free(errors);
    free(path);
    /* The same device, right after: the repaired file draws its ambient pass. */
    seed_floor m = {0};
    if (seed_floor_open(S, &m, FILE_, &FLOOR)) {
        multi_ref r;
        defaults(&r, &m.tex);
        draw_and_probe(&m, &r, "after the failed load");
    }
    seed_floor_close(S, &m);
    hfx_effect *amb = seed_load(S, "ambient.fx");
    CHECK(amb != NULL);
    if (amb) {
        seed_mesh *floor = seed_mesh_floor(S, 1);
        seed_set_transforms(S, amb, "world", "view", "projection", NULL);
        seed_clear(S, rgba_make(0, 0, 0, 1));
        CHECK_INT(seed_draw(S, amb, NULL, floor, SEED_BLEND_NONE), 1);
        CHECK_PROBE(seed_expect(S, "multilights.fx", "ambient.fx after the failure", 64, 64, rgba_make(0.05, 0.05, 0.05, 1)));
        seed_mesh_free(S, floor);
        hfx_effect_destroy(amb);
    }
    CHECK_SCENE(S);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(lights_off_leave_the_ambient_pass);
    RUN(each_light_alone);
    RUN(six_lights_and_switching);
    RUN(loop_bound_past_the_arrays);
    RUN(broken_listing_fails_and_device_survives);
}

int main(void) {
    if (seed_run_twice(&S, run_all)) return 1;
    return test_summary();
}
