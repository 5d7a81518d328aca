/* internal.h: the runtime's objects. An effect is a per-instance part (parameter values, the
 * current technique, handles) over a shared, reference-counted part (the compiled effect, its
 * GL programs and sampler objects) that clones share. The device shadows every GL state it
 * sets so that an Apply with nothing changed issues no GL call. */
#ifndef HFX_RUNTIME_INTERNAL_H
#define HFX_RUNTIME_INTERNAL_H

#include <stdint.h>
#include <string.h>

#include "compile.h"
#include "effect.h"
#include "gl/gl.h"
#include "grow.h"
#include "hfx/hfx.h"
#include "states.h"

#define HFX_MAX_UNITS 32

typedef struct hfx_shared hfx_shared;
typedef struct hfx_saved hfx_saved;

/* The GL state the device sets, as GL holds it. */
typedef struct hfx_glstate {
    GLboolean cull;
    GLenum cull_face, front_face, polygon_mode;
    GLenum provoking;      /* GL_FIRST_VERTEX_CONVENTION: D3D's flat shading takes the first vertex */
    GLboolean depth_test, depth_mask;
    GLenum depth_func;
    GLboolean blend;
    GLenum src_rgb, dst_rgb, src_a, dst_a, eq_rgb, eq_a;
    float blend_color[4];
    uint8_t color_mask[4]; /* RGBA bits 1,2,4,8 (D3D's order) per draw buffer */
    GLboolean stencil;
    struct { GLenum func; GLint ref; GLuint mask, write; GLenum fail, zfail, pass; } face[2]; /* front, back */
    GLboolean scissor, offset_fill, offset_line, offset_point;
    float offset_factor, offset_units;
    GLboolean multisample, srgb, dither, line_smooth, sample_mask;
    GLuint sample_mask_value;
    uint8_t clip_planes;
} hfx_glstate;

/* What texture.c knows of one texture name. */
typedef struct hfx_texture_note {
    GLuint name;          /* 0: a free slot */
    GLint lowered_to;     /* the MAX_LEVEL hfx wrote, or -1 */
    int stale;            /* hfx_device_texture_changed: check again at the next bind */
} hfx_texture_note;

/* Texture names hfx has checked (open addressing with linear probing). */
typedef struct hfx_texture_set {
    hfx_texture_note *notes;
    size_t cap, count; /* cap: 0 or a power of two */
} hfx_texture_set;

/* A texture unit as GL holds it. */
typedef struct hfx_unit_state {
    GLuint texture, sampler;
    GLenum target;
} hfx_unit_state;

/* A render state's current D3D value (ints, or floats for FLOAT and COLOR states). */
typedef struct hfx_rs_value {
    int32_t i;
    float f[4];
} hfx_rs_value;

/* The entry points loading SPIR-V needs beyond GL 3.3 (ARB_gl_spirv, GL 4.1's glShaderBinary,
 * GL 4.3's program interface queries), loaded only when the context has them: ok = all there. */
typedef struct hfx_gl_spirv {
    int ok;
    PFNGLSHADERBINARYPROC ShaderBinary;
    PFNGLSPECIALIZESHADERPROC SpecializeShader; /* glSpecializeShader or glSpecializeShaderARB */
    PFNGLGETPROGRAMINTERFACEIVPROC GetProgramInterfaceiv;
    PFNGLGETPROGRAMRESOURCEIVPROC GetProgramResourceiv;
} hfx_gl_spirv;

/* The back end's table: what the graphics-API-free core (load.c, params.c, techniques.c...)
 * asks of OpenGL (gl/backend.c) or Vulkan (vk/backend.c). A program links only the back end
 * whose hfx_device_create_* it calls, since nothing else names a table. */
typedef struct hfx_backend {
    const char *name;                                      /* "OpenGL", "Vulkan" */
    int (*shared_build)(hfx_shared *sh, hfx_target target); /* programs, samplers, passes */
    void (*shared_release)(hfx_shared *sh);                /* what shared_build made (any part) */
    int (*instance_init)(hfx_effect *e);                   /* the back end's per-instance part */
    void (*instance_free)(hfx_effect *e);
    void (*device_destroy)(hfx_device *dev);
    hfx_target (*target_for)(hfx_target asked);           /* the shader target it loads */
    int (*cache_usable)(const hfx_device *dev);            /* a program cache; NULL: none */
    void (*save_units)(hfx_device *dev, struct hfx_saved *s, uint32_t mask); /* begin's texture units; NULL: none */
    int (*effect_begin)(hfx_effect *e);                    /* another back end's Begin / End (GL's are gl/apply.c's) */
    int (*effect_end)(hfx_effect *e);
} hfx_backend;

struct hfx_device {
    const hfx_backend *be;
    struct hfx_vk_device *vk;      /* runtime/vk/: the Vulkan device's state, NULL on GL */
    hfx_gl gl;
    hfx_gl_spirv spirv;            /* runtime/spirv_load.c */
    char error[1024];
    uint64_t stamp;                /* last parameter version handed out */
    /* The pass whose Apply ran last, when it was a program-only pass and hfx has set no other
     * GL state since: applying it again only needs the parameters changed since. Anything that
     * changes the device's state (another pass, begin / end, the viewport) clears it. */
    const struct hfx_pass *applied;
    GLuint program;                /* bound program */
    GLenum active_unit;            /* glActiveTexture's unit */
    hfx_unit_state units[HFX_MAX_UNITS];
    hfx_glstate state;             /* shadow of GL */
    hfx_rs_value rs[HFX_ST_COUNT_];/* D3D render states as the passes set them */
    float pos_fixup[4];            /* hfx_pos_fixup for the current viewport and target */
    uint64_t pos_fixup_serial;     /* bumped when pos_fixup changes; programs compare it first */
    int flip;                      /* drawing into a framebuffer object: D3D9's row order */
    float depth_bias_scale;        /* DepthBias (0..1 depth units) to glPolygonOffset units */
    float max_anisotropy;          /* 0 without anisotropic filtering */
    int srgb_decode;               /* EXT_texture_sRGB_decode */
    float *scratch;                /* for uploads that convert int <-> float */
    size_t scratch_size;
    hfx_texture_set checked;       /* textures whose mip levels texture.c has made complete */
    char *program_cache;           /* hfx_device_set_program_cache's folder, or NULL */
    int cache_only;                /* while set, a program missing from the cache fails to build */
};

/* D3D9's sampler state for one sampler stage. */
typedef struct hfx_sampler_desc {
    int32_t address[3], mag, min, mip, max_mip_level, max_anisotropy, srgb;
    float lod_bias, border[4];
    int srgb_set; /* SRGBTexture written explicitly */
} hfx_sampler_desc;

/* A GL sampler object made from a sampler_state block, maybe with pass overrides and
 * states that read parameters at apply time. */
typedef struct hfx_rt_sampler {
    GLuint object;
    hfx_sampler_desc base, current;        /* base: constant states; current: what GL holds */
    const hfx_fx_state **dynamic;          /* PARAM-valued states, applied over base */
    uint32_t dynamic_count;
} hfx_rt_sampler;

enum { /* hfx_upload.fn */
    UP_F1, UP_F2, UP_F3, UP_F4, UP_I1, UP_I2, UP_I3, UP_I4, UP_U1, UP_U2, UP_U3, UP_U4,
    UP_M2, UP_M3, UP_M4, UP_M2x3, UP_M3x2, UP_M2x4, UP_M4x2, UP_M3x4, UP_M4x3
};

enum { /* hfx_upload.kind: how Apply calls it, decided at load */
    UK_FLOAT,   /* glUniform{1,2,3,4}fv on the words as they are */
    UK_MATRIX,  /* glUniformMatrix*fv(transpose = GL_FALSE) */
    UK_INT,     /* glUniform{1,2,3,4}iv */
    UK_UINT,    /* glUniform{1,2,3,4}uiv: an int parameter's bits into a GLSL uint (HLSL uint) */
    UK_CONVERT  /* the GLSL type's base differs from the data's (int <-> float): through scratch */
};

typedef void(APIENTRYP hfx_uniform_f)(GLint, GLsizei, const GLfloat *);
typedef void(APIENTRYP hfx_uniform_i)(GLint, GLsizei, const GLint *);
typedef void(APIENTRYP hfx_uniform_m)(GLint, GLsizei, GLboolean, const GLfloat *);

/* One glUniform* call that uploads (part of) a top-level parameter, with the GL entry point
 * resolved at load so Apply makes the call without looking at the type. */
typedef struct hfx_upload {
    union { hfx_uniform_f f; hfx_uniform_i i; hfx_uniform_m m; } call; /* unused for UK_CONVERT */
    GLint location;
    GLsizei count;          /* array elements */
    uint32_t offset;        /* in the value buffer */
    uint16_t kind, fn;      /* UK_*, UP_* */
    uint32_t words;
} hfx_upload;

enum { /* hfx_slot.mode */
    SLOT_NONE,   /* the program does not read the parameter */
    SLOT_FLOAT,  /* one UK_FLOAT upload: slot.up */
    SLOT_REG4,   /* SLOT_REG with rows of 4 components, all in registers GL kept: the registers hold
                  * the words as they are, so slot.up sends them from the values (glUniform4fv on
                  * hfx_c[reg], reg_rows elements) after a copy into the image */
    SLOT_MATRIX, /* one UK_MATRIX upload: slot.up */
    SLOT_OTHER,  /* uploads[first .. first + count) */
    SLOT_REG,    /* packed into the program's registers (hfx_c): reg, reg_rows, reg_cols, up.offset */
    SLOT_REG_PRE,/* the same, and read by preshaders: off Apply's one-change path */
    SLOT_PRE     /* read by preshaders alone */
};

/* Per program, per top-level parameter (one more for parameters outside any): its uploads and
 * the version of the value GL holds. */
typedef struct hfx_slot {
    uint64_t held;          /* stamp of the value GL holds (0: none) */
    hfx_upload up;          /* the first upload, at hand for the common single-call case */
    uint32_t mode;          /* SLOT_* */
    uint32_t first, count;  /* all its uploads */
    uint32_t reg;           /* SLOT_REG: first register */
    uint16_t reg_rows, reg_cols; /* SLOT_REG: registers, and the components used in each */
    uint32_t pad_;          /* 64 bytes: indexing is a shift */
} hfx_slot;

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

int hfx_preshaders_init(hfx_preshaders *ps, const hfx_fx_effect *fx, const hfx_fx_program *fp); /* HFX_OK or _MEMORY */
void hfx_preshaders_free(hfx_preshaders *ps);
void hfx_preshaders_mark(hfx_preshaders *ps, uint32_t root);  /* top-level parameter root changed */
/* Some preshader reads top-level parameter root. */
static inline int hfx_preshaders_read(const hfx_preshaders *ps, uint32_t root) { return ps->total && ps->count[root]; }
/* Runs the marked preshaders into regs (reg_size vec4 registers), growing range over what they wrote. */
void hfx_preshaders_run(hfx_preshaders *ps, const uint32_t *values, float *regs, uint32_t reg_size, hfx_reg_range *range);

typedef struct hfx_rt_program {
    GLuint object;
    hfx_slot *slots;        /* per top-level parameter + 1 */
    uint32_t *reads;        /* the top-level parameters the program reads, for a full scan */
    uint32_t read_count;
    hfx_upload *uploads; uint32_t upload_count;
    /* Packed parameters (HFXC_PACK_UNIFORMS): Apply copies changed ones into regs, the image of
     * hfx_c GL holds, and sends the changed range with one glUniform4fv. */
    float *regs;            /* reg_size * 4 */
    GLint *reg_locs;        /* location of hfx_c[i], for the reg_active elements GL kept */
    uint32_t reg_size, reg_active;
    hfx_uniform_f reg_call; /* glUniform4fv */
    uint64_t memo_effect;   /* the effect instance (id) whose change log this program follows */
    uint64_t memo_seen;     /* that log's length when the program last looked */
    GLint pos_fixup_loc;
    uint64_t pos_fixup_serial; /* the device's serial when pos_fixup was last compared */
    float pos_fixup[4];     /* value GL holds */
    GLint alpha_func_loc, alpha_ref_loc;
    int alpha_test;         /* either location is used */
    int32_t alpha_func;     /* values GL holds (-1: unknown) */
    float alpha_ref;
    hfx_preshaders pre;     /* marked when a parameter they read changes, run before the registers are sent */
    /* Switches (common/effect.h): the bools' words in the effect's values, and the variants with
     * them constant, variants[mask] (bit k: switch k true), each linked at the first Apply that
     * needs it; a variant GL refused is marked in switch_failed and this program used instead. */
    uint32_t switch_count;
    uint32_t switch_words[HFX_FX_MAX_SWITCHES];
    struct hfx_rt_program *variants;
    uint32_t switch_failed;
    uint32_t index;         /* in the shared programs: which compiled program this is */
    hfx_target target;
} hfx_rt_program;

/* The switches' values now, one bit each (what picks a program's variant). */
static inline uint32_t hfx_rt_switch_mask(const hfx_rt_program *p, const uint32_t *values) {
    uint32_t m = 0;
    for (uint32_t k = 0; k < p->switch_count; k++) m |= (uint32_t)(values[p->switch_words[k]] != 0) << k;
    return m;
}

/* What a pass binds on one texture unit. */
typedef struct hfx_rt_binding {
    int32_t unit;
    uint32_t sampler;       /* index into shared samplers (GL sampler object) or HFX_NONE */
    uint32_t texture_param; /* param whose texture is bound; HFX_NONE: use sampler_param */
    uint32_t sampler_param; /* a sampler param set with hfx_param_set_texture, or HFX_NONE */
    GLenum target;
} hfx_rt_binding;

typedef struct hfx_rt_pass {
    uint32_t program;       /* index into shared programs, HFX_NONE: leave the bound one */
    hfx_rt_program *prog;   /* &programs[program], NULL when none */
    int direct;             /* a program, no render states, no texture bindings: Apply's short way */
    uint32_t *render_states; uint32_t render_state_count; /* indices into fx->states */
    uint32_t groups;        /* GL state groups the pass's render states touch */
    hfx_rt_binding *bindings; uint32_t binding_count;
    /* shader arrays chosen at Apply: the variants (common/effect.h) and the EXPR states giving
     * the vertex and pixel array indices (HFX_NONE for a fixed stage) */
    const hfx_fx_variant *variants; uint32_t variant_count;
    uint32_t selector[2];
} hfx_rt_pass;

/* The shared part of an effect. */
struct hfx_shared {
    int refs;
    struct hfx_vk_shared *vk; /* runtime/vk/: pipelines' programs and samplers, NULL on GL */
    hfx_device *dev;
    hfx_fx_effect *fx;
    hfx_rt_program *programs;
    hfx_rt_sampler *samplers; uint32_t sampler_count; /* fx samplers first, then pass overrides */
    hfx_rt_pass *passes;
    uint32_t groups;        /* union of the passes' groups */
    uint32_t unit_mask;     /* units any pass binds */
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
    const hfx_rt_pass *rt;    /* &fx->sh->passes[index] */
    uint32_t index;
    /* shader arrays: the program the selectors chose, and the change log's length then (the
     * selectors run again only after a parameter changed); chosen_seen = 0: never chosen */
    hfx_rt_program *chosen;
    uint64_t chosen_seen;
    /* switches: the variant picked for `switched_base` (the pass's program, or the shader arrays'
     * choice) when its switches were switch_mask; NULL: none picked yet */
    hfx_rt_program *switched, *switched_base;
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

/* What hfx_effect_begin saved. */
struct hfx_saved {
    int active;
    hfx_glstate state;
    GLint program, active_unit;
    struct { GLint tex[4], sampler; } units[HFX_MAX_UNITS]; /* 1D, 2D, 3D, cube */
    hfx_rs_value alpha_test[3]; /* AlphaTestEnable, AlphaFunc, AlphaRef: D3D states GL does not hold */
};

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
    struct hfx_vk_instance *vk; /* runtime/vk/: per-instance Vulkan state, NULL on GL */
    hfx_param *params;
    hfx_technique *techniques;
    hfx_pass *passes;
    uint32_t current;       /* technique index */
    hfx_saved saved;
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

static inline void hfx_rt_use_program(hfx_device *dev, GLuint program) {
    if (dev->program == program) return;
    dev->gl.UseProgram(program);
    dev->program = program;
}

/* gl/backend.c: the OpenGL back end's table. */
extern const hfx_backend hfx_gl_backend;

/* state_values.c: render and sampler states as data (D3D9's defaults, a state's current value). */
void hfx_rs_defaults(hfx_rs_value *rs);
void hfx_rs_resolve(const hfx_effect *fx, const hfx_fx_state *st, hfx_rs_value *out);
/* The shader-array entry the selector state `state` (a VertexShader / PixelShader EXPR state of
 * pass `pass`; stage 0 / 1) picks now: its value truncated by Direct3D's rule (NaN 0) and clamped
 * into the entries the pass's variants name, as D3D9 clamps an array index. HFX_NONE for none. */
uint32_t hfx_rs_selected(const hfx_effect *fx, uint32_t state, uint32_t pass, int stage);

/* device_core.c */
int hfx_rt_fail(hfx_device *dev, int code, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* A load-time warning about the effect, at st's position when it has one (hfx_effect_warnings). */
void hfx_shared_warn(hfx_shared *sh, const hfx_fx_state *st, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
void hfx_gl_device_destroy(hfx_device *dev);
void hfx_rt_read_state(hfx_device *dev, hfx_glstate *s);
void hfx_rt_write_state(hfx_device *dev, const hfx_glstate *want);
void hfx_rt_bind_unit(hfx_device *dev, int unit, GLenum target, GLuint texture, GLuint sampler);

/* texture.c: the texture bound on target of the active unit, made complete with the mip
 * levels it has, the first time hfx binds it; and the set of those checked freed. */
void hfx_rt_texture_check(hfx_device *dev, GLenum target, GLuint texture);
void hfx_rt_textures_free(hfx_device *dev);
void hfx_rt_read_target(hfx_device *dev);

/* apply.c: reads the textures and samplers GL holds on the units in mask into s->units. */
void hfx_rt_save_units(hfx_device *dev, hfx_saved *s, uint32_t mask);

/* program.c */
int hfx_rt_program_build(hfx_shared *sh, uint32_t index, hfx_target target);
/* Links vs + fs into p->object (fp's attribute locations bound first; NULL for SPIR-V). */
int hfx_rt_program_link(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp, GLuint vs, GLuint fs);
/* program_cache.c: link through the device's program cache when it has one (a hit loads the
 * driver's binary; a miss calls link and stores the result); hint before glLinkProgram. */
int hfx_rt_program_cached_link(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp, const char *vs_src,
                               const char *fs_src, int (*link)(hfx_shared *, hfx_rt_program *, const hfx_fx_program *,
                                                               const char *, const char *));
void hfx_rt_program_binary_hint(hfx_device *dev, GLuint program);
int hfx_rt_program_cache_usable(const hfx_device *dev); /* a folder, and a driver that hands out binaries */
void hfx_rt_program_free(hfx_device *dev, hfx_rt_program *p);
/* The variant of program p for switch values `mask`, linked now if it was not; p if GL refused it. */
hfx_rt_program *hfx_rt_program_switched(hfx_shared *sh, hfx_rt_program *p, uint32_t mask);
void hfx_rt_upload_all(hfx_effect *fx, hfx_rt_program *p);
void hfx_rt_upload_slow(hfx_device *dev, const hfx_upload *up, const uint32_t *values);
void hfx_rt_upload_slot(hfx_effect *fx, const hfx_rt_program *p, const hfx_slot *s); /* all of a parameter's uploads */
void hfx_rt_program_extras(hfx_device *dev, hfx_rt_program *p);
void hfx_rt_program_ready(hfx_rt_program *p, uint32_t tops); /* after the uploads and extras are resolved */
/* Picks the glUniform* call for a uniform of GL type `type` holding p; 0 when they do not match. */
int hfx_rt_upload_setup(const hfx_gl *gl, GLenum type, const hfx_fx_param *p, hfx_upload *up, uint32_t *comps);
int hfx_rt_upload_add(hfx_device *dev, hfx_rt_program *p, uint32_t *cap, const hfx_upload *up); /* appends to p */

/* Packed registers: a slot for use u (hfx_fx_use_packed), and the image with its locations;
 * loc_of gives hfx_c[i]'s location (GLSL names or SPIR-V's rule), -1 past what GL kept. */
void hfx_rt_slot_pack(hfx_slot *slot, const hfx_fx_effect *fx, const hfx_fx_uniform_use *u);
int hfx_rt_regs_setup(hfx_device *dev, hfx_rt_program *p, uint32_t size, GLint (*loc_of)(void *ctx, uint32_t i), void *ctx);

/* Copies a packed parameter's words into its registers, rows padded to 4 components. */
static inline void hfx_rt_reg_fill(hfx_rt_program *p, const hfx_slot *s, const uint32_t *values) {
    const uint32_t *src = values + s->up.offset;
    float *dst = p->regs + 4 * (size_t)s->reg;
    if (s->reg_cols == 4 && s->reg_rows == 1) { /* float4 and 4x4 first, in fixed-size copies */
        memcpy(dst, src, 16);
    } else if (s->reg_cols == 4 && s->reg_rows == 4) {
        memcpy(dst, src, 64);
    } else if (s->reg_cols == 4) {
        memcpy(dst, src, 16 * (size_t)s->reg_rows);
    } else {
        for (uint32_t i = 0; i < s->reg_rows; i++) memcpy(dst + 4 * i, src + i * s->reg_cols, 4 * (size_t)s->reg_cols);
    }
}

/* A SLOT_REG4 parameter's words into its registers, as they are. */
static inline void hfx_rt_reg_put4(hfx_rt_program *p, const hfx_slot *s, const uint32_t *src) {
    float *dst = p->regs + 4 * (size_t)s->reg;
    if (s->reg_rows == 1) memcpy(dst, src, 16); /* float4 in a fixed-size copy */
    else memcpy(dst, src, 16 * (size_t)s->reg_rows);
}

/* The same, adding its registers to the range to send. */
static inline void hfx_rt_reg_copy(hfx_rt_program *p, const hfx_slot *s, const uint32_t *values, hfx_reg_range *r) {
    hfx_rt_reg_fill(p, s, values);
    uint32_t last = s->reg + s->reg_rows - 1u;
    if (s->reg < r->lo) r->lo = s->reg;
    if (last > r->hi) r->hi = last;
}

/* Sends registers [lo, hi] that GL kept. */
static inline void hfx_rt_reg_send(hfx_rt_program *p, hfx_reg_range r) {
    if (r.lo > r.hi || r.lo >= p->reg_active) return;
    uint32_t hi = r.hi < p->reg_active ? r.hi : p->reg_active - 1;
    p->reg_call(p->reg_locs[r.lo], (GLsizei)(hi - r.lo + 1), p->regs + 4 * (size_t)r.lo);
}

/* preshader.c: a GL program's preshaders (after its registers are set up); what they read joins its reads. */
int hfx_rt_preshaders_setup(hfx_rt_program *p, const hfx_fx_effect *fx, const hfx_fx_program *fp);

/* Uploads the parameters whose version differs from the one this program holds, visiting only
 * the log entries written since the program last looked when it follows this instance; returns
 * HFX_OK (so Apply can end in it). */
int hfx_rt_upload_changed(hfx_effect *fx, hfx_rt_program *p);
/* The same for a program known to follow fx's log (the pass was the last one applied). */
int hfx_rt_upload_log(hfx_effect *fx, hfx_rt_program *p);

/* spirv_load.c: programs from SPIR-V (HFX_TARGET_SPIRV), uniforms by the compiler's locations. */
void hfx_rt_spirv_init(hfx_device *dev, hfx_gl_loader load); /* at device creation */
int hfx_rt_spirv_check(hfx_device *dev, const hfx_fx_effect *fx); /* HFX_ERR_GL when GL cannot load SPIR-V */
int hfx_rt_spirv_program_build(hfx_shared *sh, uint32_t index);

/* sampler.c */
void hfx_sampler_desc_default(hfx_sampler_desc *d);
void hfx_sampler_desc_apply(hfx_sampler_desc *d, uint32_t id, const hfx_rs_value *v);
/* A sampler state into a description being built: constants into d, PARAM and EXPR ones (at
 * most 32, computed at Apply) appended to dyn. */
void hfx_sampler_state_add(const hfx_fx_state *st, hfx_sampler_desc *d, const hfx_fx_state **dyn, uint32_t *n);
/* A sampler_state block's description and its dynamic states (all but Texture). */
void hfx_sampler_desc_of(const hfx_fx_effect *fx, uint32_t sampler, hfx_sampler_desc *d, const hfx_fx_state **dyn,
                         uint32_t *n);
int hfx_rt_sampler_create(hfx_shared *sh, hfx_rt_sampler *s, const hfx_sampler_desc *base,
                          const hfx_fx_state *const *dyn, uint32_t dyn_count);
void hfx_rt_sampler_update(hfx_effect *fx, hfx_rt_sampler *s);
void hfx_rt_sampler_free(hfx_device *dev, hfx_rt_sampler *s);
int hfx_rt_samplers_make(hfx_shared *sh, uint32_t *cap);          /* the effect's samplers, in order */
void hfx_rt_sampler_check_state(hfx_shared *sh, const hfx_fx_state *st); /* notes what GL honours in part */
/* Pass-level MinFilter[n] = ... for binding b's unit: a sampler object of its own. */
int hfx_rt_sampler_override(hfx_shared *sh, uint32_t *cap, const hfx_fx_pass *fp, struct hfx_rt_binding *b);

/* passes.c: pass `index` of the effect, ready for Apply. */
int hfx_rt_pass_build(hfx_shared *sh, uint32_t *cap, uint32_t index);

/* render_states.c */
enum { /* GL state groups */
    G_CULL = 1u << 0, G_FILL = 1u << 1, G_DEPTH = 1u << 2, G_BLEND = 1u << 3, G_COLORMASK = 1u << 4,
    G_STENCIL = 1u << 5, G_SCISSOR = 1u << 6, G_DEPTHBIAS = 1u << 7, G_MSAA = 1u << 8, G_SRGB = 1u << 9,
    G_DITHER = 1u << 10, G_LINESMOOTH = 1u << 11, G_SAMPLEMASK = 1u << 12, G_CLIP = 1u << 13,
    G_ALPHATEST = 1u << 14
};
uint32_t hfx_rs_group(uint32_t id);
void hfx_rs_check(hfx_shared *sh, const hfx_fx_state *st, uint32_t program);
void hfx_rs_apply(hfx_effect *fx, const hfx_rt_pass *pass);
void hfx_rs_alpha_test(hfx_device *dev, hfx_rt_program *p);
void hfx_rs_front_face(hfx_device *dev);

/* params.c */
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

/* load.c */
/* Loads a compiled effect built by hand (tests, tools); takes fx, even on failure. */
hfx_effect *hfx_rt_effect_from_fx(hfx_device *dev, hfx_fx_effect *fx, const hfx_load_options *opt, char **errors);
char *hfx_rt_strdup(const char *s); /* malloc'ed copy, NULL when out of memory */

#endif
