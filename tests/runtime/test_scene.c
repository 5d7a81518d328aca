/* test_scene.c: hfx_effect_bind_scene (runtime/scene.c). Every standard semantic against a
 * matrix worked out by hand below from a scene chosen so that the products and inverses are
 * short, in XNA's row-vector order (docs/conventions.md): WorldView = World * View, and so on.
 * Transposes are the hand matrices with rows and columns swapped (the definition, in
 * transpose_of). Also: case-insensitive semantics, smaller matrices taking the upper-left block,
 * parameters of the wrong shape left alone, and a second call with the same scene marking nothing
 * changed, so Apply has nothing to send. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_context.h"
#include "internal.h"
#include "test.h"

static hfx_device *dev;

/* World: scale 2, then move 1 along x.  View: move 5 along -z (a camera at z = +5).
 * Projection: x' = x, y' = 2y, z' = z - w, w' = z (rows below; invertible, easy inverse). */
static const float W[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 0, 0, 1};
static const float V[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1};
static const float P[16] = {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 1, 0, 0, -1, 0};

/* W^-1: v = (v' - (1,0,0)) / 2.  V^-1: move 5 along +z.
 * P^-1: x = x', y = y'/2, z = w', w = w' - z'  (P * P^-1 = I: row 2 of P picks rows 2 + 3 of
 * P^-1 = (0,0,1,0); row 3 picks -row 2 = (0,0,0,1)). */
static const float Wi[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, 0, -0.5f, 0, 0, 1};
static const float Vi[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1};
static const float Pi[16] = {1, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0, -1, 0, 0, 1, 1};
/* WV = W * V: V only adds -5 z per unit of w, so W's last row (1,0,0,1) becomes (1,0,-5,1).
 * (WV)^-1 = V^-1 W^-1: v = (v' + (0,0,5) - (1,0,0)) / 2. */
static const float WV[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 0, -5, 1};
static const float WVi[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, 0, -0.5f, 0, 2.5f, 1};
/* VP = V * P: rows 0..2 of V pick P's rows; (0,0,-5,1) gives -5 (0,0,1,1) + (0,0,-1,0) = (0,0,-6,-5).
 * (VP)^-1 = P^-1 V^-1: each row of P^-1 plus 5 z per unit of its w: (0,0,0,-1) -> (0,0,-5,-1),
 * (0,0,1,1) -> (0,0,6,1). Check row 3: -6 (0,0,-5,-1) - 5 (0,0,6,1) = (0,0,0,1). */
static const float VP[16] = {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 1, 0, 0, -6, -5};
static const float VPi[16] = {1, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, -5, -1, 0, 0, 6, 1};
/* WVP = WV * P: (2,0,0,0), (0,4,0,0), 2 (0,0,1,1), (1,0,0,0) - 5 (0,0,1,1) + (0,0,-1,0).
 * (WVP)^-1 = P^-1 (WV)^-1: rows (1,0,0,0) -> (.5,0,0,0); (0,.5,0,0) -> (0,.25,0,0);
 * (0,0,0,-1) -> -(-.5,0,2.5,1); (0,0,1,1) -> (0,0,.5,0) + (-.5,0,2.5,1).
 * Check row 3: (.5,0,0,0) - 6 (.5,0,-2.5,-1) - 5 (-.5,0,3,1) = (0,0,0,1). */
static const float WVP[16] = {2, 0, 0, 0, 0, 4, 0, 0, 0, 0, 2, 2, 1, 0, -6, -5};
static const float WVPi[16] = {0.5f, 0, 0, 0, 0, 0.25f, 0, 0, 0.5f, 0, -2.5f, -1, -0.5f, 0, 3, 1};

static const char *const base_names[6] = {"World", "View", "Projection", "WorldView", "ViewProjection",
                                          "WorldViewProjection"};
static const float *const plain[6] = {W, V, P, WV, VP, WVP};
static const float *const inverse[6] = {Wi, Vi, Pi, WVi, VPi, WVPi};
static const char *const form_names[4] = {"", "Inverse", "Transpose", "InverseTranspose"};

static void transpose_of(float out[16], const float m[16]) {
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) out[c * 4 + r] = m[r * 4 + c];
}

/* 24 float4x4 parameters m<base>_<form> with the semantic spelled in three cases, then the rest. */
static char *effect_source(void) {
    static char src[8192];
    size_t n = 0;
    for (int b = 0; b < 6; b++)
        for (int f = 0; f < 4; f++) {
            char sem[64];
            snprintf(sem, sizeof sem, "%s%s", base_names[b], form_names[f]);
            for (char *c = sem; *c && (b + f) % 3 == 1; c++) *c = (char)(*c >= 'a' && *c <= 'z' ? *c - 32 : *c);
            n += (size_t)snprintf(src + n, sizeof src - n, "float4x4 m%d_%d : %s;\n", b, f, sem);
        }
    snprintf(src + n, sizeof src - n,
             "float3x3 normalMatrix : worldinversetranspose;\n" /* upper-left block */
             "float4x4 wvp2 : WorldViewProj;\n"                 /* the short spelling */
             "float3 eye : CameraPosition;\n"
             "float4 eye4 : VIEWPOSITION;\n"
             "float t : Time;\n"
             "float dt : ElapsedTime;\n"
             "float2 vp : ViewportPixelSize;\n"
             "int wrong : World;\n"                             /* not a float: left alone */
             "float4x4 bones[2] : World;\n"                     /* an array: left alone */
             "float4x4 other : WorldMatrix = {1,2,3,4, 5,6,7,8, 9,10,11,12, 13,14,15,16};\n"
             "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, m5_0); }\n"
             "float4 PS() : COLOR0 { return float4(t, vp.x, eye.z, 1); }\n"
             "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n");
    return src;
}

static hfx_scene the_scene(void) {
    hfx_scene s;
    memset(&s, 0, sizeof s);
    memcpy(s.world, W, sizeof W);
    memcpy(s.view, V, sizeof V);
    memcpy(s.projection, P, sizeof P);
    s.time = 2.5f;
    s.elapsed_time = 0.016f;
    s.viewport_width = 640;
    s.viewport_height = 480;
    return s;
}

static void check_floats(hfx_effect *fx, const char *name, const float *want, size_t n, const char *what) {
    float got[16];
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, name), got, n), HFX_OK);
    for (size_t i = 0; i < n; i++)
        if (fabsf(got[i] - want[i]) > 1e-6f) {
            fprintf(stderr, "%s (%s) [%zu] = %g, expected %g\n", name, what, i, got[i], want[i]);
            CHECK(0);
            return;
        }
}

static void every_matrix_semantic(void) {
    const char *src = effect_source();
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, strlen(src), "scene.fx", NULL, &errors);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_scene s = the_scene();
    CHECK_INT(hfx_effect_bind_scene(fx, &s), 24 + 7);
    for (int b = 0; b < 6; b++)
        for (int f = 0; f < 4; f++) {
            float want[16];
            const float *m = f == 0 || f == 2 ? plain[b] : inverse[b];
            if (f >= 2) transpose_of(want, m);
            else memcpy(want, m, sizeof want);
            char pname[16], what[64];
            snprintf(pname, sizeof pname, "m%d_%d", b, f);
            snprintf(what, sizeof what, "%s%s", base_names[b], form_names[f]);
            check_floats(fx, pname, want, 16, what);
        }
    /* (W^-1)^T's upper-left block: diag(0.5) */
    check_floats(fx, "normalMatrix", (const float[9]){0.5f, 0, 0, 0, 0.5f, 0, 0, 0, 0.5f}, 9, "3x3");
    check_floats(fx, "wvp2", WVP, 16, "WorldViewProj");
    check_floats(fx, "eye", (const float[3]){0, 0, 5}, 3, "V^-1's last row");
    check_floats(fx, "eye4", (const float[4]){0, 0, 5, 1}, 4, "with w = 1");
    check_floats(fx, "t", (const float[1]){2.5f}, 1, "Time");
    check_floats(fx, "dt", (const float[1]){0.016f}, 1, "ElapsedTime");
    check_floats(fx, "vp", (const float[2]){640, 480}, 2, "ViewportPixelSize");
    int i = -1;
    CHECK_INT(hfx_param_get_int(hfx_effect_param(fx, "wrong"), &i), HFX_OK);
    CHECK_INT(i, 0);
    float zero[32] = {0}, bones[32];
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "bones"), bones, 32), HFX_OK);
    CHECK(memcmp(bones, zero, sizeof bones) == 0);
    check_floats(fx, "other", (const float[16]){1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}, 16, "unknown");
    hfx_effect_destroy(fx);
}

/* The same scene again changes no value, so the change log does not grow; a new world only
 * touches what depends on it. */
static void unchanged_scene_marks_nothing(void) {
    const char *src = effect_source();
    hfx_effect *fx = hfx_effect_load_memory(dev, src, strlen(src), "scene.fx", NULL, NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_scene s = the_scene();
    hfx_effect_bind_scene(fx, &s);
    uint64_t before = fx->log_len;
    CHECK_INT(hfx_effect_bind_scene(fx, &s), 31);
    CHECK_INT(fx->log_len, before);
    /* move 3 along x instead of 1: the 4 forms of World, WorldView and WorldViewProjection change,
     * and wvp2; normalMatrix, (W^-1)^T's upper-left block, does not, nor does anything else */
    s.world[12] = 3;
    hfx_effect_bind_scene(fx, &s);
    CHECK_INT(fx->log_len - before, 3 * 4 + 1);
    float m[16];
    CHECK_INT(hfx_param_get_matrix(hfx_effect_param(fx, "m0_1"), m), HFX_OK);
    CHECK_NEAR(m[12], -1.5, 1e-6); /* W^-1 now moves by -3/2 */
    hfx_effect_destroy(fx);
}

static void semantics_known_and_nulls(void) {
    CHECK_INT(hfx_scene_semantic_known("worldviewprojectionINVERSETRANSPOSE"), 1);
    CHECK_INT(hfx_scene_semantic_known("ViewInverse"), 1);
    CHECK_INT(hfx_scene_semantic_known("ViewportPixelSize"), 1);
    CHECK_INT(hfx_scene_semantic_known("WorldInverseInverse"), 0);
    CHECK_INT(hfx_scene_semantic_known("POSITION"), 0);
    CHECK_INT(hfx_scene_semantic_known(""), 0);
    CHECK_INT(hfx_scene_semantic_known(NULL), 0);
    hfx_scene s = the_scene();
    CHECK_INT(hfx_effect_bind_scene(NULL, &s), HFX_ERR_NULL);
}

/* A singular world has no inverse: its inverse forms are zeros, never stale. */
static void singular_inverse_is_zero(void) {
    static const char src[] = "float4x4 a : WorldInverse = {1,1,1,1, 1,1,1,1, 1,1,1,1, 1,1,1,1};\n";
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "singular.fx", NULL, NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_scene s = the_scene();
    memset(s.world, 0, sizeof s.world);
    CHECK_INT(hfx_effect_bind_scene(fx, &s), 1);
    float zero[16] = {0};
    check_floats(fx, "a", zero, 16, "singular");
    hfx_effect_destroy(fx);
}

/* `Object = "SpotLight0"` or a SasBindAddress makes a View semantic another object's (FX
 * Composer's shadow effects: the light's view), so the scene leaves it alone; Object =
 * "Camera" is the scene's. */
static void another_objects_matrix_left_alone(void) {
    static const char src[] =
        "float4x4 light : View < string Object = \"SpotLight0\"; >;\n"
        "float4x4 sas : View < string SasBindAddress = \"Sas.Skeleton.MeshToJointToWorld[0]\"; >;\n"
        "float4x4 cam : View < string Object = \"Camera\"; >;\n";
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "object.fx", NULL, NULL);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_scene s = the_scene();
    CHECK_INT(hfx_effect_bind_scene(fx, &s), 1);
    float zero[16] = {0};
    check_floats(fx, "light", zero, 16, "a light's view");
    check_floats(fx, "sas", zero, 16, "a SAS address");
    check_floats(fx, "cam", V, 16, "the camera's view");
    hfx_effect_destroy(fx);
}

int main(void) {
    test_gl *gl = test_gl_create(4, 4);
    if (!gl) test_skip("no OSMesa context");
    dev = hfx_device_create_gl(test_gl_loader);
    RUN(every_matrix_semantic);
    RUN(unchanged_scene_marks_nothing);
    RUN(semantics_known_and_nulls);
    RUN(singular_inverse_is_zero);
    RUN(another_objects_matrix_left_alone);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
