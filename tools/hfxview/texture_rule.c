/* texture_rule.c: which parameters hfxview gives a texture of its own and of which kind, apart
 * from textures.c's file readers so that the web page (web/wasm/draw.c) follows the same rule
 * and the two draw an effect alike (scripts/corpus.sh compare). */
#include <string.h>
#include <strings.h>

#include "textures.h"

static int is_texture(hfx_param_type t) { return t >= HFX_TYPE_TEXTURE && t <= HFX_TYPE_TEXTURECUBE; }
static int is_sampler(hfx_param_type t) { return t >= HFX_TYPE_SAMPLER && t <= HFX_TYPE_SAMPLERCUBE; }

int hv_param_is_texture_or_sampler(hfx_param *p) {
    hfx_param_type t = hfx_param_get_type(p);
    return is_texture(t) || is_sampler(t);
}

int hv_effect_samplers_take_textures(hfx_effect *fx) {
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++)
        if (is_texture(hfx_param_get_type(hfx_effect_param_at(fx, i)))) return 0;
    return 1;
}

int hv_param_takes_texture(hfx_param *p, int samplers_too) {
    hfx_param_type type = hfx_param_get_type(p);
    return is_texture(type) || (samplers_too && is_sampler(type));
}

const char *hv_param_string_annotation(hfx_param *p, const char *const *names) {
    for (size_t i = 0; i < hfx_param_annotation_count(p); i++) {
        hfx_annotation *a = hfx_param_annotation_at(p, i);
        const char *s = hfx_annotation_string(a);
        for (size_t n = 0; s && *s && names[n]; n++)
            if (strcasecmp(hfx_annotation_name(a), names[n]) == 0) return s;
    }
    return NULL;
}

hv_tex_kind hv_texture_kind(hfx_param *p) {
    switch (hfx_param_texture_target(p)) {
    case GL_TEXTURE_CUBE_MAP: return HV_TEX_CUBE;
    case GL_TEXTURE_3D: return HV_TEX_3D;
    case GL_TEXTURE_2D: return HV_TEX_2D;
    default: break;
    }
    static const char *const type_names[] = {"ResourceType", "Type", NULL};
    const char *rt = hv_param_string_annotation(p, type_names);
    if (rt && strcasecmp(rt, "cube") == 0) return HV_TEX_CUBE;
    if (rt && (strcasecmp(rt, "3d") == 0 || strcasecmp(rt, "volume") == 0)) return HV_TEX_3D;
    hfx_param_type type = hfx_param_get_type(p);
    if (type == HFX_TYPE_TEXTURECUBE || type == HFX_TYPE_SAMPLERCUBE) return HV_TEX_CUBE;
    if (type == HFX_TYPE_TEXTURE3D || type == HFX_TYPE_SAMPLER3D) return HV_TEX_3D;
    return HV_TEX_2D;
}
