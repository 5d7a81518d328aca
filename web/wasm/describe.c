/* describe.c: the effect as the page's panels need it (techniques and passes for the pickers,
 * parameters with their annotations and current values for the parameter panel, struct
 * parameters and arrays of structs as their leaves), as JSON. */
#include <emscripten.h>
#include <stdio.h>
#include <string.h>

#include "bind.h"
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

/* Values of a scalar, vector or matrix (row-major, rows x columns), ints and bools read as
 * such; none for the rest. */
static void value_json(hfxw_json *j, const hfx_param *p) {
    hfx_param_class c = hfx_param_get_class(p);
    hfx_param_type t = hfx_param_get_type(p);
    size_t n = hfx_param_rows(p) * hfx_param_columns(p);
    float v[16];
    int iv[16], ok = 0;
    if (c <= HFX_CLASS_MATRIX && !hfx_param_elements(p) && n <= 16) {
        if (t == HFX_TYPE_INT || t == HFX_TYPE_BOOL) {
            ok = hfx_param_get_ints(p, iv, n) == HFX_OK;
            for (size_t i = 0; ok && i < n; i++) v[i] = (float)iv[i];
        } else {
            ok = hfx_param_get_floats(p, v, n) == HFX_OK;
        }
    }
    hfxw_json_raw(j, "[");
    for (size_t i = 0; ok && i < n; i++) {
        if (i) hfxw_json_raw(j, ",");
        hfxw_json_num(j, v[i]);
    }
    hfxw_json_raw(j, "]");
}

/* One parameter, named by its path ("spots[1].Color" for a leaf of a struct parameter), and
 * the top-level parameter it belongs to (group). */
/* How bind.c bound top-level parameter `group` when the effect loaded, or NULL. */
static const char *bound_how(const hfxw_session *s, const char *group) {
    for (size_t i = 0; i < s->bound_count; i++)
        if (!strcmp(hfx_param_name(hfx_effect_param_at(s->fx, i)), group)) return s->bound[i];
    return NULL;
}

static void param_json(hfxw_json *j, hfx_param *p, const char *path, const char *group) {
    hfx_param_type t = hfx_param_get_type(p);
    hfx_param_class c = hfx_param_get_class(p);
    hfxw_json_raw(j, "{"), hfxw_json_key(j, "name"), hfxw_json_str(j, path);
    hfxw_json_raw(j, ","), hfxw_json_key(j, "group"), hfxw_json_str(j, group);
    hfxw_json_raw(j, ","), hfxw_json_key(j, "semantic"), hfxw_json_str(j, hfx_param_semantic(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "class"), hfxw_json_str(j, class_names[c]);
    hfxw_json_raw(j, ","), hfxw_json_key(j, "type"), hfxw_json_str(j, type_names[t]);
    hfxw_json_raw(j, ","), hfxw_json_key(j, "rows"), hfxw_json_num(j, (double)hfx_param_rows(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "columns"), hfxw_json_num(j, (double)hfx_param_columns(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "elements"), hfxw_json_num(j, (double)hfx_param_elements(p));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "bound"), hfxw_json_str(j, bound_how(hfxw_get(), group));
    hfxw_json_raw(j, ","), hfxw_json_key(j, "texture"), hfxw_json_raw(j, hfx_param_texture_target(p) ? "true" : "false");
    hfxw_json_raw(j, ","), hfxw_json_key(j, "value"), value_json(j, p);
    hfxw_json_raw(j, ","), hfxw_json_key(j, "annotations"), hfxw_json_raw(j, "{");
    for (size_t i = 0; i < hfx_param_annotation_count(p); i++) {
        if (i) hfxw_json_raw(j, ",");
        annotation_json(j, hfx_param_annotation_at(p, i));
    }
    hfxw_json_raw(j, "}}");
}

static int is_struct(const hfx_param *p) { return hfx_param_get_class(p) == HFX_CLASS_STRUCT; }

/* A struct parameter, or an array of structs, as its leaves ("lights[0].Color", ...), each
 * settable by that path (hfxw_set_param); the panel groups them under the parameter. */
static void leaves_json(hfxw_json *j, hfx_param *p, const char *path, const char *group, int *first) {
    char sub[256];
    size_t n = hfx_param_elements(p);
    if (n && is_struct(p)) {
        for (size_t i = 0; i < n; i++)
            if ((size_t)snprintf(sub, sizeof sub, "%s[%zu]", path, i) < sizeof sub)
                leaves_json(j, hfx_param_element(p, i), sub, group, first);
        return;
    }
    if (is_struct(p)) {
        for (size_t i = 0; i < hfx_param_member_count(p); i++) {
            hfx_param *m = hfx_param_member_at(p, i);
            if ((size_t)snprintf(sub, sizeof sub, "%s.%s", path, hfx_param_name(m)) < sizeof sub)
                leaves_json(j, m, sub, group, first);
        }
        return;
    }
    if (!*first) hfxw_json_raw(j, ",");
    *first = 0;
    param_json(j, p, path, group);
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

/* {"techniques": [{name, passes}], "params": [{name, group, bound, ...}], "unbound": "A = 0, B"}
 * (the parameters bind.c left at the effect's values), or null without an effect. */
EMSCRIPTEN_KEEPALIVE const char *hfxw_describe(void) {
    hfxw_session *s = hfxw_get();
    if (!s->fx) return hfxw_answer(NULL);
    hfxw_json j = {0};
    hfxw_json_raw(&j, "{"), hfxw_json_key(&j, "techniques"), techniques_json(&j, s->fx);
    hfxw_json_raw(&j, ","), hfxw_json_key(&j, "params"), hfxw_json_raw(&j, "[");
    int first = 1;
    for (size_t i = 0; i < hfx_effect_param_count(s->fx); i++) {
        hfx_param *p = hfx_effect_param_at(s->fx, i);
        leaves_json(&j, p, hfx_param_name(p), hfx_param_name(p), &first);
    }
    hfxw_json_raw(&j, "]");
    char unbound[1024] = "";
    if (s->bound && s->bound_count == hfx_effect_param_count(s->fx)) hv_unbound_list(s->fx, s->bound, unbound, sizeof unbound);
    hfxw_json_raw(&j, ","), hfxw_json_key(&j, "unbound"), hfxw_json_str(&j, unbound);
    hfxw_json_raw(&j, "}");
    return hfxw_answer(hfxw_json_take(&j));
}
