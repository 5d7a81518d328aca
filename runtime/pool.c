/* pool.c: effect pools, D3DX's ID3DXEffectPool. Effects loaded with the same pool share every
 * top-level parameter declared `shared`, matched by name: one value, set once and seen by all.
 * Each effect keeps its own copy of the words (Apply reads them where it always does), and a
 * set on one effect writes the other members' copies and marks them changed, so each of their
 * programs uploads the value when it next applies; gets see it at once. An effect joining the
 * pool takes the value the pool holds; a shared name declared with another type is a load error
 * naming both declarations. The pool is a list of its members: a value lives as long as one of
 * them declares it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

struct hfx_pool {
    hfx_device *dev;
    hfx_effect **members;
    size_t count, cap;
};

hfx_pool *hfx_pool_create(hfx_device *dev) {
    if (!dev) return NULL;
    hfx_pool *pool = calloc(1, sizeof *pool);
    if (!pool) hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
    else pool->dev = dev;
    return pool;
}

hfx_device *hfx_pool_device(const hfx_pool *pool) { return pool ? pool->dev : NULL; }

void hfx_pool_destroy(hfx_pool *pool) {
    if (!pool) return;
    for (size_t i = 0; i < pool->count; i++) pool->members[i]->pool = NULL; /* they live on, unpooled */
    free(pool->members);
    free(pool);
}

static int is_shared(const hfx_effect *e, uint32_t i) {
    const hfx_fx_effect *f = e->sh->fx;
    return i < f->top_param_count && (f->params[i].flags & HFX_FX_PARAM_SHARED) && f->params[i].name;
}

/* A member other than e that declares `name` shared, and the parameter's index there. */
static hfx_effect *holder(const hfx_pool *pool, const hfx_effect *e, const char *name, uint32_t *index) {
    for (size_t k = 0; k < pool->count; k++) {
        hfx_effect *f = pool->members[k];
        if (f == e) continue;
        uint32_t j = hfx_fx_param_find(f->sh->fx, name);
        if (j != HFX_NONE && is_shared(f, j)) return *index = j, f;
    }
    return NULL;
}

/* The value (words and textures) of `from`'s parameter i into `to`'s j, which has its shape. */
static void copy_value(hfx_effect *to, uint32_t j, const hfx_effect *from, uint32_t i) {
    const hfx_fx_param *p = &from->sh->fx->params[i], *q = &to->sh->fx->params[j];
    if (p->words) memcpy(to->values + q->offset, from->values + p->offset, p->words * sizeof *to->values);
    hfx_rt_copy_textures(to, j, from, i);
    hfx_rt_mark_changed(to, j);
}

/* "float4x4", "float3[2]", "struct", "texture2D": how a mismatch is told. */
static void describe(char *out, size_t n, const hfx_fx_param *p) {
    static const char *const types[] = {"void", "bool", "int", "float", "string", "texture", "texture1D",
                                        "texture2D", "texture3D", "textureCUBE", "sampler", "sampler1D",
                                        "sampler2D", "sampler3D", "samplerCUBE", "pixelshader", "vertexshader"};
    const char *t = (unsigned)p->type < sizeof types / sizeof *types ? types[p->type] : "?";
    int len;
    if (p->klass == HFX_CLASS_STRUCT) len = snprintf(out, n, "a struct");
    else if (p->klass == HFX_CLASS_MATRIX) len = snprintf(out, n, "%s%ux%u", t, p->rows, p->cols);
    else if (p->klass == HFX_CLASS_VECTOR) len = snprintf(out, n, "%s%u", t, p->cols);
    else len = snprintf(out, n, "%s", t);
    if (p->elements && len > 0 && (size_t)len < n) snprintf(out + len, n - (size_t)len, "[%u]", p->elements);
}

/* file(line,col): error X9003: ... for e's parameter i against f's j. */
static int mismatch(hfx_effect *e, uint32_t i, const hfx_effect *f, uint32_t j) {
    const hfx_fx_param *p = &e->sh->fx->params[i], *q = &f->sh->fx->params[j];
    char mine[64], theirs[64];
    describe(mine, sizeof mine, p);
    describe(theirs, sizeof theirs, q);
    const char *pf = p->file ? p->file : e->sh->fx->source_name, *qf = q->file ? q->file : f->sh->fx->source_name;
    return hfx_rt_fail(e->dev, HFX_ERR_LOAD,
                       "%s(%u,%u): error X9003: shared parameter '%s' is %s here but %s in the pool's %s(%u,%u)%s",
                       pf ? pf : "effect", p->line, p->col, p->name, mine, theirs, qf ? qf : "effect", q->line, q->col,
                       strcmp(mine, theirs) == 0 ? " (the struct members differ)" : "");
}

/* Checks every shared parameter of e against the pool, then takes the pool's values. */
int hfx_rt_pool_join(hfx_pool *pool, hfx_effect *e) {
    const hfx_fx_effect *fx = e->sh->fx;
    for (uint32_t i = 0; i < fx->top_param_count; i++) {
        uint32_t j;
        hfx_effect *f = is_shared(e, i) ? holder(pool, e, fx->params[i].name, &j) : NULL;
        if (f && !hfx_rt_same_shape(f->sh->fx, j, fx, i)) return mismatch(e, i, f, j);
    }
    if (pool->count == pool->cap) {
        size_t cap = pool->cap ? pool->cap * 2 : 8;
        hfx_effect **m = realloc(pool->members, cap * sizeof *m);
        if (!m) return hfx_rt_fail(e->dev, HFX_ERR_MEMORY, "out of memory");
        pool->members = m;
        pool->cap = cap;
    }
    for (uint32_t i = 0; i < fx->top_param_count; i++) {
        uint32_t j;
        hfx_effect *f = is_shared(e, i) ? holder(pool, e, fx->params[i].name, &j) : NULL;
        if (f) copy_value(e, i, f, j);
    }
    pool->members[pool->count++] = e;
    e->pool = pool;
    return HFX_OK;
}

void hfx_rt_pool_leave(hfx_effect *e) {
    hfx_pool *pool = e->pool;
    if (!pool) return;
    for (size_t k = 0; k < pool->count; k++)
        if (pool->members[k] == e) {
            pool->members[k] = pool->members[--pool->count];
            break;
        }
    e->pool = NULL;
}

/* The first entry `was` in pool's list now names `now`. */
static void rename_member(hfx_pool *pool, const hfx_effect *was, hfx_effect *now) {
    for (size_t k = 0; pool && k < pool->count; k++)
        if (pool->members[k] == was) {
            pool->members[k] = now;
            return;
        }
}

/* hfx_effect_reload swapped the contents of fx (now the new code) and next (the old, about to
 * be destroyed): each pool's entry must name the address its contents live at. When both are
 * in one pool its list holds fx (old) and next (new): the first rename gives next, next; the
 * second fx, next. */
void hfx_rt_pool_swapped(hfx_effect *fx, hfx_effect *next) {
    rename_member(next->pool, fx, next);
    rename_member(fx->pool, next, fx);
}

/* A set on e's top-level parameter root: when it is shared, every other member's copy too. */
void hfx_rt_pool_share(hfx_effect *e, uint32_t root) {
    if (!is_shared(e, root)) return;
    const char *name = e->sh->fx->params[root].name;
    hfx_pool *pool = e->pool;
    for (size_t k = 0; k < pool->count; k++) {
        hfx_effect *f = pool->members[k];
        uint32_t j = f == e ? HFX_NONE : hfx_fx_param_find(f->sh->fx, name);
        if (j != HFX_NONE && is_shared(f, j)) copy_value(f, j, e, root);
    }
}
