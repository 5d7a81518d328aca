/* apply.c: Passes[i].Apply() on Vulkan. The pass's render states update the device's D3D9
 * state (they stay set after the pass, as in D3D9) and pick a cached pipeline; the program's
 * uniform block takes a new slice of the frame's ring only when a value it reads changed; the
 * descriptor set is written only when the ring's buffer, a texture or a sampler changed. So a
 * pass applied again with nothing changed records binds (pipeline, set, dynamic offset, dynamic
 * states) and writes no memory and no descriptor. */
#include <stdlib.h>
#include <string.h>

#include "eval_code.h"
#include "spirv_loc.h"
#include "vk/vk.h"

static int fail(hfx_device *dev, int code, const char *msg) { return hfx_rt_fail(dev, code, "hfx_pass_apply_vk: %s", msg); }

static void apply_render_states(hfx_effect *fx, const hfx_fx_pass *fp) {
    const hfx_fx_effect *e = fx->sh->fx;
    for (uint32_t i = 0; i < fp->state_count && fp->first_state + i < e->state_count; i++) {
        const hfx_fx_state *st = &e->states[fp->first_state + i];
        const hfx_state_info *info = hfx_state_by_id(st->id);
        if (info && info->scope == HFX_SS_RENDER && st->kind != HFX_FX_VALUE_UNSUPPORTED && st->id < HFX_ST_COUNT_)
            hfx_rs_resolve(fx, st, &fx->dev->rs[st->id]);
    }
}

/* The array index a VertexShader / PixelShader EXPR state gives now, HFX_NONE when none. */
static uint32_t selected(const hfx_effect *fx, const hfx_fx_pass *fp, uint32_t id) {
    const hfx_fx_effect *e = fx->sh->fx;
    for (uint32_t i = 0; i < fp->state_count && fp->first_state + i < e->state_count; i++) {
        const hfx_fx_state *st = &e->states[fp->first_state + i];
        if (st->id != id || st->kind != HFX_FX_VALUE_EXPR) continue;
        return hfx_rs_selected(fx, fp->first_state + i, (uint32_t)(fp - e->passes), id == HFX_ST_PIXELSHADER);
    }
    return HFX_NONE;
}

/* The pass's program: its own (*fixed), or the shader-array variant its selectors pick now. */
static int choose_program(hfx_pass *p, uint32_t *out, int *kept, int *fixed) {
    const hfx_fx_effect *e = p->fx->sh->fx;
    const hfx_fx_pass *fp = &e->passes[p->index];
    int variants = 0;
    for (uint32_t i = 0; i < e->variant_count && !variants; i++) variants = e->variants[i].pass == p->index;
    *out = fp->program;
    *kept = !variants && fp->program >= e->program_count && p->fx->vk->last_program;
    if (*kept) *out = p->fx->vk->last_program - 1; /* the shaders stay set */
    *fixed = !variants && !*kept;
    if (!variants)
        return *out < e->program_count ? HFX_OK : fail(p->fx->dev, HFX_ERR_NOT_FOUND, "the pass sets no shaders");
    uint32_t vs = selected(p->fx, fp, HFX_ST_VERTEXSHADER), ps = selected(p->fx, fp, HFX_ST_PIXELSHADER);
    for (uint32_t i = 0; i < e->variant_count; i++)
        if (e->variants[i].pass == p->index && e->variants[i].vs == vs && e->variants[i].ps == ps)
            return *out = e->variants[i].program, HFX_OK;
    return hfx_rt_fail(p->fx->dev, HFX_ERR_NOT_FOUND, "no program for shader array entries %d and %d (only those the "
                       "compiler reached by the driving parameter exist)", (int)vs, (int)ps);
}

/* chosen_seen for a pass whose program is its own, whatever the parameters hold. */
#define FIXED_PROGRAM UINT64_MAX

/* The same, worked out again only after a parameter changed (the change log grew): a game's
 * per-draw Apply does not re-run the selectors or scan the variants; a pass without shader
 * arrays, never again. */
static int program_of(hfx_pass *p, uint32_t *out) {
    uint64_t now = p->fx->log_len + 1;
    if (p->chosen_seen == now || p->chosen_seen == FIXED_PROGRAM) return *out = p->chosen_index, HFX_OK;
    int kept = 0, fixed = 0, rc = choose_program(p, out, &kept, &fixed);
    if (rc == HFX_OK && !kept) p->chosen_index = *out, p->chosen_seen = fixed ? FIXED_PROGRAM : now;
    return rc;
}

static int bound_of(hfx_effect *fx, uint32_t index, vk_bound **out) {
    vk_bound **slot = &fx->vk->bound[index];
    if (!*slot) {
        int rc = hfx_vk_bound_make(fx, &fx->sh->vk->programs[index], slot);
        if (rc) return rc;
    }
    *out = *slot;
    return HFX_OK;
}

/* The texture parameter a program sampler reads: `Texture[unit] = <t>` in the pass, else its
 * sampler_state's Texture, else a texture set on the sampler parameter itself. */
static uint32_t texture_param(const hfx_effect *fx, const hfx_fx_pass *fp, const hfx_fx_sampler_use *use) {
    const hfx_fx_effect *e = fx->sh->fx;
    for (uint32_t i = 0; i < fp->state_count && fp->first_state + i < e->state_count; i++) {
        const hfx_fx_state *st = &e->states[fp->first_state + i];
        if (st->id == HFX_ST_TEXTURE && st->kind == HFX_FX_VALUE_PARAM && (int32_t)st->index == use->unit &&
            st->ref < e->param_count)
            return st->ref;
    }
    const hfx_fx_sampler *s = &e->samplers[use->sampler];
    if (s->texture_param != HFX_NONE && s->texture_param < e->param_count && fx->textures[s->texture_param])
        return s->texture_param;
    return s->param;
}

static int sampler_of(hfx_effect *fx, uint32_t index, VkSampler *out) {
    const vk_fx_sampler *s = &fx->sh->vk->samplers[index];
    hfx_sampler_desc d = s->base;
    for (uint32_t i = 0; i < s->dynamic_count; i++) {
        hfx_rs_value v;
        hfx_rs_resolve(fx, s->dynamic[i], &v);
        hfx_sampler_desc_apply(&d, s->dynamic[i]->id, &v);
    }
    return hfx_vk_sampler(fx->dev, &d, out);
}

/* What each sampler binding holds now; *changed when that differs from the set's. */
static int gather_textures(hfx_effect *fx, const hfx_fx_pass *fp, const vk_program *p, vk_bound *b, int *changed) {
    for (uint32_t k = 0; k < p->sampler_count; k++) {
        const hfx_fx_sampler_use *use = &p->fp->samplers[k];
        if (use->sampler >= fx->sh->fx->sampler_count) return fail(fx->dev, HFX_ERR_LOAD, "a program names no sampler");
        uint32_t t = texture_param(fx, fp, use);
        VkImageView view = (VkImageView)(uintptr_t)fx->textures[t];
        VkImageLayout layout = (VkImageLayout)fx->texture_layouts[t];
        uint8_t dim = p->sampler_dims[k] == HFX_FX_DIM_1D ? HFX_FX_DIM_2D : p->sampler_dims[k];
        /* The application's view is of the kind hfx_param_texture_target told it (the table made
         * at load); a program that samples the texture as another kind reads what GL's empty
         * target of that kind gives. */
        if (view && fx->sh->vk->texture_dims[t] != (int8_t)dim) view = VK_NULL_HANDLE;
        if (!view) { /* none set: the default of the sampler's dimension, (0, 0, 0, 1) as D3D9 */
            view = fx->dev->vk->defaults[dim <= HFX_FX_DIM_CUBE ? dim : HFX_FX_DIM_2D].view;
            layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        }
        if (!view)
            return hfx_rt_fail(fx->dev, HFX_ERR_NOT_FOUND, "hfx_pass_apply_vk: sampler '%s' has no texture "
                               "(hfx_param_set_texture_vk; or hfx_vulkan_desc.queue for the default textures)",
                               fx->sh->fx->params[fx->sh->fx->samplers[use->sampler].param].name);
        VkSampler s;
        int rc = sampler_of(fx, use->sampler, &s);
        if (rc) return rc;
        if (b->views[k] != view || b->layouts[k] != layout || b->vk_samplers[k] != s) *changed = 1;
        b->views[k] = view, b->layouts[k] = layout, b->vk_samplers[k] = s;
    }
    return HFX_OK;
}

static int write_set(hfx_device *dev, const vk_program *p, vk_bound *b) {
    int rc = hfx_vk_descriptor_set(dev, p->set_layout, &b->set);
    if (rc) return rc;
    VkWriteDescriptorSet w[1 + 32];
    VkDescriptorImageInfo img[32];
    VkDescriptorBufferInfo buf = {b->buffer, 0, p->block_size};
    uint32_t n = 0;
    if (p->block_size)
        w[n++] = (VkWriteDescriptorSet){.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = b->set,
                                        .dstBinding = HFX_VK_BINDING_BLOCK, .descriptorCount = 1,
                                        .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, .pBufferInfo = &buf};
    for (uint32_t k = 0; k < p->sampler_count; k++) {
        img[k] = (VkDescriptorImageInfo){b->vk_samplers[k], b->views[k], b->layouts[k]};
        w[n++] = (VkWriteDescriptorSet){.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = b->set,
                                        .dstBinding = HFX_VK_BINDING_SAMPLER0 + k, .descriptorCount = 1,
                                        .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, .pImageInfo = &img[k]};
    }
    dev->vk->fn.UpdateDescriptorSets(dev->vk->device, n, w, 0, NULL);
    dev->vk->sets_written++;
    return HFX_OK;
}

/* A new slice when the block changed or the frame moved on; a new set when its contents did. */
static int update_resources(hfx_device *dev, const vk_program *p, vk_bound *b, int textures_changed) {
    struct hfx_vk_device *vk = dev->vk;
    int new_frame = b->frame != vk->serial;
    int need_set = new_frame || textures_changed || !b->set;
    if (p->block_size && (b->dirty || new_frame)) {
        VkBuffer buffer;
        uint8_t *map;
        int rc = hfx_vk_slice(dev, p->block_size, &buffer, &b->offset, &map);
        if (rc) return rc;
        memcpy(map, b->image, p->block_size);
        vk->slices_written++;
        if (buffer != b->buffer) need_set = 1;
        b->buffer = buffer;
        b->dirty = 0;
    }
    b->frame = vk->serial;
    return need_set ? write_set(dev, p, b) : HFX_OK;
}

/* D3D's DepthBias is in depth units; Vulkan's constant factor counts the format's resolution. */
static float depth_bias_units(VkFormat f, float bias) {
    if (f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D16_UNORM_S8_UINT) return bias * 65536.0f;
    return bias * 16777216.0f;
}

static void record(hfx_device *dev, VkCommandBuffer cmd, const vk_program *p, const vk_bound *b, const vk_pso *pso,
                   const hfx_vk_target *t) {
    const hfx_vk_fns *fn = &dev->vk->fn;
    const hfx_rs_value *rs = dev->rs;
    fn->CmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pso->pipeline);
    VkViewport vp = {0, 0, (float)t->width, (float)t->height, 0.0f, 1.0f};
    fn->CmdSetViewport(cmd, 0, 1, &vp);
    VkRect2D full = {{0, 0}, {t->width, t->height}};
    fn->CmdSetScissor(cmd, 0, 1, rs[HFX_ST_SCISSORTESTENABLE].i ? &t->scissor : &full);
    /* the other dynamic states only when the pipeline reads them (each is a command to record) */
    const vk_states *st = &pso->key.st;
    if (st->stencil) fn->CmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, (uint32_t)rs[HFX_ST_STENCILREF].i);
    if (st->blend) fn->CmdSetBlendConstants(cmd, rs[HFX_ST_BLENDFACTOR].f);
    if (st->depth_bias)
        fn->CmdSetDepthBias(cmd, depth_bias_units(t->depth_format, rs[HFX_ST_DEPTHBIAS].f[0]), 0.0f,
                            rs[HFX_ST_SLOPESCALEDEPTHBIAS].f[0]);
    fn->CmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p->layout, 0, 1, &b->set, p->block_size ? 1 : 0,
                              &b->offset);
    if (pso->needs_zero) {
        VkDeviceSize zero = 0;
        fn->CmdBindVertexBuffers(cmd, VK_ZERO_BINDING, 1, &dev->vk->zero.buffer, &zero);
    }
}

static void key_of(hfx_device *dev, const vk_program *p, const hfx_vk_target *t, vk_pso_key *k) {
    memset(k, 0, sizeof *k);
    k->program = p;
    k->layout = t->layout;
    k->render_pass = t->render_pass;
    k->subpass = t->subpass;
    k->color_count = t->color_count;
    k->samples = t->samples ? (uint32_t)t->samples : VK_SAMPLE_COUNT_1_BIT;
    memcpy(k->color, t->color_formats, t->color_count * sizeof *k->color);
    k->depth = t->depth_format;
    hfx_vk_states_of(dev->rs, &k->st);
}

static const char *check_target(const hfx_vk_target *t) {
    if (t->color_count > 4) return "at most 4 colour attachments";
    if (!t->width || !t->height) return "the target needs a width and a height (the viewport)";
    return NULL;
}

/* The table's pass_apply, reached from hfx_pass_apply: it has no command buffer to record into. */
int hfx_vk_pass_apply(hfx_pass *p) {
    return hfx_rt_fail(p->fx->dev, HFX_ERR_NOT_FOUND, "hfx_pass_apply: this device is Vulkan's; apply its passes "
                       "with hfx_pass_apply_vk");
}

/* The target's fields the pipeline depends on (the viewport and scissor are dynamic states). */
static int same_pipeline_target(const hfx_vk_target *a, const hfx_vk_target *b) {
    return a->render_pass == b->render_pass && a->subpass == b->subpass && a->color_count == b->color_count &&
           a->depth_format == b->depth_format && a->samples == b->samples && a->layout == b->layout &&
           memcmp(a->color_formats, b->color_formats, a->color_count * sizeof *a->color_formats) == 0;
}

/* Render states that read no parameter: applying the pass again writes the same values. */
static int states_fixed(const hfx_effect *fx, const hfx_fx_pass *fp) {
    const hfx_fx_effect *e = fx->sh->fx;
    for (uint32_t i = 0; i < fp->state_count && fp->first_state + i < e->state_count; i++) {
        const hfx_fx_state *st = &e->states[fp->first_state + i];
        const hfx_state_info *info = hfx_state_by_id(st->id);
        if (info && info->scope == HFX_SS_RENDER && (st->kind == HFX_FX_VALUE_PARAM || st->kind == HFX_FX_VALUE_EXPR))
            return 0;
    }
    return 1;
}

/* The pipeline for prog: on the short way (the same pass again, on a target of the same formats,
 * with no state set since) the last one, without building and comparing its key; otherwise
 * looked up, and the pass becomes the device's last when its render states read no parameter. */
static int pipeline_of(hfx_pass *p, const vk_program *prog, uint32_t index, const hfx_vk_target *t, int quick,
                       const vk_pso **out) {
    hfx_device *dev = p->fx->dev;
    struct hfx_vk_device *vk = dev->vk;
    if (quick && vk->quick_program == index && vk->last_pso < vk->pso_count) {
        *out = &vk->psos[vk->last_pso];
        return HFX_OK;
    }
    vk_pso_key key;
    key_of(dev, prog, t, &key);
    int rc = hfx_vk_pipeline(dev, &key, out);
    if (rc) return rc;
    if (states_fixed(p->fx, &p->fx->sh->fx->passes[p->index])) {
        dev->applied = p;
        vk->quick_target = *t;
        vk->quick_program = index;
    }
    return HFX_OK;
}

/* Apply recorded into cmd; hfx_pass_apply_vk has checked that the device is Vulkan's and that
 * cmd and t are set. */
static int apply_vk(hfx_pass *p, VkCommandBuffer cmd, const hfx_vk_target *t) {
    hfx_effect *fx = p->fx;
    hfx_device *dev = fx->dev;
    if (!dev->vk->serial) return fail(dev, HFX_ERR_NOT_FOUND, "call hfx_device_begin_frame_vk before the first Apply");
    const char *bad = check_target(t);
    if (bad) return fail(dev, HFX_ERR_COUNT, bad);
    const hfx_fx_pass *fp = &fx->sh->fx->passes[p->index];
    int quick = dev->applied == p && same_pipeline_target(&dev->vk->quick_target, t);
    if (!quick) { /* the device's states are this pass's already on the short way */
        dev->applied = NULL;
        apply_render_states(fx, fp);
    }
    uint32_t index;
    int changed = 0, rc = program_of(p, &index);
    if (rc) return rc;
    const vk_program *prog = &fx->sh->vk->programs[index];
    vk_bound *b;
    rc = bound_of(fx, index, &b);
    if (!rc) rc = gather_textures(fx, fp, prog, b, &changed);
    if (rc) return rc;
    hfx_vk_uniforms_update(fx, prog, b, t);
    if ((rc = update_resources(dev, prog, b, changed))) return rc;
    const vk_pso *pso;
    if ((rc = pipeline_of(p, prog, index, t, quick, &pso))) return rc;
    record(dev, cmd, prog, b, pso, t);
    fx->vk->last_program = index + 1;
    return HFX_OK;
}

int hfx_pass_apply_vk(hfx_pass *p, VkCommandBuffer cmd, const hfx_vk_target *t) {
    if (!p || !cmd || !t) return p ? fail(p->fx->dev, HFX_ERR_NULL, "NULL command buffer or target") : HFX_ERR_NULL;
    if (!p->fx->dev->vk) return fail(p->fx->dev, HFX_ERR_NOT_FOUND, "the effect was not loaded on a Vulkan device");
    return apply_vk(p, cmd, t);
}
