/* param_paths.c: a parameter's leaves by the names the generated GLSL gives them ("name",
 * "s.member", "a[2].member"), for the back ends that match parameters to uniforms by name:
 * GL's active uniforms, Vulkan's uniform block members (vk/reflect.c). */
#include <stdio.h>

#include "internal.h"

static int member_leaves(const hfx_fx_effect *fx, const hfx_fx_param *s, const char *path, hfx_param_leaf_fn leaf,
                         void *ctx) {
    for (uint32_t m = 0; m < s->child_count; m++) {
        const hfx_fx_param *member = &fx->params[s->first_child + m];
        char sub[300];
        int n = snprintf(sub, sizeof sub, "%s.%s", path, member->glsl_name ? member->glsl_name : member->name);
        if (n < 0 || (size_t)n >= sizeof sub) continue; /* longer than any name a back end reports */
        int rc = hfx_param_leaves(fx, s->first_child + m, sub, leaf, ctx);
        if (rc) return rc;
    }
    return HFX_OK;
}

int hfx_param_leaves(const hfx_fx_effect *fx, uint32_t index, const char *path, hfx_param_leaf_fn leaf, void *ctx) {
    const hfx_fx_param *p = &fx->params[index];
    if (p->klass == HFX_CLASS_OBJECT) return HFX_OK;
    if (p->elements && p->child_count && fx->params[p->first_child].klass == HFX_CLASS_STRUCT) {
        for (uint32_t e = 0; e < p->child_count; e++) {
            char sub[300];
            int n = snprintf(sub, sizeof sub, "%s[%u]", path, (unsigned)e);
            if (n < 0 || (size_t)n >= sizeof sub) continue;
            int rc = member_leaves(fx, &fx->params[p->first_child + e], sub, leaf, ctx);
            if (rc) return rc;
        }
        return HFX_OK;
    }
    if (p->klass == HFX_CLASS_STRUCT) return member_leaves(fx, p, path, leaf, ctx);
    return leaf(ctx, path, p);
}
