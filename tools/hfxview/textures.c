/* textures.c: default, named and user textures (see textures.h). */
#include "textures.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "image.h"
#include "render.h"

typedef hv_tex_kind tex_kind;
#define KIND_2D HV_TEX_2D
#define KIND_CUBE HV_TEX_CUBE
#define KIND_3D HV_TEX_3D

/* GL's textures: ids to delete at release. */
static uint64_t gl_make(void *ctx, const hv_image *img, hv_tex_kind kind) {
    const hv_gl *gl = ctx;
    if (kind == KIND_CUBE) return hv_texture_cube(gl, img);
    return kind == KIND_3D ? hv_texture_3d(gl, img) : hv_texture_2d(gl, img);
}

static int gl_set(hfx_param *p, uint64_t id) { return hfx_param_set_texture(p, (unsigned int)id); }

static uint64_t track(hv_textures *t, uint64_t id) {
    if (id && t->count < sizeof t->ids / sizeof t->ids[0]) t->ids[t->count++] = id;
    return id;
}

static uint64_t make(const hv_texture_maker *m, const hv_image *img, tex_kind kind) { return m->make(m->ctx, img, kind); }

/* The default texture of each kind: a checkerboard (a checkered volume for 3D), never black. */
static uint64_t checker(hv_textures *t, const hv_texture_maker *gl, tex_kind kind) {
    if (t->checker[kind]) return t->checker[kind];
    hv_image img;
    if (hv_image_default(&img, kind == KIND_3D) != 0) return 0;
    t->checker[kind] = track(t, make(gl, &img, kind));
    hv_image_free(&img);
    return t->checker[kind];
}

static uint64_t from_file(hv_textures *t, const hv_texture_maker *gl, const char *path, tex_kind kind, char *err, size_t errlen) {
    hv_image img;
    if (hv_image_load(&img, path, err, errlen) != 0) return 0;
    uint64_t id = track(t, make(gl, &img, kind));
    hv_image_free(&img);
    if (!id) snprintf(err, errlen, "cannot make a texture from '%s'", path);
    return id;
}

/* name in the effect's folder, then in each -I folder (as the effect's #includes are found). */
static int find_file(const hv_options *o, const char *name, char *out, size_t outlen) {
    if (name[0] == '/') return snprintf(out, outlen, "%s", name), access(out, R_OK) == 0;
    const char *slash = strrchr(o->input, '/');
    int dir = slash ? (int)(slash - o->input) : 1;
    snprintf(out, outlen, "%.*s/%s", dir, slash ? o->input : ".", name);
    for (size_t i = 0; access(out, R_OK) != 0; i++) {
        if (i == o->include_dir_count) return 0;
        snprintf(out, outlen, "%s/%s", o->include_dirs[i], name);
    }
    return 1;
}

/* The file the parameter's annotations name (ResourceName, or the SDK's `string name`), when
 * it can be read; else 0 and a note, and the caller falls back to the default. */
static uint64_t from_annotation(hv_textures *t, const hv_texture_maker *gl, const hv_options *o, hfx_param *p) {
    static const char *const file_names[] = {"ResourceName", "name", "File", "FileName", NULL};
    const char *name = hv_param_string_annotation(p, file_names);
    char path[1024], err[512];
    if (!name) return 0;
    if (!find_file(o, name, path, sizeof path)) {
        fprintf(stderr, "hfxview: note: %s names '%s', not found; using the default texture\n", hfx_param_name(p), name);
        return 0;
    }
    uint64_t id = from_file(t, gl, path, hv_texture_kind(p), err, sizeof err);
    if (!id) fprintf(stderr, "hfxview: note: %s; using the default texture\n", err);
    return id;
}

static int bind_given(hv_textures *t, const hv_texture_maker *gl, hfx_effect *fx, const hv_kv *given, char *err, size_t errlen) {
    char name[256];
    size_t n = (size_t)(given->value - 1 - given->name);
    if (n >= sizeof name) n = sizeof name - 1;
    memcpy(name, given->name, n);
    name[n] = '\0';
    hfx_param *p = hfx_effect_param(fx, name);
    if (!p || !hv_param_is_texture_or_sampler(p)) {
        snprintf(err, errlen, "--texture: the effect has no texture or sampler parameter '%s'", name);
        return -1;
    }
    uint64_t id = from_file(t, gl, given->value, hv_texture_kind(p), err, errlen);
    if (!id) return -1;
    gl->set(p, id);
    return 0;
}

int hv_bind_textures_with(hv_textures *t, const hv_texture_maker *gl, hfx_effect *fx, const hv_options *o, char *err,
                          size_t errlen) {
    memset(t, 0, sizeof *t);
    for (size_t k = 0; k < o->texture_count; k++)
        if (bind_given(t, gl, fx, &o->textures[k], err, errlen) != 0) return -1;
    int samplers_too = hv_effect_samplers_take_textures(fx);
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        hfx_param *p = hfx_effect_param_at(fx, i);
        unsigned int current = 0;
        if (!hv_param_takes_texture(p, samplers_too)) continue;
        if (hfx_param_get_texture(p, &current) == HFX_OK && current) continue; /* given above */
        uint64_t id = from_annotation(t, gl, o, p);
        if (!id) id = checker(t, gl, hv_texture_kind(p));
        if (id) gl->set(p, id);
    }
    return 0;
}

int hv_bind_textures(hv_textures *t, const hv_gl *gl, hfx_effect *fx, const hv_options *o, char *err, size_t errlen) {
    const hv_texture_maker m = {(void *)gl, gl_make, gl_set};
    return hv_bind_textures_with(t, &m, fx, o, err, errlen);
}

void hv_textures_release(hv_textures *t, const hv_gl *gl) {
    for (size_t i = 0; i < t->count; i++) {
        GLuint id = (GLuint)t->ids[i];
        gl->DeleteTextures(1, &id);
    }
    memset(t, 0, sizeof *t);
}
