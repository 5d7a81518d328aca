/* hfxview's matrix names: which matrix a parameter's name or semantic asks for, and that the
 * matrix handed over is that product, computed here independently from the camera. */
#include "test.h"

#include "../../tools/hfxview/bind.c"
#include "../../tools/hfxview/bind_roles.c"
#include "../../tools/hfxview/bind_sas.c"
#include "../../tools/hfxview/options.c"
#include "../../tools/hfxview/vmath.c"

static hv_scene scene;

static void expect(const char *name, int is_semantic, const float *want) {
    float m[16];
    int found = hv_scene_matrix(&scene, name, is_semantic, m);
    if (!found) fprintf(stderr, "  '%s' names no matrix\n", name);
    CHECK(found);
    for (int i = 0; found && i < 16; i++)
        if (fabsf(m[i] - want[i]) > 1e-4f) {
            fprintf(stderr, "  '%s': m[%d] = %g, expected %g\n", name, i, m[i], want[i]);
            CHECK(0);
            break;
        }
}

static void names_and_semantics(void) {
    float w[16], v[16], p[16], wv[16], vp[16], wvp[16], t[16], inv[16];
    hv_mat4_rotation_y(w, 30 * 3.14159265f / 180); /* --rotate 30 */
    hv_mat4_look_at_rh(v, hv_vec3_make(0, 1, 3), hv_vec3_make(0, 0, 0), hv_vec3_make(0, 1, 0));
    hv_mat4_perspective_fov_rh(p, 45 * 3.14159265f / 180, 1.0f, sqrtf(10.0f) / 4, 4.0f * sqrtf(10.0f)); /* near, far: |eye| / 4, 4 x |eye| */
    hv_mat4_mul(wv, w, v);
    hv_mat4_mul(vp, v, p);
    hv_mat4_mul(wvp, wv, p);
    expect("World", 1, w);
    expect("world", 0, w);
    expect("matWorld", 0, w);
    expect("worldMatrix", 0, w);
    expect("View", 1, v);
    expect("g_mView", 0, v);
    expect("Projection", 1, p);
    expect("proj", 0, p);
    expect("WorldView", 1, wv);
    expect("ViewProjection", 1, vp);
    expect("ViewProj", 0, vp);
    expect("WorldViewProjection", 1, wvp);
    expect("WORLDVIEWPROJECTION", 1, wvp); /* SAS spelling */
    expect("WorldViewProj", 0, wvp);
    expect("WvpXf", 0, wvp);
    expect("g_mWorldViewProjection", 0, wvp);
    expect("xWorld", 0, w);            /* Riemer's XNA tutorials and the Apress recipes */
    expect("xViewProjection", 0, vp);
    expect("_world", 0, w);            /* DigitalRise's private-member style */
    expect("_worldViewProj", 0, wvp);
    expect("fxWVP", 0, wvp);
    hv_mat4_invert(inv, v);
    expect("ViewInverse", 1, inv);
    expect("ViewIXf", 0, inv);
    hv_mat4_invert(inv, w);
    hv_mat4_transpose(t, inv);
    expect("WorldInverseTranspose", 1, t);
    expect("WorldITXf", 0, t);
    expect("worldIT", 0, t);
    hv_mat4_transpose(t, wvp);
    expect("WorldViewProjectionTranspose", 1, t);
    float m[16];
    CHECK(!hv_scene_matrix(&scene, "BoneMatrices", 0, m));
    CHECK(!hv_scene_matrix(&scene, "Worldly", 0, m));
    CHECK(!hv_scene_matrix(&scene, "xworld", 0, m)); /* a lower-case x is part of the name */
    CHECK(!hv_scene_matrix(&scene, "", 1, m));
}

static void light_follows_the_options(void) {
    hv_options o;
    hv_options_defaults(&o);
    o.light_position = hv_vec3_make(0, 10, 0);
    hv_scene s;
    hv_scene_from_options(&s, &o);
    /* Shining from (0,10,0) at the origin: travelling straight down. */
    CHECK_NEAR(s.light_direction.x, 0, 1e-6);
    CHECK_NEAR(s.light_direction.y, -1, 1e-6);
    o.light_direction = hv_vec3_make(3, 0, 4);
    o.light_direction_given = 1;
    hv_scene_from_options(&s, &o);
    CHECK_NEAR(s.light_direction.x, 0.6, 1e-6);
    CHECK_NEAR(s.light_direction.z, 0.8, 1e-6);
    CHECK_NEAR(s.projection[0], 1.0 / tan(3.14159265 / 8), 1e-4); /* 45 degrees, square */
}

int main(void) {
    hv_options o;
    hv_options_defaults(&o);
    o.yaw_degrees = 30;
    hv_scene_from_options(&scene, &o);
    RUN(names_and_semantics);
    RUN(light_follows_the_options);
    return test_summary();
}
