/* pointlights.fx (001): up to 50 point lights in one pass, from uniform arrays the
 * application refills every frame, as the tutorial's PointLightShader.Update does. For each of
 * the activeLights lights:
 *   att = (1 - saturate(|Lpos - P| / radius))^2
 *   color += A * Ai + att * Lc * Di * tex * N.L + Si * Sc * (R.V)^n
 * (the ambient and the specular terms are added once per light and are not attenuated: the
 * tutorial's equations, so a highlight shows even beyond a light's radius). */
#include "floor.h"
#include "lighting.h"
#include "run_twice.h"

#define FILE_ "pointlights.fx"
#define MAX_LIGHTS 50

static seed_scene *S;

typedef struct point_light {
    v3 pos;
    rgba colour;
    double radius;
} point_light;

typedef struct lights_ref {
    int active;
    point_light lights[MAX_LIGHTS];
    seed_tutorial_material m;
} lights_ref;

static rgba pointlights_shade(const seed_surface *s, const void *user) {
    const lights_ref *p = user;
    const seed_tutorial_material *m = &p->m;
    rgba tex = seed_texture_sample(m->tex, s->u, s->v, SEED_CLAMP);
    rgba sum = rgba_make(0, 0, 0, 0);
    for (int i = 0; i < p->active; i++) {
        const point_light *l = &p->lights[i];
        v3 n = v3_normalize(s->normal);
        v3 to_light = v3_sub(l->pos, s->pos);
        double k = 1 - saturate(v3_length(to_light) / l->radius);
        double att = k * k;
        v3 ld = v3_normalize(to_light);
        v3 view = v3_normalize(v3_sub(m->cam, s->pos));
        double diff = saturate(v3_dot(n, ld));
        double spec = seed_tutorial_specular(n, ld, view, m->specular_power);
        sum = rgba_add(sum, rgba_scale(m->ambient_colour, m->ambient_intensity));
        sum = rgba_add(sum, rgba_scale(rgba_mul(l->colour, tex), att * m->diffuse_intensity * diff));
        sum = rgba_add(sum, rgba_scale(m->specular_colour, m->specular_intensity * spec));
    }
    return sum;
}

static const unsigned char TEXELS[2 * 2 * 4] = {220, 200, 180, 255, 220, 200, 180, 255,
                                                 220, 200, 180, 255, 220, 200, 180, 255};

/* The tutorial's material (PointLightShader's constructor): white specular of power 50 and
 * intensity 1, no ambient, diffuse intensity 1. */
static void tutorial_material(lights_ref *r, const seed_texture *tex) {
    r->m.cam = v3_make(-3, 2, 0);
    r->m.specular_colour = rgba_make(1, 1, 1, 1);
    r->m.ambient_colour = rgba_make(1, 1, 1, 1);
    r->m.specular_power = 50;
    r->m.specular_intensity = 1;
    r->m.ambient_intensity = 0;
    r->m.diffuse_intensity = 1;
    r->m.tex = tex;
}

/* As the tutorial does: LightPosition.ToArray() etc., arrays only as long as the active
 * lights, handed to the whole array parameter. */
static void fill_whole_arrays(hfx_effect *fx, const lights_ref *r) {
    float pos[MAX_LIGHTS * 3], col[MAX_LIGHTS * 4], rad[MAX_LIGHTS];
    for (int i = 0; i < r->active; i++) {
        const point_light *l = &r->lights[i];
        pos[i * 3] = (float)l->pos.x, pos[i * 3 + 1] = (float)l->pos.y, pos[i * 3 + 2] = (float)l->pos.z;
        col[i * 4] = (float)l->colour.r, col[i * 4 + 1] = (float)l->colour.g;
        col[i * 4 + 2] = (float)l->colour.b, col[i * 4 + 3] = (float)l->colour.a;
        rad[i] = (float)l->radius;
    }
    seed_set_int(S, fx, "activeLights", r->active);
    hfx_param *p = hfx_effect_param(fx, "LightPosition");
    CHECK(p && hfx_param_set_floats(p, pos, (size_t)r->active * 3) == HFX_OK);
    p = hfx_effect_param(fx, "LightColor");
    CHECK(p && hfx_param_set_floats(p, col, (size_t)r->active * 4) == HFX_OK);
    p = hfx_effect_param(fx, "LightRadius");
    CHECK(p && hfx_param_set_floats(p, rad, (size_t)r->active) == HFX_OK);
}

/* Parameters["LightPosition"].Elements[i].SetValue(...) for each light. */
static void fill_by_element(hfx_effect *fx, const lights_ref *r) {
    seed_set_int(S, fx, "activeLights", r->active);
    hfx_param *pos = hfx_effect_param(fx, "LightPosition"), *col = hfx_effect_param(fx, "LightColor"),
              *rad = hfx_effect_param(fx, "LightRadius");
    CHECK(pos && col && rad);
    if (!pos || !col || !rad) return;
    CHECK_INT(hfx_param_elements(pos), MAX_LIGHTS);
    for (int i = 0; i < r->active; i++) {
        seed_param_v3(S, hfx_param_element(pos, (size_t)i), "LightPosition[i]", r->lights[i].pos);
        seed_param_rgba(S, hfx_param_element(col, (size_t)i), "LightColor[i]", r->lights[i].colour);
        seed_param_float(S, hfx_param_element(rad, (size_t)i), "LightRadius[i]", r->lights[i].radius);
    }
}

/* The floor from -2 to 2 fills the view: 32 pixels per unit. */
static const seed_floor_setup FLOOR = {.half = 2, .view_half = 2, .tex_width = 2, .tex_height = 2, .texels = TEXELS,
                                       .world_name = "World", .view_name = "View", .projection_name = "Projection"};

static void draw_frame(seed_floor *f, const lights_ref *r, const char *label) {
    seed_set_tutorial_material(S, f->fx, &r->m);
    seed_floor_draw(S, f, f->fx, "PointLights", SEED_BLEND_NONE, 1);
    seed_grid grid = {.x0 = 9, .step_x = 22, .y0 = 6, .step_y = 23};
    seed_floor_probe_grid(S, f, label, grid, pointlights_shade, r);
}

/* One light at (1, 0.5, 0), radius 0.8, the camera at (-3, 2, 0). The highlight is where the
 * line from the light to the camera's mirror image (-3, -2, 0) meets the floor: (0.2, 0, 0),
 * 0.94 from the light, beyond its radius: no diffuse there, the full specular. Under the
 * light (1, 0, 0) diffuse is (1 - 0.5 / 0.8)^2 = 0.140625 of Lc * tex. */
static void one_light(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        static lights_ref r;
        tutorial_material(&r, &f.tex);
        r.active = 1;
        r.lights[0] = (point_light){v3_make(1, 0.5, 0), rgba_make(0.9, 0.7, 0.5, 1), 0.8};
        fill_whole_arrays(f.fx, &r);
        draw_frame(&f, &r, "1 light");
        int x, y;
        seed_pixel_of(S, v3_make(0.2, 0, 0), &x, &y);
        CHECK_PROBE(seed_probe(S, FILE_, "highlight beyond the radius", &f.obj, x, y, pointlights_shade, &r));
        CHECK(seed_pixel(S, x, y).r > 0.9); /* the specular of intensity 1 is there */
        seed_pixel_of(S, v3_make(1, 0, 0), &x, &y);
        CHECK_PROBE(seed_probe(S, FILE_, "under the light", &f.obj, x, y, pointlights_shade, &r));
        seed_pixel_of(S, v3_make(1.6, 0, 0.3), &x, &y);
        CHECK_PROBE(seed_expect(S, FILE_, "beyond the radius, no highlight", x, y, rgba_make(0, 0, 0, 0)));
    }
    seed_floor_close(S, &f);
}

/* The attenuation profile alone (specular off): a light 0.5 above the floor with radius 1.5.
 * At distance d the floor gets Lc * tex * (0.5 / d) * (1 - d / 1.5)^2, which reaches zero at
 * the radius and stays there. */
static void attenuation_reaches_zero_at_the_radius(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        static lights_ref r;
        tutorial_material(&r, &f.tex);
        r.m.specular_intensity = 0;
        r.active = 1;
        r.lights[0] = (point_light){v3_make(0, 0.5, 0), rgba_make(1, 1, 1, 1), 1.5};
        fill_by_element(f.fx, &r);
        draw_frame(&f, &r, "attenuation profile");
        static const double ds[] = {0.5, 0.6, 0.9, 1.2, 1.4, 1.5, 1.6, 2.0};
        for (size_t i = 0; i < sizeof ds / sizeof ds[0]; i++) {
            double d = ds[i];
            int x, y;
            seed_pixel_of(S, v3_make(-sqrt(d * d - 0.25), 0, 0.2), &x, &y);
            char label[48];
            snprintf(label, sizeof label, "attenuation near d = %.2f", d);
            /* The closed form at the pixel's own distance checks the reference. */
            seed_surface surf;
            CHECK(seed_pick(S, &f.obj, 1, x, y, &surf) == 0);
            double dd = v3_distance(surf.pos, r.lights[0].pos), k = dd < 1.5 ? 1 - dd / 1.5 : 0;
            CHECK_NEAR(pointlights_shade(&surf, &r).r, 220 / 255.0 * (0.5 / dd) * k * k, 1e-9);
            CHECK_PROBE(seed_probe(S, FILE_, label, &f.obj, x, y, pointlights_shade, &r));
            if (d >= 1.5) CHECK_PROBE(seed_expect(S, FILE_, "beyond the radius: black", x, y, rgba_make(0, 0, 0, 0)));
        }
    }
    seed_floor_close(S, &f);
}

static void ring_of_lights(lights_ref *r, int n, double ring, double height, double radius, double strength) {
    r->active = n;
    for (int i = 0; i < n; i++) {
        double a = 2 * SEED_PI * i / n;
        r->lights[i].pos = v3_make(ring * cos(a), height, ring * sin(a));
        r->lights[i].colour = rgba_make(strength * (0.5 + 0.5 * cos(a)), strength * (0.5 + 0.5 * sin(a)),
                                        strength * (1 - 0.3 * (i % 3)), 1);
        r->lights[i].radius = radius;
    }
}

static void grid_of_lights(lights_ref *r, int n) {
    r->active = n;
    for (int i = 0; i < n; i++) {
        int gx = i % 7, gz = i / 7;
        r->lights[i].pos = v3_make(-1.8 + 0.6 * gx, 0.3 + 0.05 * (i % 4), -1.8 + 0.5 * gz);
        r->lights[i].colour = rgba_make(0.05 + 0.002 * gx, 0.04 + 0.003 * gz, 0.06 - 0.001 * (i % 5), 0.02);
        r->lights[i].radius = 0.9 + 0.02 * (i % 6);
    }
}

/* Ten lights on a ring, the arrays handed over whole (10 of 50 elements), a faint specular. */
static void ten_lights(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        static lights_ref r;
        tutorial_material(&r, &f.tex);
        r.m.cam = v3_make(0, 4, 0);
        r.m.specular_intensity = 0.1;
        ring_of_lights(&r, 10, 1.1, 0.6, 1.6, 0.25);
        fill_whole_arrays(f.fx, &r);
        draw_frame(&f, &r, "10 lights");
    }
    seed_floor_close(S, &f);
}

/* Fifty lights on a grid, set element by element, with a little ambient (added 50 times). */
static void fifty_lights(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        static lights_ref r;
        tutorial_material(&r, &f.tex);
        r.m.cam = v3_make(0.5, 3, -0.5);
        r.m.specular_intensity = 0.004;
        r.m.ambient_colour = rgba_make(0.1, 0.2, 0.3, 1);
        r.m.ambient_intensity = 0.01;
        grid_of_lights(&r, MAX_LIGHTS);
        fill_by_element(f.fx, &r);
        draw_frame(&f, &r, "50 lights");
    }
    seed_floor_close(S, &f);
}

/* One effect, frames with 1, 10, 50, then 1 light again: the arrays keep the stale lights
 * past activeLights, which the loop must not read. */
static void frames_with_changing_light_counts(void) {
    seed_floor f = {0};
    if (seed_floor_open(S, &f, FILE_, &FLOOR)) {
        static lights_ref r;
        tutorial_material(&r, &f.tex);
        r.m.cam = v3_make(0, 4, 0);
        r.m.specular_intensity = 0.05;
        r.active = 1;
        r.lights[0] = (point_light){v3_make(-0.5, 0.7, 0.5), rgba_make(0.6, 0.8, 0.4, 1), 2.2};
        fill_by_element(f.fx, &r);
        draw_frame(&f, &r, "frame 1: 1 light");
        ring_of_lights(&r, 10, 1.3, 0.5, 1.4, 0.2);
        fill_whole_arrays(f.fx, &r);
        draw_frame(&f, &r, "frame 2: 10 lights");
        grid_of_lights(&r, MAX_LIGHTS);
        r.m.specular_intensity = 0.004;
        fill_whole_arrays(f.fx, &r);
        draw_frame(&f, &r, "frame 3: 50 lights");
        r.active = 1;
        r.lights[0] = (point_light){v3_make(0.8, 0.6, -0.8), rgba_make(0.3, 0.9, 0.9, 1), 1.9};
        r.m.specular_intensity = 0.05;
        fill_whole_arrays(f.fx, &r);
        draw_frame(&f, &r, "frame 4: 1 light again");
    }
    seed_floor_close(S, &f);
}

/* Every test, once with the .fx loaded directly and once through .hfxo. */
static void run_all(void) {
    RUN(one_light);
    RUN(attenuation_reaches_zero_at_the_radius);
    RUN(ten_lights);
    RUN(fifty_lights);
    RUN(frames_with_changing_light_counts);
}

int main(void) {
    if (seed_run_thrice(&S, run_all)) return 1;
    return test_summary();
}
