/* reload.c: hfx_effect_reload. The new code is loaded as a whole new effect first, so a failed
 * compile or link leaves the old one untouched; on success the old instance's values that still
 * fit are copied over, and the two instances' contents are swapped so the application's
 * hfx_effect pointer stays valid, then the old contents are destroyed like any effect (its shared
 * part lives on while clones hold it). */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

static int same_name(const char *a, const char *b) {
    return a && b ? strcmp(a, b) == 0 : a == b;
}

/* Whether parameter j of b has parameter i of a's shape, recursively: the same words in the same
 * places, so the old value means the same thing to the new code. */
static int same_shape(const hfx_fx_effect *a, uint32_t i, const hfx_fx_effect *b, uint32_t j, int depth) {
    const hfx_fx_param *p = &a->params[i], *q = &b->params[j];
    if (p->klass != q->klass || p->type != q->type || p->rows != q->rows || p->cols != q->cols ||
        p->elements != q->elements || p->words != q->words || p->child_count != q->child_count || depth > 64)
        return 0;
    for (uint32_t c = 0; c < p->child_count; c++) {
        uint32_t ci = p->first_child + c, cj = q->first_child + c;
        /* members are matched by name; elements of equal arrays have equal names too */
        if (!same_name(a->params[ci].name, b->params[cj].name) ||
            a->params[ci].offset - p->offset != b->params[cj].offset - q->offset || !same_shape(a, ci, b, cj, depth + 1))
            return 0;
    }
    return 1;
}

/* Textures are per parameter (members and elements included): walk both trees together. */
static void copy_textures(hfx_effect *to, uint32_t j, const hfx_effect *from, uint32_t i, int depth) {
    to->textures[j] = from->textures[i];
    const hfx_fx_param *p = &from->sh->fx->params[i], *q = &to->sh->fx->params[j];
    for (uint32_t c = 0; c < p->child_count && depth < 64; c++)
        copy_textures(to, q->first_child + c, from, p->first_child + c, depth + 1);
}

int hfx_rt_same_shape(const hfx_fx_effect *a, uint32_t i, const hfx_fx_effect *b, uint32_t j) {
    return same_shape(a, i, b, j, 0);
}

void hfx_rt_copy_textures(hfx_effect *to, uint32_t j, const hfx_effect *from, uint32_t i) {
    copy_textures(to, j, from, i, 0);
}

/* Whether top-level parameter i of from holds something else than its file said: the
 * application (or a viewer's panel) set it. One set back to the file's value counts as unset. */
static int set_by_application(const hfx_effect *from, uint32_t i) {
    const hfx_fx_param *p = &from->sh->fx->params[i];
    const uint32_t *defaults = from->sh->fx->values;
    if (!p->words) return 0;
    return !defaults || memcmp(from->values + p->offset, defaults + p->offset, p->words * sizeof *defaults) != 0;
}

/* Top-level parameters whose shape is unchanged keep what the application set (each marked
 * changed as a set would, so the next Apply sends it); the others take the file's new default,
 * so an edited initializer shows. Textures are never in the file: they are all kept. */
static void carry_values(hfx_effect *to, const hfx_effect *from) {
    const hfx_fx_effect *a = from->sh->fx, *b = to->sh->fx;
    for (uint32_t i = 0; i < a->top_param_count; i++) {
        if (!a->params[i].name) continue;
        uint32_t j = hfx_fx_param_find(b, a->params[i].name);
        if (j == HFX_NONE || j >= b->top_param_count || !same_shape(a, i, b, j, 0)) continue;
        if (set_by_application(from, i))
            memcpy(to->values + b->params[j].offset, from->values + a->params[i].offset, a->params[i].words * sizeof *to->values);
        copy_textures(to, j, from, i, 0);
        hfx_rt_mark_changed(to, j);
    }
}

/* The current technique by name; the new effect's first when that name is gone. */
static void keep_technique(hfx_effect *to, const hfx_effect *from) {
    const hfx_fx_effect *a = from->sh->fx, *b = to->sh->fx;
    to->current = 0;
    if (from->current >= a->technique_count) return;
    for (uint32_t t = 0; t < b->technique_count; t++)
        if (same_name(a->techniques[from->current].name, b->techniques[t].name)) {
            to->current = t;
            return;
        }
}

/* Between begin and end: the new instance is begun too, holding what the old one's begin saved
 * (the back end widens it to what the new code touches), so end restores it. */
static void keep_begun(hfx_effect *to, const hfx_effect *from) {
    to->begun = from->begun;
    if (from->begun && to->dev->be->begun_carry) to->dev->be->begun_carry(to, from);
}

/* Handles point back at their effect: after the swap they must name the address they live in. */
static void point_back(hfx_effect *e) {
    const hfx_fx_effect *f = e->sh->fx;
    for (uint32_t i = 0; i < f->param_count; i++) e->params[i].fx = e;
    for (uint32_t i = 0; i < f->technique_count; i++) e->techniques[i].fx = e;
    for (uint32_t i = 0; i < f->pass_count; i++) e->passes[i].fx = e;
}

/* Puts next's contents into fx (keeping the address) and destroys fx's old contents. */
static void swap_in(hfx_effect *fx, hfx_effect *next) {
    /* Apply's short way compares pass pointers: the old passes are about to be freed */
    if (fx->dev->applied && fx->dev->applied->fx == fx) fx->dev->applied = NULL;
    hfx_effect old = *fx;
    *fx = *next;
    *next = old;
    point_back(fx);
    point_back(next);
    hfx_rt_pool_swapped(fx, next);
    hfx_effect_destroy(next);
}

static int fail_with(hfx_device *dev, char **errors, int code, const char *msg) {
    hfx_rt_fail(dev, code, "%s", msg);
    if (errors) *errors = hfx_rt_strdup(dev->error);
    return code;
}

int hfx_effect_reload(hfx_effect *fx, const char *path, const hfx_load_options *opt, char **errors) {
    if (errors) *errors = NULL;
    if (!fx) return HFX_ERR_NULL;
    if (!path) path = fx->path;
    if (!path)
        return fail_with(fx->dev, errors, HFX_ERR_NOT_FOUND,
                         "hfx_effect_reload: the effect was loaded from memory; give the path to reload from");
    hfx_load_options pooled; /* the effect stays in its pool unless opt names another */
    if (fx->pool && (!opt || !opt->pool)) {
        if (opt) pooled = *opt;
        else memset(&pooled, 0, sizeof pooled);
        pooled.pool = fx->pool;
        opt = &pooled;
    }
    hfx_effect *next = hfx_effect_load(fx->dev, path, opt, errors);
    if (!next) return HFX_ERR_LOAD;
    carry_values(next, fx);
    keep_technique(next, fx);
    keep_begun(next, fx);
    swap_in(fx, next);
    return HFX_OK;
}
