/* bind_internal.h: what bind.c, bind_roles.c and bind_sas.c share: reading and setting values,
 * and the two halves of the binding (names and roles; SAS annotations). */
#ifndef HFXVIEW_BIND_INTERNAL_H
#define HFXVIEW_BIND_INTERNAL_H

#include <stddef.h>

#include "bind.h"

#define HV_PI 3.14159265358979323846f

void hv_lower_copy(char *out, size_t cap, const char *in);
int hv_param_is_zero(const hfx_param *p);     /* numeric and all zeros: the effect gave no value */
int hv_set_vector(hfx_param *p, const float *v, size_t n, float pad); /* float scalar / vector */
int hv_set_matrix_param(hfx_param *p, const float m[16]); /* a float matrix, upper-left block */
int hv_set_scalar_default(hfx_param *p, float v);          /* only when zero; any numeric type */
int hv_set_identity_palette(hfx_param *p);                 /* every element of a matrix array */

/* The scene as a light sees it: View looks from the light at the target, Projection a 60
 * degree square frustum; for parameters that name a light (Object = "SpotLight0", LightViewProj). */
void hv_light_scene(const hv_scene *s, hv_scene *light);

/* "g_vLightDir" -> "lightdir", "matDiffuse" -> "materialdiffuse", "DirLight0DiffuseColor" ->
 * "dirlightdiffusecolor": the stem the role table is keyed by. */
void hv_name_stem(char *out, size_t cap, const char *name);

/* bind_roles.c: by name (stem) or semantic. The phrase saying how, or NULL when p is not one
 * of the known names; *set 1 when a value was written. view_only: only the per-frame ones
 * (camera position, clock). */
const char *hv_bind_by_name(hfx_param *p, const hv_scene *s, int view_only, int *set);
/* bind_sas.c: by annotation (Object, Space, SasBindAddress, UIWidget, UI defaults); same contract. */
const char *hv_bind_by_annotation(hfx_param *p, const hv_scene *s, int view_only, int *set);

#endif
