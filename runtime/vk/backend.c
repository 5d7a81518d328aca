/* backend.c: the Vulkan back end's table (internal.h's hfx_backend): an effect's shared part
 * becomes one vk_program per compiled program plus its samplers' descriptions; each instance
 * gets its per-program uniform state when a pass first applies it. */
#include <stdlib.h>
#include <string.h>

#include "vk/vk.h"

static int vk_shared_build(hfx_shared *sh, hfx_target target) {
    const hfx_fx_effect *fx = sh->fx;
    if (target != HFX_TARGET_SPIRV_VK)
        return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "a Vulkan device loads the spirv-vk target only");
    sh->vk = calloc(1, sizeof *sh->vk);
    if (!sh->vk) return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    sh->vk->programs = calloc(fx->program_count ? fx->program_count : 1, sizeof *sh->vk->programs);
    sh->vk->samplers = calloc(fx->sampler_count ? fx->sampler_count : 1, sizeof *sh->vk->samplers);
    sh->vk->texture_dims = malloc(fx->param_count ? fx->param_count : 1);
    if (!sh->vk->programs || !sh->vk->samplers || !sh->vk->texture_dims)
        return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    for (uint32_t i = 0; i < fx->param_count; i++) { /* no sampler names it (a pass's Texture[n]): 2D */
        int dim = hfx_rt_texture_dim(fx, i);
        sh->vk->texture_dims[i] = (int8_t)(dim < 0 ? HFX_FX_DIM_2D : dim);
    }
    for (uint32_t i = 0; i < fx->program_count; i++) {
        sh->vk->program_count = i + 1;
        int rc = hfx_vk_program_build(sh, i);
        if (rc) return rc;
    }
    hfx_vk_fx_samplers_make(sh);
    return HFX_OK;
}

static void vk_shared_release(hfx_shared *sh) {
    if (!sh->vk) return;
    for (uint32_t i = 0; sh->vk->programs && i < sh->vk->program_count; i++) {
        hfx_vk_pipelines_forget(sh->dev, &sh->vk->programs[i]);
        hfx_vk_program_free(sh->dev, &sh->vk->programs[i]);
    }
    free(sh->vk->programs);
    free(sh->vk->samplers);
    free(sh->vk->texture_dims);
    free(sh->vk);
    sh->vk = NULL;
}

static int vk_instance_init(hfx_effect *e) {
    e->vk = calloc(1, sizeof *e->vk);
    uint32_t n = e->sh->fx->program_count;
    if (e->vk) e->vk->bound = calloc(n ? n : 1, sizeof *e->vk->bound);
    if (e->vk && e->vk->bound) return e->vk->bound_count = n, HFX_OK;
    free(e->vk);
    e->vk = NULL;
    return hfx_rt_fail(e->dev, HFX_ERR_MEMORY, "out of memory");
}

static void vk_instance_free(hfx_effect *e) {
    if (!e->vk) return;
    for (uint32_t i = 0; e->vk->bound && i < e->vk->bound_count; i++) hfx_vk_bound_free(e->vk->bound[i]);
    free(e->vk->bound);
    free(e->vk);
    e->vk = NULL;
}

/* Whatever target the options ask for, Vulkan loads its own. */
static hfx_target vk_target_for(hfx_target asked) {
    (void)asked;
    return HFX_TARGET_SPIRV_VK;
}

static void vk_destroy(hfx_device *dev) { hfx_vk_device_destroy(dev); }

/* D3DX's Begin / End: the render states the passes set are put back at End (the core's
 * apply.c checks the order). */
static int vk_effect_begin(hfx_effect *e) {
    memcpy(e->vk->saved, e->dev->rs, sizeof e->vk->saved);
    return HFX_OK;
}

static int vk_effect_end(hfx_effect *e) {
    memcpy(e->dev->rs, e->vk->saved, sizeof e->vk->saved);
    e->dev->applied = NULL; /* the states changed under the last pass */
    return HFX_OK;
}

/* Reload between begin and end: end restores what the old instance's begin saved. */
static void vk_begun_carry(hfx_effect *to, const hfx_effect *from) {
    memcpy(to->vk->saved, from->vk->saved, sizeof to->vk->saved);
}

const hfx_backend hfx_vk_backend = {
    .name = "Vulkan",
    .shared_build = vk_shared_build,
    .shared_release = vk_shared_release,
    .instance_init = vk_instance_init,
    .instance_free = vk_instance_free,
    .device_destroy = vk_destroy,
    .target_for = vk_target_for,
    .pass_apply = hfx_vk_pass_apply,
    .effect_begin = vk_effect_begin,
    .effect_end = vk_effect_end,
    .begun_carry = vk_begun_carry,
};

int hfx_param_set_texture_vk(hfx_param *p, VkImageView view, VkImageLayout layout) {
    if (!p) return HFX_ERR_NULL;
    if (!p->fx->dev->vk) return hfx_rt_fail(p->fx->dev, HFX_ERR_TYPE, "hfx_param_set_texture_vk: not a Vulkan device");
    if (!(p->accept & ACC_TEXTURE)) return hfx_rt_fail(p->fx->dev, HFX_ERR_TYPE, "'%s': not a texture or sampler", p->info->name);
    p->fx->textures[p->index] = (uint64_t)(uintptr_t)view;
    p->fx->texture_layouts[p->index] = (uint32_t)layout;
    if (p->fx->pool) hfx_rt_pool_share(p->fx, p->root);
    return HFX_OK;
}
