/* bind.h: filling an effect's parameters without code, the way FX Composer does: the standard
 * SAS semantics through the runtime's hfx_effect_bind_scene, then matrices by name or other
 * spellings (World, matWorldViewProj, WorldITXf...), the camera position, and light and material
 * parameters the seed tutorials use (LightDirection, direccionLuz, posicionLuz, LightPosition[],
 * structs of lights...). Lights and materials are only given values when the effect left them
 * at zero (no initializer), so an effect's own defaults win, unless --light names the light;
 * the camera position always follows the camera. */
#ifndef HFXVIEW_BIND_H
#define HFXVIEW_BIND_H

#include <stddef.h>

#include "hfx/hfx.h"
#include "options.h"
#include "vmath.h"

typedef struct hv_scene {
    float world[16], view[16], projection[16];
    hv_vec3 eye, at;
    hv_vec3 light_position, light_direction; /* direction: where the light travels */
    float light_color[3];
    int light_given;                         /* --light: override the effect's own light values */
    int width, height;
} hv_scene;

void hv_scene_from_options(hv_scene *s, const hv_options *o);

/* Which matrix a name or semantic asks for ("WorldViewProj", "ViewInverse", "matWorldIT",
 * "WorldITXf"...): 1 with out filled, or 0 when it names none. */
int hv_scene_matrix(const hv_scene *s, const char *name, int is_semantic, float out[16]);

/* Sets every matrix, camera, light and material parameter it recognises; the count set. */
int hv_bind_scene(hfx_effect *fx, const hv_scene *s);
/* Only what follows the camera and the viewport (semantics, matrices, the camera position), as
 * a viewer does every frame: lights and materials keep what the user set, zeros included. */
int hv_bind_view(hfx_effect *fx, const hv_scene *s);

/* --set NAME=VALUES: NAME may be "a", "a[2]", "a[1].Member"; VALUES are comma-separated
 * numbers, or true / false. 0, or -1 with a message. */
int hv_set_param(hfx_effect *fx, const char *name, const char *values, char *err, size_t errlen);

/* The parameter a path like "lights[1].Color" names, or NULL. */
hfx_param *hv_find_param(hfx_effect *fx, const char *path);

#endif
