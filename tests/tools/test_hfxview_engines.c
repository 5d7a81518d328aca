/* test_hfxview_engines.c: the binding's conventions for engines' and samples' names beyond the
 * stock ones (tools/hfxview/bind*.c), one small effect each, the bound values worked out by
 * hand; then hfxview end to end where the picture is the point (an instanced effect, IEX's
 * whole-transform Projection, a shadow-map depth), probed against the effect's equations.
 *
 * The scene: camera at (0, 0, 3) looking at the origin (View = a move of -3 along z), light at
 * (0, 0, 5), a 128 x 128 image, World the identity. The planes fit the scene: far 4 times the
 * eye's distance, 12; near a quarter of it, 0.75 (under half the 2 units to the sphere). */
#include "test.h"

#include <string.h>

#include "../../tools/hfxview/bind.c"
#include "../../tools/hfxview/bind_roles.c"
#include "../../tools/hfxview/bind_sas.c"
#include "../../tools/hfxview/options.c"
#include "../../tools/hfxview/vmath.c"
#include "files.h"
#include "gl_context.h"
#include "view_support.h"

static hfx_device *dev;
static hv_scene scene;

static const float camera_view[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -3, 1};

static hfx_effect *load(const char *src) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, strlen(src), "engines.fx", NULL, &errors);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    return fx;
}

static void expect(hfx_effect *fx, const char *name, const float *want, size_t n) {
    float got[16];
    hfx_param *p = hv_find_param(fx, name);
    if (!p || hfx_param_get_floats(p, got, n) != HFX_OK) {
        fprintf(stderr, "  %s: no such float parameter\n", name);
        CHECK(0);
        return;
    }
    for (size_t i = 0; i < n; i++)
        if (fabsf(got[i] - want[i]) > 1e-5f * (1 + fabsf(want[i]))) {
            fprintf(stderr, "  %s[%zu] = %g, expected %g\n", name, i, got[i], want[i]);
            CHECK(0);
            return;
        }
}

/* XNA's CreatePerspectiveFieldOfView(45 degrees, 1, 0.75, 12), written out: m[10] = f / (n - f),
 * m[14] = n f / (n - f), m[11] = -1. */
static void projection_45(float p[16]) {
    float y = 1.0f / tanf(22.5f * HV_PI / 180.0f);
    memset(p, 0, 16 * sizeof *p);
    p[0] = y, p[5] = y, p[10] = 12.0f / (0.75f - 12.0f), p[11] = -1, p[14] = 0.75f * 12.0f / (0.75f - 12.0f);
}

/* The far plane fits the scene (4 x 3 = 12), and what names the camera's planes follows it:
 * depth / CameraFar spans a visible part of 0..1 (shadow maps, G-buffers). Fog left at zero
 * starts at the far plane and ends at twice it: no fog in view. */
static void far_plane_and_fog(void) {
    hfx_effect *fx = load("float CameraNear : CAMERANEAR;\nfloat CameraFar : CAMERAFAR;\nfloat4x4 View;\nfloat4x4 Projection;\n"
                          "float FogStart;\nfloat FogEnd;\nfloat FogNear : FOG_NEAR;\nfloat FogFar : FOG_FAR;\n"
                          "float FogKept = 3;\n");
    if (!fx) return;
    float p[16];
    projection_45(p);
    hv_bind_scene(fx, &scene);
    expect(fx, "CameraNear", (const float[1]){0.75f}, 1);
    expect(fx, "CameraFar", (const float[1]){12}, 1);
    expect(fx, "Projection", p, 16);
    expect(fx, "FogStart", (const float[1]){12}, 1);
    expect(fx, "FogEnd", (const float[1]){24}, 1);
    expect(fx, "FogNear", (const float[1]){12}, 1);
    expect(fx, "FogFar", (const float[1]){24}, 1);
    expect(fx, "FogKept", (const float[1]){3}, 1);
    hfx_effect_destroy(fx);
}

/* The camera's directions follow the view (also in the per-frame binding); a billboard's
 * allowed rotation axis and other "up"s are the world's +y. */
static void camera_directions(void) {
    hfx_effect *fx = load("float4 CameraForward : VIEW_FORWARD;\nfloat3 xCamUp;\nfloat3 xAllowedRotDir;\n"
                          "float3 CameraDirection = float3(5, 5, 5);\n");
    if (!fx) return;
    hv_bind_scene(fx, &scene);
    expect(fx, "CameraForward", (const float[4]){0, 0, -1, 0}, 4);
    expect(fx, "xCamUp", (const float[3]){0, 1, 0}, 3);
    expect(fx, "xAllowedRotDir", (const float[3]){0, 1, 0}, 3);
    expect(fx, "CameraDirection", (const float[3]){0, 0, -1}, 3); /* follows the camera, like its position */
    hv_scene later = scene;
    later.eye = hv_vec3_make(3, 0, 0);
    hv_mat4_look_at_rh(later.view, later.eye, later.at, hv_vec3_make(0, 1, 0));
    hv_bind_view(fx, &later);
    expect(fx, "CameraForward", (const float[4]){-1, 0, 0, 0}, 4);
    hfx_effect_destroy(fx);
}

/* XNA-Shader-Programming's `vec` prefix (vecLightDir, vecEye); screen sizes; DigitalRise's
 * SceneNodeType (1: a static object, G-buffer depth positive); intensities named Power; a texel
 * of the 256-texel size the binding gives texture sizes. */
static void names_and_sizes(void) {
    hfx_effect *fx = load("float4 vecLightDir;\nfloat4 vecEye;\nfloat2 ScreenResolution;\nfloat2 TargetSize;\n"
                          "float2 Viewport;\nfloat4 ViewportRect;\nfloat SceneNodeType : SCENENODETYPE;\n"
                          "float LightPower;\nfloat AmbientPower;\nfloat TexelWidth;\n");
    if (!fx) return;
    hv_bind_scene(fx, &scene);
    expect(fx, "vecLightDir", (const float[4]){0, 0, -1, 0}, 4);
    expect(fx, "vecEye", (const float[4]){0, 0, 3, 1}, 4);
    expect(fx, "ScreenResolution", (const float[2]){128, 128}, 2);
    expect(fx, "TargetSize", (const float[2]){128, 128}, 2);
    expect(fx, "Viewport", (const float[2]){128, 128}, 2);
    expect(fx, "ViewportRect", (const float[4]){0, 0, 0, 0}, 4); /* four numbers: not a size */
    expect(fx, "SceneNodeType", (const float[1]){1}, 1);
    expect(fx, "LightPower", (const float[1]){1}, 1);
    expect(fx, "AmbientPower", (const float[1]){0.2f}, 1);
    expect(fx, "TexelWidth", (const float[1]){1.0f / 256}, 1);
    hfx_effect_destroy(fx);
    fx = load("float2 TargetSize;\nfloat2 SourceSize;\n"); /* DigitalRise's filters: pixels, no matrix */
    if (fx) CHECK_INT(hv_effect_wants_pixels(fx), 1);
    hfx_effect_destroy(fx);
    fx = load("float2 ScreenResolution;\n"); /* XNA's post-processing: SpriteBatch's vertex shader, clip space */
    if (fx) CHECK_INT(hv_effect_wants_pixels(fx), 0);
    hfx_effect_destroy(fx);
}

/* IEX: an effect that declares TransMatrix (the world) gets the whole transform in Projection;
 * without TransMatrix, Projection is the projection. */
static void iex_matrices(void) {
    hfx_effect *fx = load("float4x4 Projection;\nfloat4x4 TransMatrix;\nfloat4x4 matView;\nfloat4x4 matProjection;\n");
    if (!fx) return;
    float p[16], wvp[16], id[16];
    projection_45(p);
    hv_mat4_mul(wvp, camera_view, p);
    hv_mat4_identity(id);
    hv_bind_scene(fx, &scene);
    expect(fx, "Projection", wvp, 16);
    expect(fx, "TransMatrix", id, 16);
    expect(fx, "matView", camera_view, 16);
    expect(fx, "matProjection", p, 16);
    hfx_effect_destroy(fx);
}

/* IEX's ShadowProjection is the light's View * Projection (the light at (0, 0, 5): its View a
 * move of -5 along z; a 60 degree square frustum, near 5 / 4 = 1.25, far 4 x 5 = 20); MatView
 * with a capital M. */
static void iex_shadow_and_matview(void) {
    hfx_effect *fx = load("float4x4 TransMatrix;\nfloat4x4 ShadowProjection;\nfloat4x4 MatView;\n");
    if (!fx) return;
    float lv[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1}, lp[16], want[16];
    hv_mat4_perspective_fov_rh(lp, 60.0f * HV_PI / 180.0f, 1.0f, 1.25f, 20.0f);
    hv_mat4_mul(want, lv, lp);
    hv_bind_scene(fx, &scene);
    expect(fx, "ShadowProjection", want, 16);
    expect(fx, "MatView", camera_view, 16);
    hfx_effect_destroy(fx);
}

/* A projection and no matrix that carries a view (UltimaXNA's ProjectionMatrix and WorldMatrix):
 * it maps pixels, SpriteBatch's projection (2/128, -2/128, the half-pixel offset), and the
 * effect draws the image's rectangle. With a View it is the camera's projection. */
static void lone_projection_maps_pixels(void) {
    hfx_effect *fx = load("float4x4 ProjectionMatrix;\nfloat4x4 WorldMatrix;\n");
    if (!fx) return;
    hv_bind_scene(fx, &scene);
    expect(fx, "ProjectionMatrix",
           (const float[16]){2.0f / 128, 0, 0, 0, 0, -2.0f / 128, 0, 0, 0, 0, -1, 0, -1 - 1.0f / 128, 1 + 1.0f / 128, 0, 1}, 16);
    CHECK_INT(hv_effect_wants_pixels(fx), 1);
    hfx_effect_destroy(fx);
    fx = load("float4x4 ProjectionMatrix;\nfloat4x4 ViewMatrix;\n");
    if (!fx) return;
    float p[16];
    projection_45(p);
    hv_bind_scene(fx, &scene);
    expect(fx, "ProjectionMatrix", p, 16);
    CHECK_INT(hv_effect_wants_pixels(fx), 0);
    hfx_effect_destroy(fx);
    /* DigitalRise's UpsampleFilter: a target size and a projection read only to rebuild depth */
    fx = load("float2 TargetSize;\nfloat4x4 Projection : PROJECTION;\n");
    if (fx) CHECK_INT(hv_effect_wants_pixels(fx), 1);
    hfx_effect_destroy(fx);
}

/* DigitalRise's light names by their endings (PointLightDiffuse the light's colour, ...Specular
 * white, SpotlightDirection the light's, AmbientLightUp the world's up), ShadowMaskChannel the
 * first channel; a spot cone (the XNA recipes' deferred spot light); a Scale left at zero is 1;
 * loop counts left at zero get a few iterations. */
static void light_endings_cones_scales_loops(void) {
    hfx_effect *fx = load("float3 PointLightDiffuse;\nfloat3 PointLightSpecular;\nfloat3 SpotlightDirection;\n"
                          "float3 AmbientLightUp;\nfloat4 ShadowMaskChannel;\nfloat3 xConeDirection;\n"
                          "float xConeAngle;\nfloat xConeDecay;\nfloat4 Scale;\nfloat4 ScaleFactor;\n"
                          "float Offset;\nint Iterations;\nfloat3 StepSize;\n");
    if (!fx) return;
    hv_bind_scene(fx, &scene);
    expect(fx, "PointLightDiffuse", (const float[3]){1, 1, 1}, 3); /* hv_options' default light: white */
    expect(fx, "PointLightSpecular", (const float[3]){1, 1, 1}, 3);
    expect(fx, "SpotlightDirection", (const float[3]){0, 0, -1}, 3);
    expect(fx, "AmbientLightUp", (const float[3]){0, 1, 0}, 3);
    expect(fx, "ShadowMaskChannel", (const float[4]){1, 0, 0, 0}, 4);
    expect(fx, "xConeDirection", (const float[3]){0, 0, -1}, 3);
    expect(fx, "xConeAngle", (const float[1]){0.5f}, 1);
    expect(fx, "xConeDecay", (const float[1]){2}, 1);
    expect(fx, "Scale", (const float[4]){1, 1, 1, 1}, 4);
    expect(fx, "ScaleFactor", (const float[4]){1, 1, 1, 1}, 4);
    expect(fx, "Offset", (const float[1]){0}, 1); /* zero is a fine offset */
    expect(fx, "StepSize", (const float[3]){1.0f / 32, 1.0f / 32, 1.0f / 32}, 3);
    int n = 0;
    CHECK(hfx_param_get_ints(hv_find_param(fx, "Iterations"), &n, 1) == HFX_OK);
    CHECK_INT(n, 32);
    hfx_effect_destroy(fx);
}

/* The near plane fits the scene as the far plane does: a quarter of the eye's distance, at most
 * half way to the unit sphere's nearest point, at least 0.1. */
static void near_plane_fits(void) {
    hv_vec3 o = hv_vec3_make(0, 0, 0);
    CHECK(fabsf(hv_scene_near(hv_vec3_make(0, 0, 3), o) - 0.75f) < 1e-6f);  /* 3 / 4 */
    CHECK(fabsf(hv_scene_near(hv_vec3_make(0, 0, 5), o) - 1.25f) < 1e-6f);  /* 5 / 4 */
    CHECK(fabsf(hv_scene_near(hv_vec3_make(0, 0, 2), o) - 0.5f) < 1e-6f);   /* 2 / 4 = (2 - 1) / 2 */
    CHECK(fabsf(hv_scene_near(hv_vec3_make(0, 0, 1.4f), o) - 0.2f) < 1e-6f); /* (1.4 - 1) / 2 under 0.35 */
    CHECK(fabsf(hv_scene_near(hv_vec3_make(0, 0, 1.1f), o) - 0.1f) < 1e-6f); /* 0.05 raised to 0.1 */
    CHECK(fabsf(scene.znear - 0.75f) < 1e-6f);
}

/* A mirror plane's normal (DigitalRise's ReflectionNormal) is the world's up; an animation's tween
 * its end; Riemer's cloud cover his 1.1; a wave's Frequency and a Length (divisors) 1, an
 * Amplitude 0.05; half the viewport (MomoXna's gViewHalfDim : VIEWPORT_HALF_DIMENSION) 64 x 64;
 * a billboard's Width and Height 1; a Depth to clear to 1; values the effect gives are kept. */
static void normals_tweens_waves_half_sizes(void) {
    hfx_effect *fx = load("float3 ReflectionNormal;\nfloat4 PlaneNormal = float4(1, 0, 0, 0);\nfloat tween4;\n"
                          "float xOvercast;\nfloat Frequency;\nfloat ClothLength;\nfloat Amplitude;\n"
                          "float2 gViewHalfDim : VIEWPORT_HALF_DIMENSION;\nfloat2 HalfScreenSize;\n"
                          "float2 ViewportHalf = float2(3, 4);\nfloat _width;\nfloat _height;\nfloat Depth;\n");
    if (!fx) return;
    hv_bind_scene(fx, &scene);
    expect(fx, "ReflectionNormal", (const float[3]){0, 1, 0}, 3);
    expect(fx, "PlaneNormal", (const float[4]){1, 0, 0, 0}, 4);
    expect(fx, "tween4", (const float[1]){1}, 1);
    expect(fx, "xOvercast", (const float[1]){1.1f}, 1);
    expect(fx, "Frequency", (const float[1]){1}, 1);
    expect(fx, "ClothLength", (const float[1]){1}, 1);
    expect(fx, "Amplitude", (const float[1]){0.05f}, 1);
    expect(fx, "gViewHalfDim", (const float[2]){64, 64}, 2);
    expect(fx, "HalfScreenSize", (const float[2]){64, 64}, 2);
    expect(fx, "ViewportHalf", (const float[2]){64, 64}, 2); /* follows the viewport like ViewportSize */
    expect(fx, "_width", (const float[1]){1}, 1); /* DigitalRise's billboard size */
    expect(fx, "_height", (const float[1]){1}, 1);
    expect(fx, "Depth", (const float[1]){1}, 1); /* ClearGBuffer's: the far plane, as Clear's 1 */
    CHECK(hv_effect_wants_pixels(fx)); /* a half viewport and no matrix: the effect maps pixels */
    hfx_effect_destroy(fx);
}

/* ---- hfxview end to end -------------------------------------------------------------------- */

static char *hfxview, *tmp;

static int run_view(const char *fx_text, view_png *img) {
    return view_run_effect(hfxview, tmp, fx_text, "--camera eye=0,0,3,at=0,0,0", img, NULL);
}

#define RED_PS "float4 PS() : COLOR0 { return float4(1, 0, 0, 1); }\n"
#define TECH "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"

/* The sphere (radius 1) seen from 3 units: red at the centre, the background in a corner. */
static void expect_sphere(const char *fx) {
    view_png img;
    if (!run_view(fx, &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 64, 64, 255, 0, 0, 0));
    CHECK(view_pixel_near(&img, 1, 1, 100, 149, 237, 0));
    view_png_free(&img);
}

/* XNA's instancing sample reads the instance's world from BLENDWEIGHT0..3 (transposed);
 * DigitalRise reads three world columns and a colour from BLENDWEIGHT0..3. The viewer gives
 * the rows of the identity: one instance where the mesh is. */
static void instancing_inputs(void) {
    expect_sphere("float4x4 World, View, Projection;\n"
                  "float4 VS(float4 p : POSITION0, float4x4 inst : BLENDWEIGHT) : POSITION0 {\n"
                  "    return mul(mul(mul(mul(p, transpose(inst)), World), View), Projection); }\n" RED_PS TECH);
    expect_sphere("float4x4 View, Projection;\n"
                  "float4 VS(float4 p : POSITION0, float4 c0 : BLENDWEIGHT0, float4 c1 : BLENDWEIGHT1,\n"
                  "          float4 c2 : BLENDWEIGHT2, float4 colorAndAlpha : BLENDWEIGHT3) : POSITION0 {\n"
                  "    float4x4 w = transpose(float4x4(c0, c1, c2, float4(0, 0, 0, 1)));\n"
                  "    return mul(mul(mul(p, w), View), Projection) * colorAndAlpha.a; }\n" RED_PS TECH);
}

/* IEX's effects multiply by Projection alone: the whole transform, so the sphere is in view. */
static void iex_effect_shows_its_mesh(void) {
    expect_sphere("float4x4 Projection;\nfloat4x4 TransMatrix;\n"
                  "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, Projection); }\n" RED_PS TECH);
}

/* UltimaXNA's isometric world: mul(mul(p, WorldMatrix), ProjectionMatrix), nothing else: the
 * image's rectangle in pixels, red to every corner. */
static void lone_projection_fills_the_image(void) {
    view_png img;
    if (!run_view("float4x4 ProjectionMatrix;\nfloat4x4 WorldMatrix;\n"
                  "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(mul(p, WorldMatrix), ProjectionMatrix); }\n"
                  RED_PS TECH, &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 0, 0, 255, 0, 0, 0));
    CHECK(view_pixel_near(&img, 127, 127, 255, 0, 0, 0));
    view_png_free(&img);
}

/* DigitalRise's shadow map: (-z_view - CameraNear) / (CameraFar - CameraNear) in red. At the
 * centre the sphere's front is 2 units from the eye: (2 - 0.75) / (12 - 0.75) = 0.11111, 28.3 of
 * 255 (it was 4.8, black, with a far plane of 100 and a near plane of 0.1). */
static void shadow_map_depth_is_visible(void) {
    static const char fx[] =
        "float4x4 World : WORLD;\nfloat4x4 View : VIEW;\nfloat4x4 Projection : PROJECTION;\n"
        "float CameraNear : CAMERANEAR;\nfloat CameraFar : CAMERAFAR;\n"
        "struct V { float4 p : POSITION0; float d : TEXCOORD0; };\n"
        "V VS(float4 p : POSITION0) { V o; float4 v = mul(mul(p, World), View); o.p = mul(v, Projection);\n"
        "    o.d = (-v.z - CameraNear) / (CameraFar - CameraNear); return o; }\n"
        "float4 PS(float d : TEXCOORD0) : COLOR0 { return float4(d, 0, 0, 1); }\n" TECH;
    view_png img;
    if (!run_view(fx, &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 64, 64, 28, 0, 0, 1));
    view_png_free(&img);
}

/* XNA-Shader-Programming's depth map writes 1 - z/w. At the centre the sphere's front is 2 units
 * from the eye; with near 0.75 and far 12, z/w = f / (f - n) (1 - n / d) = (12 / 11.25) (1 -
 * 0.375) = 0.66667, so red 1 - z/w = 0.33333, 85 of 255 (with a near plane of 0.1 it was 0.053,
 * 13.5, and 9.9 at the fitted far plane's edge of the mesh: black). */
static void depth_map_one_minus_z_over_w(void) {
    static const char fx[] =
        "float4x4 matWorldViewProj;\n"
        "struct V { float4 p : POSITION0; float d : TEXCOORD0; };\n"
        "V VS(float4 p : POSITION0) { V o; o.p = mul(p, matWorldViewProj); o.d = 1 - o.p.z / o.p.w; return o; }\n"
        "float4 PS(float d : TEXCOORD0) : COLOR0 { return float4(d, 0, 0, 1); }\n" TECH;
    view_png img;
    if (!run_view(fx, &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 64, 64, 85, 0, 0, 1));
    view_png_free(&img);
}

/* DigitalRise's log-space blur reads the first 3 of 23 weights and combines samples as
 * log(sum w_i e^s_i): with every sample s = 1, 1 + log(w0 + w1 + w2). The Gaussian kernel in
 * XNA's bloom order gives w0 + w1 + w2 = (1 + 2 e^-0.5) / (1 + 2 (e^-0.5 + e^-2 + e^-4.5 + e^-8 +
 * e^-12.5 + ...)) = 2.21306 / 2.50663 = 0.88288, log = -0.12453: red 0.87547, 223 of 255 (equal
 * weights gave 1 + log(3 / 23) = -1.04: black). */
static void log_blur_weights(void) {
    static const char fx[] =
        "float4x4 WorldViewProjection;\nfloat Weights[23];\n"
        "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, WorldViewProjection); }\n"
        "float4 PS() : COLOR0 { return float4(1 + log(Weights[0] + Weights[1] + Weights[2]), 0, 0, 1); }\n" TECH;
    view_png img;
    if (!run_view(fx, &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 64, 64, 223, 0, 0, 1));
    view_png_free(&img);
}

/* MomoXna's text maps pixels with half the viewport as its vertex shader does (Direct3D 9's half
 * pixel moved back, y flipped about the middle, divided by the half size). The image's
 * rectangle in pixels lands on the whole image: red in every corner. */
static void half_viewport_maps_pixels(void) {
    view_png img;
    if (!run_view("float2 gViewHalfDim : VIEWPORT_HALF_DIMENSION;\n"
                  "float4 VS(float4 p : POSITION0) : POSITION0 {\n"
                  "    float2 q = p.xy - float2(0.5 + gViewHalfDim.x, 0.5); q.y = gViewHalfDim.y - q.y;\n"
                  "    return float4(q / gViewHalfDim, 0, 1); }\n"
                  RED_PS "technique T { pass P { CullMode = None; VertexShader = compile vs_2_0 VS();\n"
                  "    PixelShader = compile ps_2_0 PS(); } }\n", &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 0, 0, 255, 0, 0, 0));
    CHECK(view_pixel_near(&img, 127, 127, 255, 0, 0, 0));
    CHECK(view_pixel_near(&img, 0, 127, 255, 0, 0, 0));
    view_png_free(&img);
}

int main(void) {
    test_gl *gl = test_gl_create(4, 4);
    if (!gl) test_skip("no OSMesa context");
    dev = hfx_device_create_gl(test_gl_loader);
    hv_options o;
    hv_options_defaults(&o);
    o.eye = hv_vec3_make(0, 0, 3);
    o.light_position = hv_vec3_make(0, 0, 5);
    o.width = o.height = 128;
    hv_scene_from_options(&scene, &o);
    RUN(far_plane_and_fog);
    RUN(camera_directions);
    RUN(names_and_sizes);
    RUN(iex_matrices);
    RUN(iex_shadow_and_matview);
    RUN(lone_projection_maps_pixels);
    RUN(light_endings_cones_scales_loops);
    RUN(near_plane_fits);
    RUN(normals_tweens_waves_half_sizes);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    hfxview = view_build_path("tools/hfxview/hfxview");
    if (hfxview) {
        tmp = test_temp_dir();
        RUN(instancing_inputs);
        RUN(iex_effect_shows_its_mesh);
        RUN(shadow_map_depth_is_visible);
        RUN(lone_projection_fills_the_image);
        RUN(depth_map_one_minus_z_over_w);
        RUN(log_blur_weights);
        RUN(half_viewport_maps_pixels);
        test_remove_dir(tmp);
        free(tmp);
        free(hfxview);
    }
    return test_summary();
}
