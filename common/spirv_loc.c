/* spirv_loc.c: SPIR-V uniform locations; see spirv_loc.h. */
#include "spirv_loc.h"

#include <string.h>

/* Small: the builder caps parameters at 2^20 values and 2^16 elements and members. */
static uint64_t param_locations(const hfx_fx_effect *fx, uint32_t i, int depth) {
    if (i >= fx->param_count || depth > 64) return 0;
    const hfx_fx_param *p = &fx->params[i];
    if (p->elements) {
        uint64_t each = p->child_count ? param_locations(fx, p->first_child, depth + 1) : 1;
        return each * p->elements;
    }
    if (p->klass == HFX_CLASS_STRUCT) {
        uint64_t n = 0;
        for (uint32_t c = 0; c < p->child_count; c++) n += param_locations(fx, p->first_child + c, depth + 1);
        return n;
    }
    return 1;
}

uint64_t hfx_fx_param_locations(const hfx_fx_effect *fx, uint32_t i) { return fx ? param_locations(fx, i, 0) : 0; }

/* Packed parameters (HFXC_PACK_UNIFORMS) take no location of their own: hfx_c holds them. */
int64_t hfx_fx_spirv_uniform(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *name, size_t len,
                             uint64_t *loc) {
    uint64_t at = 0;
    for (uint32_t k = 0; k < p->uniform_count; k++) {
        uint32_t param = p->uniforms[k].param;
        if (param >= fx->param_count || hfx_fx_use_packed(p, &p->uniforms[k])) continue;
        const char *g = fx->params[param].glsl_name;
        if (g && strlen(g) == len && strncmp(g, name, len) == 0) {
            *loc = at;
            return k;
        }
        at += param_locations(fx, param, 0);
    }
    *loc = at + p->reg_count;
    return -1;
}

uint64_t hfx_fx_spirv_regs_location(const hfx_fx_effect *fx, const hfx_fx_program *p) {
    if (!fx || !p) return 0;
    uint64_t end;
    hfx_fx_spirv_uniform(fx, p, "", 0, &end); /* no GLSL name is empty */
    return end - p->reg_count;
}

int hfx_fx_spirv_is_regs(const hfx_fx_program *p, const char *name, size_t len) {
    return p->reg_count && len == strlen(HFX_FX_REGS_NAME) && strncmp(name, HFX_FX_REGS_NAME, len) == 0;
}

int64_t hfx_fx_spirv_sampler(const hfx_fx_program *p, const char *name, size_t len) {
    for (uint32_t k = 0; k < p->sampler_count; k++) {
        const char *g = p->samplers[k].glsl_name;
        if (g && strlen(g) == len && strncmp(g, name, len) == 0) return k;
    }
    return -1;
}

static const char *const known_internal[HFX_SPIRV_KNOWN_COUNT] = {"hfx_pos_fixup", "hfx_alpha_func", "hfx_alpha_ref"};

int64_t hfx_fx_spirv_known(const char *name, size_t len) {
    for (uint32_t i = 0; i < HFX_SPIRV_KNOWN_COUNT; i++)
        if (strlen(known_internal[i]) == len && strncmp(known_internal[i], name, len) == 0) return i;
    return -1;
}

int32_t hfx_fx_spirv_location(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *glsl_name) {
    if (!fx || !p || !glsl_name) return -1;
    size_t len = strlen(glsl_name);
    uint64_t loc;
    int64_t k = hfx_fx_spirv_uniform(fx, p, glsl_name, len, &loc);
    if (k < 0 && hfx_fx_spirv_is_regs(p, glsl_name, len)) {
        loc = hfx_fx_spirv_regs_location(fx, p);
    } else if (k < 0) {
        int64_t smp = hfx_fx_spirv_sampler(p, glsl_name, len), known = hfx_fx_spirv_known(glsl_name, len);
        if (smp >= 0) loc += (uint64_t)smp;
        else if (known >= 0) loc += p->sampler_count + (uint64_t)known;
        else return -1;
    }
    return loc > INT32_MAX ? -1 : (int32_t)loc;
}
