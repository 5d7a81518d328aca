/* textures.h: giving every texture parameter an image: the one named with --texture, else the
 * file its annotations name (FX Composer's ResourceName, the SDK's `string name`; PNG, JPEG,
 * DDS...) found beside the effect or in a -I folder, else a mipmapped checkerboard made in
 * code (a checkered volume for 3D textures), so an untextured effect still shows its mapping. */
#ifndef HFXVIEW_TEXTURES_H
#define HFXVIEW_TEXTURES_H

#include <stddef.h>

#include "gl.h"
#include "hfx/hfx.h"
#include "options.h"

typedef struct hv_textures {
    unsigned int ids[64];
    size_t count;
    unsigned int checker[3]; /* the default 2D, cube and 3D textures, made on first use */
} hv_textures;

/* 0, or -1 with a message (--texture: an unknown parameter name or an unreadable image).
 * Files named by annotations that cannot be read are a note on stderr and the default. */
int hv_bind_textures(hv_textures *t, const hv_gl *gl, hfx_effect *fx, const hv_options *o, char *err, size_t errlen);
void hv_textures_release(hv_textures *t, const hv_gl *gl);

#endif
