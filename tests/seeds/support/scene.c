/* scene.c: context, meshes, effect plumbing and probes for the seed acceptance tests. */
#include "scene.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "effect.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "scene_gpu.h"

void seed_note(seed_scene *s, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "  harness: ");
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\n");
    va_end(ap);
    s->errors++;
}

seed_scene *seed_scene_create(int width, int height) { return seed_scene_create_version(width, height, 3, 3); }

seed_scene *seed_scene_create_version(int width, int height, int major, int minor) {
    seed_scene *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    s->width = width;
    s->height = height;
    s->d3d9_centres = 1;
    if (!seed_gpu_open(s, major, minor)) {
        seed_scene_destroy(s);
        return NULL;
    }
    float id[16];
    xm_identity(id);
    seed_camera(s, id, id);
    seed_clear(s, rgba_make(0, 0, 0, 0));
    return s;
}

void seed_scene_destroy(seed_scene *s) {
    if (!s) return;
    seed_gpu_close(s);
    free(s);
}

hfx_device *seed_device(seed_scene *s) { return s->dev; }
void seed_use_target(seed_scene *s, hfx_target target) { s->target = target; }
hfx_target seed_target(const seed_scene *s) { return s->target; }
int seed_width(const seed_scene *s) { return s->width; }
int seed_height(const seed_scene *s) { return s->height; }

int seed_take_errors(seed_scene *s) {
    int n = s->errors;
    s->errors = 0;
    return n;
}

/* ---- cameras ---- */

void seed_camera(seed_scene *s, const float view[16], const float proj[16]) {
    float vp[16];
    memcpy(s->view, view, sizeof s->view);
    memcpy(s->proj, proj, sizeof s->proj);
    xm_mul(vp, s->view, s->proj);
    s->inv_ok = xm_invert(s->inv_vp, vp);
}

const float *seed_view(const seed_scene *s) { return s->view; }
const float *seed_projection(const seed_scene *s) { return s->proj; }

void seed_camera_top(seed_scene *s, double half) {
    float view[16], proj[16];
    xm_look_at(view, v3_make(0, 10, 0), v3_make(0, 0, 0), v3_make(0, 0, -1));
    xm_orthographic(proj, 2 * half, 2 * half * s->height / s->width, 1, 20);
    seed_camera(s, view, proj);
}

void seed_use_d3d9_pixel_centres(seed_scene *s, int on) { s->d3d9_centres = on; }

/* ---- meshes ---- */

static void put_vertex(seed_vertex *out, v3 p, v3 n, double u, double v) {
    out->pos[0] = (float)p.x;
    out->pos[1] = (float)p.y;
    out->pos[2] = (float)p.z;
    out->normal[0] = (float)n.x;
    out->normal[1] = (float)n.y;
    out->normal[2] = (float)n.z;
    out->uv[0] = (float)u;
    out->uv[1] = (float)v;
}

static v3 vertex_pos(const seed_vertex *v) { return v3_make(v->pos[0], v->pos[1], v->pos[2]); }

/* Puts the triangle clockwise as seen from the side `outward` points to: XNA's front faces. */
static void orient_triangle(seed_vertex t[3], v3 outward) {
    v3 a = vertex_pos(&t[0]), b = vertex_pos(&t[1]), c = vertex_pos(&t[2]);
    if (v3_dot(v3_cross(v3_sub(b, a), v3_sub(c, a)), outward) > 0) {
        seed_vertex tmp = t[1];
        t[1] = t[2];
        t[2] = tmp;
    }
}

static seed_mesh *upload_mesh(seed_scene *s, seed_vertex *v, int count) {
    seed_mesh *m = calloc(1, sizeof *m);
    if (!m) {
        free(v);
        return NULL;
    }
    m->v = v;
    m->count = count;
    v3 c = v3_make(0, 0, 0);
    for (int i = 0; i < count; i++) c = v3_add(c, vertex_pos(&v[i]));
    m->centre = count ? v3_scale(c, 1.0 / count) : c;
    for (int i = 0; i < count; i++) m->radius = maxd(m->radius, v3_distance(m->centre, vertex_pos(&v[i])));
    seed_gpu_mesh_upload(s, m);
    return m;
}

seed_mesh *seed_mesh_quad(seed_scene *s, v3 o, v3 eu, v3 ev, v3 normal, double u0, double v0, double u1,
                          double v1) {
    seed_vertex *v = calloc(6, sizeof *v);
    if (!v) return NULL;
    v3 p[4] = {o, v3_add(o, eu), v3_add(v3_add(o, eu), ev), v3_add(o, ev)};
    double uv[4][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    static const int tri[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) put_vertex(&v[i], p[tri[i]], normal, uv[tri[i]][0], uv[tri[i]][1]);
    orient_triangle(v, normal);
    orient_triangle(v + 3, normal);
    return upload_mesh(s, v, 6);
}

seed_mesh *seed_mesh_floor(seed_scene *s, double half) {
    return seed_mesh_quad(s, v3_make(-half, 0, -half), v3_make(2 * half, 0, 0), v3_make(0, 0, 2 * half),
                          v3_make(0, 1, 0), 0, 0, 1, 1);
}

static v3 sphere_point(int i, int j, int slices, int stacks, double *u, double *v) {
    double phi = 2 * SEED_PI * i / slices, theta = SEED_PI * j / stacks;
    *u = (double)i / slices;
    *v = (double)j / stacks;
    return v3_make(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
}

seed_mesh *seed_mesh_sphere(seed_scene *s, double radius, int slices, int stacks) {
    seed_vertex *v = calloc((size_t)slices * stacks * 6, sizeof *v);
    if (!v) return NULL;
    int n = 0;
    for (int j = 0; j < stacks; j++)
        for (int i = 0; i < slices; i++) {
            int ci[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
            static const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int t = 0; t < 2; t++) {
                if ((j == 0 && t == 0) || (j == stacks - 1 && t == 1)) continue; /* degenerate at a pole */
                v3 centre = v3_make(0, 0, 0);
                for (int k = 0; k < 3; k++) {
                    const int *c = ci[tri[t][k]];
                    double u, vv;
                    v3 unit = sphere_point(c[0], c[1], slices, stacks, &u, &vv);
                    put_vertex(&v[n + k], v3_scale(unit, radius), unit, u, vv);
                    centre = v3_add(centre, unit);
                }
                orient_triangle(&v[n], centre);
                n += 3;
            }
        }
    return upload_mesh(s, v, n);
}

void seed_mesh_free(seed_scene *s, seed_mesh *m) {
    if (!m) return;
    seed_gpu_mesh_free(s, m);
    free(m->v);
    free(m);
}

seed_object seed_object_at(const seed_mesh *m, const float world[16]) {
    seed_object o;
    o.mesh = m;
    if (world) memcpy(o.world, world, sizeof o.world);
    else xm_identity(o.world);
    return o;
}

/* ---- effects ---- */

void seed_use_hfxo(seed_scene *s, int on) { s->via_hfxo = on; }

/* hfxc's library compiles, hfx_fx_write_hfxo serialises, hfx_effect_load_memory loads the bytes
 * as hfxc's output would be loaded from disk. */
static hfx_effect *load_via_hfxo(seed_scene *s, const char *seed_file, const char *path) {
    hfxc_options co;
    memset(&co, 0, sizeof co);
    co.targets = 1u << s->target;
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    opt.target = s->target;
    if (s->via_hfxo == 2) co.flags |= HFXC_VIA_D3D9 | HFXC_PACK_UNIFORMS; /* source -> D3D9 bytecode -> reader -> GLSL */
    if (s->via_hfxo == 3) co.flags |= HFXC_D3D9_BYTECODE; /* source -> fx_2_0 (hfxc /T fx_2_0 /Fo) -> fx_2_0's loader */
    char *why = NULL;
    hfxc_result *r = hfxc_compile_file(path, s->target == HFX_TARGET_GLSL330 && s->via_hfxo < 2 ? NULL : &co);
    const struct hfx_fx_effect *compiled = r ? hfxc_result_effect(r) : NULL;
    void *data = NULL;
    size_t size = 0;
    hfx_effect *fx = NULL;
    char *errors = NULL;
    if (!compiled) {
        char *text = r ? hfxc_diagnostics_text(r) : NULL;
        seed_note(s, "compiling %s failed: %s", seed_file, text ? text : "");
        free(text);
    } else if (s->via_hfxo == 3 ? !(data = hfxc_result_fx2(r, 0, &size, &why))
                                 : hfx_fx_write_hfxo(compiled, &data, &size) != 0) {
        seed_note(s, "writing %s as %s failed: %s", seed_file, s->via_hfxo == 3 ? "fx_2_0" : ".hfxo", why ? why : "");
    } else {
        fx = hfx_effect_load_memory(s->dev, data, size, seed_file, &opt, &errors);
        if (!fx) seed_note(s, "loading %s from .hfxo failed: %s", seed_file, errors && *errors ? errors : hfx_device_last_error(s->dev));
    }
    hfx_free(errors);
    free(why);
    free(data);
    hfxc_result_free(r);
    return fx;
}

hfx_effect *seed_load(seed_scene *s, const char *seed_file) {
    if (!s->dev) {
        seed_note(s, "no hfx device: cannot load %s", seed_file);
        return NULL;
    }
    char *path = test_seed_path(seed_file);
    if (s->via_hfxo) {
        hfx_effect *fx = path ? load_via_hfxo(s, seed_file, path) : NULL;
        free(path);
        return fx;
    }
    char *errors = NULL;
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    opt.target = s->target;
    hfx_effect *fx = path ? hfx_effect_load(s->dev, path, &opt, &errors) : NULL;
    if (!fx)
        seed_note(s, "loading %s failed: %s%s", seed_file, errors && *errors ? errors : "",
             errors && *errors ? "" : hfx_device_last_error(s->dev));
    else if (errors && *errors)
        printf("  %s compiled with: %s\n", seed_file, errors);
    hfx_free(errors);
    free(path);
    return fx;
}

static hfx_param *param(seed_scene *s, hfx_effect *fx, const char *name) {
    hfx_param *p = fx ? hfx_effect_param(fx, name) : NULL;
    if (!p) seed_note(s, "no parameter '%s'", name);
    return p;
}

void seed_check_set(seed_scene *s, int rc, const char *what) {
    if (rc != HFX_OK) seed_note(s, "setting %s failed (%d): %s", what, rc, hfx_device_last_error(s->dev));
}

void seed_param_float(seed_scene *s, hfx_param *p, const char *what, double v) {
    if (p) seed_check_set(s, hfx_param_set_float(p, (float)v), what);
}

void seed_param_int(seed_scene *s, hfx_param *p, const char *what, int v) {
    if (p) seed_check_set(s, hfx_param_set_int(p, v), what);
}

void seed_param_v3(seed_scene *s, hfx_param *p, const char *what, v3 v) {
    float f[3] = {(float)v.x, (float)v.y, (float)v.z};
    if (p) seed_check_set(s, hfx_param_set_floats(p, f, 3), what);
}

void seed_param_rgba(seed_scene *s, hfx_param *p, const char *what, rgba c) {
    float f[4] = {(float)c.r, (float)c.g, (float)c.b, (float)c.a};
    if (p) seed_check_set(s, hfx_param_set_floats(p, f, 4), what);
}

void seed_set_matrix(seed_scene *s, hfx_effect *fx, const char *name, const float m[16]) {
    hfx_param *p = param(s, fx, name);
    if (p) seed_check_set(s, hfx_param_set_matrix(p, m), name);
}

void seed_set_float(seed_scene *s, hfx_effect *fx, const char *name, double v) {
    seed_param_float(s, param(s, fx, name), name, v);
}

void seed_set_int(seed_scene *s, hfx_effect *fx, const char *name, int v) {
    seed_param_int(s, param(s, fx, name), name, v);
}

void seed_set_bool(seed_scene *s, hfx_effect *fx, const char *name, int v) {
    hfx_param *p = param(s, fx, name);
    if (p) seed_check_set(s, hfx_param_set_bool(p, v), name);
}

void seed_set_v3(seed_scene *s, hfx_effect *fx, const char *name, v3 v) {
    seed_param_v3(s, param(s, fx, name), name, v);
}

void seed_set_rgba(seed_scene *s, hfx_effect *fx, const char *name, rgba c) {
    seed_param_rgba(s, param(s, fx, name), name, c);
}

void seed_set_texture(seed_scene *s, hfx_effect *fx, const char *name, const seed_texture *t) {
    hfx_param *p = param(s, fx, name);
    if (p) seed_check_set(s, seed_gpu_set_texture(s, p, t), name);
}

hfx_param *seed_member(seed_scene *s, hfx_effect *fx, const char *array, size_t index, const char *member) {
    hfx_param *a = param(s, fx, array);
    hfx_param *e = a ? hfx_param_element(a, index) : NULL;
    hfx_param *m = e ? hfx_param_member(e, member) : NULL;
    if (a && !m) seed_note(s, "no parameter %s[%zu].%s", array, index, member);
    return m;
}

void seed_set_transforms(seed_scene *s, hfx_effect *fx, const char *world, const char *view,
                         const char *projection, const float world_m[16]) {
    float id[16];
    xm_identity(id);
    seed_set_matrix(s, fx, world, world_m ? world_m : id);
    seed_set_matrix(s, fx, view, s->view);
    seed_set_matrix(s, fx, projection, s->proj);
}

/* ---- textures ---- */

void seed_smooth_texels(unsigned char t[4 * 4 * 4]) {
    static const unsigned char ramp[4] = {120, 160, 200, 160}, blue[4] = {150, 190, 150, 110};
    static const unsigned char fade[4] = {0, 30, 60, 30};
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            unsigned char *p = t + (y * 4 + x) * 4;
            p[0] = ramp[x];
            p[1] = ramp[y];
            p[2] = blue[(x + y) % 4];
            p[3] = (unsigned char)(255 - fade[y]);
        }
}

static int address(int i, int n, seed_address mode) {
    if (mode == SEED_CLAMP) return i < 0 ? 0 : i >= n ? n - 1 : i;
    int r = i % n;
    return r < 0 ? r + n : r;
}

static rgba texel(const seed_texture *t, int x, int y) {
    const unsigned char *p = t->texels + ((size_t)y * t->width + x) * 4;
    return rgba_make(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0, p[3] / 255.0);
}

rgba seed_texture_sample(const seed_texture *t, double u, double v, seed_address mode) {
    double x = u * t->width - 0.5, y = v * t->height - 0.5;
    double fx = floor(x), fy = floor(y), a = x - fx, b = y - fy;
    int x0 = address((int)fx, t->width, mode), x1 = address((int)fx + 1, t->width, mode);
    int y0 = address((int)fy, t->height, mode), y1 = address((int)fy + 1, t->height, mode);
    rgba top = rgba_add(rgba_scale(texel(t, x0, y0), 1 - a), rgba_scale(texel(t, x1, y0), a));
    rgba bottom = rgba_add(rgba_scale(texel(t, x0, y1), 1 - a), rgba_scale(texel(t, x1, y1), a));
    return rgba_add(rgba_scale(top, 1 - b), rgba_scale(bottom, b));
}

/* ---- probes ---- */

static void sample_ndc(const seed_scene *s, int x, int y, int d3d9, double *nx, double *ny) {
    double off = d3d9 ? 0.0 : 0.5;
    *nx = -1.0 + 2.0 * (x + off) / s->width;
    *ny = 1.0 - 2.0 * (y + off) / s->height;
}

/* The world-space segment from the near plane (t = 0) to the far plane (t = 1). */
static int pixel_ray(const seed_scene *s, double nx, double ny, v3 *origin, v3 *dir) {
    const double *inv = s->inv_vp;
    if (!s->inv_ok) return 0;
    v3 ends[2];
    for (int k = 0; k < 2; k++) {
        double in[4] = {nx, ny, (double)k, 1}, o[4];
        for (int j = 0; j < 4; j++) o[j] = in[0] * inv[j] + in[1] * inv[4 + j] + in[2] * inv[8 + j] + in[3] * inv[12 + j];
        ends[k] = v3_make(o[0] / o[3], o[1] / o[3], o[2] / o[3]);
    }
    *origin = ends[0];
    *dir = v3_sub(ends[1], ends[0]);
    return 1;
}

typedef struct world_vertex { v3 pos, normal; double u, v; } world_vertex;

static world_vertex to_world(const seed_vertex *sv, const float world[16]) {
    world_vertex w;
    w.pos = xm_point(world, vertex_pos(sv));
    w.normal = xm_direction(world, v3_make(sv->normal[0], sv->normal[1], sv->normal[2]));
    w.u = sv->uv[0];
    w.v = sv->uv[1];
    return w;
}

/* Moller-Trumbore; on a hit inside (0, best) sets *t and the barycentrics of vertices 1 and 2. */
static int hit_triangle(v3 o, v3 d, v3 a, v3 b, v3 c, double best, double *t, double *b1, double *b2) {
    v3 e1 = v3_sub(b, a), e2 = v3_sub(c, a), p = v3_cross(d, e2);
    double det = v3_dot(e1, p);
    if (fabs(det) < 1e-14) return 0;
    v3 tv = v3_sub(o, a), q = v3_cross(tv, e1);
    double u = v3_dot(tv, p) / det, v = v3_dot(d, q) / det, tt = v3_dot(e2, q) / det;
    if (u < 0 || v < 0 || u + v > 1 || tt <= 0 || tt >= best) return 0;
    *t = tt;
    *b1 = u;
    *b2 = v;
    return 1;
}

/* (p, w) * m for a row-major double matrix, w = 1 for points and 0 for directions. */
static v3 affine_apply(const double m[16], v3 p, double w) {
    return v3_make(p.x * m[0] + p.y * m[4] + p.z * m[8] + w * m[12], p.x * m[1] + p.y * m[5] + p.z * m[9] + w * m[13],
                   p.x * m[2] + p.y * m[6] + p.z * m[10] + w * m[14]);
}

/* Whether the line o + t d comes within r of c (a cheap reject before the triangles). */
static int near_sphere(v3 o, v3 d, v3 c, double r) {
    double dd = v3_dot(d, d);
    if (dd <= 0) return 0;
    v3 oc = v3_sub(c, o);
    double t = v3_dot(oc, d) / dd;
    v3 closest = v3_sub(oc, v3_scale(d, t));
    return v3_dot(closest, closest) <= r * r;
}

static int pick_at(const seed_scene *s, const seed_object *objects, int n, double nx, double ny, seed_surface *out) {
    v3 o, d;
    if (!pixel_ray(s, nx, ny, &o, &d)) return -1;
    double best = 1.0;
    int found = -1;
    for (int k = 0; k < n; k++) {
        const seed_mesh *m = objects[k].mesh;
        /* World is affine: intersect in object space, where t and the barycentrics are the same. */
        double inv[16];
        if (!xm_invert(inv, objects[k].world)) continue;
        v3 oo = affine_apply(inv, o, 1), od = affine_apply(inv, d, 0);
        if (!near_sphere(oo, od, m->centre, m->radius * 1.001 + 1e-9)) continue;
        for (int i = 0; i + 2 < m->count; i += 3) {
            double t, b1, b2;
            if (!hit_triangle(oo, od, vertex_pos(&m->v[i]), vertex_pos(&m->v[i + 1]), vertex_pos(&m->v[i + 2]), best,
                              &t, &b1, &b2))
                continue;
            world_vertex w[3];
            for (int j = 0; j < 3; j++) w[j] = to_world(&m->v[i + j], objects[k].world);
            best = t;
            found = k;
            double b0 = 1 - b1 - b2;
            out->pos = v3_add(v3_add(v3_scale(w[0].pos, b0), v3_scale(w[1].pos, b1)), v3_scale(w[2].pos, b2));
            out->normal = v3_add(v3_add(v3_scale(w[0].normal, b0), v3_scale(w[1].normal, b1)),
                                 v3_scale(w[2].normal, b2));
            out->u = w[0].u * b0 + w[1].u * b1 + w[2].u * b2;
            out->v = w[0].v * b0 + w[1].v * b1 + w[2].v * b2;
            v3 face = v3_cross(v3_sub(w[1].pos, w[0].pos), v3_sub(w[2].pos, w[0].pos));
            out->front = v3_dot(face, d) > 0; /* clockwise seen from the camera */
        }
    }
    return found;
}

int seed_pick(seed_scene *s, const seed_object *objects, int n, int x, int y, seed_surface *out) {
    return seed_pick_offset(s, objects, n, x, y, 0, 0, out);
}

int seed_pick_offset(seed_scene *s, const seed_object *objects, int n, int x, int y, double dx, double dy,
                     seed_surface *out) {
    double nx, ny;
    sample_ndc(s, x, y, s->d3d9_centres, &nx, &ny);
    return pick_at(s, objects, n, nx + 2.0 * dx / s->width, ny - 2.0 * dy / s->height, out);
}

int seed_pick_certain(seed_scene *s, const seed_object *objects, int n, int x, int y, seed_surface *out) {
    static const double d[4][2] = {{-0.1, -0.1}, {0.1, -0.1}, {-0.1, 0.1}, {0.1, 0.1}};
    seed_surface tmp;
    int hit = seed_pick(s, objects, n, x, y, out);
    for (int k = 0; k < 4; k++)
        if (seed_pick_offset(s, objects, n, x, y, d[k][0], d[k][1], &tmp) != hit) return -2;
    return hit;
}

rgba seed_pixel(seed_scene *s, int x, int y) {
    unsigned char p[4];
    seed_gpu_read(s, x, y, p);
    return rgba_make(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0, p[3] / 255.0);
}

static void record(seed_scene *s, const char *name, double diff) {
    char file[64];
    snprintf(file, sizeof file, "%s%s", name,
             s->via_hfxo == 3 ? " via fx_2_0" : s->via_hfxo == 2 ? " via D3D9 bytecode" : s->via_hfxo ? " via .hfxo" : "");
    seed_file_report *r = NULL;
    for (int i = 0; i < s->file_count; i++)
        if (strcmp(s->files[i].file, file) == 0) r = &s->files[i];
    if (!r && s->file_count < SEED_MAX_FILES) {
        r = &s->files[s->file_count++];
        snprintf(r->file, sizeof r->file, "%s", file);
    }
    if (!r) return;
    r->probes++;
    if (diff > r->max_diff) r->max_diff = diff;
}

static double pixel_diff(const unsigned char got[4], rgba e, double want[4]) {
    want[0] = saturate(e.r) * 255, want[1] = saturate(e.g) * 255;
    want[2] = saturate(e.b) * 255, want[3] = saturate(e.a) * 255;
    double diff = 0;
    for (int i = 0; i < 4; i++) diff = maxd(diff, fabs(got[i] - want[i]));
    return diff;
}

double seed_expect(seed_scene *s, const char *file, const char *label, int x, int y, rgba e) {
    unsigned char got[4];
    double want[4];
    seed_gpu_read(s, x, y, got);
    double diff = pixel_diff(got, e, want);
    printf("  %-22s %-34s (%3d,%3d) expected %5.1f %5.1f %5.1f %5.1f got %3d %3d %3d %3d diff %.2f%s\n", file,
           label, x, y, want[0], want[1], want[2], want[3], got[0], got[1], got[2], got[3], diff,
           diff > SEED_TOLERANCE ? "  <-- FAIL" : "");
    record(s, file, diff);
    return diff;
}

double seed_probe(seed_scene *s, const char *file, const char *label, const seed_object *obj, int x, int y,
                  seed_shade_fn shade, const void *user) {
    double nx, ny;
    seed_surface surf, other;
    sample_ndc(s, x, y, s->d3d9_centres, &nx, &ny);
    if (pick_at(s, obj, 1, nx, ny, &surf) < 0) {
        printf("  %-22s %-34s (%3d,%3d) misses the object: probe badly placed\n", file, label, x, y);
        return 999;
    }
    rgba e = shade(&surf, user);
    double diff = seed_expect(s, file, label, x, y, e);
    /* On a failure, say whether the half-pixel question alone could explain it, to point at
     * tutorial0's pixel_centres_follow_direct3d9 rather than at the seed's equations. */
    sample_ndc(s, x, y, !s->d3d9_centres, &nx, &ny);
    if (diff > SEED_TOLERANCE && pick_at(s, obj, 1, nx, ny, &other) >= 0) {
        rgba e2 = shade(&other, user);
        double want[4];
        unsigned char got[4];
        seed_gpu_read(s, x, y, got);
        double d2 = pixel_diff(got, e2, want);
        if (d2 <= SEED_TOLERANCE)
            printf("  note: the pixel matches the reference at the %s pixel centre (diff %.2f)\n",
                   s->d3d9_centres ? "GL" : "Direct3D 9", d2);
    }
    return diff;
}

void seed_pixel_of(const seed_scene *s, v3 world, int *x, int *y) {
    float vp[16];
    xm_mul(vp, s->view, s->proj);
    double w;
    v3 c = xm_point_w(vp, world, &w);
    double nx = c.x / w, ny = c.y / w, off = s->d3d9_centres ? 0.0 : 0.5;
    *x = (int)floor((nx + 1) * 0.5 * s->width - off + 0.5);
    *y = (int)floor((1 - ny) * 0.5 * s->height - off + 0.5);
}

void seed_save_png(seed_scene *s, const char *name) {
    const char *dir = getenv("HFX_BUILD_DIR");
    char path[512];
    snprintf(path, sizeof path, "%s/seed-images", dir && *dir ? dir : "/tmp");
    mkdir(path, 0777);
    snprintf(path + strlen(path), sizeof path - strlen(path), "/%s.png", name);
    if (seed_gpu_write_png(s, path) == 0) printf("  image: %s\n", path);
}

void seed_report(const seed_scene *s) {
    for (int i = 0; i < s->file_count; i++)
        printf("seed-acceptance: %-34s probes %3d  max difference %.2f/255\n", s->files[i].file,
               s->files[i].probes, s->files[i].max_diff);
}
