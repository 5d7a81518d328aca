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
#include "scene.h"

#include "files.h"

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
        v3 refl = v3_normalize(v3_sub(v3_scale(n, 2 * maxd(v3_dot(l, n), 0)), l));
        v3 view = v3_normalize(v3_sub(r->cam, p));
        double rs = hlsl_pow(maxd(v3_dot(refl, view), 0), r->n);
        rgba spec = rgba_scale(rgba_mul(lc, r->specular), r->ks * rs);
        c = rgba_add(c, rgba_scale(rgba_mul(spec, m), rd));
    }
    return c;
}

static double distance_att(v3 p, v3 light, double range, double c1, double c2, double c3) {
    double d = v3_distance(p, light);
    return d <= range ? mind(1 / (c1 + c2 * d + c3 * d * d), 1) : 0;
}

static rgba spot(const multi_ref *r, const spot_light *s, v3 p, v3 n, rgba m) {
    v3 l = v3_normalize(v3_sub(s->pos, p)), axis = v3_normalize(v3_sub(s->pos, s->target));
    double cos_a = maxd(v3_dot(axis, l), 0), cos_t = cos(s->inner), cos_f = cos(s->outer);
    double k = cos_a <= cos_f ? 0 : cos_a >= cos_t ? 1 : hlsl_pow((cos_a - cos_f) / (cos_t - cos_f), s->falloff);
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

static void set_dir(hfx_effect *fx, int i, const dir_light *d) {
    seed_param_v3(S, seed_member(S, fx, "direccionales", (size_t)i, "Direccion"), "Direccion", d->dir);
    seed_param_rgba(S, seed_member(S, fx, "direccionales", (size_t)i, "Color"), "Color", d->colour);
    seed_param_int(S, seed_member(S, fx, "direccionales", (size_t)i, "Encender"), "Encender", d->on);
}

static void set_point(hfx_effect *fx, int i, const point_light *p) {
    seed_param_v3(S, seed_member(S, fx, "puntuales", (size_t)i, "Posicion"), "Posicion", p->pos);
    seed_param_rgba(S, seed_member(S, fx, "puntuales", (size_t)i, "Color"), "Color", p->colour);
    seed_param_float(S, seed_member(S, fx, "puntuales", (size_t)i, "Rango"), "Rango", p->range);
    seed_param_float(S, seed_member(S, fx, "puntuales", (size_t)i, "C1"), "C1", p->c1);
    seed_param_float(S, seed_member(S, fx, "puntuales", (size_t)i, "C2"), "C2", p->c2);
    seed_param_float(S, seed_member(S, fx, "puntuales", (size_t)i, "C3"), "C3", p->c3);
    seed_param_int(S, seed_member(S, fx, "puntuales", (size_t)i, "Atenuar"), "Atenuar", p->attenuate);
    seed_param_int(S, seed_member(S, fx, "puntuales", (size_t)i, "Encender"), "Encender", p->on);
}

static void set_spot(hfx_effect *fx, int i, const spot_light *s) {
    seed_param_v3(S, seed_member(S, fx, "spots", (size_t)i, "Posicion"), "Posicion", s->pos);
    seed_param_v3(S, seed_member(S, fx, "spots", (size_t)i, "Blanco"), "Blanco", s->target);
    seed_param_rgba(S, seed_member(S, fx, "spots", (size_t)i, "Color"), "Color", s->colour);
    seed_param_float(S, seed_member(S, fx, "spots", (size_t)i, "AnguloInterno"), "AnguloInterno", s->inner);
    seed_param_float(S, seed_member(S, fx, "spots", (size_t)i, "AnguloExterno"), "AnguloExterno", s->outer);
    seed_param_float(S, seed_member(S, fx, "spots", (size_t)i, "Falloff"), "Falloff", s->falloff);
    seed_param_float(S, seed_member(S, fx, "spots", (size_t)i, "Rango"), "Rango", s->range);
    seed_param_float(S, seed_member(S, fx, "spots", (size_t)i, "C1"), "C1", s->c1);
    seed_param_float(S, seed_member(S, fx, "spots", (size_t)i, "C2"), "C2", s->c2);
    seed_param_float(S, seed_member(S, fx, "spots", (size_t)i, "C3"), "C3", s->c3);
    seed_param_int(S, seed_member(S, fx, "spots", (size_t)i, "Atenuar"), "Atenuar", s->attenuate);
    seed_param_int(S, seed_member(S, fx, "spots", (size_t)i, "Encender"), "Encender", s->on);
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

typedef struct multi_scene {
    hfx_effect *fx;
    seed_mesh *floor;
    seed_object obj;
    unsigned char texels[64];
    seed_texture tex;
} multi_scene;

static int open_scene(multi_scene *m) {
    m->fx = seed_load(S, FILE_);
    seed_smooth_texels(m->texels);
    m->tex = seed_texture_make(S, 4, 4, m->texels);
    m->floor = seed_mesh_floor(S, 2);
    m->obj = seed_object_at(m->floor, NULL);
    seed_camera_top(S, 2);
    if (m->fx) seed_set_transforms(S, m->fx, "world", "view", "projection", NULL);
    return m->fx != NULL;
}

static void close_scene(multi_scene *m) {
    CHECK(m->fx != NULL);
    if (m->fx) hfx_effect_destroy(m->fx);
    seed_texture_free(S, &m->tex);
    seed_mesh_free(S, m->floor);
    CHECK_SCENE(S);
}

static void draw_and_probe(multi_scene *m, const multi_ref *r, const char *label) {
    set_all(m->fx, r);
    seed_clear(S, rgba_make(0, 0, 0, 0));
    CHECK_INT(seed_draw(S, m->fx, r->textured ? "Texturizado" : "Material", m->floor, SEED_BLEND_ADD_AFTER_FIRST), 2);
    for (int y = 5; y < 128; y += 19)
        for (int x = 7; x < 128; x += 20)
            CHECK_PROBE(seed_probe(S, FILE_, label, &m->obj, x, y, multilights_shade, r));
}

/* Every light off (their fields start at zero): pass 1's .07 plus pass 2's black, alpha 1. */
static void lights_off_leave_the_ambient_pass(void) {
    multi_scene m = {0};
    if (open_scene(&m)) {
        multi_ref r;
        defaults(&r, &m.tex);
        seed_clear(S, rgba_make(0, 0, 0, 0));
        CHECK_INT(seed_draw(S, m.fx, "Material", m.floor, SEED_BLEND_ADD_AFTER_FIRST), 2);
        CHECK_PROBE(seed_expect(S, FILE_, "no lights, by hand", 64, 64, rgba_make(0.07, 0.07, 0.07, 1)));
        CHECK_PROBE(seed_expect(S, FILE_, "no lights, by hand", 10, 100, rgba_make(0.07, 0.07, 0.07, 1)));
        draw_and_probe(&m, &r, "no lights");
    }
    close_scene(&m);
}

/* Each light alone, through element 0 and element 1 of its array. */
static void each_light_alone(void) {
    multi_scene m = {0};
    if (open_scene(&m)) {
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
        seed_clear(S, rgba_make(0, 0, 0, 0));
        CHECK_INT(seed_draw(S, m.fx, "Material", m.floor, SEED_BLEND_ADD_AFTER_FIRST), 2);
        double rd = 1 / sqrt(1.29);
        CHECK_PROBE(seed_expect(S, FILE_, "direccionales[0] by hand", 40, 90,
                                rgba_make(0.07 + rd * 0.8 * 0.24, 0.07 + rd * 0.7 * 0.34, 0.07 + rd * 0.6 * 0.39, 1)));
    }
    close_scene(&m);
}

/* All six, then the specular, then the texture; then lights switched off one by one. */
static void six_lights_and_switching(void) {
    multi_scene m = {0};
    if (open_scene(&m)) {
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
    close_scene(&m);
}

/* numLuces = 2 stays inside the arrays: the same picture as the default 4, whose extra
 * iterations read elements that do not exist. */
static void loop_bound_past_the_arrays(void) {
    multi_scene m = {0};
    if (open_scene(&m)) {
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
        seed_clear(S, rgba_make(0, 0, 0, 0));
        CHECK_INT(seed_draw(S, m.fx, "Material", m.floor, SEED_BLEND_ADD_AFTER_FIRST), 2);
        for (int y = 9; y < 128; y += 29)
            for (int x = 9; x < 128; x += 29)
                CHECK_PROBE(seed_probe(S, FILE_, "numLuces 1: elements 0 only", &m.obj, x, y, multilights_shade, &first));
    }
    close_scene(&m);
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
    multi_scene m = {0};
    if (open_scene(&m)) {
        multi_ref r;
        defaults(&r, &m.tex);
        draw_and_probe(&m, &r, "after the failed load");
    }
    close_scene(&m);
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
