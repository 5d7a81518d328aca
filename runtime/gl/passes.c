/* passes.c: an effect's passes for Apply: the program, the render states to set, and the
 * texture units to bind (which texture, which GL sampler object, on which target). */
#include <stdlib.h>

#include "gl/gl_int.h"

/* 1D textures are 2D textures of height 1 (docs/conventions.md: the GLSL samples them so,
 * and GL ES has no 1D textures). */
static GLenum dim_target(hfx_fx_dim dim) {
    switch (dim) {
    case HFX_FX_DIM_1D: return GL_TEXTURE_2D;
    case HFX_FX_DIM_3D: return GL_TEXTURE_3D;
    case HFX_FX_DIM_CUBE: return GL_TEXTURE_CUBE_MAP;
    default: return GL_TEXTURE_2D;
    }
}

/* The GL target for a texture or sampler parameter; generic ones follow the sampler's use. */
static GLenum param_target(const hfx_fx_effect *fx, uint32_t param, hfx_fx_dim dim) {
    if (param >= fx->param_count) return dim_target(dim);
    switch (fx->params[param].type) {
    case HFX_TYPE_TEXTURE1D: case HFX_TYPE_SAMPLER1D:
    case HFX_TYPE_TEXTURE2D: case HFX_TYPE_SAMPLER2D: return GL_TEXTURE_2D;
    case HFX_TYPE_TEXTURE3D: case HFX_TYPE_SAMPLER3D: return GL_TEXTURE_3D;
    case HFX_TYPE_TEXTURECUBE: case HFX_TYPE_SAMPLERCUBE: return GL_TEXTURE_CUBE_MAP;
    default: return dim_target(dim);
    }
}

static hfx_rt_binding *binding_for(hfx_rt_pass *rp, int32_t unit) {
    for (uint32_t i = 0; i < rp->binding_count; i++)
        if (rp->bindings[i].unit == unit) return &rp->bindings[i];
    hfx_rt_binding *b = &rp->bindings[rp->binding_count++];
    b->unit = unit;
    b->sampler = HFX_NONE;
    b->texture_param = HFX_NONE;
    b->sampler_param = HFX_NONE;
    b->target = GL_TEXTURE_2D;
    return b;
}

static void bind_sampler_use(const hfx_fx_effect *fx, hfx_rt_binding *b, uint32_t sampler) {
    const hfx_fx_sampler *s = &fx->samplers[sampler];
    b->sampler = sampler;
    b->texture_param = s->texture_param;
    b->sampler_param = s->param;
    b->target = param_target(fx, s->texture_param != HFX_NONE ? s->texture_param : s->param, s->dim);
}

/* The units a program samples on, with their samplers (a variant pass: all its programs'). */
static void bind_program_samplers(const hfx_fx_effect *fx, hfx_rt_pass *rp, uint32_t program) {
    const hfx_fx_program *prog = &fx->programs[program];
    for (uint32_t i = 0; i < prog->sampler_count; i++)
        if (prog->samplers[i].unit >= 0 && prog->samplers[i].unit < HFX_MAX_UNITS &&
            prog->samplers[i].sampler < fx->sampler_count)
            bind_sampler_use(fx, binding_for(rp, prog->samplers[i].unit), prog->samplers[i].sampler);
}

/* The pass's variants (a run of fx->variants) and its VertexShader / PixelShader EXPR states. */
static void find_variants(const hfx_fx_effect *fx, hfx_rt_pass *rp, uint32_t index) {
    const hfx_fx_pass *fp = &fx->passes[index];
    rp->selector[0] = rp->selector[1] = HFX_NONE;
    for (uint32_t i = 0; i < fx->variant_count; i++)
        if (fx->variants[i].pass == index) {
            if (!rp->variant_count) rp->variants = &fx->variants[i];
            rp->variant_count++;
        }
    for (uint32_t i = 0; rp->variant_count && i < fp->state_count; i++) {
        const hfx_fx_state *st = &fx->states[fp->first_state + i];
        if (st->kind != HFX_FX_VALUE_EXPR) continue;
        if (st->id == HFX_ST_VERTEXSHADER) rp->selector[0] = fp->first_state + i;
        if (st->id == HFX_ST_PIXELSHADER) rp->selector[1] = fp->first_state + i;
    }
}

int hfx_rt_pass_build(hfx_shared *sh, uint32_t *cap, uint32_t index) {
    const hfx_fx_effect *fx = sh->fx;
    const hfx_fx_pass *fp = &fx->passes[index];
    hfx_rt_pass *rp = &sh->gl->passes[index];
    rp->program = fp->program < fx->program_count ? fp->program : HFX_NONE;
    rp->prog = rp->program != HFX_NONE ? &sh->gl->programs[rp->program] : NULL;
    rp->render_states = calloc(fp->state_count ? fp->state_count : 1, sizeof *rp->render_states);
    rp->bindings = calloc(HFX_MAX_UNITS, sizeof *rp->bindings);
    if (!rp->render_states || !rp->bindings) return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    if (rp->program != HFX_NONE) bind_program_samplers(fx, rp, rp->program);
    find_variants(fx, rp, index);
    for (uint32_t i = 0; i < rp->variant_count; i++) bind_program_samplers(fx, rp, rp->variants[i].program);
    uint32_t override_units = 0;
    for (uint32_t i = 0; i < fp->state_count && fp->first_state + i < fx->state_count; i++) {
        const hfx_fx_state *st = &fx->states[fp->first_state + i];
        const hfx_state_info *info = hfx_state_by_id(st->id);
        if (!info || st->kind == HFX_FX_VALUE_UNSUPPORTED) {
            hfx_rs_check(sh, st, rp->program);
            continue;
        }
        if (info->scope == HFX_SS_SAMPLER) hfx_rt_sampler_check_state(sh, st);
        if (info && info->scope == HFX_SS_RENDER) {
            rp->render_states[rp->render_state_count++] = fp->first_state + i;
            rp->groups |= hfx_rs_group(st->id);
        }
        if (info && (info->scope == HFX_SS_TEXTURE || info->scope == HFX_SS_SAMPLER) && st->index >= HFX_MAX_UNITS) {
            hfx_shared_warn(sh, st, "'%s[%u]': sampler stage out of range; ignored", info->name, (unsigned)st->index);
            continue;
        }
        if (st->id == HFX_ST_TEXTURE && st->kind == HFX_FX_VALUE_PARAM) {
            hfx_rt_binding *b = binding_for(rp, (int32_t)st->index);
            b->texture_param = st->ref;
            b->target = param_target(fx, st->ref, HFX_FX_DIM_2D);
        } else if (st->id == HFX_ST_SAMPLER && st->kind == HFX_FX_VALUE_PARAM && st->ref < fx->param_count &&
                   fx->params[st->ref].sampler < fx->sampler_count) {
            bind_sampler_use(fx, binding_for(rp, (int32_t)st->index), fx->params[st->ref].sampler);
        } else if (info && info->scope == HFX_SS_SAMPLER) {
            override_units |= 1u << st->index;
            binding_for(rp, (int32_t)st->index);
        } else if (info && info->scope != HFX_SS_SHADER) {
            hfx_rs_check(sh, st, rp->program);
        }
    }
    for (uint32_t i = 0; i < rp->binding_count; i++) {
        hfx_rt_binding *b = &rp->bindings[i];
        if (override_units & (1u << b->unit) || b->sampler == HFX_NONE) {
            int rc = hfx_rt_sampler_override(sh, cap, fp, b);
            if (rc) return rc;
        }
        sh->gl->unit_mask |= 1u << b->unit;
    }
    sh->gl->groups |= rp->groups;
    rp->direct = rp->prog && !rp->render_state_count && !rp->binding_count;
    return HFX_OK;
}

/* hfx_param_texture_target on GL: the target the passes bind the texture on (a plain `texture`
 * takes its samplers' dimension, param_target); 0 when no pass binds it. */
unsigned int hfx_gl_texture_target(const hfx_param *p) {
    const hfx_gl_shared *gl = p->fx->sh->gl;
    for (uint32_t i = 0; i < p->fx->sh->fx->pass_count; i++)
        for (uint32_t b = 0; b < gl->passes[i].binding_count; b++) {
            const hfx_rt_binding *bd = &gl->passes[i].bindings[b];
            if (bd->texture_param == p->index || bd->sampler_param == p->index) return bd->target;
        }
    return 0;
}
