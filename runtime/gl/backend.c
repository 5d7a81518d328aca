/* backend.c: the OpenGL back end's table (internal.h's hfx_backend): an effect's shared part
 * becomes GL programs, sampler objects and passes ready for Apply. */
#include <stdlib.h>

#include "internal.h"

/* Every program, then the samplers, then the passes (which name both); GL errors left behind
 * by a failed step are drained so the next call starts clean. */
static int gl_shared_build(hfx_shared *sh, hfx_target target) {
    const hfx_fx_effect *fx = sh->fx;
    if (target == HFX_TARGET_SPIRV && hfx_rt_spirv_check(sh->dev, fx)) return HFX_ERR_GL;
    sh->programs = calloc(fx->program_count ? fx->program_count : 1, sizeof *sh->programs);
    sh->passes = calloc(fx->pass_count ? fx->pass_count : 1, sizeof *sh->passes);
    if (!sh->programs || !sh->passes) return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    uint32_t cap = 0;
    int rc = HFX_OK;
    for (uint32_t i = 0; i < fx->program_count && !rc; i++)
        rc = target == HFX_TARGET_SPIRV ? hfx_rt_spirv_program_build(sh, i) : hfx_rt_program_build(sh, i, target);
    if (!rc) rc = hfx_rt_samplers_make(sh, &cap);
    for (uint32_t i = 0; i < fx->pass_count && !rc; i++) rc = hfx_rt_pass_build(sh, &cap, i);
    while (sh->dev->gl.GetError() != GL_NO_ERROR) {}
    return rc;
}

static void gl_shared_release(hfx_shared *sh) {
    hfx_device *dev = sh->dev;
    if (sh->programs)
        for (uint32_t i = 0; i < sh->fx->program_count; i++) hfx_rt_program_free(dev, &sh->programs[i]);
    free(sh->programs);
    for (uint32_t i = 0; i < sh->sampler_count; i++) hfx_rt_sampler_free(dev, &sh->samplers[i]);
    free(sh->samplers);
    if (sh->passes)
        for (uint32_t i = 0; i < sh->fx->pass_count; i++) {
            free(sh->passes[i].render_states);
            free(sh->passes[i].bindings);
        }
    free(sh->passes);
}

static hfx_target gl_target_for(hfx_target asked) { return asked; }

const hfx_backend hfx_gl_backend = {
    "OpenGL", gl_shared_build, gl_shared_release, NULL, NULL, hfx_gl_device_destroy, gl_target_for,
    hfx_rt_program_cache_usable, hfx_rt_save_units, NULL, NULL,
};
