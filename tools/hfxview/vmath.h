/* vmath.h: the little matrix algebra hfxview needs, in XNA's conventions: 4x4 matrices are
 * row-major float[16], vectors are rows (v' = v * M), translation sits in m[12..14], and
 * projections are Direct3D style (depth 0..1) and right-handed like XNA's Matrix.Create*. */
#ifndef HFXVIEW_VMATH_H
#define HFXVIEW_VMATH_H

typedef struct hv_vec3 { float x, y, z; } hv_vec3;

hv_vec3 hv_vec3_make(float x, float y, float z);        /* (x, y, z) */
hv_vec3 hv_vec3_sub(hv_vec3 a, hv_vec3 b);              /* a - b */
hv_vec3 hv_vec3_add(hv_vec3 a, hv_vec3 b);              /* a + b */
hv_vec3 hv_vec3_scale(hv_vec3 a, float s);              /* a * s */
hv_vec3 hv_vec3_cross(hv_vec3 a, hv_vec3 b);            /* a x b */
float hv_vec3_dot(hv_vec3 a, hv_vec3 b);                /* a . b */
float hv_vec3_length(hv_vec3 a);                        /* |a| */
hv_vec3 hv_vec3_normalize(hv_vec3 a);                   /* a / |a|, or a when |a| is 0 */

void hv_mat4_identity(float m[16]);                                    /* I */
void hv_mat4_mul(float out[16], const float a[16], const float b[16]); /* a * b: a first, then b */
void hv_mat4_translation(float m[16], float x, float y, float z);      /* XNA CreateTranslation */
void hv_mat4_scale(float m[16], float x, float y, float z);            /* XNA CreateScale */
void hv_mat4_rotation_x(float m[16], float radians);                   /* XNA CreateRotationX */
void hv_mat4_rotation_y(float m[16], float radians);                   /* XNA CreateRotationY */
void hv_mat4_transpose(float out[16], const float m[16]);              /* rows become columns */
int hv_mat4_invert(float out[16], const float m[16]);                  /* 0 when singular (out = I) */
void hv_mat4_look_at_rh(float m[16], hv_vec3 eye, hv_vec3 at, hv_vec3 up); /* XNA CreateLookAt */
/* XNA CreatePerspectiveFieldOfView: right-handed, looks down -z, depth 0 at near and 1 at far. */
void hv_mat4_perspective_fov_rh(float m[16], float fov_y, float aspect, float znear, float zfar);
hv_vec3 hv_mat4_transform_point(const float m[16], hv_vec3 v, float *w); /* (v, 1) * m; w may be NULL */
hv_vec3 hv_mat4_transform_normal(const float m[16], hv_vec3 v);          /* (v, 0) * m */

#endif
