/* seedmath.h: the vector and matrix algebra the seed references need, written for the tests
 * (independent of hfx and of hfxview). Conventions are XNA's: 4x4 matrices are row-major
 * float[16] with translation in m[12..14], vectors are rows (v' = v * M), projections are
 * right-handed and Direct3D style (clip depth 0 at the near plane, 1 at the far plane).
 * Reference shading works in double; the GPU works in float, far below 1/255 apart. */
#ifndef HFX_SEEDMATH_H
#define HFX_SEEDMATH_H

#include <math.h>

#define SEED_PI 3.14159265358979323846

typedef struct v3 { double x, y, z; } v3;
typedef struct rgba { double r, g, b, a; } rgba; /* an HLSL float4 colour */

static inline v3 v3_make(double x, double y, double z) { v3 v = {x, y, z}; return v; }
static inline v3 v3_add(v3 a, v3 b) { return v3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline v3 v3_sub(v3 a, v3 b) { return v3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline v3 v3_scale(v3 a, double s) { return v3_make(a.x * s, a.y * s, a.z * s); }
static inline v3 v3_neg(v3 a) { return v3_make(-a.x, -a.y, -a.z); }
static inline double v3_dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline v3 v3_cross(v3 a, v3 b) {
    return v3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double v3_length(v3 a) { return sqrt(v3_dot(a, a)); }
static inline double v3_distance(v3 a, v3 b) { return v3_length(v3_sub(a, b)); }
/* HLSL normalize: a / |a| (a zero vector gives NaNs on a GPU; references never pass one). */
static inline v3 v3_normalize(v3 a) { double l = v3_length(a); return l > 0 ? v3_scale(a, 1.0 / l) : a; }

static inline rgba rgba_make(double r, double g, double b, double a) { rgba c = {r, g, b, a}; return c; }
static inline rgba rgba_add(rgba a, rgba b) { return rgba_make(a.r + b.r, a.g + b.g, a.b + b.b, a.a + b.a); }
static inline rgba rgba_mul(rgba a, rgba b) { return rgba_make(a.r * b.r, a.g * b.g, a.b * b.b, a.a * b.a); }
static inline rgba rgba_scale(rgba a, double s) { return rgba_make(a.r * s, a.g * s, a.b * s, a.a * s); }

static inline double saturate(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }
static inline double maxd(double a, double b) { return a > b ? a : b; }
static inline double mind(double a, double b) { return a < b ? a : b; }
/* HLSL pow for x >= 0: exp2(y * log2(x)), so pow(0, y > 0) is 0. */
static inline double hlsl_pow(double x, double y) { return x <= 0 ? (y > 0 ? 0.0 : 1.0) : pow(x, y); }

/* Matrices (XNA order). */
void xm_identity(float m[16]);                                     /* Matrix.Identity */
void xm_mul(float out[16], const float a[16], const float b[16]);  /* a * b: a applies first */
void xm_translation(float m[16], double x, double y, double z);    /* Matrix.CreateTranslation */
void xm_scale(float m[16], double x, double y, double z);          /* Matrix.CreateScale */
void xm_rotation_x(float m[16], double radians);                   /* Matrix.CreateRotationX */
void xm_rotation_y(float m[16], double radians);                   /* Matrix.CreateRotationY */
void xm_look_at(float m[16], v3 eye, v3 target, v3 up);            /* Matrix.CreateLookAt */
void xm_perspective_fov(float m[16], double fov_y, double aspect, double znear, double zfar);
void xm_orthographic(float m[16], double width, double height, double znear, double zfar);
int xm_invert(double out[16], const float m[16]);                  /* 0 when singular */
v3 xm_point(const float m[16], v3 p);                              /* (p, 1) * m, w ignored */
v3 xm_direction(const float m[16], v3 d);                          /* (d, 0) * m: mul(float4(n,0), World) */
/* (p, 1) * m with the full 4 components: returns x, y, z and sets *w. */
v3 xm_point_w(const float m[16], v3 p, double *w);

#endif
