/* load.c: effects from .fx / .hfxo into GL objects; clones; destruction. A failed load
 * deletes what it made and leaves the device as it was. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compile.h"
#include "internal.h"

void hfx_shared_warn(hfx_shared *sh, const hfx_fx_state *st, const char *fmt, ...) {
    char msg[512], line[700];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const char *name = sh->fx->source_name ? sh->fx->source_name : "effect";
    if (st && st->line)
        snprintf(line, sizeof line, "%s(%u,%u): warning: %s\n", name, (unsigned)st->line, (unsigned)st->col, msg);
    else
        snprintf(line, sizeof line, "%s: warning: %s\n", name, msg);
    size_t n = strlen(line);
    char *w = realloc(sh->warnings, sh->warnings_len + n + 1);
    if (!w) return;
    memcpy(w + sh->warnings_len, line, n + 1);
    sh->warnings = w;
    sh->warnings_len += n;
}

/* 1D textures are 2D textures of height 1 (docs/conventions.md: the GLSL samples them so,
 * and GL ES has no 1D textures). */
static GLenum dim_target(hfx_fx_dim dim) {
    switch (dim) {
    case HFX_FX_DIM_1D: return GL_TEXTURE_2D;
    case HFX_FX_DIM_3D: return GL_TEXTURE_3D;
    case HFX_FX_DIM_CUBE: return GL_TEXTURE_CUBE_MAP;
    default: return GL_TEXTURE_2D;
    }
}

/* The GL target for a texture or sampler parameter; generic ones follow the sampler's use. */
static GLenum param_target(const hfx_fx_effect *fx, uint32_t param, hfx_fx_dim dim) {
    if (param >= fx->param_count) return dim_target(dim);
    switch (fx->params[param].type) {
    case HFX_TYPE_TEXTURE1D: case HFX_TYPE_SAMPLER1D:
    case HFX_TYPE_TEXTURE2D: case HFX_TYPE_SAMPLER2D: return GL_TEXTURE_2D;
    case HFX_TYPE_TEXTURE3D: case HFX_TYPE_SAMPLER3D: return GL_TEXTURE_3D;
    case HFX_TYPE_TEXTURECUBE: case HFX_TYPE_SAMPLERCUBE: return GL_TEXTURE_CUBE_MAP;
    default: return dim_target(dim);
    }
}

static int push_sampler(hfx_shared *sh, uint32_t *cap, const hfx_sampler_desc *base,
                        const hfx_fx_state *const *dyn, uint32_t dyn_count, uint32_t *index) {
    if (!HFX_GROW(sh->samplers, sh->sampler_count, *cap, 8)) return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    *index = sh->sampler_count;
    int rc = hfx_rt_sampler_create(sh, &sh->samplers[sh->sampler_count++], base, dyn, dyn_count);
    return rc ? hfx_rt_fail(sh->dev, rc, "could not create a GL sampler object") : HFX_OK;
}

/* Adds a state to a sampler being built: constants into the description, PARAM and EXPR ones
 * (computed at Apply) to dyn. */
static void add_sampler_state(const hfx_fx_state *st, hfx_sampler_desc *d, const hfx_fx_state **dyn, uint32_t *n) {
    if (st->kind == HFX_FX_VALUE_UNSUPPORTED) return; /* reported by check_sampler_state */
    if (st->kind == HFX_FX_VALUE_PARAM || st->kind == HFX_FX_VALUE_EXPR) {
        if (*n < 32) dyn[(*n)++] = st;
        return;
    }
    hfx_rs_value v;
    hfx_rs_resolve(NULL, st, &v);
    hfx_sampler_desc_apply(d, st->id, &v);
}

static void sampler_desc_of(const hfx_fx_effect *fx, uint32_t sampler, hfx_sampler_desc *d,
                            const hfx_fx_state **dyn, uint32_t *n) {
    hfx_sampler_desc_default(d);
    *n = 0;
    if (sampler >= fx->sampler_count) return;
    const hfx_fx_sampler *s = &fx->samplers[sampler];
    for (uint32_t i = 0; i < s->state_count && s->first_state + i < fx->state_count; i++) {
        const hfx_fx_state *st = &fx->states[s->first_state + i];
        if (st->id != HFX_ST_TEXTURE) add_sampler_state(st, d, dyn, n);
    }
}

/* Reports, once at load, a sampler state GL honours only in part. */
static void check_sampler_state(hfx_shared *sh, const hfx_fx_state *st) {
    const hfx_state_info *info = hfx_state_by_id(st->id);
    const char *name = info ? info->name : "?";
    if (st->kind == HFX_FX_VALUE_UNSUPPORTED) {
        hfx_shared_warn(sh, st, "'%s': this value cannot be expressed in GL; ignored", name);
    } else if ((st->id == HFX_ST_MINFILTER || st->id == HFX_ST_MAGFILTER || st->id == HFX_ST_MIPFILTER) &&
               st->kind == HFX_FX_VALUE_INT && st->i > 3) {
        hfx_shared_warn(sh, st, "'%s': %s filtering is not available in GL; filtering linearly", name,
                        info ? hfx_state_value_name(info, st->i) : "this");
    } else if (st->id == HFX_ST_SRGBTEXTURE && st->kind == HFX_FX_VALUE_INT && st->i && !sh->dev->srgb_decode) {
        hfx_shared_warn(sh, st, "'%s': without EXT_texture_sRGB_decode, only textures with an sRGB format are decoded", name);
    }
}

static int make_samplers(hfx_shared *sh, uint32_t *cap) {
    for (uint32_t i = 0; i < sh->fx->sampler_count; i++) {
        const hfx_fx_sampler *fs = &sh->fx->samplers[i];
        for (uint32_t k = 0; k < fs->state_count; k++) check_sampler_state(sh, &sh->fx->states[fs->first_state + k]);
        hfx_sampler_desc d;
        const hfx_fx_state *dyn[32];
        uint32_t n, index;
        sampler_desc_of(sh->fx, i, &d, dyn, &n);
        int rc = push_sampler(sh, cap, &d, dyn, n, &index);
        if (rc) return rc;
    }
    return HFX_OK;
}

static hfx_rt_binding *binding_for(hfx_rt_pass *rp, int32_t unit) {
    for (uint32_t i = 0; i < rp->binding_count; i++)
        if (rp->bindings[i].unit == unit) return &rp->bindings[i];
    hfx_rt_binding *b = &rp->bindings[rp->binding_count++];
    b->unit = unit;
    b->sampler = HFX_NONE;
    b->texture_param = HFX_NONE;
    b->sampler_param = HFX_NONE;
    b->target = GL_TEXTURE_2D;
    return b;
}

static void bind_sampler_use(const hfx_fx_effect *fx, hfx_rt_binding *b, uint32_t sampler) {
    const hfx_fx_sampler *s = &fx->samplers[sampler];
    b->sampler = sampler;
    b->texture_param = s->texture_param;
    b->sampler_param = s->param;
    b->target = param_target(fx, s->texture_param != HFX_NONE ? s->texture_param : s->param, s->dim);
}

/* Pass-level MinFilter[n] = ...: a sampler object for unit n from the bound sampler's states
 * with the pass's on top (the pass is the more specific). */
static int override_unit(hfx_shared *sh, uint32_t *cap, const hfx_fx_pass *fp, hfx_rt_binding *b) {
    const hfx_fx_effect *fx = sh->fx;
    hfx_sampler_desc d;
    const hfx_fx_state *dyn[32];
    uint32_t n, index;
    sampler_desc_of(fx, b->sampler, &d, dyn, &n);
    int any = 0;
    for (uint32_t i = 0; i < fp->state_count; i++) {
        const hfx_fx_state *st = &fx->states[fp->first_state + i];
        const hfx_state_info *info = hfx_state_by_id(st->id);
        if (!info || info->scope != HFX_SS_SAMPLER || st->id == HFX_ST_SAMPLER || (int32_t)st->index != b->unit)
            continue;
        add_sampler_state(st, &d, dyn, &n);
        any = 1;
    }
    if (!any) return HFX_OK;
    int rc = push_sampler(sh, cap, &d, dyn, n, &index);
    if (!rc) b->sampler = index;
    return rc;
}

static int build_pass(hfx_shared *sh, uint32_t *cap, uint32_t index) {
    const hfx_fx_effect *fx = sh->fx;
    const hfx_fx_pass *fp = &fx->passes[index];
    hfx_rt_pass *rp = &sh->passes[index];
    rp->program = fp->program < fx->program_count ? fp->program : HFX_NONE;
    rp->prog = rp->program != HFX_NONE ? &sh->programs[rp->program] : NULL;
    rp->render_states = calloc(fp->state_count ? fp->state_count : 1, sizeof *rp->render_states);
    rp->bindings = calloc(HFX_MAX_UNITS, sizeof *rp->bindings);
    if (!rp->render_states || !rp->bindings) return hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    if (rp->program != HFX_NONE) {
        const hfx_fx_program *prog = &fx->programs[rp->program];
        for (uint32_t i = 0; i < prog->sampler_count; i++)
            if (prog->samplers[i].unit >= 0 && prog->samplers[i].unit < HFX_MAX_UNITS &&
                prog->samplers[i].sampler < fx->sampler_count)
                bind_sampler_use(fx, binding_for(rp, prog->samplers[i].unit), prog->samplers[i].sampler);
    }
    uint32_t override_units = 0;
    for (uint32_t i = 0; i < fp->state_count && fp->first_state + i < fx->state_count; i++) {
        const hfx_fx_state *st = &fx->states[fp->first_state + i];
        const hfx_state_info *info = hfx_state_by_id(st->id);
        if (!info || st->kind == HFX_FX_VALUE_UNSUPPORTED) {
            hfx_rs_check(sh, st, rp->program);
            continue;
        }
        if (info->scope == HFX_SS_SAMPLER) check_sampler_state(sh, st);
        if (info && info->scope == HFX_SS_RENDER) {
            rp->render_states[rp->render_state_count++] = fp->first_state + i;
            rp->groups |= hfx_rs_group(st->id);
        }
        if (info && (info->scope == HFX_SS_TEXTURE || info->scope == HFX_SS_SAMPLER) && st->index >= HFX_MAX_UNITS) {
            hfx_shared_warn(sh, st, "'%s[%u]': sampler stage out of range; ignored", info->name, (unsigned)st->index);
            continue;
        }
        if (st->id == HFX_ST_TEXTURE && st->kind == HFX_FX_VALUE_PARAM) {
            hfx_rt_binding *b = binding_for(rp, (int32_t)st->index);
            b->texture_param = st->ref;
            b->target = param_target(fx, st->ref, HFX_FX_DIM_2D);
        } else if (st->id == HFX_ST_SAMPLER && st->kind == HFX_FX_VALUE_PARAM && st->ref < fx->param_count &&
                   fx->params[st->ref].sampler < fx->sampler_count) {
            bind_sampler_use(fx, binding_for(rp, (int32_t)st->index), fx->params[st->ref].sampler);
        } else if (info && info->scope == HFX_SS_SAMPLER) {
            override_units |= 1u << st->index;
            binding_for(rp, (int32_t)st->index);
        } else if (info && info->scope != HFX_SS_SHADER) {
            hfx_rs_check(sh, st, rp->program);
        }
    }
    for (uint32_t i = 0; i < rp->binding_count; i++) {
        hfx_rt_binding *b = &rp->bindings[i];
        if (override_units & (1u << b->unit) || b->sampler == HFX_NONE) {
            int rc = override_unit(sh, cap, fp, b);
            if (rc) return rc;
        }
        sh->unit_mask |= 1u << b->unit;
    }
    sh->groups |= rp->groups;
    rp->direct = rp->prog && !rp->render_state_count && !rp->binding_count;
    return HFX_OK;
}

/* Everything but the compiled effect, which a failed load hands back to its caller. */
static void shared_release(hfx_shared *sh) {
    hfx_device *dev = sh->dev;
    if (sh->programs)
        for (uint32_t i = 0; i < sh->fx->program_count; i++) hfx_rt_program_free(dev, &sh->programs[i]);
    free(sh->programs);
    for (uint32_t i = 0; i < sh->sampler_count; i++) hfx_rt_sampler_free(dev, &sh->samplers[i]);
    free(sh->samplers);
    if (sh->passes)
        for (uint32_t i = 0; i < sh->fx->pass_count; i++) {
            free(sh->passes[i].render_states);
            free(sh->passes[i].bindings);
        }
    free(sh->passes);
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
    return target == HFX_TARGET_SPIRV ? hfx_rt_spirv_check(dev, fx) : HFX_OK;
}

static hfx_shared *shared_create(hfx_device *dev, hfx_fx_effect *fx, hfx_target target) {
    if (check_effect(dev, fx, target)) return NULL;
    hfx_shared *sh = calloc(1, sizeof *sh);
    if (!sh) return NULL;
    sh->refs = 1;
    sh->dev = dev;
    sh->fx = fx;
    sh->programs = calloc(fx->program_count ? fx->program_count : 1, sizeof *sh->programs);
    sh->passes = calloc(fx->pass_count ? fx->pass_count : 1, sizeof *sh->passes);
    sh->annotations = calloc(fx->annotation_count ? fx->annotation_count : 1, sizeof *sh->annotations);
    if (!sh->programs || !sh->passes || !sh->annotations) {
        hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
        shared_release(sh);
        return NULL;
    }
    for (uint32_t i = 0; i < fx->annotation_count; i++) sh->annotations[i] = (struct hfx_annotation){sh, &fx->annotations[i]};
    uint32_t cap = 0;
    int rc = HFX_OK;
    for (uint32_t i = 0; i < fx->program_count && !rc; i++)
        rc = target == HFX_TARGET_SPIRV ? hfx_rt_spirv_program_build(sh, i) : hfx_rt_program_build(sh, i, target);
    if (!rc) rc = make_samplers(sh, &cap);
    for (uint32_t i = 0; i < fx->pass_count && !rc; i++) rc = build_pass(sh, &cap, i);
    while (dev->gl.GetError() != GL_NO_ERROR) {}
    if (rc) {
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
    free(e->values), free(e->stamps), free(e->textures), free(e->params), free(e->techniques), free(e->passes);
    free(e->log);
    free(e->path);
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
    e->params = calloc(fx->param_count ? fx->param_count : 1, sizeof *e->params);
    e->techniques = calloc(fx->technique_count ? fx->technique_count : 1, sizeof *e->techniques);
    e->passes = calloc(fx->pass_count ? fx->pass_count : 1, sizeof *e->passes);
    uint32_t ring = 64; /* at least four changes of every parameter between two looks */
    while (ring < 4 * (uint64_t)fx->top_param_count + 64 && ring < (1u << 30)) ring *= 2;
    e->log_mask = ring - 1;
    e->log = malloc(ring * sizeof *e->log);
    if (!e->values || !e->stamps || !e->textures || !e->params || !e->techniques || !e->passes || !e->log) {
        instance_free(e);
        return NULL;
    }
    e->stamp = &sh->dev->stamp;
    e->id = ++sh->dev->stamp;
    const uint32_t *values = src ? src->values : fx->values;
    if (values && fx->value_words) memcpy(e->values, values, fx->value_words * sizeof *e->values);
    for (uint32_t i = 0; i <= fx->top_param_count; i++) e->stamps[i] = src ? src->stamps[i] : ++sh->dev->stamp;
    if (src) memcpy(e->textures, src->textures, fx->param_count * sizeof *e->textures);
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
    for (uint32_t i = 0; i < fx->pass_count; i++) e->passes[i] = (hfx_pass){e, &sh->passes[i], i};
    e->current = src ? src->current : 0;
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

/* Loads a compiled effect (taking it); on failure frees it and reports in dev and *errors. */
static hfx_effect *load_compiled(hfx_device *dev, hfx_fx_effect *fx, const hfx_load_options *opt, char **errors) {
    hfx_target target = opt ? opt->target : HFX_TARGET_GLSL330;
    if ((unsigned)target >= HFX_TARGET_COUNT) target = HFX_TARGET_GLSL330;
    hfx_shared *sh = shared_create(dev, fx, target);
    hfx_effect *e = sh ? instance_create(sh, NULL) : NULL;
    if (!e) {
        if (sh) shared_free(sh);
        else hfx_fx_effect_free(fx);
        if (!dev->error[0]) hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
        if (errors) *errors = *errors ? append_line(*errors, NULL, dev->error) : dup_string(dev->error);
        return NULL;
    }
    return e;
}

static hfx_effect *load(hfx_device *dev, const char *path, const void *data, size_t size, const char *name,
                        const hfx_load_options *opt, char **errors) {
    if (errors) *errors = NULL;
    if (!dev) return NULL;
    dev->error[0] = '\0';
    hfx_fx_effect *fx;
    if (data && hfx_fx_is_hfxo(data, size)) {
        char err[512] = "";
        fx = hfx_fx_read_hfxo(data, size, err, sizeof err);
        if (!fx) hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: %s", name, err);
    } else {
        char *diag = NULL;
        fx = hfx_rt_compile_fx(path, data, size, name, opt, &diag);
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

static int is_hfxo_file(const char *path, void **data, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    unsigned char head[16];
    size_t n = fread(head, 1, sizeof head, f);
    int hfxo = hfx_fx_is_hfxo(head, n);
    if (hfxo && fseek(f, 0, SEEK_END) == 0) {
        long len = ftell(f);
        *data = len > 0 ? malloc((size_t)len) : NULL;
        if (*data && fseek(f, 0, SEEK_SET) == 0 && fread(*data, 1, (size_t)len, f) == (size_t)len) *size = (size_t)len;
        else free(*data), *data = NULL, hfxo = -1;
    }
    fclose(f);
    return hfxo;
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
        hfx_rt_fail(dev, HFX_ERR_LOAD, "%s: cannot read the file", path);
        if (errors) *errors = dup_string(dev->error);
        return NULL;
    }
    hfx_effect *e = load(dev, path, data, size, path, opt, errors);
    free(data);
    if (e && !(e->path = dup_string(path))) { /* hfx_effect_reload reads it again */
        hfx_effect_destroy(e);
        hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
        if (errors) free(*errors), *errors = dup_string(dev->error);
        return NULL;
    }
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
    return load(dev, NULL, data, size, name ? name : "memory", opt, errors);
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
    if (e && src->path && !(e->path = dup_string(src->path))) { /* a clone reloads from the same file */
        instance_free(e);
        e = NULL;
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
    if (e->dev->applied && e->dev->applied->fx == e) e->dev->applied = NULL; /* its address may come back */
    if (--e->sh->refs == 0) shared_free(e->sh);
    instance_free(e);
}

hfx_device *hfx_effect_device(const hfx_effect *e) { return e ? e->dev : NULL; }

const char *hfx_effect_warnings(const hfx_effect *e) {
    return e && e->sh->warnings ? e->sh->warnings : "";
}
