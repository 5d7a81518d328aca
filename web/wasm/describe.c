/* describe.c: the effect as the page's panels need it (techniques and passes for the pickers,
 * parameters with their annotations and current values for the parameter panel), as JSON. */
#include <emscripten.h>
#include <stdio.h>

#include "json.h"
#include "session.h"

static const char *const type_names[] = {
    "void", "bool", "int", "float", "string", "texture", "texture1D", "texture2D", "texture3D", "textureCUBE",
    "sampler", "sampler1D", "sampler2D", "sampler3D", "samplerCUBE", "pixelshader", "vertexshader"};
static const char *const class_names[] = {"scalar", "vector", "matrix", "object", "struct"};

static void annotation_json(hfxw_json *j, hfx_annotation *a) {
    hfx_param_type t = hfx_annotation_type(a);
    hfxw_json_key(j, hfx_annotation_name(a));
    float v = 0;
    if (t == HFX_TYPE_STRING) hfxw_json_str(j, hfx_annotation_string(a));
    else if ((t == HFX_TYPE_FLOAT || t == HFX_TYPE_INT || t == HFX_TYPE_BOOL) && hfx_annotation_float(a, &v) == HFX_OK)
        hfxw_json_num(j, v);
    else hfxw_json_raw(j, "null");
}

/* Values of a scalar, vector or matrix (row-major, rows x columns); none for the rest. */
static void value_json(hfxw_json *j, const hfx_param *p) {
    hfx_param_class c = hfx_param_get_class(p);
    size_t n = hfx_param_rows(p) * hfx_param_columns(p);
    float v[16];
    hfxw_json_raw(j, "[");
    if (c <= HFX_CLASS_MATRIX && !hfx_param_elements(p) && n <= 16 && hfx_param_get_floats(p, v, n) == HFX_OK)
        for (size_t i = 0; i < n; i++) {
            if (i) hfxw_json_raw(j, ",");
            hfxw_json_num(j, v[i]);
        }
    hfxw_json_raw(j, "]");
}

static void param_json(hfxw_json *j, hfx_param *p) {
    hfx_param_type t = hfx_param_get_type(p);
    hfx_param_class c = hfx_param_get_class(p);
    hfxw_json_raw(j, "{"), hfxw_json_key(j, "name"), hfxw_json_str(j, hfx_param_name(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "semantic"), hfxw_json_str(j, hfx_param_semantic(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "class"), hfxw_json_str(j, class_names[c]);
    hfxw_json_raw(j, ","), hfxw_json_key(j, "type"), hfxw_json_str(j, type_names[t]);
    hfxw_json_raw(j, ","), hfxw_json_key(j, "rows"), hfxw_json_num(j, (double)hfx_param_rows(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "columns"), hfxw_json_num(j, (double)hfx_param_columns(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "elements"), hfxw_json_num(j, (double)hfx_param_elements(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "texture"), hfxw_json_raw(j, hfx_param_texture_target(p) ? "true" : "false");
    hfxw_json_raw(j, ","), hfxw_json_key(j, "value"), value_json(j, p);
    hfxw_json_raw(j, ","), hfxw_json_key(j, "annotations"), hfxw_json_raw(j, "{");
    for (size_t i = 0; i < hfx_param_annotation_count(p); i++) {
        if (i) hfxw_json_raw(j, ",");
        annotation_json(j, hfx_param_annotation_at(p, i));
    }
    hfxw_json_raw(j, "}}");
}

static void techniques_json(hfxw_json *j, hfx_effect *fx) {
    hfxw_json_raw(j, "[");
    for (size_t i = 0; i < hfx_effect_technique_count(fx); i++) {
        hfx_technique *t = hfx_effect_technique_at(fx, i);
        hfxw_json_raw(j, i ? ",{" : "{"), hfxw_json_key(j, "name"), hfxw_json_str(j, hfx_technique_name(t));
        hfxw_json_raw(j, ","), hfxw_json_key(j, "passes"), hfxw_json_raw(j, "[");
        for (size_t k = 0; k < hfx_technique_pass_count(t); k++) {
            if (k) hfxw_json_raw(j, ",");
            hfxw_json_str(j, hfx_pass_name(hfx_technique_pass(t, k)));
        }
        hfxw_json_raw(j, "]}");
    }
    hfxw_json_raw(j, "]");
}

/* {"techniques": [{name, passes}], "params": [...]}, or null without an effect. */
EMSCRIPTEN_KEEPALIVE const char *hfxw_describe(void) {
    hfxw_session *s = hfxw_get();
    if (!s->fx) return hfxw_answer(NULL);
    hfxw_json j = {0};
    hfxw_json_raw(&j, "{"), hfxw_json_key(&j, "techniques"), techniques_json(&j, s->fx);
    hfxw_json_raw(&j, ","), hfxw_json_key(&j, "params"), hfxw_json_raw(&j, "[");
    for (size_t i = 0; i < hfx_effect_param_count(s->fx); i++) {
        if (i) hfxw_json_raw(&j, ",");
        param_json(&j, hfx_effect_param_at(s->fx, i));
    }
    hfxw_json_raw(&j, "]}");
    return hfxw_answer(hfxw_json_take(&j));
}
