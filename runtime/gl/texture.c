/* texture.c: textures complete the way D3D9 sees them.
 *
 * A D3D9 texture has the mip levels it was created with, and a sampler whose MipFilter asks
 * for more samples the last one it has. GL calls a texture whose chain stops before 1x1
 * incomplete as soon as the sampler's min filter uses mipmaps, and an incomplete texture
 * samples black: a one-level texture under `MipFilter = Linear` (the seeds' samplers) would
 * draw black. So the first time hfx binds a texture it counts the levels GL holds and, when
 * the chain is short and GL_TEXTURE_MAX_LEVEL reaches past it, lowers MAX_LEVEL to the last
 * level there is: the texture is then complete under every filter, as in D3D9.
 * Each texture is checked once (no GL query on later Applies). hfx_device_texture_changed
 * asks for a new check after the application adds levels (glGenerateMipmap: MAX_LEVEL is
 * raised back when hfx lowered it and the chain is now whole) or reuses the name. */
#include <stdlib.h>

#include "gl/gl_int.h"

static size_t slot_of(const hfx_texture_set *s, GLuint name) {
    size_t mask = s->cap - 1, i = (name * 2654435761u) & mask;
    while (s->notes[i].name && s->notes[i].name != name) i = (i + 1) & mask;
    return i;
}

static hfx_texture_note *find(hfx_texture_set *s, GLuint name) {
    if (!s->cap) return NULL;
    hfx_texture_note *n = &s->notes[slot_of(s, name)];
    return n->name ? n : NULL;
}

static int grow(hfx_texture_set *s) {
    size_t cap = s->cap ? s->cap * 2 : 16;
    hfx_texture_set bigger = {calloc(cap, sizeof(hfx_texture_note)), cap, s->count};
    if (!bigger.notes) return 0;
    for (size_t i = 0; i < s->cap; i++)
        if (s->notes[i].name) bigger.notes[slot_of(&bigger, s->notes[i].name)] = s->notes[i];
    free(s->notes);
    *s = bigger;
    return 1;
}

/* NULL without memory: the texture is then checked again at its next bind, slower but right. */
static hfx_texture_note *add(hfx_texture_set *s, GLuint name) {
    if ((s->count + 1) * 2 > s->cap && !grow(s)) return NULL;
    hfx_texture_note *n = &s->notes[slot_of(s, name)];
    *n = (hfx_texture_note){name, -1, 0};
    s->count++;
    return n;
}

void hfx_rt_textures_free(hfx_device *dev) { free(dev->gl->checked.notes); }

/* The face or target GL's level queries take for a texture bound on target. */
static GLenum level_target(GLenum target) {
    return target == GL_TEXTURE_CUBE_MAP ? GL_TEXTURE_CUBE_MAP_POSITIVE_X : target;
}

static GLint level_size(hfx_device *dev, GLenum target, GLint level) {
    GLint w = 0, h = 0, d = 0;
    GLenum t = level_target(target);
    dev->gl->fn.GetTexLevelParameteriv(t, level, GL_TEXTURE_WIDTH, &w);
    dev->gl->fn.GetTexLevelParameteriv(t, level, GL_TEXTURE_HEIGHT, &h);
    if (target == GL_TEXTURE_3D) dev->gl->fn.GetTexLevelParameteriv(t, level, GL_TEXTURE_DEPTH, &d);
    GLint m = w > h ? w : h;
    return m > d ? m : d;
}

/* Levels from base to 1x1 in a full chain whose base level is size texels across. */
static GLint full_chain(GLint size) {
    GLint n = 1;
    while (size > 1) size >>= 1, n++;
    return n;
}

/* The texture bound on target of the active unit: MAX_LEVEL at its last level when its chain
 * is short; GL's default back when hfx had lowered it and the chain has become whole. */
static void complete_levels(hfx_device *dev, GLenum target, hfx_texture_note *note) {
    GLint base = 0, max = 0;
    dev->gl->fn.GetTexParameteriv(target, GL_TEXTURE_BASE_LEVEL, &base);
    dev->gl->fn.GetTexParameteriv(target, GL_TEXTURE_MAX_LEVEL, &max);
    int ours = note->lowered_to >= 0 && max == note->lowered_to; /* else the application set it */
    note->lowered_to = -1;
    GLint size = level_size(dev, target, base);
    if (size <= 0) return; /* no image yet: nothing D3D9 could sample either */
    GLint want = full_chain(size), have = 1;
    while (have < want && level_size(dev, target, base + have) > 0) have++;
    GLint last = base + have - 1;
    if (have == want) {
        if (ours) dev->gl->fn.TexParameteri(target, GL_TEXTURE_MAX_LEVEL, 1000);
    } else if (max > last || ours) {
        dev->gl->fn.TexParameteri(target, GL_TEXTURE_MAX_LEVEL, last);
        note->lowered_to = last;
    }
}

void hfx_rt_texture_check(hfx_device *dev, GLenum target, GLuint texture) {
    if (!texture) return;
    hfx_texture_note *note = find(&dev->gl->checked, texture);
    if (note && !note->stale) return;
    hfx_texture_note fresh = {texture, -1, 0};
    if (!note) note = add(&dev->gl->checked, texture);
    complete_levels(dev, target, note ? note : &fresh);
    if (note) note->stale = 0;
}

/* A unit still holding the texture is marked stale too, so the next Apply binds and checks it. */
void hfx_device_texture_changed(hfx_device *dev, unsigned int texture) {
    if (!dev || !texture || dev->be != &hfx_gl_backend) return;
    hfx_texture_note *note = find(&dev->gl->checked, texture);
    if (note) note->stale = 1;
    for (int u = 0; u < HFX_MAX_UNITS; u++)
        if (dev->gl->units[u].texture == texture) dev->gl->units[u].target = 0;
}
