/* textures.h: giving every texture parameter an image: the one named with --texture, else a
 * mipmapped checkerboard made in code, so an untextured effect still shows its mapping. */
#ifndef HFXVIEW_TEXTURES_H
#define HFXVIEW_TEXTURES_H

#include <stddef.h>

#include "gl.h"
#include "hfx/hfx.h"
#include "options.h"

typedef struct hv_textures {
    unsigned int ids[64];
    size_t count;
    unsigned int checker_2d, checker_cube;
} hv_textures;

/* 0, or -1 with a message (an unknown parameter name or an unreadable image). */
int hv_bind_textures(hv_textures *t, const hv_gl *gl, hfx_effect *fx, const hv_kv *given, size_t given_count,
                     char *err, size_t errlen);
void hv_textures_release(hv_textures *t, const hv_gl *gl);

#endif
