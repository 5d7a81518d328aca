/* hfxview's matrices against values worked out by hand from XNA's definitions. */
#include "test.h"

#include "../../tools/hfxview/vmath.c"

#define EPS 1e-5

static void check_matrix(const float *m, const float *want, int line) {
    for (int i = 0; i < 16; i++)
        if (fabsf(m[i] - want[i]) > 1e-5f) {
            fprintf(stderr, "line %d: m[%d] = %g, expected %g\n", line, i, m[i], want[i]);
            test_current_failed_ = 1;
            test_checks_failed_++;
        }
}

static void translation_lives_in_row_four(void) {
    float m[16];
    hv_mat4_translation(m, 1, 2, 3);
    float want[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1};
    check_matrix(m, want, __LINE__);
    float w;
    hv_vec3 p = hv_mat4_transform_point(m, hv_vec3_make(10, 20, 30), &w);
    CHECK_NEAR(p.x, 11, EPS);
    CHECK_NEAR(p.y, 22, EPS);
    CHECK_NEAR(p.z, 33, EPS);
    CHECK_NEAR(w, 1, EPS);
    hv_vec3 n = hv_mat4_transform_normal(m, hv_vec3_make(0, 1, 0)); /* directions ignore translation */
    CHECK_NEAR(n.x, 0, EPS);
    CHECK_NEAR(n.y, 1, EPS);
}

static void row_vectors_apply_the_left_matrix_first(void) {
    float t[16], s[16], ts[16], st[16];
    hv_mat4_translation(t, 1, 0, 0);
    hv_mat4_scale(s, 2, 2, 2);
    hv_mat4_mul(ts, t, s); /* translate, then scale: origin -> (1,0,0) -> (2,0,0) */
    hv_mat4_mul(st, s, t); /* scale, then translate: origin -> (0,0,0) -> (1,0,0) */
    CHECK_NEAR(hv_mat4_transform_point(ts, hv_vec3_make(0, 0, 0), NULL).x, 2, EPS);
    CHECK_NEAR(hv_mat4_transform_point(st, hv_vec3_make(0, 0, 0), NULL).x, 1, EPS);
}

static void rotation_y_turns_x_towards_minus_z(void) {
    float m[16];
    hv_mat4_rotation_y(m, 3.14159265f / 2);
    /* Right-hand rule about +y: +x goes to -z (XNA's CreateRotationY). */
    hv_vec3 p = hv_mat4_transform_point(m, hv_vec3_make(1, 0, 0), NULL);
    CHECK_NEAR(p.x, 0, EPS);
    CHECK_NEAR(p.y, 0, EPS);
    CHECK_NEAR(p.z, -1, EPS);
    hv_mat4_rotation_x(m, 3.14159265f / 2); /* +y goes to +z */
    p = hv_mat4_transform_point(m, hv_vec3_make(0, 1, 0), NULL);
    CHECK_NEAR(p.z, 1, EPS);
    CHECK_NEAR(p.y, 0, EPS);
}

static void look_at_down_minus_z_is_a_translation(void) {
    float m[16];
    hv_mat4_look_at_rh(m, hv_vec3_make(0, 0, 5), hv_vec3_make(0, 0, 0), hv_vec3_make(0, 1, 0));
    float want[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1};
    check_matrix(m, want, __LINE__);
}

static void look_at_from_plus_x(void) {
    float m[16];
    /* Camera on +x looking at the origin: z axis = +x, x axis = up x z = (0,0,-1), y = (0,1,0). */
    hv_mat4_look_at_rh(m, hv_vec3_make(3, 0, 0), hv_vec3_make(0, 0, 0), hv_vec3_make(0, 1, 0));
    float want[16] = {0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, -3, 1};
    check_matrix(m, want, __LINE__);
    hv_vec3 o = hv_mat4_transform_point(m, hv_vec3_make(0, 0, 0), NULL);
    CHECK_NEAR(o.z, -3, EPS); /* in front of a right-handed camera means negative z */
    hv_vec3 r = hv_mat4_transform_point(m, hv_vec3_make(0, 0, -1), NULL);
    CHECK_NEAR(r.x, 1, EPS); /* world -z is on the camera's right */
}

static void perspective_maps_near_to_0_and_far_to_1(void) {
    float m[16], w;
    hv_mat4_perspective_fov_rh(m, 3.14159265f / 2, 1.0f, 1.0f, 10.0f);
    /* fov 90: yScale = 1/tan(45) = 1; m33 = f/(n-f) = -10/9; m43 = n f/(n-f) = -10/9; m34 = -1. */
    float want[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -10.0f / 9, -1, 0, 0, -10.0f / 9, 0};
    check_matrix(m, want, __LINE__);
    hv_vec3 n = hv_mat4_transform_point(m, hv_vec3_make(0, 0, -1), &w);
    CHECK_NEAR(n.z / w, 0, EPS);
    hv_vec3 f = hv_mat4_transform_point(m, hv_vec3_make(0, 0, -10), &w);
    CHECK_NEAR(f.z / w, 1, 1e-5);
    hv_vec3 e = hv_mat4_transform_point(m, hv_vec3_make(2, 0, -2), &w); /* 45 degrees right: screen edge */
    CHECK_NEAR(e.x / w, 1, EPS);
    hv_mat4_perspective_fov_rh(m, 3.14159265f / 2, 2.0f, 1.0f, 10.0f);
    CHECK_NEAR(m[0], 0.5, EPS); /* xScale = yScale / aspect */
}

static void inverse_and_transpose(void) {
    float t[16], inv[16], want[16], r[16], s[16], m[16], p[16];
    hv_mat4_translation(t, 1, 2, 3);
    CHECK(hv_mat4_invert(inv, t));
    hv_mat4_translation(want, -1, -2, -3);
    check_matrix(inv, want, __LINE__);
    hv_mat4_rotation_y(r, 0.3f);
    hv_mat4_scale(s, 2, 3, 4);
    hv_mat4_mul(m, s, r);
    hv_mat4_mul(m, m, t);
    CHECK(hv_mat4_invert(inv, m));
    hv_mat4_mul(p, m, inv);
    hv_mat4_identity(want);
    check_matrix(p, want, __LINE__);
    float singular[16] = {0};
    CHECK(!hv_mat4_invert(inv, singular));
    float a[16] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
    float at[16] = {0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15};
    hv_mat4_transpose(a, a);
    check_matrix(a, at, __LINE__);
}

static void vectors(void) {
    hv_vec3 c = hv_vec3_cross(hv_vec3_make(1, 0, 0), hv_vec3_make(0, 1, 0));
    CHECK_NEAR(c.z, 1, EPS);
    CHECK_NEAR(hv_vec3_length(hv_vec3_make(3, 4, 12)), 13, EPS);
    hv_vec3 n = hv_vec3_normalize(hv_vec3_make(0, 0, 0)); /* no NaN from a zero vector */
    CHECK(n.x == 0 && n.y == 0 && n.z == 0);
}

int main(void) {
    RUN(translation_lives_in_row_four);
    RUN(row_vectors_apply_the_left_matrix_first);
    RUN(rotation_y_turns_x_towards_minus_z);
    RUN(look_at_down_minus_z_is_a_translation);
    RUN(look_at_from_plus_x);
    RUN(perspective_maps_near_to_0_and_far_to_1);
    RUN(inverse_and_transpose);
    RUN(vectors);
    return test_summary();
}
