/* internal.h: the runtime's graphics-API-free core. An effect is a per-instance part (parameter
 * values, the current technique, handles) over a shared, reference-counted part (the compiled
 * effect) that clones share. The device, the shared part and the instance each hold a pointer to
 * their back end's part (gl/gl_int.h, vk/vk.h), and the core reaches a back end only through its
 * table (hfx_backend), so nothing here names an OpenGL or Vulkan type. One section per .c file,
 * in the chibicc way: tests/runtime/header_sections.cmake checks that each function a section
 * declares is defined in that file. */
#ifndef HFX_RUNTIME_INTERNAL_H
#define HFX_RUNTIME_INTERNAL_H

#include <stdint.h>
#include <string.h>

#include "compile.h"
#include "effect.h"
#include "grow.h"
#include "hfx/hfx.h"
#include "states.h"

typedef struct hfx_shared hfx_shared;

/* A render state's current D3D value (ints, or floats for FLOAT and COLOR states). */
typedef struct hfx_rs_value {
    int32_t i;
    float f[4];
} hfx_rs_value;

/* The back end's table: what the core (load.c, params.c, apply.c...) asks of OpenGL
 * (gl/backend.c) or Vulkan (vk/backend.c). A program links only the back end whose
 * hfx_device_create_* it calls, since nothing else names a table. */
typedef struct hfx_backend {
    const char *name;                                      /* "OpenGL", "Vulkan" */
    int (*shared_build)(hfx_shared *sh, hfx_target target); /* programs, samplers, passes */
    void (*shared_release)(hfx_shared *sh);                /* what shared_build made (any part) */
    int (*instance_init)(hfx_effect *e);                   /* the back end's per-instance part */
    void (*instance_free)(hfx_effect *e);
    void (*device_destroy)(hfx_device *dev);
    hfx_target (*target_for)(hfx_target asked);           /* the shader target it loads */
    int (*cache_usable)(const hfx_device *dev);            /* a program cache; NULL: none */
    /* hfx_pass_apply (Passes[i].Apply()); a back end whose Apply needs more (Vulkan's command
     * buffer and target) refuses here and has its own entry (hfx_pass_apply_vk). */
    int (*pass_apply)(hfx_pass *p);
    /* Begin saves what the passes will change, End puts it back; apply.c checks the order. */
    int (*effect_begin)(hfx_effect *e);
    int (*effect_end)(hfx_effect *e);
    /* hfx_effect_reload between begin and end: what begin saved passes from the old instance
     * to the new one, so that end still restores it. NULL: nothing to carry. */
    void (*begun_carry)(hfx_effect *to, const hfx_effect *from);
    /* hfx_param_texture_target where the back end binds textures itself; NULL: the samplers'
     * dimension (apply.c). */
    unsigned int (*texture_target)(const hfx_param *p);
} hfx_backend;

/* A device: the core's part, and its back end's (exactly one of gl, vk is set). */
struct hfx_device {
    const hfx_backend *be;
    struct hfx_gl_device *gl;      /* runtime/gl/: the GL context's table and shadow, NULL on Vulkan */
    struct hfx_vk_device *vk;      /* runtime/vk/: the Vulkan device's state, NULL on GL */
    char error[1024];
    uint64_t stamp;                /* last parameter version handed out */
    /* The pass whose Apply ran last, when the back end has set no other state since: applying
     * it again only needs the parameters changed since. GL: a program-only pass; Vulkan: a pass
     * whose render states read no parameter (its pipeline is kept, not looked up again). Anything
     * that changes the device's state (another pass, begin / end, the viewport, a render state
     * set by hand) clears it, and so does freeing or reloading the pass's effect. */
    const struct hfx_pass *applied;
    hfx_rs_value rs[HFX_ST_COUNT_];/* D3D render states as the passes set them */
    float max_anisotropy;          /* 0 without anisotropic filtering (state_values.c clamps to it) */
    int cache_only;                /* while set, a program missing from the back end's cache fails to build */
};

/* D3D9's sampler state for one sampler stage. */
typedef struct hfx_sampler_desc {
    int32_t address[3], mag, min, mip, max_mip_level, max_anisotropy, srgb;
    float lod_bias, border[4];
    int srgb_set; /* SRGBTexture written explicitly */
} hfx_sampler_desc;

/* A program's preshaders at run time (preshader.c, any back end): per top-level parameter the
 * preshaders that read it (deps[first[r] .. first[r] + count[r])), which are marked, and how
 * many ran (tests check that nothing else runs). */
typedef struct hfx_preshaders {
    const hfx_fx_program *src;
    uint32_t *deps, *first, *count;
    uint8_t *dirty;
    uint32_t total, pending;
    uint64_t runs;
} hfx_preshaders;

/* A range of registers to send; empty ({UINT32_MAX, 0}) while lo > hi. */
typedef struct hfx_reg_range { uint32_t lo, hi; } hfx_reg_range;

/* preshader.c */
int hfx_preshaders_init(hfx_preshaders *ps, const hfx_fx_effect *fx, const hfx_fx_program *fp); /* HFX_OK or _MEMORY */
void hfx_preshaders_free(hfx_preshaders *ps);
void hfx_preshaders_mark(hfx_preshaders *ps, uint32_t root);  /* top-level parameter root changed */
/* Some preshader reads top-level parameter root. */
static inline int hfx_preshaders_read(const hfx_preshaders *ps, uint32_t root) { return ps->total && ps->count[root]; }
/* Runs the marked preshaders into regs (reg_size vec4 registers), growing range over what they wrote. */
void hfx_preshaders_run(hfx_preshaders *ps, const uint32_t *values, float *regs, uint32_t reg_size, hfx_reg_range *range);

/* The shared part of an effect. */
struct hfx_shared {
    int refs;
    struct hfx_vk_shared *vk; /* runtime/vk/: pipelines' programs and samplers, NULL on GL */
    hfx_device *dev;
    hfx_fx_effect *fx;
    struct hfx_gl_shared *gl; /* runtime/gl/: programs, sampler objects, passes; NULL on Vulkan */
    char *warnings;
    size_t warnings_len;
    struct hfx_annotation *annotations;
};

struct hfx_annotation {
    hfx_shared *sh;
    const hfx_fx_annotation *a;
};

/* What a parameter accepts, computed at load (hfx_param.accept): the set functions test one
 * mask and the count against words, and only a refusal or an array prefix takes the long way. */
enum {
    ACC_BOOL = 1u << 0,    /* a bool scalar (set_bool / get_bool) */
    ACC_INT = 1u << 1,     /* an int scalar */
    ACC_FLOAT = 1u << 2,   /* a float scalar */
    ACC_FLOATS = 1u << 3,  /* float-valued scalar, vector, matrix or array of them */
    ACC_INTS = 1u << 4,    /* int- or bool-valued ... */
    ACC_RAW_INTS = 1u << 5,/* int-valued: set_ints stores the words as given (bools become 0/1) */
    ACC_MATRIX = 1u << 6,  /* a float matrix up to 4x4, not an array */
    ACC_TEXTURE = 1u << 7, /* a texture or sampler, not an array */
    ACC_WHOLE = 1u << 8    /* count == words is a valid count */
};

struct hfx_param {
    uint32_t *value;          /* the instance's words for this parameter */
    hfx_effect *fx;
    size_t floats_n, ints_n;  /* the count set_floats / set_ints take without a second look (else SIZE_MAX) */
    uint32_t words;           /* info->words */
    uint32_t root;            /* the top-level parameter that holds it (top_param_count: none) */
    uint32_t accept;          /* ACC_* */
    uint32_t index;
    const hfx_fx_param *info; /* fx->sh->fx->params[index] */
};

struct hfx_technique {
    hfx_effect *fx;
    uint32_t index;
};

struct hfx_pass {
    hfx_effect *fx;
    const struct hfx_rt_pass *rt; /* GL: &fx->sh->gl->passes[index] (set by gl's instance_init) */
    uint32_t index;
    /* shader arrays: the program the selectors chose, and the change log's length then (the
     * selectors run again only after a parameter changed); chosen_seen = 0: never chosen */
    struct hfx_rt_program *chosen;
    uint64_t chosen_seen;
    /* switches (GL): the variant picked for `switched_base` (the pass's program, or the shader
     * arrays' choice) when its switches were switch_mask; NULL: none picked yet */
    struct hfx_rt_program *switched, *switched_base;
    uint32_t switch_mask;
    uint32_t chosen_index;  /* Vulkan: the program index chosen then (chosen_seen as above) */
};

/* A file's modification time and size as last seen; exists = 0 for a missing file. */
typedef struct hfx_file_stamp {
    int64_t sec, nsec, size;
    int exists;
} hfx_file_stamp;

/* The files an effect came from (hfx_effect_dependencies) and their stamps (watch.c). */
typedef struct hfx_watch {
    struct hfx_rt_files files;  /* compile.h */
    hfx_file_stamp *stamps;     /* one per file */
} hfx_watch;

struct hfx_effect {
    /* Change log, so Apply visits only the parameters changed since a program last looked:
     * top-level indices in change order, in a ring of log_mask + 1 entries; a program that fell
     * more than a ring behind (or last followed another instance) scans all it reads. */
    uint32_t *log;
    uint64_t log_len;       /* entries ever written */
    uint64_t *stamps;       /* per top-level parameter + 1: version of its value */
    uint64_t *stamp;        /* &dev->stamp: last version handed out (device-wide) */
    uint32_t log_mask;
    uint64_t id;            /* unique per instance on the device */
    hfx_shared *sh;
    hfx_device *dev;
    uint32_t *values;       /* copy of fx->values */
    uint64_t *textures;     /* per parameter: a GL texture name, or a VkImageView */
    uint32_t *texture_layouts; /* per parameter: the VkImageLayout it is sampled in (Vulkan) */
    struct hfx_gl_instance *gl; /* runtime/gl/: what begin saved, NULL on Vulkan */
    struct hfx_vk_instance *vk; /* runtime/vk/: per-instance Vulkan state, NULL on GL */
    hfx_param *params;
    hfx_technique *techniques;
    hfx_pass *passes;
    uint32_t current;       /* technique index */
    int begun;              /* between hfx_effect_begin and hfx_effect_end */
    char *path;             /* the file hfx_effect_load read (owned), for hfx_effect_reload; NULL from memory */
    hfx_watch watch;        /* the files it was loaded from, for hfx_effect_reload_if_changed */
    uint32_t *sas_plan;     /* scene.c: parameters with a standard semantic, (index << 8 | id) */
    uint32_t sas_count;
    int sas_ready;          /* sas_plan made (on the first hfx_effect_bind_scene) */
    struct hfx_pool *pool;  /* pool.c: the pool whose `shared` parameters it shares, or NULL */
};

/* A top-level parameter's value changed: a new version, and an entry in the change log. */
static inline void hfx_rt_mark_changed(hfx_effect *fx, uint32_t root) {
    fx->stamps[root] = ++*fx->stamp;
    fx->log[fx->log_len++ & fx->log_mask] = root;
}

/* state_values.c: render and sampler states as data (D3D9's defaults, a state's current value). */
void hfx_rs_defaults(hfx_rs_value *rs);
void hfx_rs_resolve(const hfx_effect *fx, const hfx_fx_state *st, hfx_rs_value *out);
/* The shader-array entry the selector state `state` (a VertexShader / PixelShader EXPR state of
 * pass `pass`; stage 0 / 1) picks now: its value truncated by Direct3D's rule (NaN 0) and clamped
 * into the entries the pass's variants name, as D3D9 clamps an array index. HFX_NONE for none. */
uint32_t hfx_rs_selected(const hfx_effect *fx, uint32_t state, uint32_t pass, int stage);
/* D3D9's sampler states as data, for any back end's samplers. */
void hfx_sampler_desc_default(hfx_sampler_desc *d);
void hfx_sampler_desc_apply(hfx_sampler_desc *d, uint32_t id, const hfx_rs_value *v);
/* A sampler state into a description being built: constants into d, PARAM and EXPR ones (at
 * most 32, computed at Apply) appended to dyn. */
void hfx_sampler_state_add(const hfx_fx_state *st, hfx_sampler_desc *d, const hfx_fx_state **dyn, uint32_t *n);
/* A sampler_state block's description and its dynamic states (all but Texture). */
void hfx_sampler_desc_of(const hfx_fx_effect *fx, uint32_t sampler, hfx_sampler_desc *d, const hfx_fx_state **dyn,
                         uint32_t *n);

/* params.c */
/* The hfx_fx_dim (1D as 2D) of the first sampler that samples parameter `param` or is it, -1 when
 * none: what hfx_param_texture_target tells the application where the back end does not choose. */
int hfx_rt_texture_dim(const hfx_fx_effect *fx, uint32_t param);
void hfx_rt_param_changed(hfx_effect *fx, uint32_t root);
uint32_t hfx_rt_param_accept(const hfx_fx_param *i);

/* param_paths.c: leaf(ctx, path, param) for each value leaf of parameter index (struct members
 * and the elements of an array of structs one by one, objects skipped), path being its GLSL
 * name under path; stops at the first nonzero return and returns it. */
typedef int (*hfx_param_leaf_fn)(void *ctx, const char *path, const hfx_fx_param *p);
int hfx_param_leaves(const hfx_fx_effect *fx, uint32_t index, const char *path, hfx_param_leaf_fn leaf, void *ctx);

/* pool.c */
int hfx_rt_pool_join(struct hfx_pool *pool, hfx_effect *e); /* checks shared types, takes the pool's values */
void hfx_rt_pool_leave(hfx_effect *e);
void hfx_rt_pool_share(hfx_effect *e, uint32_t root);        /* after a set of e's top-level parameter root */
void hfx_rt_pool_swapped(hfx_effect *fx, hfx_effect *next);  /* hfx_effect_reload swapped their contents */

/* reload.c: parameter j of b has parameter i of a's shape (same words in the same places). */
int hfx_rt_same_shape(const hfx_fx_effect *a, uint32_t i, const hfx_fx_effect *b, uint32_t j);
/* The textures of from's parameter i and its members / elements into to's j (the same shape). */
void hfx_rt_copy_textures(hfx_effect *to, uint32_t j, const hfx_effect *from, uint32_t i);

/* watch.c */
int hfx_rt_watch_set(hfx_watch *w, struct hfx_rt_files *files); /* takes files; 0 or -1 */
int hfx_rt_watch_copy(hfx_watch *to, const hfx_watch *from);
void hfx_rt_watch_free(hfx_watch *w);

/* device_core.c */
int hfx_rt_fail(hfx_device *dev, int code, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* A load-time warning about the effect, at st's position when it has one (hfx_effect_warnings). */
void hfx_shared_warn(hfx_shared *sh, const hfx_fx_state *st, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* load.c */
/* Loads a compiled effect built by hand (tests, tools); takes fx, even on failure. */
hfx_effect *hfx_rt_effect_from_fx(hfx_device *dev, hfx_fx_effect *fx, const hfx_load_options *opt, char **errors);
char *hfx_rt_strdup(const char *s); /* malloc'ed copy, NULL when out of memory */

#endif
