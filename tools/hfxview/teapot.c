/* teapot.c: the Utah teapot, Martin Newell's 32 bicubic Bezier patches (1975, public domain),
 * typed in from the published data and tessellated. The data is z-up with the bottom at z = 0:
 * the lid, rim, body and bottom are surfaces of revolution made of four quadrant patches each,
 * whose rows are quarter circles drawn as cubic Beziers (control points (r, 0), (r, -k r),
 * (k r, -r), (0, -r), k = 0.56; 0.5625 on the knob's top ring), so they are given here as their
 * profiles; the handle and spout are given as the patches of their y <= 0 half, mirrored in y.
 * 6 profiles x 4 quadrants + 4 halves x 2 = 32 patches over 306 distinct control points. */
#include "teapot.h"

#include <math.h>

#include "vmath.h"

/* One point of a profile: radius, height, and the quarter circle's k. */
typedef struct { float r, h, k; } profile_point;

#define K 0.56f
static const profile_point profiles[6][4] = {
    {{0.0f, 3.15f, K}, {0.8f, 3.15f, 0.5625f}, {0.0f, 2.85f, K}, {0.2f, 2.7f, K}},   /* lid: the knob */
    {{0.2f, 2.7f, K}, {0.4f, 2.55f, K}, {1.3f, 2.55f, K}, {1.3f, 2.4f, K}},           /* lid */
    {{1.4f, 2.4f, K}, {1.3375f, 2.53125f, K}, {1.4375f, 2.53125f, K}, {1.5f, 2.4f, K}}, /* rim */
    {{1.5f, 2.4f, K}, {1.75f, 1.875f, K}, {2.0f, 1.35f, K}, {2.0f, 0.9f, K}},         /* body, upper */
    {{2.0f, 0.9f, K}, {2.0f, 0.45f, K}, {1.5f, 0.225f, K}, {1.5f, 0.15f, K}},         /* body, lower */
    {{1.5f, 0.15f, K}, {1.5f, 0.075f, K}, {1.425f, 0.0f, K}, {0.0f, 0.0f, K}},        /* bottom */
};
#undef K

/* The handle's and spout's y <= 0 halves: 4 rows of 4 (x, y, z); each row runs across the
 * tube from its y = 0 edge round to the other. */
static const float halves[4][16][3] = {
    {{-1.6f, 0, 2.025f}, {-1.6f, -0.3f, 2.025f}, {-1.5f, -0.3f, 2.25f}, {-1.5f, 0, 2.25f}, /* handle, upper */
     {-2.3f, 0, 2.025f}, {-2.3f, -0.3f, 2.025f}, {-2.5f, -0.3f, 2.25f}, {-2.5f, 0, 2.25f},
     {-2.7f, 0, 2.025f}, {-2.7f, -0.3f, 2.025f}, {-3.0f, -0.3f, 2.25f}, {-3.0f, 0, 2.25f},
     {-2.7f, 0, 1.8f}, {-2.7f, -0.3f, 1.8f}, {-3.0f, -0.3f, 1.8f}, {-3.0f, 0, 1.8f}},
    {{-2.7f, 0, 1.8f}, {-2.7f, -0.3f, 1.8f}, {-3.0f, -0.3f, 1.8f}, {-3.0f, 0, 1.8f}, /* handle, lower */
     {-2.7f, 0, 1.575f}, {-2.7f, -0.3f, 1.575f}, {-3.0f, -0.3f, 1.35f}, {-3.0f, 0, 1.35f},
     {-2.5f, 0, 1.125f}, {-2.5f, -0.3f, 1.125f}, {-2.65f, -0.3f, 0.9375f}, {-2.65f, 0, 0.9375f},
     {-2.0f, 0, 0.9f}, {-2.0f, -0.3f, 0.9f}, {-1.9f, -0.3f, 0.6f}, {-1.9f, 0, 0.6f}},
    {{1.7f, 0, 1.425f}, {1.7f, -0.66f, 1.425f}, {1.7f, -0.66f, 0.6f}, {1.7f, 0, 0.6f}, /* spout, base */
     {2.6f, 0, 1.425f}, {2.6f, -0.66f, 1.425f}, {3.1f, -0.66f, 0.825f}, {3.1f, 0, 0.825f},
     {2.3f, 0, 2.1f}, {2.3f, -0.25f, 2.1f}, {2.4f, -0.25f, 2.025f}, {2.4f, 0, 2.025f},
     {2.7f, 0, 2.4f}, {2.7f, -0.25f, 2.4f}, {3.3f, -0.25f, 2.4f}, {3.3f, 0, 2.4f}},
    {{2.7f, 0, 2.4f}, {2.7f, -0.25f, 2.4f}, {3.3f, -0.25f, 2.4f}, {3.3f, 0, 2.4f}, /* spout, tip */
     {2.8f, 0, 2.475f}, {2.8f, -0.25f, 2.475f}, {3.525f, -0.25f, 2.49375f}, {3.525f, 0, 2.49375f},
     {2.9f, 0, 2.475f}, {2.9f, -0.15f, 2.475f}, {3.45f, -0.15f, 2.5125f}, {3.45f, 0, 2.5125f},
     {2.8f, 0, 2.4f}, {2.8f, -0.15f, 2.4f}, {3.2f, -0.15f, 2.4f}, {3.2f, 0, 2.4f}},
};

/* Patch i's 16 control points, z-up: i < 24 a quadrant of a profile (i % 4: the quadrant,
 * x and y mirrored as its bits say), else a half of the handle or spout (odd: mirrored in y). */
void hv_teapot_patch(int i, float cp[16][3]) {
    if (i < 24) {
        const profile_point *pr = profiles[i / 4];
        float sx = (i & 1) ? -1.0f : 1.0f, sy = (i & 2) ? -1.0f : 1.0f;
        for (int row = 0; row < 4; row++) {
            float r = pr[row].r, k = pr[row].k, ring[4][2] = {{r, 0}, {r, -k * r}, {k * r, -r}, {0, -r}};
            for (int c = 0; c < 4; c++) { /* + 0: a mirrored 0 stays +0, so equal points compare equal */
                cp[row * 4 + c][0] = sx * ring[c][0] + 0.0f;
                cp[row * 4 + c][1] = sy * ring[c][1] + 0.0f;
                cp[row * 4 + c][2] = pr[row].h;
            }
        }
        return;
    }
    const float(*h)[3] = halves[(i - 24) / 2];
    float sy = (i & 1) ? -1.0f : 1.0f;
    for (int p = 0; p < 16; p++) cp[p][0] = h[p][0], cp[p][1] = sy * h[p][1] + 0.0f, cp[p][2] = h[p][2];
}

/* Bernstein weights of degree 3 at t, and their derivatives. */
static void bernstein(float t, float b[4], float d[4]) {
    float s = 1.0f - t;
    b[0] = s * s * s, b[1] = 3 * s * s * t, b[2] = 3 * s * t * t, b[3] = t * t * t;
    d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * s * t, d[2] = 6 * s * t - 3 * t * t, d[3] = 3 * t * t;
}

/* Point and (unnormalised) cross(dP/du, dP/dv) of a patch at (u along rows, v along columns). */
static void evaluate(const float cp[16][3], float u, float v, hv_vec3 *pos, hv_vec3 *cross) {
    float bu[4], du[4], bv[4], dv[4], p[3] = {0}, pu[3] = {0}, pv[3] = {0};
    bernstein(u, bu, du);
    bernstein(v, bv, dv);
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            for (int k = 0; k < 3; k++) {
                p[k] += bu[r] * bv[c] * cp[r * 4 + c][k];
                pu[k] += du[r] * bv[c] * cp[r * 4 + c][k];
                pv[k] += bu[r] * dv[c] * cp[r * 4 + c][k];
            }
    *pos = hv_vec3_make(p[0], p[1], p[2]);
    *cross = hv_vec3_cross(hv_vec3_make(pu[0], pu[1], pu[2]), hv_vec3_make(pv[0], pv[1], pv[2]));
}

/* Which way is out, at a patch's middle: a profile's outside is on the left going down it,
 * (-dh, dr) in the (radius, height) plane; a half of the handle or spout faces away from y = 0. */
static hv_vec3 outward_hint(int i, const float cp[16][3]) {
    hv_vec3 pos, n;
    evaluate(cp, 0.5f, 0.5f, &pos, &n);
    if (i >= 24) return hv_vec3_make(0, pos.y, 0);
    const profile_point *pr = profiles[i / 4];
    float dr = pr[3].r - pr[0].r + pr[2].r - pr[1].r, dh = pr[3].h - pr[0].h + pr[2].h - pr[1].h;
    hv_vec3 radial = hv_vec3_normalize(hv_vec3_make(pos.x, pos.y, 0));
    return hv_vec3_add(hv_vec3_scale(radial, -dh), hv_vec3_make(0, 0, dr));
}

/* A unit normal; at a pole (a row squeezed to one point) the cross product vanishes, and the
 * normal is taken a little inside the patch. */
static hv_vec3 normal_at(const float cp[16][3], float u, float v, float sign) {
    hv_vec3 pos, n;
    evaluate(cp, u, v, &pos, &n);
    if (hv_vec3_length(n) < 1e-5f) evaluate(cp, fminf(fmaxf(u, 1e-3f), 1 - 1e-3f), fminf(fmaxf(v, 1e-3f), 1 - 1e-3f), &pos, &n);
    return hv_vec3_scale(hv_vec3_normalize(n), sign);
}

/* z-up to hfxview's y-up (a rotation about x: (x, y, z) -> (x, z, -y)). */
static void put_y_up(float out[3], hv_vec3 v) { out[0] = v.x, out[1] = v.z, out[2] = -v.y; }

static hv_vec3 position(const hv_mesh *m, uint32_t i) { return hv_vec3_make(m->v[i].pos[0], m->v[i].pos[1], m->v[i].pos[2]); }

static void add_unless_flat(hv_mesh *m, uint32_t a, uint32_t b, uint32_t c) {
    hv_vec3 pa = position(m, a);
    if (m->oom || hv_vec3_length(hv_vec3_cross(hv_vec3_sub(position(m, b), pa), hv_vec3_sub(position(m, c), pa))) <= 1e-9f) return;
    hv_mesh_add_triangle(m, a, b, c);
}

static void add_patch(hv_mesh *m, int i, int n) {
    float cp[16][3];
    hv_teapot_patch(i, cp);
    hv_vec3 pos, mid;
    evaluate(cp, 0.5f, 0.5f, &pos, &mid);
    float sign = hv_vec3_dot(mid, outward_hint(i, cp)) < 0 ? -1.0f : 1.0f;
    uint32_t base = (uint32_t)m->vcount;
    for (int r = 0; r <= n; r++)
        for (int c = 0; c <= n; c++) {
            float u = (float)r / (float)n, v = (float)c / (float)n, p[3], nn[3], uv[2] = {v, u};
            hv_vec3 cross;
            evaluate(cp, u, v, &pos, &cross);
            put_y_up(p, pos);
            put_y_up(nn, normal_at(cp, u, v, sign));
            hv_mesh_add_vertex(m, p, nn, uv);
        }
    for (int r = 0; r < n && !m->oom; r++)
        for (int c = 0; c < n; c++) {
            uint32_t a = base + (uint32_t)(r * (n + 1) + c), b = a + 1, d = a + (uint32_t)(n + 1), e = d + 1;
            add_unless_flat(m, a, b, d); /* a quad at a pole is one triangle */
            add_unless_flat(m, b, e, d);
        }
}

void hv_teapot_add(hv_mesh *m, int divisions) {
    for (int i = 0; i < HV_TEAPOT_PATCHES; i++) add_patch(m, i, divisions);
}
