/* techniques.c: techniques and passes as the effect describes them (names, order, the current
 * technique, attribute semantics): no graphics API, shared by every back end. */
#include <ctype.h>
#include <string.h>
#include <strings.h>

#include "internal.h"

hfx_technique *hfx_effect_technique(hfx_effect *fx, const char *name) {
    if (!fx) return NULL;
    if (!name) return hfx_rt_fail(fx->dev, HFX_ERR_NULL, "NULL technique name"), NULL;
    for (uint32_t i = 0; i < fx->sh->fx->technique_count; i++)
        if (fx->sh->fx->techniques[i].name && strcmp(fx->sh->fx->techniques[i].name, name) == 0) return &fx->techniques[i];
    return hfx_rt_fail(fx->dev, HFX_ERR_NOT_FOUND, "no technique named '%s'", name), NULL;
}

hfx_technique *hfx_effect_technique_at(hfx_effect *fx, size_t i) {
    if (!fx) return NULL;
    if (i >= fx->sh->fx->technique_count) return hfx_rt_fail(fx->dev, HFX_ERR_NOT_FOUND, "no technique %zu", i), NULL;
    return &fx->techniques[i];
}

size_t hfx_effect_technique_count(const hfx_effect *fx) { return fx ? fx->sh->fx->technique_count : 0; }

void hfx_effect_set_current_technique(hfx_effect *fx, hfx_technique *t) {
    if (!fx) return;
    if (!t || t->fx != fx) {
        hfx_rt_fail(fx->dev, t ? HFX_ERR_NOT_FOUND : HFX_ERR_NULL, "technique does not belong to this effect");
        return;
    }
    fx->current = t->index;
}

hfx_technique *hfx_effect_current_technique(hfx_effect *fx) {
    if (!fx || fx->current >= fx->sh->fx->technique_count) return NULL;
    return &fx->techniques[fx->current];
}

const char *hfx_technique_name(const hfx_technique *t) {
    return t && t->fx->sh->fx->techniques[t->index].name ? t->fx->sh->fx->techniques[t->index].name : "";
}

size_t hfx_technique_pass_count(const hfx_technique *t) { return t ? t->fx->sh->fx->techniques[t->index].pass_count : 0; }

hfx_pass *hfx_technique_pass(hfx_technique *t, size_t i) {
    if (!t) return NULL;
    const hfx_fx_technique *ft = &t->fx->sh->fx->techniques[t->index];
    if (i >= ft->pass_count) return hfx_rt_fail(t->fx->dev, HFX_ERR_NOT_FOUND, "no pass %zu", i), NULL;
    return &t->fx->passes[ft->first_pass + i];
}

hfx_pass *hfx_technique_pass_by_name(hfx_technique *t, const char *name) {
    if (!t) return NULL;
    if (!name) return hfx_rt_fail(t->fx->dev, HFX_ERR_NULL, "NULL pass name"), NULL;
    const hfx_fx_technique *ft = &t->fx->sh->fx->techniques[t->index];
    for (uint32_t i = 0; i < ft->pass_count; i++) {
        const char *n = t->fx->sh->fx->passes[ft->first_pass + i].name;
        if (n && strcmp(n, name) == 0) return &t->fx->passes[ft->first_pass + i];
    }
    return hfx_rt_fail(t->fx->dev, HFX_ERR_NOT_FOUND, "no pass named '%s'", name), NULL;
}

const char *hfx_pass_name(const hfx_pass *p) {
    return p && p->fx->sh->fx->passes[p->index].name ? p->fx->sh->fx->passes[p->index].name : "";
}

/* "POSITION" means "POSITION0"; case does not matter. */
static int same_semantic(const char *canonical, const char *s) {
    size_t n = strlen(s);
    if (strcasecmp(canonical, s) == 0) return 1;
    return n && !isdigit((unsigned char)s[n - 1]) && strncasecmp(canonical, s, n) == 0 && strcmp(canonical + n, "0") == 0;
}

static int program_location(const hfx_fx_effect *fx, uint32_t prog, const char *semantic) {
    if (prog == HFX_NONE) return -1;
    const hfx_fx_program *fp = &fx->programs[prog];
    for (uint32_t i = 0; i < fp->attribute_count; i++)
        if (fp->attributes[i].semantic && same_semantic(fp->attributes[i].semantic, semantic)) return fp->attributes[i].location;
    return -1;
}

/* A pass with shader variants (ShaderIndex): the location any of its programs gives the
 * semantic (the compiler fixes a location per semantic, so they agree). Read from the compiled
 * effect, so it answers the same on every back end. */
int hfx_pass_attribute_location(const hfx_pass *p, const char *semantic) {
    if (!p || !semantic) return -1;
    const hfx_fx_effect *fx = p->fx->sh->fx;
    uint32_t prog = fx->passes[p->index].program;
    if (prog < fx->program_count) return program_location(fx, prog, semantic);
    for (uint32_t v = 0; v < fx->variant_count; v++) {
        if (fx->variants[v].pass != p->index) continue;
        int loc = program_location(fx, fx->variants[v].program, semantic);
        if (loc >= 0) return loc;
    }
    return -1;
}
