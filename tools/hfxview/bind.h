/* bind.h: filling an effect's parameters without code, the one binding hfxview and the web
 * page share. In order: the standard SAS semantics through the runtime's hfx_effect_bind_scene;
 * FX Composer / DXSAS annotations (Object = "SpotLight0" gives the light's matrices and
 * vectors, Space, SasBindAddress, UIWidget = "Color", UIMin); then names, case-insensitively,
 * after the DirectX SDK's and engines' decorations are stripped (g_, m_, Hungarian f/v/c, mat,
 * x, fx): matrices (World, matWorldViewProj, WorldITXf, MatrixTransform: SpriteBatch's pixel
 * projection), XNA's stock effects' and samples' lights and materials (DirLight0DiffuseColor,
 * diffuseLightColor, EnvironmentMapAmount), the DirectX SDK's (g_LightDir, g_MaterialDiffuseColor,
 * g_matDiffuse), engines' (Color, lightIntensity, invLightRadius), the seed tutorials' Spanish
 * ones, a clock for time (g_fTime, CurrentTime), post-processing weights and intensities,
 * particle sizes and durations; identity for matrix arrays (bone palettes). Lights, materials
 * and weights are only given values when the effect left them at zero (no initializer), so an
 * effect's own defaults win, unless --light names the light; the camera position and the clock
 * always follow the scene. tools/hfxview/README.md lists every convention. */
#ifndef HFXVIEW_BIND_H
#define HFXVIEW_BIND_H

#include <stddef.h>

#include "hfx/hfx.h"
#include "options.h"
#include "vmath.h"

typedef struct hv_scene {
    float world[16], view[16], projection[16];
    float znear, zfar;                       /* the projection's planes (hv_scene_far) */
    hv_vec3 eye, at;
    hv_vec3 light_position, light_direction; /* direction: where the light travels */
    float light_color[3];
    int light_given;                         /* --light: override the effect's own light values */
    int width, height;
    float time, elapsed_time;                /* seconds: a running clock in a window, fixed headless */
} hv_scene;

enum { HV_HEADLESS_TIME_SECONDS = 1 };       /* time parameters in pictures: reproducible */

/* The far plane fits the scene, as a model viewer fits its clipping planes to what it shows:
 * 4 times the eye's distance from what it looks at (the unit-sphere mesh seen from 3 units
 * sits in the first third of the range), so depth an effect writes normalised by the far plane
 * (shadow maps, G-buffers: depth / CameraFar) spans a visible part of 0..1. */
float hv_scene_far(hv_vec3 eye, hv_vec3 at);
/* The near plane fits the scene too: a quarter of the eye's distance (0.75 for the default
 * camera; far / near 16), at most half way to the nearest point of the unit sphere the meshes
 * fit in, at least 0.1. Depth maps written as z / w or 1 - z / w (XNA-Shader-Programming's
 * `1 - z/w`) then spread over a visible range: with a near plane of 0.1 the whole mesh sat in
 * the last 5% of it and came out black. */
float hv_scene_near(hv_vec3 eye, hv_vec3 at);

void hv_scene_from_options(hv_scene *s, const hv_options *o);

/* Which matrix a name or semantic asks for ("WorldViewProj", "ViewInverse", "matWorldIT",
 * "WorldITXf"...): 1 with out filled, or 0 when it names none. */
int hv_scene_matrix(const hv_scene *s, const char *name, int is_semantic, float out[16]);

/* Sets every matrix, camera, light and material parameter it recognises; the count recognised. */
int hv_bind_scene(hfx_effect *fx, const hv_scene *s);
/* The same, saying how: how[i] for hfx_effect_param_at(fx, i) (i < count) is a phrase such as
 * "semantic WorldViewProjection" or "name: light direction", or NULL when nothing recognised
 * the parameter (it keeps the effect's value). */
int hv_bind_scene_report(hfx_effect *fx, const hv_scene *s, const char **how, size_t count);
/* The numeric parameters no convention recognised, as ", "-separated "Name" or "Name = 0" (still
 * zero: the likely reason for a black picture) into out; how many. */
size_t hv_unbound_list(hfx_effect *fx, const char *const *how, char *out, size_t cap);
/* 1 when the effect draws in pixels: SpriteBatch's MatrixTransform (SpriteEffect and its kin),
 * or a viewport size and no matrix (DigitalRise's post-processing maps pixels itself): a
 * viewer then draws the image's rectangle rather than a sphere. */
int hv_effect_wants_pixels(hfx_effect *fx);
/* Only what follows the camera and the viewport (semantics, matrices, the camera position), as
 * a viewer does every frame: lights and materials keep what the user set, zeros included. */
int hv_bind_view(hfx_effect *fx, const hv_scene *s);

/* --set NAME=VALUES: NAME may be "a", "a[2]", "a[1].Member"; VALUES are comma-separated
 * numbers, or true / false. 0, or -1 with a message. */
int hv_set_param(hfx_effect *fx, const char *name, const char *values, char *err, size_t errlen);

/* The parameter a path like "lights[1].Color" names, or NULL. */
hfx_param *hv_find_param(hfx_effect *fx, const char *path);

#endif
