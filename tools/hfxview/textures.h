/* textures.h: giving every texture parameter an image: the one named with --texture, else the
 * file its annotations name (FX Composer's ResourceName, the SDK's `string name`; PNG, JPEG,
 * DDS...) found beside the effect or in a -I folder, else a mipmapped checkerboard made in
 * code (a checkered volume for 3D textures), so an untextured effect still shows its mapping. */
#ifndef HFXVIEW_TEXTURES_H
#define HFXVIEW_TEXTURES_H

#include <stddef.h>
#include <stdint.h>

#include "gl.h"
#include "hfx/hfx.h"
#include "image.h"
#include "options.h"

typedef struct hv_textures {
    uint64_t ids[64];        /* what the maker made (GL: texture names to delete) */
    size_t count;
    uint64_t checker[3];     /* the default 2D, cube and 3D textures, made on first use */
} hv_textures;

typedef enum { HV_TEX_2D, HV_TEX_CUBE, HV_TEX_3D } hv_tex_kind;

/* Where the textures are made: GL's (hv_bind_textures) or --vulkan's (vulkan.c). make returns
 * a non-zero handle (a GL name, a VkImageView), 0 on failure; set gives it to a parameter. */
typedef struct hv_texture_maker {
    void *ctx;
    uint64_t (*make)(void *ctx, const hv_image *img, hv_tex_kind kind);
    int (*set)(hfx_param *p, uint64_t handle);
} hv_texture_maker;

/* 0, or -1 with a message (--texture: an unknown parameter name or an unreadable image).
 * Files named by annotations that cannot be read are a note on stderr and the default. */
int hv_bind_textures_with(hv_textures *t, const hv_texture_maker *m, hfx_effect *fx, const hv_options *o, char *err,
                          size_t errlen);
/* hfxview's rule (texture_rule.c, shared with the web page): every texture parameter takes a
 * texture; samplers take one of their own only when the effect has no texture parameter that
 * could feed them (hv_effect_samplers_take_textures gives samplers_too). */
int hv_effect_samplers_take_textures(hfx_effect *fx);
int hv_param_takes_texture(hfx_param *p, int samplers_too);
int hv_param_is_texture_or_sampler(hfx_param *p);
/* The kind of texture p takes: its sampler's target, else a ResourceType / Type annotation
 * ("cube", "3d", "volume"), else its type; 2D by default. */
hv_tex_kind hv_texture_kind(hfx_param *p);
/* The first non-empty string annotation of p named one of names (NULL-terminated), or NULL. */
const char *hv_param_string_annotation(hfx_param *p, const char *const *names);
int hv_bind_textures(hv_textures *t, const hv_gl *gl, hfx_effect *fx, const hv_options *o, char *err, size_t errlen);
void hv_textures_release(hv_textures *t, const hv_gl *gl);

#endif
