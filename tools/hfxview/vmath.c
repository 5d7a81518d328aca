/* vmath.c: XNA-convention matrices (see vmath.h). */
#include "vmath.h"

#include <math.h>
#include <string.h>

hv_vec3 hv_vec3_make(float x, float y, float z) { hv_vec3 v = {x, y, z}; return v; }
hv_vec3 hv_vec3_sub(hv_vec3 a, hv_vec3 b) { return hv_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
hv_vec3 hv_vec3_add(hv_vec3 a, hv_vec3 b) { return hv_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
hv_vec3 hv_vec3_scale(hv_vec3 a, float s) { return hv_vec3_make(a.x * s, a.y * s, a.z * s); }
float hv_vec3_dot(hv_vec3 a, hv_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float hv_vec3_length(hv_vec3 a) { return sqrtf(hv_vec3_dot(a, a)); }

hv_vec3 hv_vec3_cross(hv_vec3 a, hv_vec3 b) {
    return hv_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

hv_vec3 hv_vec3_normalize(hv_vec3 a) {
    float len = hv_vec3_length(a);
    return len > 0.0f ? hv_vec3_scale(a, 1.0f / len) : a;
}

void hv_mat4_identity(float m[16]) {
    memset(m, 0, 16 * sizeof *m);
    m[0] = m[5] = m[10] = m[15] = 1.0f;
}

void hv_mat4_mul(float out[16], const float a[16], const float b[16]) {
    float r[16]; /* out may alias a or b */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            float s = 0.0f;
            for (int k = 0; k < 4; k++) s += a[i * 4 + k] * b[k * 4 + j];
            r[i * 4 + j] = s;
        }
    memcpy(out, r, sizeof r);
}

void hv_mat4_translation(float m[16], float x, float y, float z) {
    hv_mat4_identity(m);
    m[12] = x;
    m[13] = y;
    m[14] = z;
}

void hv_mat4_scale(float m[16], float x, float y, float z) {
    hv_mat4_identity(m);
    m[0] = x;
    m[5] = y;
    m[10] = z;
}

void hv_mat4_rotation_x(float m[16], float radians) {
    float c = cosf(radians), s = sinf(radians);
    hv_mat4_identity(m);
    m[5] = c;
    m[6] = s;
    m[9] = -s;
    m[10] = c;
}

void hv_mat4_rotation_y(float m[16], float radians) {
    float c = cosf(radians), s = sinf(radians);
    hv_mat4_identity(m);
    m[0] = c;
    m[2] = -s;
    m[8] = s;
    m[10] = c;
}

void hv_mat4_transpose(float out[16], const float m[16]) {
    float r[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) r[j * 4 + i] = m[i * 4 + j];
    memcpy(out, r, sizeof r);
}

/* Gauss-Jordan with partial pivoting: short, and exact enough for view and world matrices. */
int hv_mat4_invert(float out[16], const float m[16]) {
    double a[4][8];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            a[i][j] = m[i * 4 + j];
            a[i][j + 4] = i == j;
        }
    for (int col = 0; col < 4; col++) {
        int pivot = col;
        for (int r = col + 1; r < 4; r++)
            if (fabs(a[r][col]) > fabs(a[pivot][col])) pivot = r;
        if (fabs(a[pivot][col]) < 1e-12) {
            hv_mat4_identity(out);
            return 0;
        }
        for (int j = 0; j < 8; j++) {
            double t = a[col][j];
            a[col][j] = a[pivot][j];
            a[pivot][j] = t;
        }
        double inv = 1.0 / a[col][col];
        for (int j = 0; j < 8; j++) a[col][j] *= inv;
        for (int r = 0; r < 4; r++) {
            if (r == col) continue;
            double f = a[r][col];
            for (int j = 0; j < 8; j++) a[r][j] -= f * a[col][j];
        }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) out[i * 4 + j] = (float)a[i][j + 4];
    return 1;
}

void hv_mat4_look_at_rh(float m[16], hv_vec3 eye, hv_vec3 at, hv_vec3 up) {
    hv_vec3 z = hv_vec3_normalize(hv_vec3_sub(eye, at)); /* the camera looks down its -z */
    hv_vec3 x = hv_vec3_normalize(hv_vec3_cross(up, z));
    hv_vec3 y = hv_vec3_cross(z, x);
    float r[16] = {x.x, y.x, z.x, 0, x.y, y.y, z.y, 0, x.z, y.z, z.z, 0,
                   -hv_vec3_dot(x, eye), -hv_vec3_dot(y, eye), -hv_vec3_dot(z, eye), 1};
    memcpy(m, r, sizeof r);
}

void hv_mat4_perspective_fov_rh(float m[16], float fov_y, float aspect, float znear, float zfar) {
    float ys = 1.0f / tanf(fov_y * 0.5f), xs = ys / aspect;
    memset(m, 0, 16 * sizeof *m);
    m[0] = xs;
    m[5] = ys;
    m[10] = zfar / (znear - zfar);
    m[11] = -1.0f;
    m[14] = znear * zfar / (znear - zfar);
}

hv_vec3 hv_mat4_transform_point(const float m[16], hv_vec3 v, float *w) {
    if (w) *w = v.x * m[3] + v.y * m[7] + v.z * m[11] + m[15];
    return hv_vec3_make(v.x * m[0] + v.y * m[4] + v.z * m[8] + m[12], v.x * m[1] + v.y * m[5] + v.z * m[9] + m[13],
                        v.x * m[2] + v.y * m[6] + v.z * m[10] + m[14]);
}

hv_vec3 hv_mat4_transform_normal(const float m[16], hv_vec3 v) {
    return hv_vec3_make(v.x * m[0] + v.y * m[4] + v.z * m[8], v.x * m[1] + v.y * m[5] + v.z * m[9],
                        v.x * m[2] + v.y * m[6] + v.z * m[10]);
}
