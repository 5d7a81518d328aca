/* test_hfxview_conventions.c: the binding hfxview and the web page share (tools/hfxview/bind*.c),
 * one small effect per convention, the values it binds checked exactly against values worked
 * out by hand from a scene chosen to make them short; then hfxview end to end on effects that
 * drew nothing before (a sprite effect, a skinned one, DirectX SDK light names), probed.
 *
 * The scene: camera at (0, 0, 3) looking at the origin (View = a move of -3 along z), light at
 * (0, 0, 5) shining at the origin (direction (0, 0, -1), its View a move of -5 along z), light
 * colour (0.5, 0.75, 1), a 128 x 128 image, World the identity. */
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

static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static const float camera_view[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -3, 1};
static const float light_view[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1};

static hfx_effect *load(const char *src) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, strlen(src), "conventions.fx", NULL, &errors);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    return fx;
}

/* Parameter name of fx holds want[0..n) (within 1e-6: products of short numbers). */
static void expect(hfx_effect *fx, const char *name, const float *want, size_t n) {
    float got[64];
    hfx_param *p = hv_find_param(fx, name);
    CHECK(p != NULL);
    if (!p || hfx_param_get_floats(p, got, n) != HFX_OK) {
        fprintf(stderr, "  %s: no such float parameter\n", name);
        CHECK(0);
        return;
    }
    for (size_t i = 0; i < n; i++)
        if (fabsf(got[i] - want[i]) > 1e-6f) {
            fprintf(stderr, "  %s[%zu] = %g, expected %g\n", name, i, got[i], want[i]);
            CHECK(0);
            return;
        }
}

/* How the report says parameter name was bound. */
static void expect_how(hfx_effect *fx, const char **how, const char *name, const char *want) {
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++)
        if (!strcmp(hfx_param_name(hfx_effect_param_at(fx, i)), name)) {
            if (!want) CHECK(how[i] == NULL);
            else CHECK_STR(how[i] ? how[i] : "(null)", want);
            return;
        }
    CHECK(0);
}

static const float white[4] = {1, 1, 1, 1}, grey[4] = {0.2f, 0.2f, 0.2f, 1}, light_rgb[4] = {0.5f, 0.75f, 1, 1};
static const float light_dir[4] = {0, 0, -1, 0}, light_pos[4] = {0, 0, 5, 1};

/* FX Composer / DXSAS: Object names the light (its View; its position, here in view space:
 * (0,0,5) moved by -3 along z), SasBindAddress, UIWidget, UIMin. */
static void sas_annotations(void) {
    hfx_effect *fx = load(
        "float4x4 gSlicerXf : View < string Object = \"SpotLight0\"; >;\n"
        "float4x4 gCamXf : View < string Object = \"Camera\"; >;\n"
        "float3 gLampPos : Position < string Object = \"PointLight0\"; string Space = \"View\"; >;\n"
        "float3 gLampColor : Diffuse < string Object = \"PointLight0\"; >;\n"
        "float3 gLampDir : Direction < string Object = \"DirectionalLight0\"; >;\n"
        "float4x4 gBones[2] < string SasBindAddress = \"Sas.Skeleton.MeshToJointToWorld[*]\"; >;\n"
        "float4x4 gView < string SasBindAddress = \"Sas.Camera.WorldToView\"; >;\n"
        "float gNow < string SasBindAddress = \"Sas.Time.Now\"; >;\n"
        "float3 gSurface < string UIWidget = \"Color\"; >;\n"
        "float gBump < float UIMin = 0.5; float UIMax = 2; >;\n"
        "float gKept < string UIWidget = \"Color\"; > = 0.25;\n");
    if (!fx) return;
    const char *how[16] = {0};
    CHECK_INT(hv_bind_scene_report(fx, &scene, how, 16), 10); /* all but gKept, which keeps its 0.25 */
    expect(fx, "gSlicerXf", light_view, 16);
    expect(fx, "gCamXf", camera_view, 16);
    expect(fx, "gLampPos", (const float[3]){0, 0, 2}, 3);
    expect(fx, "gLampColor", light_rgb, 3);
    expect(fx, "gLampDir", light_dir, 3);
    expect(fx, "gBones[0]", identity, 16);
    expect(fx, "gBones[1]", identity, 16);
    expect(fx, "gView", camera_view, 16);
    expect(fx, "gNow", (const float[1]){1}, 1);
    expect(fx, "gSurface", white, 3);
    expect(fx, "gBump", (const float[1]){0.5f}, 1);
    expect(fx, "gKept", (const float[1]){0.25f}, 1);
    expect_how(fx, how, "gSlicerXf", "annotation Object: the light's matrix");
    expect_how(fx, how, "gBones", "SasBindAddress: identity bones");
    expect_how(fx, how, "gSurface", "annotation UIWidget Color: white");
    hfx_effect_destroy(fx);
}

/* XNA's stock effects (BasicEffect, EnvironmentMapEffect, SpriteEffect), XNA's samples. */
static void xna_names(void) {
    hfx_effect *fx = load(
        "float4 DiffuseColor;\n"
        "float3 DirLight0Direction;\n"
        "float3 DirLight0DiffuseColor;\n"
        "float3 DirLight0SpecularColor;\n"
        "float3 DirLight1DiffuseColor;\n"
        "float EnvironmentMapAmount;\n"
        "float4x4 MatrixTransform;\n"
        "float4 ambientLightColor;\n"
        "float4 diffuseLightColor;\n"
        "float4 specularLightColor;\n"
        "float3 EmissiveColor;\n");
    if (!fx) return;
    const char *how[16] = {0};
    hv_bind_scene_report(fx, &scene, how, 16);
    expect(fx, "DiffuseColor", white, 4);
    expect(fx, "DirLight0Direction", light_dir, 3);
    expect(fx, "DirLight0DiffuseColor", light_rgb, 3);
    expect(fx, "DirLight0SpecularColor", white, 3);
    expect(fx, "DirLight1DiffuseColor", light_rgb, 3);
    expect(fx, "EnvironmentMapAmount", (const float[1]){1}, 1);
    /* SpriteBatch's CreateOrthographicOffCenter(0, 128, 128, 0, 0, 1): 2/128, -2/128, -1; the
     * translation (-1, 1, 0) moved half a pixel (1/128 in clip space) left and up, as on D3D9 */
    expect(fx, "MatrixTransform",
           (const float[16]){2.0f / 128, 0, 0, 0, 0, -2.0f / 128, 0, 0, 0, 0, -1, 0, -1 - 1.0f / 128, 1 + 1.0f / 128, 0, 1}, 16);
    expect(fx, "ambientLightColor", grey, 4);
    expect(fx, "diffuseLightColor", light_rgb, 4);
    expect(fx, "specularLightColor", white, 4);
    expect(fx, "EmissiveColor", (const float[3]){0, 0, 0}, 3); /* zero is right for emission */
    expect_how(fx, how, "EmissiveColor", NULL);
    expect_how(fx, how, "MatrixTransform", "name: SpriteBatch's pixel projection");
    CHECK_INT(hv_effect_wants_pixels(fx), 1);
    hfx_effect_destroy(fx);
}

/* The DirectX SDK's prefixes on every kind (g_, Hungarian f / v / m, mat for materials), and
 * engines' names, any letter case. */
static void directx_sdk_and_engine_names(void) {
    hfx_effect *fx = load(
        "float3 g_LightDir;\n"
        "float4 g_LightDiffuse;\n"
        "float4 g_MaterialDiffuseColor;\n"
        "float4 g_matDiffuse;\n"
        "float4 g_matAmbient;\n"
        "float g_fTime;\n"
        "float3 g_vLightPos;\n"
        "float4x4 mWorldViewProj;\n"
        "float4x4 g_mLightViewProj;\n"
        "float3 LIGHTDIRECTION;\n"
        "float4 Color;\n"
        "float lightIntensity;\n"
        "float invLightRadius;\n"
        "float CurrentTime;\n"
        "float4x4 TextureTransform;\n");
    if (!fx) return;
    const char *how[16] = {0};
    hv_bind_scene_report(fx, &scene, how, 16);
    expect(fx, "g_LightDir", light_dir, 3);
    expect(fx, "g_LightDiffuse", light_rgb, 4);
    expect(fx, "g_MaterialDiffuseColor", white, 4);
    expect(fx, "g_matDiffuse", white, 4);
    expect(fx, "g_matAmbient", grey, 4);
    expect(fx, "g_fTime", (const float[1]){1}, 1); /* headless: the fixed HV_HEADLESS_TIME_SECONDS */
    expect(fx, "g_vLightPos", light_pos, 3);
    expect(fx, "LIGHTDIRECTION", light_dir, 3);
    expect(fx, "Color", white, 4);
    expect(fx, "lightIntensity", (const float[1]){1}, 1);
    expect(fx, "invLightRadius", (const float[1]){0.2f}, 1);
    expect(fx, "CurrentTime", (const float[1]){1}, 1);
    expect(fx, "TextureTransform", identity, 16);
    expect_how(fx, how, "TextureTransform", "identity (no convention names it)");
    /* WorldViewProj with World = I: View * Projection; the light's: its View * a 60 degree square frustum */
    float proj[16], want[16];
    hv_mat4_mul(want, camera_view, scene.projection);
    expect(fx, "mWorldViewProj", want, 16);
    hv_mat4_perspective_fov_rh(proj, 60.0f * HV_PI / 180.0f, 1.0f, 1.25f, 20.0f); /* near, far: 1/4, 4 x the light's distance */
    hv_mat4_mul(want, light_view, proj);
    expect(fx, "g_mLightViewProj", want, 16);
    expect_how(fx, how, "g_mLightViewProj", "name: the light's matrix");
    hfx_effect_destroy(fx);
}

/* Bone palettes get the identity (a float4x3 one its upper-left block); post-processing weights
 * are a Gaussian kernel summing to 1; intensities, particle sizes and durations get values only where the effect gave none. */
static void palettes_weights_and_defaults(void) {
    hfx_effect *fx = load(
        "float4x3 Bones[3];\n"
        "float SampleWeights[15];\n"
        "float BloomIntensity;\n"
        "float BaseIntensity = 0.75;\n"
        "float StartSize;\n"
        "float Duration;\n"
        "float EndSize = 3;\n"
        "float4 Mystery;\n"
        "float Known = 2;\n");
    if (!fx) return;
    const char *how[16] = {0};
    hv_bind_scene_report(fx, &scene, how, 16);
    expect(fx, "Bones[2]", (const float[12]){1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, 12);
    /* A Gaussian of one sample's deviation in XNA's bloom order (the centre, then a pair at each
     * distance), over 15 entries: e^(-d^2 / 2) / S, S = 1 + 2 (e^-0.5 + e^-2 + ... + e^-24.5) =
     * 2.5066283 (sqrt(2 pi) to 7 digits), so the centre is 0.3989423, the first pair 0.2419707,
     * the second 0.0539910, the third 0.0044318: the standard normal density. */
    float w[15], sum = 0;
    for (int i = 0; i < 15; i++) w[i] = expf(-0.5f * (float)((i + 1) / 2) * (float)((i + 1) / 2));
    for (int i = 0; i < 15; i++) sum += w[i];
    for (int i = 0; i < 15; i++) w[i] /= sum;
    CHECK(fabsf(w[0] - 0.3989423f) < 1e-6f && fabsf(w[2] - 0.2419707f) < 1e-6f);
    CHECK(fabsf(w[4] - 0.0539910f) < 1e-6f && fabsf(w[6] - 0.0044318f) < 1e-6f);
    expect(fx, "SampleWeights", w, 15);
    expect(fx, "BloomIntensity", (const float[1]){1}, 1);
    expect(fx, "BaseIntensity", (const float[1]){0.75f}, 1);
    expect(fx, "StartSize", (const float[1]){0.5f}, 1);
    expect(fx, "Duration", (const float[1]){2}, 1);
    expect(fx, "EndSize", (const float[1]){3}, 1);
    expect_how(fx, how, "Mystery", NULL);
    char list[256];
    CHECK_INT(hv_unbound_list(fx, how, list, sizeof list), 2);
    CHECK_STR(list, "Mystery = 0, Known");
    hfx_effect_destroy(fx);
}

/* Names the table lacks, by their ending: a light's colour, a colour (white; fog and emission
 * stay black), a density, a texture's size, the far plane. A viewport size and no matrix: the
 * effect draws in pixels (DigitalRise's post-processing). */
static void endings_and_pixel_effects(void) {
    hfx_effect *fx = load("float3 SunLight;\nfloat4 InstanceColor;\nfloat4 FogColor;\nfloat Density;\n"
                          "float2 ReflectionTextureSize;\nfloat CameraFar;\nfloat2 ViewportSize : VIEWPORTSIZE;\n");
    if (!fx) return;
    hv_bind_scene(fx, &scene);
    expect(fx, "SunLight", light_rgb, 3);
    expect(fx, "InstanceColor", white, 4);
    expect(fx, "FogColor", (const float[4]){0, 0, 0, 0}, 4);
    expect(fx, "Density", (const float[1]){1}, 1);
    expect(fx, "ReflectionTextureSize", (const float[2]){256, 256}, 2);
    expect(fx, "CameraFar", (const float[1]){12}, 1); /* the scene's far plane: 4 x the eye's distance */
    expect(fx, "ViewportSize", (const float[2]){128, 128}, 2);
    CHECK_INT(hv_effect_wants_pixels(fx), 1);
    hfx_effect_destroy(fx);
    fx = load("float2 ViewportSize;\nfloat4x4 World;\n");
    if (fx) CHECK_INT(hv_effect_wants_pixels(fx), 0); /* a matrix: it places its mesh in the scene */
    hfx_effect_destroy(fx);
}

/* The view-only binding (each frame) moves the clock and the camera, and leaves lights alone. */
static void view_binding_follows_the_clock(void) {
    hfx_effect *fx = load("float Time;\nfloat3 LightDir;\nfloat3 EyePosition;\n");
    if (!fx) return;
    hv_scene later = scene;
    later.time = 7.5f;
    later.eye = hv_vec3_make(1, 2, 3);
    hv_bind_view(fx, &later);
    expect(fx, "Time", (const float[1]){7.5f}, 1);
    expect(fx, "EyePosition", (const float[3]){1, 2, 3}, 3);
    expect(fx, "LightDir", (const float[3]){0, 0, 0}, 3);
    hfx_effect_destroy(fx);
}

/* ---- hfxview end to end -------------------------------------------------------------------- */

static char *hfxview, *tmp;

static int run_view(const char *fx_text, const char *args, view_png *img, char **out) {
    return view_run_effect(hfxview, tmp, fx_text, args, img, out);
}

#define RED_PS "float4 PS() : COLOR0 { return float4(1, 0, 0, 1); }\n"
#define TECH "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"

/* A SpriteEffect-like effect: MatrixTransform is SpriteBatch's pixel projection and the mesh the
 * image's rectangle in pixels, so every pixel is the sprite's (red), corners included. */
static void sprite_effect_fills_the_image(void) {
    view_png img;
    char *out = NULL;
    if (run_view("float4x4 MatrixTransform;\n"
                 "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, MatrixTransform); }\n" RED_PS TECH,
                 "", &img, &out)) {
        CHECK(view_pixel_near(&img, 64, 64, 255, 0, 0, 0));
        CHECK(view_pixel_near(&img, 0, 0, 255, 0, 0, 0));
        CHECK(view_pixel_near(&img, 127, 127, 255, 0, 0, 0));
        view_png_free(&img);
    } else {
        CHECK(0);
    }
    free(out);
}

/* Skinning through Bones[] (identity) then WorldViewProj: the sphere, red at the centre; the
 * background in the corner. */
static void skinned_effect_shows_its_mesh(void) {
    view_png img;
    char *out = NULL;
    if (run_view("float4x4 Bones[4];\nfloat4x4 WorldViewProj;\n"
                 "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(mul(p, Bones[0]), WorldViewProj); }\n" RED_PS TECH,
                 "", &img, &out)) {
        CHECK(view_pixel_near(&img, 64, 64, 255, 0, 0, 0));
        CHECK(view_pixel_near(&img, 1, 1, 100, 149, 237, 0));
        view_png_free(&img);
    } else {
        CHECK(0);
    }
    free(out);
}

/* DirectX SDK and XNA sample names, camera in front and the light behind it: at the centre
 * N = (0,0,1) and the light travels along -z, so N.L = 1: g_LightDiffuse (white, the default
 * light) * 0.5 * 1 + ambientLightColor 0.2 = 0.7 -> 178.5. An unknown parameter is printed as
 * not bound; --list says how each one was. */
static void directx_names_light_the_sphere(void) {
    static const char fx[] =
        "float4x4 g_mWorldViewProjection;\nfloat3 g_LightDir;\nfloat4 g_LightDiffuse;\nfloat4 ambientLightColor;\n"
        "float4 Mystery;\n"
        "struct V { float4 p : POSITION0; float3 n : TEXCOORD0; };\n"
        "V VS(float4 p : POSITION0, float3 n : NORMAL0) { V o; o.p = mul(p, g_mWorldViewProjection); o.n = n; return o; }\n"
        "float4 PS(float3 n : TEXCOORD0) : COLOR0 {\n"
        "    float d = saturate(dot(normalize(n), -g_LightDir));\n"
        "    return float4(g_LightDiffuse.rgb * 0.5 * d + ambientLightColor.rgb + Mystery.rgb, 1);\n"
        "}\n" TECH;
    view_png img;
    char *out = NULL;
    if (run_view(fx, "--camera eye=0,0,3,at=0,0,0 --light position=0,0,5", &img, &out)) {
        CHECK(view_pixel_near(&img, 64, 64, 179, 179, 179, 1));
        view_png_free(&img);
    } else {
        CHECK(0);
    }
    CHECK_CONTAINS(out, "hfxview: 1 parameter not bound, left at the effect's values: Mystery = 0\n");
    free(out);
    out = NULL;
    char *cmd = view_format("%s %s/view.fx --list", hfxview, tmp); /* the file run_view wrote */
    CHECK_INT(view_run(cmd, &out), 0);
    CHECK_CONTAINS(out, "parameter g_LightDir  (name: light direction)\n");
    CHECK_CONTAINS(out, "parameter Mystery  (not bound: the effect's value)\n");
    free(cmd);
    free(out);
}

/* --technique all: each technique into OUT.N.png, named on stdout (the corpus survey's mode). */
static void every_technique(void) {
    static const char fx[] =
        "float4x4 MatrixTransform;\n"
        "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, MatrixTransform); }\n"
        "float4 Red() : COLOR0 { return float4(1, 0, 0, 1); }\n"
        "float4 Green() : COLOR0 { return float4(0, 1, 0, 1); }\n"
        "technique A { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Red(); } }\n"
        "technique B { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Green(); } }\n";
    char *path = view_format("%s/two.fx", tmp), *out = NULL;
    FILE *f = fopen(path, "w");
    if (f) fputs(fx, f), fclose(f);
    char *cmd = view_format("%s %s --technique all -o %s/two.png --size 16x16", hfxview, path, tmp);
    CHECK_INT(view_run(cmd, &out), 0);
    CHECK_CONTAINS(out, "technique 0 A\ntechnique 1 B\n");
    view_png img;
    char *png = view_format("%s/two.1.png", tmp);
    if (view_png_read(&img, png) == 0) {
        CHECK(view_pixel_near(&img, 8, 8, 0, 255, 0, 0));
        view_png_free(&img);
    } else {
        CHECK(0);
    }
    free(png), free(cmd), free(out), free(path);
}

/* --technique all --pass each: every pass alone into OUT.T.P.png, "pass T P NAME" on stdout
 * (scripts/fx2_oracle.sh's mode): pass 1 of A is blue alone, not pass 0's red under it. */
static void every_pass(void) {
    static const char fx[] =
        "float4x4 MatrixTransform;\n"
        "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, MatrixTransform); }\n"
        "float4 Red() : COLOR0 { return float4(1, 0, 0, 1); }\n"
        "float4 Blue() : COLOR0 { return float4(0, 0, 1, 0.5); }\n"
        "technique A { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Red(); }\n"
        "  pass Q { AlphaBlendEnable = true; SrcBlend = SrcAlpha; DestBlend = InvSrcAlpha;\n"
        "           VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Blue(); } }\n"
        "technique B { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Red(); } }\n";
    char *path = view_format("%s/passes.fx", tmp), *out = NULL;
    FILE *f = fopen(path, "w");
    if (f) fputs(fx, f), fclose(f);
    char *cmd = view_format("%s %s --technique all --pass each -o %s/passes.png --size 16x16 --background 0,1,0",
                            hfxview, path, tmp);
    CHECK_INT(view_run(cmd, &out), 0);
    CHECK_CONTAINS(out, "technique 0 A\npass 0 0 P\npass 0 1 Q\ntechnique 1 B\npass 1 0 P\n");
    static const struct { const char *file; int r, g, b; } want[] = {
        {"passes.0.0.png", 255, 0, 0}, /* red alone */
        {"passes.0.1.png", 0, 128, 128}, /* blue at alpha 0.5 over the green clear: (0, 0.5, 0.5) */
        {"passes.1.0.png", 255, 0, 0},
    };
    for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
        view_png img;
        char *png = view_format("%s/%s", tmp, want[i].file);
        if (view_png_read(&img, png) == 0) {
            CHECK(view_pixel_near(&img, 8, 8, want[i].r, want[i].g, want[i].b, 1));
            view_png_free(&img);
        } else {
            CHECK(0);
        }
        free(png);
    }
    free(cmd), free(out), free(path);
}

int main(void) {
    test_gl *gl = test_gl_create(4, 4);
    if (!gl) test_skip("no OSMesa context");
    dev = hfx_device_create_gl(test_gl_loader);
    hv_options o;
    hv_options_defaults(&o);
    o.eye = hv_vec3_make(0, 0, 3);
    o.light_position = hv_vec3_make(0, 0, 5);
    o.light_color[0] = 0.5f, o.light_color[1] = 0.75f, o.light_color[2] = 1;
    o.width = o.height = 128;
    hv_scene_from_options(&scene, &o);
    RUN(sas_annotations);
    RUN(xna_names);
    RUN(directx_sdk_and_engine_names);
    RUN(palettes_weights_and_defaults);
    RUN(view_binding_follows_the_clock);
    RUN(endings_and_pixel_effects);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    hfxview = view_build_path("tools/hfxview/hfxview");
    if (hfxview) {
        tmp = test_temp_dir();
        RUN(sprite_effect_fills_the_image);
        RUN(skinned_effect_shows_its_mesh);
        RUN(directx_names_light_the_sphere);
        RUN(every_technique);
        RUN(every_pass);
        test_remove_dir(tmp);
        free(tmp);
        free(hfxview);
    }
    return test_summary();
}
