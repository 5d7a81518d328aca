/* load.c: effects from .fx / .hfxo (told apart by their first bytes) into the back end's
 * objects (its table's shared_build and instance_init); the shared part's and the instances'
 * lifetimes; clones; destruction. A failed load deletes what it made and leaves the device as
 * it was. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compile.h"
#include "internal.h"

/* Everything but the compiled effect, which a failed load hands back to its caller. */
static void shared_release(hfx_shared *sh) {
    sh->dev->be->shared_release(sh);
    free(sh->annotations);
    free(sh->warnings);
    free(sh);
}

static void shared_free(hfx_shared *sh) {
    if (!sh) return;
    hfx_fx_effect *fx = sh->fx;
    shared_release(sh);
    hfx_fx_effect_free(fx);
}

static int check_effect(hfx_device *dev, const hfx_fx_effect *fx, hfx_target target) {
    const char *name = fx->source_name ? fx->source_name : "effect";
    if (fx->program_count && !(fx->targets & (1u << target)))
        return hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: the effect carries no code for the requested shader target", name);
    for (uint32_t i = 0; i < fx->param_count; i++) {
        const hfx_fx_param *p = &fx->params[i];
        if ((uint64_t)p->offset + p->words > fx->value_words || (uint64_t)p->first_child + p->child_count > fx->param_count)
            return hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: parameter %u lies outside the effect's data", name, (unsigned)i);
    }
    if (fx->top_param_count > fx->param_count)
        return hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: more top-level parameters than parameters", name);
    for (uint32_t i = 0; i < fx->param_count; i++) {
        const hfx_fx_param *p = &fx->params[i];
        if ((uint64_t)p->first_annotation + p->annotation_count > fx->annotation_count)
            return hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: parameter %u lies outside the effect's data", name, (unsigned)i);
    }
    for (uint32_t i = 0; i < fx->state_count; i++)
        if (fx->states[i].kind == HFX_FX_VALUE_PARAM && fx->states[i].ref >= fx->param_count)
            return hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: state %u names no parameter", name, (unsigned)i);
    for (uint32_t i = 0; i < fx->sampler_count; i++) {
        const hfx_fx_sampler *sm = &fx->samplers[i];
        if (sm->param >= fx->param_count || (sm->texture_param != HFX_NONE && sm->texture_param >= fx->param_count) ||
            (uint64_t)sm->first_state + sm->state_count > fx->state_count)
            return hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: sampler %u lies outside the effect's data", name, (unsigned)i);
    }
    for (uint32_t i = 0; i < fx->pass_count; i++)
        if ((uint64_t)fx->passes[i].first_state + fx->passes[i].state_count > fx->state_count ||
            (uint64_t)fx->passes[i].first_annotation + fx->passes[i].annotation_count > fx->annotation_count)
            return hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: pass %u lies outside the effect's data", name, (unsigned)i);
    for (uint32_t i = 0; i < fx->technique_count; i++)
        if ((uint64_t)fx->techniques[i].first_pass + fx->techniques[i].pass_count > fx->pass_count ||
            (uint64_t)fx->techniques[i].first_annotation + fx->techniques[i].annotation_count > fx->annotation_count)
            return hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: technique %u lies outside the effect's data", name, (unsigned)i);
    return HFX_OK;
}

static hfx_shared *shared_create(hfx_device *dev, hfx_fx_effect *fx, hfx_target target) {
    if (check_effect(dev, fx, target)) return NULL;
    hfx_shared *sh = calloc(1, sizeof *sh);
    if (!sh) return NULL;
    sh->refs = 1;
    sh->dev = dev;
    sh->fx = fx;
    sh->annotations = calloc(fx->annotation_count ? fx->annotation_count : 1, sizeof *sh->annotations);
    if (!sh->annotations) {
        hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
        shared_release(sh);
        return NULL;
    }
    for (uint32_t i = 0; i < fx->annotation_count; i++) sh->annotations[i] = (struct hfx_annotation){sh, &fx->annotations[i]};
    if (dev->be->shared_build(sh, target)) {
        shared_release(sh);
        return NULL;
    }
    return sh;
}

static uint32_t root_of(const hfx_fx_effect *fx, uint32_t i) {
    for (int guard = 0; fx->params[i].parent != HFX_NONE && fx->params[i].parent < fx->param_count && guard < 64; guard++)
        i = fx->params[i].parent;
    return i;
}

static void instance_free(hfx_effect *e) {
    if (e->dev->be->instance_free) e->dev->be->instance_free(e);
    free(e->values), free(e->stamps), free(e->textures), free(e->texture_layouts), free(e->params), free(e->techniques), free(e->passes);
    free(e->log);
    free(e->path);
    hfx_rt_watch_free(&e->watch);
    free(e->sas_plan);
    free(e);
}

/* A new instance over sh: values and stamps copied from src when cloning. */
static hfx_effect *instance_create(hfx_shared *sh, const hfx_effect *src) {
    const hfx_fx_effect *fx = sh->fx;
    hfx_effect *e = calloc(1, sizeof *e);
    if (!e) return NULL;
    e->sh = sh;
    e->dev = sh->dev;
    e->values = calloc(fx->value_words ? fx->value_words : 1, sizeof *e->values);
    e->stamps = calloc((size_t)fx->top_param_count + 1, sizeof *e->stamps); /* + 1: outside any */
    e->textures = calloc(fx->param_count ? fx->param_count : 1, sizeof *e->textures);
    e->texture_layouts = calloc(fx->param_count ? fx->param_count : 1, sizeof *e->texture_layouts);
    e->params = calloc(fx->param_count ? fx->param_count : 1, sizeof *e->params);
    e->techniques = calloc(fx->technique_count ? fx->technique_count : 1, sizeof *e->techniques);
    e->passes = calloc(fx->pass_count ? fx->pass_count : 1, sizeof *e->passes);
    uint32_t ring = 64; /* at least four changes of every parameter between two looks */
    while (ring < 4 * (uint64_t)fx->top_param_count + 64 && ring < (1u << 30)) ring *= 2;
    e->log_mask = ring - 1;
    e->log = malloc(ring * sizeof *e->log);
    if (!e->values || !e->stamps || !e->textures || !e->texture_layouts || !e->params || !e->techniques || !e->passes || !e->log) {
        instance_free(e);
        return NULL;
    }
    e->stamp = &sh->dev->stamp;
    e->id = ++sh->dev->stamp;
    const uint32_t *values = src ? src->values : fx->values;
    if (values && fx->value_words) memcpy(e->values, values, fx->value_words * sizeof *e->values);
    for (uint32_t i = 0; i <= fx->top_param_count; i++) e->stamps[i] = src ? src->stamps[i] : ++sh->dev->stamp;
    if (src) memcpy(e->textures, src->textures, fx->param_count * sizeof *e->textures);
    if (src) memcpy(e->texture_layouts, src->texture_layouts, fx->param_count * sizeof *e->texture_layouts);
    for (uint32_t i = 0; i < fx->param_count; i++) {
        const hfx_fx_param *fp = &fx->params[i];
        uint32_t root = root_of(fx, i);
        uint32_t accept = hfx_rt_param_accept(fp);
        e->params[i] = (hfx_param){e->values + fp->offset, e,
                                   (accept & ACC_FLOATS) && (accept & ACC_WHOLE) ? fp->words : SIZE_MAX,
                                   (accept & ACC_RAW_INTS) && (accept & ACC_WHOLE) ? fp->words : SIZE_MAX, fp->words,
                                   root < fx->top_param_count ? root : fx->top_param_count, accept, i, fp};
    }
    for (uint32_t i = 0; i < fx->technique_count; i++) e->techniques[i] = (hfx_technique){e, i};
    for (uint32_t i = 0; i < fx->pass_count; i++) e->passes[i] = (hfx_pass){.fx = e, .index = i};
    e->current = src ? src->current : 0;
    if (sh->dev->be->instance_init && sh->dev->be->instance_init(e)) {
        instance_free(e);
        return NULL;
    }
    return e;
}

static char *dup_string(const char *s) {
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

char *hfx_rt_strdup(const char *s) { return dup_string(s); }

/* Diagnostics with only warnings still need to say why the load failed: the reason goes on a
 * line of its own after them (name may be NULL when msg names its file already). */
static char *append_line(char *text, const char *name, const char *msg) {
    size_t have = text ? strlen(text) : 0, n = have + (name ? strlen(name) : 0) + strlen(msg) + 5;
    char *t = realloc(text, n);
    if (!t) return text;
    /* compile_none.c's message is one line without its newline */
    snprintf(t + have, n - have, "%s%s%s%s\n", have && t[have - 1] != '\n' ? "\n" : "", name ? name : "",
             name ? ": " : "", msg);
    return t;
}

/* Joins the pool the options name (which must be this device's). */
static int join_pool(hfx_pool *pool, hfx_effect *e) {
    if (hfx_pool_device(pool) != e->dev)
        return hfx_rt_fail(e->dev, HFX_ERR_LOAD, "the effect pool belongs to another device");
    return hfx_rt_pool_join(pool, e);
}

/* Loads a compiled effect (taking it); on failure frees it and reports in dev and *errors. */
static hfx_effect *load_compiled(hfx_device *dev, hfx_fx_effect *fx, const hfx_load_options *opt, char **errors) {
    hfx_target target = opt ? opt->target : HFX_TARGET_GLSL330;
    if ((unsigned)target >= HFX_TARGET_COUNT) target = HFX_TARGET_GLSL330;
    hfx_shared *sh = shared_create(dev, fx, target);
    hfx_effect *e = sh ? instance_create(sh, NULL) : NULL;
    if (e && opt && opt->pool && join_pool(opt->pool, e) != HFX_OK) {
        if (errors) *errors = *errors ? append_line(*errors, NULL, dev->error) : dup_string(dev->error);
        hfx_effect_destroy(e);
        return NULL;
    }
    if (!e) {
        if (sh) shared_free(sh);
        else hfx_fx_effect_free(fx);
        if (!dev->error[0]) hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
        if (errors) *errors = *errors ? append_line(*errors, NULL, dev->error) : dup_string(dev->error);
        return NULL;
    }
    return e;
}

/* A .fx whose every program the device's cache holds: compiled without glslang's self-check
 * (the cached binaries were made from this very GLSL, checked when they were written) and
 * built from the cache alone. NULL when anything is missing or fails: the caller then loads
 * the usual way, self-check included. Saves most of a cached .fx load (bench/bench_load). */
static hfx_effect *load_cached_fx(hfx_device *dev, const char *path, const void *data, size_t size, const char *name,
                                  const hfx_load_options *opt, char **errors, hfx_rt_files *deps) {
    if ((opt && (opt->no_self_check || opt->target == HFX_TARGET_SPIRV)) || !dev->be->cache_usable ||
        !dev->be->cache_usable(dev))
        return NULL;
    hfx_load_options quick = opt ? *opt : (hfx_load_options){0};
    quick.no_self_check = 1;
    char *diag = NULL;
    hfx_fx_effect *fx = hfx_rt_compile_fx_deps(path, data, size, name, &quick, &diag, deps);
    hfx_effect *e = NULL;
    if (fx) {
        if (!fx->source_name) fx->source_name = dup_string(name);
        dev->cache_only = 1;
        e = load_compiled(dev, fx, &quick, NULL);
        dev->cache_only = 0;
    }
    if (e && errors) *errors = diag; /* the warnings, as a load's */
    else free(diag);
    if (!e && deps) hfx_rt_files_free(deps);
    dev->error[0] = '\0';
    return e;
}

/* deps receives the files a .fx compile read (empty for a .hfxo). */
static hfx_effect *load(hfx_device *dev, const char *path, const void *data, size_t size, const char *name,
                        const hfx_load_options *opt, char **errors, hfx_rt_files *deps) {
    if (errors) *errors = NULL;
    if (!dev) return NULL;
    hfx_load_options own; /* the back end's own target (Vulkan loads SPIR-V for Vulkan, whatever was asked) */
    hfx_target asked = opt ? opt->target : HFX_TARGET_GLSL330;
    if (dev->be->target_for(asked) != asked) {
        own = opt ? *opt : (hfx_load_options){0};
        own.target = dev->be->target_for(asked);
        opt = &own;
    }
    dev->error[0] = '\0';
    hfx_fx_effect *fx;
    bool is_hfxo = data && hfx_fx_is_hfxo(data, size);
    hfx_effect *cached = is_hfxo ? NULL : load_cached_fx(dev, path, data, size, name, opt, errors, deps);
    if (cached) return cached;
    if (is_hfxo) {
        char err[512] = "";
        fx = hfx_fx_read_hfxo(data, size, err, sizeof err);
        if (!fx) hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: %s", name, err);
    } else {
        char *diag = NULL;
        fx = hfx_rt_compile_fx_deps(path, data, size, name, opt, &diag, deps);
        if (!fx && (!diag || !strstr(diag, "error"))) diag = append_line(diag, name, "error: the effect did not compile");
        if (!fx) hfx_rt_fail(dev, HFX_ERR_LOAD, "%s", diag ? diag : "the effect did not compile");
        if (errors) *errors = diag;
        else free(diag);
    }
    if (!fx) {
        if (errors && !*errors) *errors = dup_string(dev->error);
        return NULL;
    }
    if (!fx->source_name) fx->source_name = dup_string(name);
    return load_compiled(dev, fx, opt, errors);
}

/* The list holding path alone (empty when out of memory). */
static hfx_rt_files one_file(const char *path) {
    hfx_rt_files f = {calloc(1, sizeof(char *)), 0};
    if (f.paths && (f.paths[0] = dup_string(path))) f.count = 1;
    return f;
}

static int is_hfxo_file(const char *path, void **data, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    unsigned char head[16];
    size_t n = fread(head, 1, sizeof head, f);
    int hfxo = hfx_fx_is_hfxo(head, n);
    if (hfxo && fseek(f, 0, SEEK_END) == 0) {
        long len = ftell(f);
        *data = len > 0 ? malloc((size_t)len) : NULL;
        if (len > 0 && !*data) hfxo = -2; /* out of memory, not a bad file */
        else if (*data && fseek(f, 0, SEEK_SET) == 0 && fread(*data, 1, (size_t)len, f) == (size_t)len) *size = (size_t)len;
        else free(*data), *data = NULL, hfxo = -1;
    }
    fclose(f);
    return hfxo;
}

/* A loaded effect whose bookkeeping could not be allocated: destroyed, and the load fails. */
static hfx_effect *drop_for_memory(hfx_effect *e, hfx_device *dev, char **errors) {
    hfx_effect_destroy(e);
    hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
    if (errors) free(*errors), *errors = dup_string(dev->error);
    return NULL;
}

hfx_effect *hfx_effect_load(hfx_device *dev, const char *path, const hfx_load_options *opt, char **errors) {
    if (errors) *errors = NULL;
    if (!dev) return NULL;
    if (!path) {
        hfx_rt_fail(dev, HFX_ERR_NULL, "hfx_effect_load: NULL path");
        if (errors) *errors = dup_string(dev->error);
        return NULL;
    }
    void *data = NULL;
    size_t size = 0;
    int kind = is_hfxo_file(path, &data, &size);
    if (kind < 0) {
        if (kind == -2) hfx_rt_fail(dev, HFX_ERR_MEMORY, "%s: out of memory reading the file", path);
        else hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: cannot read the file", path);
        if (errors) *errors = dup_string(dev->error);
        return NULL;
    }
    hfx_rt_files deps = {NULL, 0};
    hfx_effect *e = load(dev, path, data, size, path, opt, errors, &deps);
    free(data);
    if (e && !deps.count) hfx_rt_files_free(&deps), deps = one_file(path); /* a .hfxo: itself */
    if (e && (!(e->path = dup_string(path)) || hfx_rt_watch_set(&e->watch, &deps))) /* reload reads them again */
        e = drop_for_memory(e, dev, errors);
    hfx_rt_files_free(&deps);
    return e;
}

hfx_effect *hfx_effect_load_memory(hfx_device *dev, const void *data, size_t size, const char *name,
                                   const hfx_load_options *opt, char **errors) {
    if (errors) *errors = NULL;
    if (!dev) return NULL;
    if (!data) {
        hfx_rt_fail(dev, HFX_ERR_NULL, "hfx_effect_load_memory: NULL data");
        if (errors) *errors = dup_string(dev->error);
        return NULL;
    }
    hfx_rt_files deps = {NULL, 0}; /* what it included, found beside name */
    hfx_effect *e = load(dev, NULL, data, size, name ? name : "memory", opt, errors, &deps);
    if (e && hfx_rt_watch_set(&e->watch, &deps)) e = drop_for_memory(e, dev, errors);
    hfx_rt_files_free(&deps);
    return e;
}

/* For tests and tools that build an effect by hand: takes fx. */
hfx_effect *hfx_rt_effect_from_fx(hfx_device *dev, hfx_fx_effect *fx, const hfx_load_options *opt, char **errors) {
    if (errors) *errors = NULL;
    if (!dev || !fx) {
        hfx_fx_effect_free(fx);
        return NULL;
    }
    dev->error[0] = '\0';
    return load_compiled(dev, fx, opt, errors);
}

hfx_effect *hfx_effect_clone(const hfx_effect *src) {
    if (!src) return NULL;
    hfx_effect *e = instance_create(src->sh, src);
    if (e && ((src->path && !(e->path = dup_string(src->path))) || hfx_rt_watch_copy(&e->watch, &src->watch))) {
        instance_free(e); /* a clone reloads from the same files */
        e = NULL;
    }
    if (e && src->pool && hfx_rt_pool_join(src->pool, e) != HFX_OK) { /* D3DX's clones keep the pool */
        instance_free(e);
        return NULL;
    }
    if (!e) {
        hfx_rt_fail(src->dev, HFX_ERR_MEMORY, "out of memory");
        return NULL;
    }
    src->sh->refs++;
    return e;
}

void hfx_effect_destroy(hfx_effect *e) {
    if (!e) return;
    hfx_rt_pool_leave(e);
    if (e->dev->applied && e->dev->applied->fx == e) e->dev->applied = NULL; /* its address may come back */
    if (--e->sh->refs == 0) shared_free(e->sh);
    instance_free(e);
}

hfx_device *hfx_effect_device(const hfx_effect *e) { return e ? e->dev : NULL; }

const char *hfx_effect_warnings(const hfx_effect *e) {
    return e && e->sh->warnings ? e->sh->warnings : "";
}
