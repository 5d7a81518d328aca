/* effect.c: owning and querying the compiled effect (effect.h). */
#include "effect.h"

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "eval_code.h"

void hfx_fx_program_clear(hfx_fx_program *p) {
    if (!p) return;
    for (int s = 0; s < HFX_STAGE_COUNT; s++)
        for (int t = 0; t < HFX_TARGET_COUNT; t++) free(p->code[s][t].data);
    for (int s = 0; s < HFX_STAGE_COUNT; s++) free(p->d3d9[s].data);
    for (uint32_t a = 0; a < p->attribute_count; a++) {
        free(p->attributes[a].semantic);
        free(p->attributes[a].glsl_name);
    }
    free(p->attributes);
    for (uint32_t a = 0; a < p->sampler_count; a++) free(p->samplers[a].glsl_name);
    free(p->samplers);
    free(p->uniforms);
    free(p->preshaders);
    free(p->pre_code);
    memset(p, 0, sizeof *p);
}

void hfx_fx_effect_free(hfx_fx_effect *fx) {
    if (!fx) return;
    free(fx->source_name);
    for (uint32_t i = 0; fx->params && i < fx->param_count; i++) {
        free(fx->params[i].name);
        free(fx->params[i].semantic);
        free(fx->params[i].glsl_name);
        free(fx->params[i].string);
        free(fx->params[i].file);
        free(fx->params[i].d3d9.data);
    }
    free(fx->params);
    free(fx->values);
    free(fx->exprs);
    free(fx->variants);
    for (uint32_t i = 0; fx->annotations && i < fx->annotation_count; i++) {
        free(fx->annotations[i].name);
        free(fx->annotations[i].data);
        free(fx->annotations[i].string);
    }
    free(fx->annotations);
    free(fx->states);
    free(fx->samplers);
    for (uint32_t i = 0; fx->programs && i < fx->program_count; i++) hfx_fx_program_clear(&fx->programs[i]);
    free(fx->programs);
    for (uint32_t i = 0; fx->passes && i < fx->pass_count; i++) free(fx->passes[i].name);
    free(fx->passes);
    for (uint32_t i = 0; fx->techniques && i < fx->technique_count; i++) free(fx->techniques[i].name);
    free(fx->techniques);
    free(fx);
}

uint32_t hfx_fx_param_find(const hfx_fx_effect *fx, const char *name) {
    if (!fx || !name) return HFX_NONE;
    for (uint32_t i = 0; i < fx->top_param_count; i++)
        if (fx->params[i].name && strcmp(fx->params[i].name, name) == 0) return i;
    return HFX_NONE;
}

/* The top-level parameter holding value word `word`, or HFX_NONE. */
static uint32_t param_at_word(const hfx_fx_effect *fx, uint32_t word) {
    for (uint32_t i = 0; fx && i < fx->top_param_count && i < fx->param_count; i++)
        if (word >= fx->params[i].offset && word - fx->params[i].offset < fx->params[i].words) return i;
    return HFX_NONE;
}

uint32_t hfx_fx_param_read_at(const hfx_fx_effect *fx, const uint32_t *code, uint32_t at) {
    uint32_t op = code[at] & 0xffu;
    return op == HFX_EVC_PARAM || op == HFX_EVC_ELEMENT ? param_at_word(fx, code[at + 1]) : HFX_NONE;
}

int hfx_fx_param_evaluable(const hfx_fx_param *p) {
    bool numeric = p->klass == HFX_CLASS_SCALAR || p->klass == HFX_CLASS_VECTOR || p->klass == HFX_CLASS_MATRIX;
    return numeric && p->words >= 1 && p->words <= HFX_EV_MAX_COMPONENTS;
}

uint32_t hfx_fx_param_packable(const hfx_fx_effect *fx, uint32_t i) {
    if (!fx || i >= fx->top_param_count || i >= fx->param_count) return 0;
    const hfx_fx_param *p = &fx->params[i];
    if (p->parent != HFX_NONE || p->elements || p->type != HFX_TYPE_FLOAT || !p->glsl_name) return 0;
    if (p->klass != HFX_CLASS_SCALAR && p->klass != HFX_CLASS_VECTOR && p->klass != HFX_CLASS_MATRIX) return 0;
    if (p->rows < 1 || p->rows > 4 || p->cols < 1 || p->cols > 4) return 0;
    if (p->klass != HFX_CLASS_MATRIX && p->rows != 1) return 0;
    return p->klass == HFX_CLASS_MATRIX ? p->rows : 1;
}

int hfx_fx_param_switchable(const hfx_fx_effect *fx, uint32_t i) {
    if (!fx || i >= fx->top_param_count || i >= fx->param_count) return 0;
    const hfx_fx_param *p = &fx->params[i];
    return p->parent == HFX_NONE && !p->elements && p->type == HFX_TYPE_BOOL && p->klass == HFX_CLASS_SCALAR &&
           p->words == 1 && p->glsl_name;
}

/* A deep copy is a round trip through the .hfxo form: one code path to trust, not two. */
hfx_fx_effect *hfx_fx_effect_copy(const hfx_fx_effect *fx) {
    void *data = NULL;
    size_t size = 0;
    if (!fx || hfx_fx_write_hfxo(fx, &data, &size) != 0) return NULL;
    hfx_fx_effect *copy = hfx_fx_read_hfxo(data, size, NULL, 0);
    free(data);
    return copy;
}
