/* apply.c: Apply, begin and end on GL, reached through the back end's table from the core's
 * hfx_pass_apply / hfx_effect_begin / hfx_effect_end (runtime/apply.c). Apply binds the pass's
 * program, uploads the parameters that changed since that program last saw them, binds textures
 * and sampler objects, and sets render states; everything goes through the device's shadow, so
 * an Apply with nothing changed makes no GL call. */
#include "gl/gl_int.h"

static void bind_textures(hfx_effect *fx, const hfx_rt_pass *rp) {
    for (uint32_t i = 0; i < rp->binding_count; i++) {
        const hfx_rt_binding *b = &rp->bindings[i];
        GLuint tex = b->texture_param != HFX_NONE ? fx->textures[b->texture_param] : 0;
        if (!tex && b->sampler_param != HFX_NONE) tex = fx->textures[b->sampler_param];
        GLuint sampler = 0;
        if (b->sampler != HFX_NONE) {
            hfx_rt_sampler *s = &fx->sh->gl->samplers[b->sampler];
            hfx_rt_sampler_update(fx, s);
            sampler = s->object;
        }
        if (b->texture_param == HFX_NONE && b->sampler_param == HFX_NONE) {
            /* only sampler states for this stage (MinFilter[3] = ...): the texture stays */
            hfx_unit_state *u = &fx->dev->gl->units[b->unit];
            if (u->sampler != sampler) fx->dev->gl->fn.BindSampler((GLuint)b->unit, u->sampler = sampler);
            continue;
        }
        hfx_rt_bind_unit(fx->dev, b->unit, b->target, tex, sampler);
    }
}

/* Front face (D3D's clockwise, flipped in a framebuffer object), the first vertex as flat
 * shading's provoking vertex (D3D's), program, its position fixup and alpha-test uniforms. */
static inline void apply_program(hfx_device *dev, hfx_rt_program *prog) {
    GLenum front = dev->gl->flip ? GL_CCW : GL_CW; /* hfx_rs_front_face */
    if (dev->gl->state.front_face != front) dev->gl->fn.FrontFace(dev->gl->state.front_face = front);
    if (dev->gl->state.provoking != GL_FIRST_VERTEX_CONVENTION)
        dev->gl->fn.ProvokingVertex(dev->gl->state.provoking = GL_FIRST_VERTEX_CONVENTION);
    if (!prog) return;
    hfx_rt_use_program(dev, prog->object);
    if (prog->pos_fixup_serial != dev->gl->pos_fixup_serial || prog->alpha_test) hfx_rt_program_extras(dev, prog);
}

/* The array index a selector state gives now (HFX_NONE for a fixed stage). */
static uint32_t selected(const hfx_effect *fx, const hfx_rt_pass *rp, int stage) {
    return hfx_rs_selected(fx, rp->selector[stage], (uint32_t)(rp - fx->sh->gl->passes), stage);
}

/* A pass drawn from shader arrays: the program of the entries its selectors pick now, as
 * D3D9 evaluates `VertexShader = (VSArray[VSIndices[ShaderIndex]]);` at Apply. */
static hfx_rt_program *variant_program(hfx_effect *fx, const hfx_rt_pass *rp) {
    uint32_t vs = selected(fx, rp, 0), ps = selected(fx, rp, 1);
    for (uint32_t i = 0; i < rp->variant_count; i++)
        if (rp->variants[i].vs == vs && rp->variants[i].ps == ps) return &fx->sh->gl->programs[rp->variants[i].program];
    hfx_rt_fail(fx->dev, HFX_ERR_NOT_FOUND, "no program for shader array entries %d and %d (only those the compiler "
                "reached by the driving parameter exist)", (int)vs, (int)ps);
    return NULL;
}

/* The program of a pass with shader arrays: chosen again only when a parameter changed since. */
static hfx_rt_program *chosen_program(hfx_pass *p) {
    hfx_effect *fx = p->fx;
    if (p->chosen && p->chosen_seen == fx->log_len + 1) return p->chosen;
    p->chosen = variant_program(fx, p->rt);
    p->chosen_seen = fx->log_len + 1;
    return p->chosen;
}

/* The variant of base for its switches' values now (hfx_rt_program_switched), kept while they stay. */
static hfx_rt_program *switched_program(hfx_pass *p, hfx_rt_program *base) {
    uint32_t mask = hfx_rt_switch_mask(base, p->fx->values);
    if (p->switched && p->switched_base == base && p->switch_mask == mask) return p->switched;
    p->switched_base = base;
    p->switch_mask = mask;
    return p->switched = hfx_rt_program_switched(p->fx->sh, base, mask);
}

/* Everything a pass sets: render states, program, uploads, textures. */
static int apply_full(hfx_pass *p) {
    hfx_effect *fx = p->fx;
    const hfx_rt_pass *rp = p->rt;
    if (rp->render_state_count) hfx_rs_apply(fx, rp); /* first: the alpha test reads these states */
    hfx_rt_program *prog = rp->variant_count ? chosen_program(p) : rp->prog;
    if (rp->variant_count && !prog) return HFX_ERR_NOT_FOUND;
    if (prog && prog->switch_count) prog = switched_program(p, prog);
    apply_program(fx->dev, prog);
    if (prog && (prog->memo_seen != fx->log_len || prog->memo_effect != fx->id)) hfx_rt_upload_changed(fx, prog);
    if (rp->binding_count) bind_textures(fx, rp);
    return HFX_OK;
}

/* A pass other than the last one applied; a program-only one becomes the device's last. */
static __attribute__((noinline)) int apply_first(hfx_pass *p) {
    hfx_device *dev = p->fx->dev;
    dev->applied = NULL;
    int rc = apply_full(p);
    if (p->rt->direct) dev->applied = p;
    return rc;
}

/* The same program-only pass again, with no other state set since, only uploads what the
 * parameters' log holds past what its program saw: the per-draw path of a game loop. */
int hfx_gl_pass_apply(hfx_pass *p) {
    hfx_effect *fx = p->fx;
    if (fx->dev->applied != p) return apply_first(p);
    hfx_rt_program *prog = p->rt->prog;
    if (prog->switch_count) { /* the variant apply_full picked; a bool can change only with the log */
        hfx_rt_program *base = prog;
        prog = p->switched;
        if (prog->memo_seen != fx->log_len && hfx_rt_switch_mask(base, fx->values) != p->switch_mask)
            return apply_first(p);
    }
    uint64_t seen = prog->memo_seen;
    if (seen == fx->log_len) return HFX_OK;
    if (seen + 1 != fx->log_len) return hfx_rt_upload_log(fx, prog);
    /* one change since the last Apply (a per-object World, say): no loop, no saved registers */
    uint32_t r = fx->log[seen & fx->log_mask];
    hfx_slot *s = &prog->slots[r];
    uint64_t stamp = fx->stamps[r];
    if (s->held == stamp || (s->mode != SLOT_FLOAT && s->mode != SLOT_REG4)) return hfx_rt_upload_log(fx, prog);
    prog->memo_seen = seen + 1;
    s->held = stamp;
    const uint32_t *src = fx->values + s->up.offset;
    if (s->mode == SLOT_REG4) hfx_rt_reg_put4(prog, s, src); /* the image stays whole for a later range */
    s->up.call.f(s->up.location, s->up.count, (const void *)src);
    return HFX_OK;
}

/* begin / end: save the GL state the effect touches and put it back, leaving the shadow
 * equal to what GL holds (so state changed by the application between frames is seen). */

static const GLenum unit_targets[4] = {GL_TEXTURE_BINDING_1D, GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_3D,
                                       GL_TEXTURE_BINDING_CUBE_MAP};
static const GLenum bind_targets[4] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP};

/* Reads the textures and samplers GL holds on the units in mask into s->units. */
static void save_units(hfx_device *dev, hfx_saved *s, uint32_t mask) {
    for (int u = 0; u < HFX_MAX_UNITS; u++) {
        if (!(mask & (1u << u))) continue;
        dev->gl->fn.ActiveTexture(GL_TEXTURE0 + (GLenum)u);
        for (int t = 0; t < 4; t++) dev->gl->fn.GetIntegerv(unit_targets[t], &s->units[u].tex[t]);
        dev->gl->fn.GetIntegerv(GL_SAMPLER_BINDING, &s->units[u].sampler);
    }
    dev->gl->fn.ActiveTexture(dev->gl->active_unit);
}

/* The shadow is read back first (hfx_device_sync), so the snapshot is the shadow. */
int hfx_gl_effect_begin(hfx_effect *fx) {
    hfx_device *dev = fx->dev;
    hfx_saved *s = &fx->gl->saved;
    hfx_device_sync(dev);
    s->state = dev->gl->state;
    s->program = (GLint)dev->gl->program;
    s->active_unit = (GLint)dev->gl->active_unit;
    save_units(dev, s, fx->sh->gl->unit_mask);
    s->alpha_test[0] = dev->rs[HFX_ST_ALPHATESTENABLE];
    s->alpha_test[1] = dev->rs[HFX_ST_ALPHAFUNC];
    s->alpha_test[2] = dev->rs[HFX_ST_ALPHAREF];
    return HFX_OK;
}

int hfx_gl_effect_end(hfx_effect *fx) {
    hfx_device *dev = fx->dev;
    hfx_saved *s = &fx->gl->saved;
    dev->applied = NULL;
    hfx_rt_write_state(dev, &s->state);
    hfx_rt_use_program(dev, (GLuint)s->program);
    for (int u = 0; u < HFX_MAX_UNITS; u++) {
        if (!(fx->sh->gl->unit_mask & (1u << u))) continue;
        dev->gl->fn.ActiveTexture(GL_TEXTURE0 + (GLenum)u);
        for (int t = 0; t < 4; t++) dev->gl->fn.BindTexture(bind_targets[t], (GLuint)s->units[u].tex[t]);
        dev->gl->fn.BindSampler((GLuint)u, (GLuint)s->units[u].sampler);
        dev->gl->units[u].target = 0;
        dev->gl->units[u].sampler = (GLuint)s->units[u].sampler;
    }
    dev->gl->fn.ActiveTexture((GLenum)s->active_unit);
    dev->gl->active_unit = (GLenum)s->active_unit;
    /* D3DX's End restores the states the passes set; GL's are restored above, the alpha test
     * lives in hfx's shadow and reaches the shaders at the next Apply */
    dev->rs[HFX_ST_ALPHATESTENABLE] = s->alpha_test[0];
    dev->rs[HFX_ST_ALPHAFUNC] = s->alpha_test[1];
    dev->rs[HFX_ST_ALPHAREF] = s->alpha_test[2];
    return HFX_OK;
}

/* Reload between begin and end: end restores the units of the effect's shared part, and begin
 * saved only the old part's. Units only the new code binds have not been touched by the effect
 * since begin, so what GL holds on them now is what begin would have saved; units only the old
 * code bound are kept in the new mask so end still puts them back. The new shared part is this
 * instance's alone, so widening its mask changes no one else. */
void hfx_gl_begun_carry(hfx_effect *to, const hfx_effect *from) {
    to->gl->saved = from->gl->saved;
    uint32_t fresh = to->sh->gl->unit_mask & ~from->sh->gl->unit_mask;
    to->sh->gl->unit_mask |= from->sh->gl->unit_mask;
    if (fresh) save_units(to->dev, &to->gl->saved, fresh);
}
