/* seedmath.c: XNA's Matrix.Create* written from their documented element formulas. */
#include "seedmath.h"

#include <string.h>

void xm_identity(float m[16]) {
    memset(m, 0, 16 * sizeof *m);
    m[0] = m[5] = m[10] = m[15] = 1;
}

void xm_mul(float out[16], const float a[16], const float b[16]) {
    float r[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 4; k++) s += (double)a[i * 4 + k] * b[k * 4 + j];
            r[i * 4 + j] = (float)s;
        }
    memcpy(out, r, sizeof r);
}

void xm_translation(float m[16], double x, double y, double z) {
    xm_identity(m);
    m[12] = (float)x;
    m[13] = (float)y;
    m[14] = (float)z;
}

void xm_scale(float m[16], double x, double y, double z) {
    xm_identity(m);
    m[0] = (float)x;
    m[5] = (float)y;
    m[10] = (float)z;
}

void xm_rotation_x(float m[16], double radians) {
    double c = cos(radians), s = sin(radians);
    xm_identity(m);
    m[5] = (float)c;
    m[6] = (float)s;
    m[9] = (float)-s;
    m[10] = (float)c;
}

void xm_rotation_y(float m[16], double radians) {
    double c = cos(radians), s = sin(radians);
    xm_identity(m);
    m[0] = (float)c;
    m[2] = (float)-s;
    m[8] = (float)s;
    m[10] = (float)c;
}

void xm_look_at(float m[16], v3 eye, v3 target, v3 up) {
    v3 z = v3_normalize(v3_sub(eye, target)); /* the camera looks down its -z */
    v3 x = v3_normalize(v3_cross(up, z));
    v3 y = v3_cross(z, x);
    float r[16] = {(float)x.x, (float)y.x, (float)z.x, 0,
                   (float)x.y, (float)y.y, (float)z.y, 0,
                   (float)x.z, (float)y.z, (float)z.z, 0,
                   (float)-v3_dot(x, eye), (float)-v3_dot(y, eye), (float)-v3_dot(z, eye), 1};
    memcpy(m, r, sizeof r);
}

void xm_perspective_fov(float m[16], double fov_y, double aspect, double znear, double zfar) {
    double ys = 1.0 / tan(fov_y * 0.5), xs = ys / aspect;
    memset(m, 0, 16 * sizeof *m);
    m[0] = (float)xs;
    m[5] = (float)ys;
    m[10] = (float)(zfar / (znear - zfar));
    m[11] = -1;
    m[14] = (float)(znear * zfar / (znear - zfar));
}

void xm_orthographic(float m[16], double width, double height, double znear, double zfar) {
    xm_identity(m);
    m[0] = (float)(2.0 / width);
    m[5] = (float)(2.0 / height);
    m[10] = (float)(1.0 / (znear - zfar));
    m[14] = (float)(znear / (znear - zfar));
}

int xm_invert(double out[16], const float m[16]) {
    double a[4][8];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 8; j++) a[i][j] = j < 4 ? m[i * 4 + j] : (j - 4 == i);
    for (int c = 0; c < 4; c++) {
        int p = c;
        for (int r = c + 1; r < 4; r++)
            if (fabs(a[r][c]) > fabs(a[p][c])) p = r;
        if (fabs(a[p][c]) < 1e-12) return 0;
        for (int j = 0; j < 8; j++) {
            double t = a[c][j];
            a[c][j] = a[p][j];
            a[p][j] = t;
        }
        double d = a[c][c];
        for (int j = 0; j < 8; j++) a[c][j] /= d;
        for (int r = 0; r < 4; r++) {
            if (r == c) continue;
            double f = a[r][c];
            for (int j = 0; j < 8; j++) a[r][j] -= f * a[c][j];
        }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) out[i * 4 + j] = a[i][j + 4];
    return 1;
}

v3 xm_point_w(const float m[16], v3 p, double *w) {
    double in[4] = {p.x, p.y, p.z, 1}, o[4];
    for (int j = 0; j < 4; j++) o[j] = in[0] * m[j] + in[1] * m[4 + j] + in[2] * m[8 + j] + in[3] * m[12 + j];
    if (w) *w = o[3];
    return v3_make(o[0], o[1], o[2]);
}

v3 xm_point(const float m[16], v3 p) { return xm_point_w(m, p, NULL); }

v3 xm_direction(const float m[16], v3 d) {
    return v3_make(d.x * m[0] + d.y * m[4] + d.z * m[8], d.x * m[1] + d.y * m[5] + d.z * m[9],
                   d.x * m[2] + d.y * m[6] + d.z * m[10]);
}
