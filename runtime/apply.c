/* apply.c: Passes[i].Apply(), Begin and End for every back end. The core checks the handles
 * and the order of the calls (D3DX refuses a second Begin before End), and the back end's table
 * does the work: GL's Apply keeps its own short way for a pass applied again (gl/apply.c), so
 * the dispatch costs one indirect call per Apply. Vulkan's Apply records into a command buffer,
 * so it has its own entry (hfx_pass_apply_vk, vk/apply.c) and refuses hfx_pass_apply. */
#include "internal.h"

int hfx_pass_apply(hfx_pass *p) {
    if (!p) return HFX_ERR_NULL;
    return p->fx->dev->be->pass_apply(p);
}

/* A second snapshot would make end restore the effect's own states rather than the
 * application's, so a second begin is refused (hfx_device_sync re-reads GL state instead). */
int hfx_effect_begin(hfx_effect *fx) {
    if (!fx) return HFX_ERR_NULL;
    if (fx->begun)
        return hfx_rt_fail(fx->dev, HFX_ERR_STATE, "hfx_effect_begin twice without hfx_effect_end (%s)",
                           hfx_result_string(HFX_ERR_STATE));
    int rc = fx->dev->be->effect_begin(fx);
    if (rc == HFX_OK) fx->begun = 1;
    return rc;
}

int hfx_effect_end(hfx_effect *fx) {
    if (!fx) return HFX_ERR_NULL;
    if (!fx->begun)
        return hfx_rt_fail(fx->dev, HFX_ERR_STATE, "hfx_effect_end without hfx_effect_begin (%s)",
                           hfx_result_string(HFX_ERR_STATE));
    fx->begun = 0;
    return fx->dev->be->effect_end(fx);
}
