/* mesh.c: the built-in shapes (sphere, plane, quad, cube, torus, and the Utah teapot of
 * teapot.c) and the steps every mesh goes through (normals, tangents, winding). */
#include "mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "teapot.h"
#include "vmath.h"

#define PI 3.14159265358979323846f

const char *const hv_mesh_names[] = {"sphere", "plane", "quad", "cube", "torus", "teapot", NULL};

static int grow(void **p, size_t *cap, size_t need, size_t size) {
    if (need <= *cap) return 1;
    size_t n = *cap ? *cap * 2 : 256;
    while (n < need) n *= 2;
    void *q = realloc(*p, n * size);
    if (!q) return 0;
    *p = q;
    *cap = n;
    return 1;
}

uint32_t hv_mesh_add_vertex(hv_mesh *m, const float pos[3], const float normal[3], const float uv[2]) {
    if (m->oom || !grow((void **)&m->v, &m->vcap, m->vcount + 1, sizeof *m->v)) {
        m->oom = 1;
        return 0;
    }
    hv_vertex *v = &m->v[m->vcount];
    memset(v, 0, sizeof *v);
    memcpy(v->pos, pos, sizeof v->pos);
    if (normal) memcpy(v->normal, normal, sizeof v->normal);
    if (uv) memcpy(v->uv, uv, sizeof v->uv);
    return (uint32_t)m->vcount++;
}

void hv_mesh_add_triangle(hv_mesh *m, uint32_t a, uint32_t b, uint32_t c) {
    if (m->oom || !grow((void **)&m->idx, &m->icap, m->icount + 3, sizeof *m->idx)) {
        m->oom = 1;
        return;
    }
    m->idx[m->icount++] = a;
    m->idx[m->icount++] = b;
    m->idx[m->icount++] = c;
}

void hv_mesh_free(hv_mesh *m) {
    free(m->v);
    free(m->idx);
    memset(m, 0, sizeof *m);
}

static hv_vec3 vpos(const hv_mesh *m, uint32_t i) { return hv_vec3_make(m->v[i].pos[0], m->v[i].pos[1], m->v[i].pos[2]); }
static hv_vec3 vnorm(const hv_mesh *m, uint32_t i) {
    return hv_vec3_make(m->v[i].normal[0], m->v[i].normal[1], m->v[i].normal[2]);
}
static void put3(float out[3], hv_vec3 v) { out[0] = v.x; out[1] = v.y; out[2] = v.z; }

static hv_vec3 face_cross(const hv_mesh *m, size_t t) {
    hv_vec3 a = vpos(m, m->idx[t]), b = vpos(m, m->idx[t + 1]), c = vpos(m, m->idx[t + 2]);
    return hv_vec3_cross(hv_vec3_sub(b, a), hv_vec3_sub(c, a));
}

void hv_mesh_compute_normals(hv_mesh *m) {
    for (size_t i = 0; i < m->vcount; i++) memset(m->v[i].normal, 0, sizeof m->v[i].normal);
    for (size_t t = 0; t + 2 < m->icount; t += 3) {
        hv_vec3 n = face_cross(m, t); /* length is twice the area: bigger faces weigh more */
        for (int k = 0; k < 3; k++) {
            float *vn = m->v[m->idx[t + k]].normal;
            vn[0] += n.x;
            vn[1] += n.y;
            vn[2] += n.z;
        }
    }
    for (size_t i = 0; i < m->vcount; i++) put3(m->v[i].normal, hv_vec3_normalize(vnorm(m, i)));
}

/* Any unit vector perpendicular to n, for vertices whose texture mapping is degenerate. */
static hv_vec3 any_perpendicular(hv_vec3 n) {
    hv_vec3 axis = fabsf(n.x) < 0.9f ? hv_vec3_make(1, 0, 0) : hv_vec3_make(0, 1, 0);
    return hv_vec3_normalize(hv_vec3_cross(axis, n));
}

static void compute_tangents(hv_mesh *m) {
    hv_vec3 *acc = calloc(m->vcount ? m->vcount * 2 : 1, sizeof *acc);
    if (!acc) {
        m->oom = 1;
        return;
    }
    for (size_t t = 0; t + 2 < m->icount; t += 3) {
        const hv_vertex *v0 = &m->v[m->idx[t]], *v1 = &m->v[m->idx[t + 1]], *v2 = &m->v[m->idx[t + 2]];
        hv_vec3 e1 = hv_vec3_sub(vpos(m, m->idx[t + 1]), vpos(m, m->idx[t]));
        hv_vec3 e2 = hv_vec3_sub(vpos(m, m->idx[t + 2]), vpos(m, m->idx[t]));
        float du1 = v1->uv[0] - v0->uv[0], dv1 = v1->uv[1] - v0->uv[1];
        float du2 = v2->uv[0] - v0->uv[0], dv2 = v2->uv[1] - v0->uv[1];
        float det = du1 * dv2 - du2 * dv1;
        if (fabsf(det) < 1e-12f) continue;
        hv_vec3 tu = hv_vec3_scale(hv_vec3_sub(hv_vec3_scale(e1, dv2), hv_vec3_scale(e2, dv1)), 1.0f / det);
        hv_vec3 tv = hv_vec3_scale(hv_vec3_sub(hv_vec3_scale(e2, du1), hv_vec3_scale(e1, du2)), 1.0f / det);
        for (int k = 0; k < 3; k++) {
            uint32_t i = m->idx[t + k];
            acc[2 * i] = hv_vec3_add(acc[2 * i], tu);
            acc[2 * i + 1] = hv_vec3_add(acc[2 * i + 1], tv);
        }
    }
    for (size_t i = 0; i < m->vcount; i++) {
        hv_vec3 n = vnorm(m, i);
        /* Gram-Schmidt: the tangent frame must be orthogonal to the normal to be usable. */
        hv_vec3 t = hv_vec3_sub(acc[2 * i], hv_vec3_scale(n, hv_vec3_dot(n, acc[2 * i])));
        t = hv_vec3_length(t) > 1e-8f ? hv_vec3_normalize(t) : any_perpendicular(n);
        hv_vec3 b = hv_vec3_sub(acc[2 * i + 1], hv_vec3_scale(n, hv_vec3_dot(n, acc[2 * i + 1])));
        b = hv_vec3_sub(b, hv_vec3_scale(t, hv_vec3_dot(t, b)));
        b = hv_vec3_length(b) > 1e-8f ? hv_vec3_normalize(b) : hv_vec3_cross(n, t);
        put3(m->v[i].tangent, t);
        put3(m->v[i].binormal, b);
    }
    free(acc);
}

/* In a right-handed world a triangle a, b, c that looks clockwise from outside has
 * (b - a) x (c - a) pointing inward, against the vertex normals. */
static void wind_clockwise(hv_mesh *m) {
    for (size_t t = 0; t + 2 < m->icount; t += 3) {
        hv_vec3 n = hv_vec3_add(hv_vec3_add(vnorm(m, m->idx[t]), vnorm(m, m->idx[t + 1])), vnorm(m, m->idx[t + 2]));
        if (hv_vec3_dot(face_cross(m, t), n) > 0.0f) {
            uint32_t s = m->idx[t + 1];
            m->idx[t + 1] = m->idx[t + 2];
            m->idx[t + 2] = s;
        }
    }
}

void hv_mesh_finish(hv_mesh *m) {
    if (m->oom) return;
    for (size_t i = 0; i < m->vcount; i++) put3(m->v[i].normal, hv_vec3_normalize(vnorm(m, i)));
    compute_tangents(m);
    wind_clockwise(m);
}

/* A (cols+1) x (rows+1) vertex grid where vertex (i, j) comes from fn(u, v, ...), u = i/cols,
 * v = j/rows, stitched into quads; pole rows whose vertices coincide give single triangles. */
typedef void (*grid_fn)(float u, float v, const void *ctx, float pos[3], float normal[3]);

static void add_grid(hv_mesh *m, int cols, int rows, grid_fn fn, const void *ctx) {
    uint32_t base = (uint32_t)m->vcount;
    for (int j = 0; j <= rows; j++)
        for (int i = 0; i <= cols; i++) {
            float u = (float)i / cols, v = (float)j / rows, pos[3], normal[3], uv[2] = {u, v};
            fn(u, v, ctx, pos, normal);
            hv_mesh_add_vertex(m, pos, normal, uv);
        }
    for (int j = 0; j < rows; j++)
        for (int i = 0; i < cols; i++) {
            uint32_t a = base + (uint32_t)(j * (cols + 1) + i), b = a + 1, c = a + (uint32_t)(cols + 1), d = c + 1;
            if (m->oom) return;
            hv_vec3 pa = vpos(m, a), pb = vpos(m, b), pc = vpos(m, c), pd = vpos(m, d);
            if (hv_vec3_length(hv_vec3_cross(hv_vec3_sub(pb, pa), hv_vec3_sub(pc, pa))) > 1e-9f)
                hv_mesh_add_triangle(m, a, b, c);
            if (hv_vec3_length(hv_vec3_cross(hv_vec3_sub(pc, pb), hv_vec3_sub(pd, pb))) > 1e-9f)
                hv_mesh_add_triangle(m, b, d, c);
        }
}

static void sphere_fn(float u, float v, const void *ctx, float pos[3], float normal[3]) {
    float phi = u * 2.0f * PI, theta = v * PI; /* v = 0 at the north pole, like a texture's top row */
    float st = v <= 0.0f || v >= 1.0f ? 0.0f : sinf(theta); /* exact poles: their quads degenerate */
    normal[0] = st * sinf(phi);
    normal[1] = v <= 0.0f ? 1.0f : v >= 1.0f ? -1.0f : cosf(theta);
    normal[2] = st * cosf(phi);
    memcpy(pos, normal, 3 * sizeof *pos);
}

typedef struct { float major, minor; } torus_ctx;

static void torus_fn(float u, float v, const void *ctx, float pos[3], float normal[3]) {
    const torus_ctx *t = ctx;
    float a = u * 2.0f * PI, b = v * 2.0f * PI;
    /* Stands in the xy plane, facing the default camera, so the hole shows. */
    hv_vec3 center = hv_vec3_make(t->major * cosf(a), t->major * sinf(a), 0.0f);
    hv_vec3 n = hv_vec3_make(cosf(b) * cosf(a), cosf(b) * sinf(a), sinf(b));
    put3(normal, n);
    put3(pos, hv_vec3_add(center, hv_vec3_scale(n, t->minor)));
}

typedef struct { hv_vec3 origin, du, dv, normal; } face_ctx;

static void face_fn(float u, float v, const void *ctx, float pos[3], float normal[3]) {
    const face_ctx *f = ctx;
    put3(pos, hv_vec3_add(f->origin, hv_vec3_add(hv_vec3_scale(f->du, u), hv_vec3_scale(f->dv, v))));
    put3(normal, f->normal);
}

/* A flat face: origin is the corner at uv (0, 0) (the image's top left). */
static void add_face(hv_mesh *m, hv_vec3 origin, hv_vec3 du, hv_vec3 dv, int divisions) {
    face_ctx f = {origin, du, dv, hv_vec3_normalize(hv_vec3_cross(dv, du))};
    add_grid(m, divisions, divisions, face_fn, &f);
}

static void make_cube(hv_mesh *m) {
    const float h = 0.6f;
    /* Each face seen from outside: u to the right, v down. */
    add_face(m, hv_vec3_make(-h, h, h), hv_vec3_make(2 * h, 0, 0), hv_vec3_make(0, -2 * h, 0), 1);   /* +z */
    add_face(m, hv_vec3_make(h, h, -h), hv_vec3_make(-2 * h, 0, 0), hv_vec3_make(0, -2 * h, 0), 1);  /* -z */
    add_face(m, hv_vec3_make(h, h, h), hv_vec3_make(0, 0, -2 * h), hv_vec3_make(0, -2 * h, 0), 1);   /* +x */
    add_face(m, hv_vec3_make(-h, h, -h), hv_vec3_make(0, 0, 2 * h), hv_vec3_make(0, -2 * h, 0), 1);  /* -x */
    add_face(m, hv_vec3_make(-h, h, -h), hv_vec3_make(2 * h, 0, 0), hv_vec3_make(0, 0, 2 * h), 1);   /* +y */
    add_face(m, hv_vec3_make(-h, -h, h), hv_vec3_make(2 * h, 0, 0), hv_vec3_make(0, 0, -2 * h), 1);  /* -y */
}

/* The Utah teapot (teapot.c), its height centred on the origin and its lid's axis on y,
 * scaled so the spout's tip touches the unit sphere. */
static void make_teapot(hv_mesh *m) {
    hv_teapot_add(m, 8);
    for (size_t i = 0; i < m->vcount; i++) m->v[i].pos[1] -= 3.15f / 2.0f; /* Newell's height */
    float r = 0;
    for (size_t i = 0; i < m->vcount; i++) r = fmaxf(r, hv_vec3_length(vpos(m, (uint32_t)i)));
    for (size_t i = 0; i < m->vcount; i++)
        for (int k = 0; k < 3; k++) m->v[i].pos[k] /= r > 0 ? r : 1;
}

int hv_mesh_builtin(hv_mesh *m, const char *name) {
    memset(m, 0, sizeof *m);
    if (!strcmp(name, "sphere")) {
        add_grid(m, 48, 24, sphere_fn, NULL);
    } else if (!strcmp(name, "plane")) { /* horizontal, 2 x 2, facing +y, like FX Composer's plane */
        add_face(m, hv_vec3_make(-1, 0, -1), hv_vec3_make(2, 0, 0), hv_vec3_make(0, 0, 2), 16);
    } else if (!strcmp(name, "quad")) {  /* upright, 2 x 2, facing the default camera */
        add_face(m, hv_vec3_make(-1, 1, 0), hv_vec3_make(2, 0, 0), hv_vec3_make(0, -2, 0), 1);
    } else if (!strcmp(name, "cube")) {
        make_cube(m);
    } else if (!strcmp(name, "torus")) {
        torus_ctx t = {0.7f, 0.3f};
        add_grid(m, 48, 24, torus_fn, &t);
    } else if (!strcmp(name, "teapot")) {
        make_teapot(m);
    } else {
        return -1;
    }
    hv_mesh_finish(m);
    return m->oom ? -1 : 0;
}

int hv_mesh_load(hv_mesh *m, const char *spec, char *err, size_t errlen) {
    for (int i = 0; hv_mesh_names[i]; i++)
        if (!strcmp(spec, hv_mesh_names[i])) {
            if (hv_mesh_builtin(m, spec) == 0) return 0;
            snprintf(err, errlen, "out of memory building the %s mesh", spec);
            hv_mesh_free(m);
            return -1;
        }
    return hv_mesh_load_obj(m, spec, err, errlen);
}

/* Two triangles covering a width x height image in pixels, x right and y down from the top-left
 * corner, z 0, uv 0..1 with v = 0 at the top (Direct3D's convention), clockwise on screen: the
 * input of post-processing vertex shaders that divide by the viewport size (DigitalRise's
 * ScreenToProjection). Not fitted to the unit sphere: the positions are the point. */
int hv_mesh_screen(hv_mesh *m, int width, int height) {
    memset(m, 0, sizeof *m);
    const float w = (float)width, h = (float)height, n[3] = {0, 0, -1};
    const float pos[4][3] = {{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}}, uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    uint32_t idx[4];
    for (int i = 0; i < 4; i++) idx[i] = hv_mesh_add_vertex(m, pos[i], n, uv[i]);
    hv_mesh_add_triangle(m, idx[0], idx[1], idx[2]);
    hv_mesh_add_triangle(m, idx[0], idx[2], idx[3]);
    for (size_t i = 0; i < m->vcount && !m->oom; i++) {
        m->v[i].tangent[0] = 1;
        m->v[i].binormal[1] = 1;
    }
    return m->oom ? -1 : 0;
}

const hv_vertex_constant hv_vertex_constants[] = {
    {"COLOR0", {1, 1, 1, 1}}, {"COLOR1", {0, 0, 0, 0}}, {"BLENDWEIGHT0", {1, 0, 0, 0}},
    {"BLENDWEIGHT1", {0, 1, 0, 0}}, {"BLENDWEIGHT2", {0, 0, 1, 0}}, {"BLENDWEIGHT3", {0, 0, 0, 1}},
    {"BLENDINDICES0", {0, 0, 0, 0}}, {"PSIZE0", {1, 0, 0, 0}},
};
const size_t hv_vertex_constant_count = sizeof hv_vertex_constants / sizeof hv_vertex_constants[0];
