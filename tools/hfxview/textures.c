/* textures.c: default and user textures (see textures.h). */
#include "textures.h"

#include <stdio.h>
#include <string.h>

#include "image.h"
#include "render.h"

static int is_texture(hfx_param_type t) { return t >= HFX_TYPE_TEXTURE && t <= HFX_TYPE_TEXTURECUBE; }
static int is_sampler(hfx_param_type t) { return t >= HFX_TYPE_SAMPLER && t <= HFX_TYPE_SAMPLERCUBE; }
static int is_cube(hfx_param_type t) { return t == HFX_TYPE_TEXTURECUBE || t == HFX_TYPE_SAMPLERCUBE; }

static unsigned int track(hv_textures *t, unsigned int id) {
    if (id && t->count < sizeof t->ids / sizeof t->ids[0]) t->ids[t->count++] = id;
    return id;
}

static unsigned int checker(hv_textures *t, const hv_gl *gl, int cube) {
    unsigned int *slot = cube ? &t->checker_cube : &t->checker_2d;
    if (*slot) return *slot;
    static const unsigned char light[4] = {235, 235, 235, 255}, dark[4] = {90, 90, 100, 255};
    hv_image img;
    if (hv_image_checker(&img, 256, 8, light, dark) != 0) return 0;
    *slot = track(t, cube ? hv_texture_cube(gl, &img) : hv_texture_2d(gl, &img));
    hv_image_free(&img);
    return *slot;
}

static unsigned int from_file(hv_textures *t, const hv_gl *gl, const char *path, int cube, char *err, size_t errlen) {
    hv_image img;
    if (hv_image_load(&img, path, err, errlen) != 0) return 0;
    unsigned int id = track(t, cube ? hv_texture_cube(gl, &img) : hv_texture_2d(gl, &img));
    hv_image_free(&img);
    if (!id) snprintf(err, errlen, "cannot make a texture from '%s'", path);
    return id;
}

static int has_texture_params(hfx_effect *fx) {
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++)
        if (is_texture(hfx_param_get_type(hfx_effect_param_at(fx, i)))) return 1;
    return 0;
}

int hv_bind_textures(hv_textures *t, const hv_gl *gl, hfx_effect *fx, const hv_kv *given, size_t given_count,
                     char *err, size_t errlen) {
    memset(t, 0, sizeof *t);
    for (size_t k = 0; k < given_count; k++) {
        char name[256];
        size_t n = (size_t)(given[k].value - 1 - given[k].name);
        if (n >= sizeof name) n = sizeof name - 1;
        memcpy(name, given[k].name, n);
        name[n] = '\0';
        hfx_param *p = hfx_effect_param(fx, name);
        if (!p || !(is_texture(hfx_param_get_type(p)) || is_sampler(hfx_param_get_type(p)))) {
            snprintf(err, errlen, "--texture: the effect has no texture or sampler parameter '%s'", name);
            return -1;
        }
        unsigned int id = from_file(t, gl, given[k].value, is_cube(hfx_param_get_type(p)), err, errlen);
        if (!id) return -1;
        hfx_param_set_texture(p, id);
    }
    /* Samplers only get the checker when no texture parameter can feed them. */
    int samplers_too = !has_texture_params(fx);
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        hfx_param *p = hfx_effect_param_at(fx, i);
        hfx_param_type type = hfx_param_get_type(p);
        unsigned int current = 0;
        if (!(is_texture(type) || (samplers_too && is_sampler(type)))) continue;
        if (hfx_param_get_texture(p, &current) == HFX_OK && current) continue; /* given above */
        if (type == HFX_TYPE_TEXTURE1D || type == HFX_TYPE_TEXTURE3D || type == HFX_TYPE_SAMPLER1D ||
            type == HFX_TYPE_SAMPLER3D)
            continue; /* no default for these: they sample black, as an unset D3D texture does */
        unsigned int id = checker(t, gl, is_cube(type));
        if (id) hfx_param_set_texture(p, id);
    }
    return 0;
}

void hv_textures_release(hv_textures *t, const hv_gl *gl) {
    if (t->count) gl->DeleteTextures((GLsizei)t->count, t->ids);
    memset(t, 0, sizeof *t);
}
