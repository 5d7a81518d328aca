/* json.c: --annotations and --reflect, with cJSON (docs/annotations.md has the schema).
 * Everything comes from the compiled effect, so a .hfxo would describe itself the same way. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "cli.h"
#include "eval_code.h"
#include "states.h"

static const char *class_name(hfx_param_class k) {
    static const char *const names[] = {"scalar", "vector", "matrix", "object", "struct"};
    return (unsigned)k < sizeof names / sizeof *names ? names[k] : "unknown";
}

static const char *type_name(hfx_param_type t) {
    static const char *const names[] = {"void", "bool", "int", "float", "string", "texture", "texture1D",
                                        "texture2D", "texture3D", "textureCUBE", "sampler", "sampler1D",
                                        "sampler2D", "sampler3D", "samplerCUBE", "pixelshader", "vertexshader"};
    return (unsigned)t < sizeof names / sizeof *names ? names[t] : "unknown";
}

/* The shortest decimal that reads back as the same float: 0.05F prints as 0.05. */
static double short_float(float f) {
    char buf[32];
    for (int precision = 6; precision <= 9; precision++) {
        snprintf(buf, sizeof buf, "%.*g", precision, (double)f);
        double d = strtod(buf, NULL);
        if ((float)d == f) return d;
    }
    return f;
}

static cJSON *word_json(uint32_t w, hfx_param_type type) {
    if (type == HFX_TYPE_FLOAT) {
        float f;
        memcpy(&f, &w, sizeof f);
        return cJSON_CreateNumber(f != f ? 0.0 : short_float(f));
    }
    if (type == HFX_TYPE_BOOL) return cJSON_CreateBool(w != 0);
    return cJSON_CreateNumber((int32_t)w);
}

/* Numbers: one value for a scalar, a flat array (row-major) otherwise. */
static cJSON *words_json(const uint32_t *w, uint32_t n, hfx_param_type type, bool scalar) {
    if (scalar && n == 1) return word_json(w[0], type);
    cJSON *a = cJSON_CreateArray();
    for (uint32_t i = 0; i < n; i++) cJSON_AddItemToArray(a, word_json(w[i], type));
    return a;
}

static cJSON *annotations_json(const hfx_fx_effect *fx, uint32_t first, uint32_t count) {
    cJSON *list = cJSON_CreateArray();
    for (uint32_t i = 0; i < count && first != HFX_NONE; i++) {
        const hfx_fx_annotation *a = &fx->annotations[first + i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", a->name);
        cJSON_AddStringToObject(o, "type", type_name(a->type));
        cJSON_AddStringToObject(o, "class", class_name(a->klass));
        if (a->type == HFX_TYPE_STRING) {
            cJSON_AddStringToObject(o, "value", a->string ? a->string : "");
        } else {
            cJSON_AddNumberToObject(o, "rows", a->rows);
            cJSON_AddNumberToObject(o, "columns", a->cols);
            cJSON_AddItemToObject(o, "value", words_json(a->data, a->count, a->type, a->klass == HFX_CLASS_SCALAR));
        }
        cJSON_AddItemToArray(list, o);
    }
    return list;
}

static cJSON *state_json(const hfx_fx_effect *fx, const hfx_fx_state *s) {
    const hfx_state_info *info = hfx_state_by_id(s->id);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "name", info ? info->name : "?");
    if (s->index) cJSON_AddNumberToObject(o, "index", s->index);
    switch (s->kind) {
    case HFX_FX_VALUE_INT: {
        const char *name = info ? hfx_state_value_name(info, s->i) : NULL;
        if (info && info->kind == HFX_SV_BOOL) cJSON_AddBoolToObject(o, "value", s->i != 0);
        else if (name) cJSON_AddStringToObject(o, "value", name);
        else if (info && info->kind == HFX_SV_COLOR) cJSON_AddNumberToObject(o, "value", (uint32_t)s->i); /* D3DCOLOR */
        else cJSON_AddNumberToObject(o, "value", s->i);
        if (name || (info && info->kind == HFX_SV_BOOL)) cJSON_AddNumberToObject(o, "number", s->i);
        break;
    }
    case HFX_FX_VALUE_FLOAT:
        if (s->count == 1) cJSON_AddNumberToObject(o, "value", short_float(s->f[0]));
        else {
            cJSON *a = cJSON_AddArrayToObject(o, "value");
            for (uint32_t i = 0; i < s->count && i < 4; i++) cJSON_AddItemToArray(a, cJSON_CreateNumber(short_float(s->f[i])));
        }
        break;
    case HFX_FX_VALUE_PARAM:
        if (s->ref != HFX_NONE) cJSON_AddStringToObject(o, "parameter", fx->params[s->ref].name);
        else cJSON_AddNullToObject(o, "parameter");
        break;
    case HFX_FX_VALUE_PROGRAM:
        if (s->ref != HFX_NONE) cJSON_AddNumberToObject(o, "program", s->ref);
        else cJSON_AddNullToObject(o, "program");
        break;
    case HFX_FX_VALUE_EXPR: /* computed from parameters when the pass is applied */
        cJSON_AddNumberToObject(o, "expression_words", s->count);
        break;
    default:
        cJSON_AddBoolToObject(o, "unsupported", 1);
        break;
    }
    return o;
}

static cJSON *states_json(const hfx_fx_effect *fx, uint32_t first, uint32_t count) {
    cJSON *list = cJSON_CreateArray();
    for (uint32_t i = 0; i < count; i++) cJSON_AddItemToArray(list, state_json(fx, &fx->states[first + i]));
    return list;
}

/* Numbers for numerics (arrays flat); {member: default} for a struct, one per element of an array. */
static cJSON *default_json(const hfx_fx_effect *fx, uint32_t i, int depth) {
    const hfx_fx_param *p = &fx->params[i];
    if (p->klass != HFX_CLASS_STRUCT || depth > 32) return words_json(fx->values + p->offset, p->words, p->type, false);
    if (p->elements) {
        cJSON *a = cJSON_CreateArray();
        for (uint32_t e = 0; e < p->child_count; e++) cJSON_AddItemToArray(a, default_json(fx, p->first_child + e, depth + 1));
        return a;
    }
    cJSON *o = cJSON_CreateObject();
    for (uint32_t m = 0; m < p->child_count; m++) {
        const hfx_fx_param *c = &fx->params[p->first_child + m];
        if (c->words) cJSON_AddItemToObject(o, c->name, default_json(fx, p->first_child + m, depth + 1));
    }
    return o;
}

static cJSON *param_json(const hfx_fx_effect *fx, uint32_t i, bool reflect, int depth) {
    const hfx_fx_param *p = &fx->params[i];
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "name", p->name);
    cJSON_AddStringToObject(o, "type", type_name(p->type));
    cJSON_AddStringToObject(o, "class", class_name(p->klass));
    cJSON_AddNumberToObject(o, "rows", p->rows);
    cJSON_AddNumberToObject(o, "columns", p->cols);
    cJSON_AddNumberToObject(o, "elements", p->elements);
    if (p->semantic) cJSON_AddStringToObject(o, "semantic", p->semantic);
    else cJSON_AddNullToObject(o, "semantic");
    if (p->string) cJSON_AddStringToObject(o, "default", p->string);
    else if (p->words) cJSON_AddItemToObject(o, "default", default_json(fx, i, 0));
    if (reflect) {
        if (p->glsl_name) cJSON_AddStringToObject(o, "glsl_name", p->glsl_name);
        cJSON_AddNumberToObject(o, "offset", p->offset);
        cJSON_AddNumberToObject(o, "words", p->words);
    }
    cJSON_AddItemToObject(o, "annotations", annotations_json(fx, p->first_annotation, p->annotation_count));
    /* Struct members (of the struct, or of an array's first element: every element has them). */
    uint32_t s = p->klass == HFX_CLASS_STRUCT && p->elements && p->child_count ? p->first_child : i;
    const hfx_fx_param *sp = &fx->params[s];
    if (p->klass == HFX_CLASS_STRUCT && depth < 32) {
        cJSON *members = cJSON_AddArrayToObject(o, "members");
        for (uint32_t m = 0; m < sp->child_count && sp->first_child != HFX_NONE; m++)
            cJSON_AddItemToArray(members, param_json(fx, sp->first_child + m, reflect, depth + 1));
    }
    return o;
}

static cJSON *samplers_json(const hfx_fx_effect *fx) {
    cJSON *list = cJSON_CreateArray();
    for (uint32_t i = 0; i < fx->sampler_count; i++) {
        const hfx_fx_sampler *s = &fx->samplers[i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", fx->params[s->param].name);
        if (s->texture_param != HFX_NONE) cJSON_AddStringToObject(o, "texture", fx->params[s->texture_param].name);
        else cJSON_AddNullToObject(o, "texture");
        static const char *const dims[] = {"2D", "1D", "3D", "CUBE"};
        cJSON_AddStringToObject(o, "dimension", (unsigned)s->dim < 4 ? dims[s->dim] : "?");
        cJSON_AddItemToObject(o, "states", states_json(fx, s->first_state, s->state_count));
        cJSON_AddItemToArray(list, o);
    }
    return list;
}

/* A preshader: its registers and the parameters it reads (once each, in reading order). */
static cJSON *preshader_json(const hfx_fx_effect *fx, const hfx_fx_program *p, const hfx_fx_preshader *q) {
    cJSON *e = cJSON_CreateObject();
    cJSON_AddNumberToObject(e, "register", q->reg);
    cJSON_AddNumberToObject(e, "rows", q->rows);
    cJSON_AddNumberToObject(e, "cols", q->cols);
    cJSON *reads = cJSON_AddArrayToObject(e, "parameters");
    const uint32_t *code = p->pre_code + q->first;
    for (uint32_t at = 0; at < q->words; at = hfx_evc_next(code, at, q->words)) {
        uint32_t r = hfx_fx_param_read_at(fx, code, at);
        bool seen = false;
        const cJSON *it;
        cJSON_ArrayForEach(it, reads) seen |= r != HFX_NONE && strcmp(it->valuestring, fx->params[r].name) == 0;
        if (r != HFX_NONE && !seen) cJSON_AddItemToArray(reads, cJSON_CreateString(fx->params[r].name));
    }
    return e;
}

static cJSON *program_json(const hfx_fx_effect *fx, uint32_t index) {
    const hfx_fx_program *p = &fx->programs[index];
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "index", index);
    cJSON *u = cJSON_AddArrayToObject(o, "uniforms");
    for (uint32_t i = 0; i < p->uniform_count; i++) {
        const hfx_fx_param *q = &fx->params[p->uniforms[i].param];
        cJSON *e = cJSON_CreateObject();
        cJSON_AddStringToObject(e, "parameter", q->name);
        if (q->glsl_name) cJSON_AddStringToObject(e, "glsl_name", q->glsl_name);
        if (hfx_fx_use_packed(p, &p->uniforms[i])) cJSON_AddNumberToObject(e, "register", p->uniforms[i].reg);
        cJSON_AddItemToArray(u, e);
    }
    cJSON *a = cJSON_AddArrayToObject(o, "attributes");
    for (uint32_t i = 0; i < p->attribute_count; i++) {
        cJSON *e = cJSON_CreateObject();
        cJSON_AddStringToObject(e, "semantic", p->attributes[i].semantic);
        cJSON_AddStringToObject(e, "glsl_name", p->attributes[i].glsl_name);
        cJSON_AddNumberToObject(e, "location", p->attributes[i].location);
        cJSON_AddItemToArray(a, e);
    }
    cJSON *s = cJSON_AddArrayToObject(o, "samplers");
    for (uint32_t i = 0; i < p->sampler_count; i++) {
        cJSON *e = cJSON_CreateObject();
        cJSON_AddStringToObject(e, "glsl_name", p->samplers[i].glsl_name);
        cJSON_AddStringToObject(e, "sampler", fx->params[fx->samplers[p->samplers[i].sampler].param].name);
        cJSON_AddNumberToObject(e, "unit", p->samplers[i].unit);
        cJSON_AddItemToArray(s, e);
    }
    cJSON *t = cJSON_AddArrayToObject(o, "targets");
    for (int k = 0; k < HFX_TARGET_COUNT; k++)
        if (p->code[HFX_STAGE_VERTEX][k].data || p->code[HFX_STAGE_FRAGMENT][k].data)
            cJSON_AddItemToArray(t, cJSON_CreateString(cli_target_name(k)));
    cJSON_AddBoolToObject(o, "alpha_test", (p->flags & HFX_FX_PROGRAM_ALPHA_TEST) != 0);
    if (p->reg_count) cJSON_AddNumberToObject(o, "registers", p->reg_count);
    if (p->preshader_count) {
        cJSON *pre = cJSON_AddArrayToObject(o, "preshaders");
        for (uint32_t i = 0; i < p->preshader_count; i++) cJSON_AddItemToArray(pre, preshader_json(fx, p, &p->preshaders[i]));
    }
    return o;
}

/* A pass drawn from shader arrays: its variants, each with the array indices and its program. */
static void variants_json(cJSON *po, const hfx_fx_effect *fx, uint32_t pass) {
    cJSON *list = NULL;
    for (uint32_t i = 0; i < fx->variant_count; i++) {
        const hfx_fx_variant *v = &fx->variants[i];
        if (v->pass != pass) continue;
        if (!list) list = cJSON_AddArrayToObject(po, "variants");
        cJSON *o = cJSON_CreateObject();
        if (v->vs != HFX_NONE) cJSON_AddNumberToObject(o, "vertex_index", v->vs);
        if (v->ps != HFX_NONE) cJSON_AddNumberToObject(o, "pixel_index", v->ps);
        cJSON_AddItemToObject(o, "program", program_json(fx, v->program));
        cJSON_AddItemToArray(list, o);
    }
}

static cJSON *techniques_json(const hfx_fx_effect *fx, bool reflect) {
    cJSON *list = cJSON_CreateArray();
    for (uint32_t t = 0; t < fx->technique_count; t++) {
        const hfx_fx_technique *tq = &fx->techniques[t];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", tq->name);
        cJSON_AddItemToObject(o, "annotations", annotations_json(fx, tq->first_annotation, tq->annotation_count));
        cJSON *passes = cJSON_AddArrayToObject(o, "passes");
        for (uint32_t i = 0; i < tq->pass_count; i++) {
            const hfx_fx_pass *p = &fx->passes[tq->first_pass + i];
            cJSON *po = cJSON_CreateObject();
            cJSON_AddStringToObject(po, "name", p->name);
            cJSON_AddItemToObject(po, "annotations", annotations_json(fx, p->first_annotation, p->annotation_count));
            cJSON_AddItemToObject(po, "states", states_json(fx, p->first_state, p->state_count));
            if (reflect) {
                if (p->program != HFX_NONE) cJSON_AddItemToObject(po, "program", program_json(fx, p->program));
                else cJSON_AddNullToObject(po, "program");
                variants_json(po, fx, tq->first_pass + i);
            }
            cJSON_AddItemToArray(passes, po);
        }
        cJSON_AddItemToArray(list, o);
    }
    return list;
}

static cJSON *effect_json(const char *input, const hfx_fx_effect *fx, bool reflect) {
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "file", input);
    if (!fx) {
        cJSON_AddNullToObject(o, "effect");
        return o;
    }
    cJSON *params = cJSON_AddArrayToObject(o, "parameters");
    for (uint32_t i = 0; i < fx->top_param_count; i++) cJSON_AddItemToArray(params, param_json(fx, i, reflect, 0));
    cJSON_AddItemToObject(o, "samplers", samplers_json(fx));
    cJSON_AddItemToObject(o, "techniques", techniques_json(fx, reflect));
    if (reflect) {
        cJSON *t = cJSON_AddArrayToObject(o, "targets");
        for (int k = 0; k < HFX_TARGET_COUNT; k++)
            if (fx->targets & (1u << k)) cJSON_AddItemToArray(t, cJSON_CreateString(cli_target_name(k)));
        cJSON_AddNumberToObject(o, "programs", fx->program_count);
    }
    return o;
}

char *cli_json(const cli_job *jobs, size_t count, bool reflect) {
    cJSON *root;
    if (count == 1) {
        root = effect_json(jobs[0].input, jobs[0].effect, reflect);
    } else {
        root = cJSON_CreateArray();
        for (size_t i = 0; i < count; i++) cJSON_AddItemToArray(root, effect_json(jobs[i].input, jobs[i].effect, reflect));
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    return text;
}
