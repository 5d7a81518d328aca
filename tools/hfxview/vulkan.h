/* vulkan.h: hfxview --vulkan, headless on a Vulkan device (built when the Vulkan back end and the
 * tests' Vulkan context are: HFX_HAVE_VULKAN_VIEW). */
#ifndef HFXVIEW_VULKAN_H
#define HFXVIEW_VULKAN_H

#include <stddef.h>

#include "hfx/hfx.h"
#include "image.h"
#include "mesh.h"
#include "options.h"

typedef struct hv_vk hv_vk;

/* A width x height offscreen target and its hfx device in *dev (owned by the hv_vk). 0, or -1 with err. */
int hv_vk_open(hv_vk **out, int width, int height, hfx_device **dev, char *err, size_t errlen);
/* Draws the technique over the mesh (as hv_draw_technique does) and reads the picture; HFX_OK or
 * the first error (*failed_pass says which pass). */
int hv_vk_render(hv_vk *g, hfx_effect *fx, hfx_technique *t, const hv_options *o, const hv_mesh *m, hv_image *img,
                 size_t *failed_pass);
size_t hv_vk_pipelines(const hv_vk *g);   /* pipelines the device made */
int hv_vk_close(hv_vk *g);                 /* destroy the effects first; the validation messages sent */

#endif
