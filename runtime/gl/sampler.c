/* sampler.c: D3D9 sampler states as GL sampler objects: an effect's sampler_state blocks and
 * pass-level overrides described (hfx_sampler_desc) and made into objects, updated at Apply
 * when a state reads a parameter.
 *
 * - MinFilter + MipFilter make GL_TEXTURE_MIN_FILTER (MipFilter None: no mipmapping);
 *   Anisotropic filters linearly and sets GL_TEXTURE_MAX_ANISOTROPY to MaxAnisotropy when
 *   the context has anisotropic filtering; PyramidalQuad / GaussianQuad filter linearly.
 * - MaxMipLevel is D3D's most detailed mip level used (0 = the largest), which is a clamp of
 *   the level of detail from below: GL_TEXTURE_MIN_LOD, not GL_TEXTURE_MAX_LEVEL.
 * - SRGBTexture: GL decodes sRGB per texture format, not per sampler. With
 *   EXT_texture_sRGB_decode the sampler sets GL_TEXTURE_SRGB_DECODE_EXT (DECODE for TRUE,
 *   SKIP_DECODE for FALSE), so an sRGB-format texture behaves as D3D9 asks; a texture with a
 *   linear format is never decoded, so SRGBTexture = TRUE needs the application to create
 *   its textures with an sRGB internal format (GL_SRGB8_ALPHA8). */
#include <stdlib.h>
#include <string.h>

#include "gl/gl_int.h"


static GLint gl_address(int32_t d3d) {
    switch (d3d) {
    case 2: return GL_MIRRORED_REPEAT;
    case 3: return GL_CLAMP_TO_EDGE;
    case 4: return GL_CLAMP_TO_BORDER;
    case 5: return GL_MIRROR_CLAMP_TO_EDGE;
    default: return GL_REPEAT;
    }
}

static int linear(int32_t f) { return f >= 2; } /* Linear, Anisotropic, PyramidalQuad, GaussianQuad... */

static GLint gl_min_filter(int32_t min, int32_t mip) {
    if (mip == 0) return linear(min) ? GL_LINEAR : GL_NEAREST;
    if (mip == 1) return linear(min) ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
    return linear(min) ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
}

static float anisotropy(const hfx_device *dev, const hfx_sampler_desc *d) {
    if (d->min != 3 && d->mag != 3) return 1.0f;
    float a = d->max_anisotropy < 1 ? 1.0f : (float)d->max_anisotropy;
    return a > dev->max_anisotropy ? dev->max_anisotropy : a;
}

/* Sets the GL parameters where want differs from have (all of them when have is NULL). */
static void write_desc(hfx_device *dev, GLuint s, const hfx_sampler_desc *have, const hfx_sampler_desc *want) {
    static const GLenum wrap[3] = {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R};
    hfx_gl *gl = &dev->gl->fn;
    for (int i = 0; i < 3; i++)
        if (!have || have->address[i] != want->address[i]) gl->SamplerParameteri(s, wrap[i], gl_address(want->address[i]));
    if (!have || have->mag != want->mag) gl->SamplerParameteri(s, GL_TEXTURE_MAG_FILTER, linear(want->mag) ? GL_LINEAR : GL_NEAREST);
    if (!have || have->min != want->min || have->mip != want->mip)
        gl->SamplerParameteri(s, GL_TEXTURE_MIN_FILTER, gl_min_filter(want->min, want->mip));
    if (dev->max_anisotropy > 0 && (!have || anisotropy(dev, have) != anisotropy(dev, want)))
        gl->SamplerParameterf(s, GL_TEXTURE_MAX_ANISOTROPY, anisotropy(dev, want));
    if (!have || have->max_mip_level != want->max_mip_level)
        gl->SamplerParameterf(s, GL_TEXTURE_MIN_LOD, (float)want->max_mip_level);
    if (!have || have->lod_bias != want->lod_bias) gl->SamplerParameterf(s, GL_TEXTURE_LOD_BIAS, want->lod_bias);
    if (!have || memcmp(have->border, want->border, sizeof want->border) != 0)
        gl->SamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, want->border);
    if (dev->gl->srgb_decode && want->srgb_set && (!have || have->srgb != want->srgb || !have->srgb_set))
        gl->SamplerParameteri(s, GL_TEXTURE_SRGB_DECODE_EXT, want->srgb ? GL_DECODE_EXT : GL_SKIP_DECODE_EXT);
}

int hfx_rt_sampler_create(hfx_shared *sh, hfx_rt_sampler *s, const hfx_sampler_desc *base,
                          const hfx_fx_state *const *dyn, uint32_t dyn_count) {
    hfx_device *dev = sh->dev;
    memset(s, 0, sizeof *s);
    s->base = *base;
    s->current = *base;
    if (dyn_count) {
        s->dynamic = malloc(dyn_count * sizeof *s->dynamic);
        if (!s->dynamic) return HFX_ERR_MEMORY;
        memcpy(s->dynamic, dyn, dyn_count * sizeof *s->dynamic);
        s->dynamic_count = dyn_count;
    }
    dev->gl->fn.GenSamplers(1, &s->object);
    if (!s->object) return HFX_ERR_GL;
    write_desc(dev, s->object, NULL, base);
    return HFX_OK;
}

/* States that read parameters: recompute from the base and write what changed. */
void hfx_rt_sampler_update(hfx_effect *fx, hfx_rt_sampler *s) {
    if (!s->dynamic_count) return;
    hfx_sampler_desc want = s->base;
    for (uint32_t i = 0; i < s->dynamic_count; i++) {
        hfx_rs_value v;
        hfx_rs_resolve(fx, s->dynamic[i], &v);
        hfx_sampler_desc_apply(&want, s->dynamic[i]->id, &v);
    }
    if (memcmp(&want, &s->current, sizeof want) == 0) return;
    write_desc(fx->dev, s->object, &s->current, &want);
    s->current = want;
}

void hfx_rt_sampler_free(hfx_device *dev, hfx_rt_sampler *s) {
    /* GL unbinds a deleted sampler from every unit, and may give its name to a later one: the
     * shadow follows, or it would skip binding that one */
    for (int u = 0; s->object && u < HFX_MAX_UNITS; u++)
        if (dev->gl->units[u].sampler == s->object) dev->gl->units[u].sampler = 0;
    if (s->object) dev->gl->fn.DeleteSamplers(1, &s->object);
    free(s->dynamic);
    memset(s, 0, sizeof *s);
}

/* ---- sampler descriptions of an effect: its sampler_state blocks and pass overrides ---- */

static int push_sampler(hfx_shared *sh, uint32_t *cap, const hfx_sampler_desc *base,
                        const hfx_fx_state *const *dyn, uint32_t dyn_count, uint32_t *index) {
    if (!HFX_GROW(sh->gl->samplers, sh->gl->sampler_count, *cap, 8)) return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    *index = sh->gl->sampler_count;
    int rc = hfx_rt_sampler_create(sh, &sh->gl->samplers[sh->gl->sampler_count++], base, dyn, dyn_count);
    return rc ? hfx_rt_fail(sh->dev, rc, "could not create a GL sampler object") : HFX_OK;
}

/* Reports, once at load, a sampler state GL honours only in part. */
void hfx_rt_sampler_check_state(hfx_shared *sh, const hfx_fx_state *st) {
    const hfx_state_info *info = hfx_state_by_id(st->id);
    const char *name = info ? info->name : "?";
    if (st->kind == HFX_FX_VALUE_UNSUPPORTED) {
        hfx_shared_warn(sh, st, "'%s': this value cannot be expressed in GL; ignored", name);
    } else if ((st->id == HFX_ST_MINFILTER || st->id == HFX_ST_MAGFILTER || st->id == HFX_ST_MIPFILTER) &&
               st->kind == HFX_FX_VALUE_INT && st->i > 3) {
        hfx_shared_warn(sh, st, "'%s': %s filtering is not available in GL; filtering linearly", name,
                        info ? hfx_state_value_name(info, st->i) : "this");
    } else if (st->id == HFX_ST_SRGBTEXTURE && st->kind == HFX_FX_VALUE_INT && st->i && !sh->dev->gl->srgb_decode) {
        hfx_shared_warn(sh, st, "'%s': without EXT_texture_sRGB_decode, only textures with an sRGB format are decoded", name);
    }
}

/* The effect's sampler_state blocks as GL sampler objects, in order, with their load-time notes. */
int hfx_rt_samplers_make(hfx_shared *sh, uint32_t *cap) {
    for (uint32_t i = 0; i < sh->fx->sampler_count; i++) {
        const hfx_fx_sampler *fs = &sh->fx->samplers[i];
        for (uint32_t k = 0; k < fs->state_count; k++) hfx_rt_sampler_check_state(sh, &sh->fx->states[fs->first_state + k]);
        hfx_sampler_desc d;
        const hfx_fx_state *dyn[32];
        uint32_t n, index;
        hfx_sampler_desc_of(sh->fx, i, &d, dyn, &n);
        int rc = push_sampler(sh, cap, &d, dyn, n, &index);
        if (rc) return rc;
    }
    return HFX_OK;
}

/* Pass-level MinFilter[n] = ...: a sampler object for unit n from the bound sampler's states
 * with the pass's on top (the pass is the more specific). */
int hfx_rt_sampler_override(hfx_shared *sh, uint32_t *cap, const hfx_fx_pass *fp, hfx_rt_binding *b) {
    const hfx_fx_effect *fx = sh->fx;
    hfx_sampler_desc d;
    const hfx_fx_state *dyn[32];
    uint32_t n, index;
    hfx_sampler_desc_of(fx, b->sampler, &d, dyn, &n);
    int any = 0;
    for (uint32_t i = 0; i < fp->state_count; i++) {
        const hfx_fx_state *st = &fx->states[fp->first_state + i];
        const hfx_state_info *info = hfx_state_by_id(st->id);
        if (!info || info->scope != HFX_SS_SAMPLER || st->id == HFX_ST_SAMPLER || (int32_t)st->index != b->unit)
            continue;
        hfx_sampler_state_add(st, &d, dyn, &n);
        any = 1;
    }
    if (!any) return HFX_OK;
    int rc = push_sampler(sh, cap, &d, dyn, n, &index);
    if (!rc) b->sampler = index;
    return rc;
}

