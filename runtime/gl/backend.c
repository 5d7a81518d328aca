/* backend.c: the OpenGL back end's table (internal.h's hfx_backend): an effect's shared part
 * becomes GL programs, sampler objects and passes ready for Apply (hfx_shared.gl); each
 * instance gets room for what begin saves (hfx_effect.gl). */
#include <stdlib.h>

#include "gl/gl_int.h"

/* Every program, then the samplers, then the passes (which name both); GL errors left behind
 * by a failed step are drained so the next call starts clean. */
static int gl_shared_build(hfx_shared *sh, hfx_target target) {
    const hfx_fx_effect *fx = sh->fx;
    if (target == HFX_TARGET_SPIRV && hfx_rt_spirv_check(sh->dev, fx)) return HFX_ERR_GL;
    sh->gl = calloc(1, sizeof *sh->gl);
    if (!sh->gl) return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    sh->gl->programs = calloc(fx->program_count ? fx->program_count : 1, sizeof *sh->gl->programs);
    sh->gl->passes = calloc(fx->pass_count ? fx->pass_count : 1, sizeof *sh->gl->passes);
    if (!sh->gl->programs || !sh->gl->passes) return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    uint32_t cap = 0;
    int rc = HFX_OK;
    for (uint32_t i = 0; i < fx->program_count && !rc; i++)
        rc = target == HFX_TARGET_SPIRV ? hfx_rt_spirv_program_build(sh, i) : hfx_rt_program_build(sh, i, target);
    if (!rc) rc = hfx_rt_samplers_make(sh, &cap);
    for (uint32_t i = 0; i < fx->pass_count && !rc; i++) rc = hfx_rt_pass_build(sh, &cap, i);
    while (sh->dev->gl->fn.GetError() != GL_NO_ERROR) {}
    return rc;
}

static void gl_shared_release(hfx_shared *sh) {
    hfx_device *dev = sh->dev;
    if (!sh->gl) return;
    if (sh->gl->programs)
        for (uint32_t i = 0; i < sh->fx->program_count; i++) hfx_rt_program_free(dev, &sh->gl->programs[i]);
    free(sh->gl->programs);
    for (uint32_t i = 0; i < sh->gl->sampler_count; i++) hfx_rt_sampler_free(dev, &sh->gl->samplers[i]);
    free(sh->gl->samplers);
    if (sh->gl->passes)
        for (uint32_t i = 0; i < sh->fx->pass_count; i++) {
            free(sh->gl->passes[i].render_states);
            free(sh->gl->passes[i].bindings);
        }
    free(sh->gl->passes);
    free(sh->gl);
    sh->gl = NULL;
}

/* The instance's passes point at the shared part's, ready for Apply. */
static int gl_instance_init(hfx_effect *e) {
    e->gl = calloc(1, sizeof *e->gl);
    if (!e->gl) return hfx_rt_fail(e->dev, HFX_ERR_MEMORY, "out of memory");
    for (uint32_t i = 0; i < e->sh->fx->pass_count; i++) e->passes[i].rt = &e->sh->gl->passes[i];
    return HFX_OK;
}

static void gl_instance_free(hfx_effect *e) {
    free(e->gl);
    e->gl = NULL;
}

static hfx_target gl_target_for(hfx_target asked) { return asked; }

const hfx_backend hfx_gl_backend = {
    .name = "OpenGL",
    .shared_build = gl_shared_build,
    .shared_release = gl_shared_release,
    .instance_init = gl_instance_init,
    .instance_free = gl_instance_free,
    .device_destroy = hfx_gl_device_destroy,
    .target_for = gl_target_for,
    .cache_usable = hfx_rt_program_cache_usable,
    .pass_apply = hfx_gl_pass_apply,
    .effect_begin = hfx_gl_effect_begin,
    .effect_end = hfx_gl_effect_end,
    .begun_carry = hfx_gl_begun_carry,
    .texture_target = hfx_gl_texture_target,
};
