#include "effect.h"

#include <stdlib.h>
#include <string.h>

void hfx_fx_effect_free(hfx_fx_effect *fx) {
    if (!fx) return;
    free(fx->source_name);
    for (uint32_t i = 0; i < fx->param_count; i++) {
        free(fx->params[i].name);
        free(fx->params[i].semantic);
        free(fx->params[i].glsl_name);
    }
    free(fx->params);
    free(fx->values);
    for (uint32_t i = 0; i < fx->annotation_count; i++) {
        free(fx->annotations[i].name);
        free(fx->annotations[i].data);
        free(fx->annotations[i].string);
    }
    free(fx->annotations);
    free(fx->states);
    free(fx->samplers);
    for (uint32_t i = 0; i < fx->program_count; i++) {
        hfx_fx_program *p = &fx->programs[i];
        for (int s = 0; s < HFX_STAGE_COUNT; s++)
            for (int t = 0; t < HFX_TARGET_COUNT; t++) free(p->code[s][t].data);
        for (uint32_t a = 0; a < p->attribute_count; a++) {
            free(p->attributes[a].semantic);
            free(p->attributes[a].glsl_name);
        }
        free(p->attributes);
        for (uint32_t a = 0; a < p->sampler_count; a++) free(p->samplers[a].glsl_name);
        free(p->samplers);
        free(p->uniforms);
    }
    free(fx->programs);
    for (uint32_t i = 0; i < fx->pass_count; i++) free(fx->passes[i].name);
    free(fx->passes);
    for (uint32_t i = 0; i < fx->technique_count; i++) free(fx->techniques[i].name);
    free(fx->techniques);
    free(fx);
}

uint32_t hfx_fx_param_find(const hfx_fx_effect *fx, const char *name) {
    if (!fx || !name) return HFX_NONE;
    for (uint32_t i = 0; i < fx->top_param_count; i++)
        if (fx->params[i].name && strcmp(fx->params[i].name, name) == 0) return i;
    return HFX_NONE;
}
