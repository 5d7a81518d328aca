/* gl_int.h: the OpenGL back end's objects. The device's GL part (hfx_device.gl) holds the
 * context's entry points and shadows every GL state it sets, so that an Apply with nothing
 * changed issues no GL call; an effect's shared part (hfx_shared.gl) holds its GL programs,
 * sampler objects and passes ready for Apply; an instance's (hfx_effect.gl) what begin saved.
 * The core (internal.h) reaches all this only through hfx_gl_backend. One section per .c file
 * of runtime/gl/ (tests/runtime/header_sections.cmake checks them). */
#ifndef HFX_RUNTIME_GL_INT_H
#define HFX_RUNTIME_GL_INT_H

#include "gl/gl.h"
#include "internal.h"

#define HFX_MAX_UNITS 32

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

/* The entry points loading SPIR-V needs beyond GL 3.3 (ARB_gl_spirv, GL 4.1's glShaderBinary,
 * GL 4.3's program interface queries), loaded only when the context has them: ok = all there. */
typedef struct hfx_gl_spirv {
    int ok;
    PFNGLSHADERBINARYPROC ShaderBinary;
    PFNGLSPECIALIZESHADERPROC SpecializeShader; /* glSpecializeShader or glSpecializeShaderARB */
    PFNGLGETPROGRAMINTERFACEIVPROC GetProgramInterfaceiv;
    PFNGLGETPROGRAMRESOURCEIVPROC GetProgramResourceiv;
} hfx_gl_spirv;

/* The device's GL part. */
struct hfx_gl_device {
    hfx_gl fn;                     /* the context's entry points (gl.h) */
    hfx_gl_spirv spirv;            /* spirv_load.c */
    GLuint program;                /* bound program */
    GLenum active_unit;            /* glActiveTexture's unit */
    hfx_unit_state units[HFX_MAX_UNITS];
    hfx_glstate state;             /* shadow of GL */
    float pos_fixup[4];            /* hfx_pos_fixup for the current viewport and target */
    uint64_t pos_fixup_serial;     /* bumped when pos_fixup changes; programs compare it first */
    int flip;                      /* drawing into a framebuffer object: D3D9's row order */
    float depth_bias_scale;        /* DepthBias (0..1 depth units) to glPolygonOffset units */
    int srgb_decode;               /* EXT_texture_sRGB_decode */
    float *scratch;                /* for uploads that convert int <-> float */
    size_t scratch_size;
    hfx_texture_set checked;       /* textures whose mip levels texture.c has made complete */
    char *program_cache;           /* hfx_device_set_program_cache's folder, or NULL */
};

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

/* An effect's shared part on GL (hfx_shared.gl). */
typedef struct hfx_gl_shared {
    hfx_rt_program *programs;
    hfx_rt_sampler *samplers; uint32_t sampler_count; /* fx samplers first, then pass overrides */
    hfx_rt_pass *passes;
    uint32_t groups;        /* union of the passes' groups */
    uint32_t unit_mask;     /* units any pass binds */
} hfx_gl_shared;

/* What hfx_effect_begin saved: the GL state the effect's passes touch (gl/apply.c). */
typedef struct hfx_saved {
    hfx_glstate state;
    GLint program, active_unit;
    struct { GLint tex[4], sampler; } units[HFX_MAX_UNITS]; /* 1D, 2D, 3D, cube */
    hfx_rs_value alpha_test[3]; /* AlphaTestEnable, AlphaFunc, AlphaRef: D3D states GL does not hold */
} hfx_saved;

/* An effect instance's GL part (hfx_effect.gl). */
struct hfx_gl_instance {
    hfx_saved saved;
};

static inline void hfx_rt_use_program(hfx_device *dev, GLuint program) {
    if (dev->gl->program == program) return;
    dev->gl->fn.UseProgram(program);
    dev->gl->program = program;
}

/* backend.c: the OpenGL back end's table. */
extern const hfx_backend hfx_gl_backend;

/* device.c: the device's creation and destruction, and the shadow written through functions
 * that skip calls GL would not notice. */
void hfx_gl_device_destroy(hfx_device *dev);
void hfx_rt_read_state(hfx_device *dev, hfx_glstate *s);
void hfx_rt_write_state(hfx_device *dev, const hfx_glstate *want);
void hfx_rt_bind_unit(hfx_device *dev, int unit, GLenum target, GLuint texture, GLuint sampler);
void hfx_rt_read_target(hfx_device *dev); /* the viewport and framebuffer the position fixup follows */

/* texture.c: the texture bound on target of the active unit, made complete with the mip
 * levels it has, the first time hfx binds it; and the set of those checked freed. */
void hfx_rt_texture_check(hfx_device *dev, GLenum target, GLuint texture);
void hfx_rt_textures_free(hfx_device *dev);

/* apply.c: Apply, Begin and End on GL (the table's pass_apply, effect_begin, effect_end,
 * begun_carry). */
int hfx_gl_pass_apply(hfx_pass *p);
int hfx_gl_effect_begin(hfx_effect *fx);
int hfx_gl_effect_end(hfx_effect *fx);
void hfx_gl_begun_carry(hfx_effect *to, const hfx_effect *from);

/* program.c */
int hfx_rt_program_build(hfx_shared *sh, uint32_t index, hfx_target target);
/* Links vs + fs into p->object (fp's attribute locations bound first; NULL for SPIR-V). */
int hfx_rt_program_link(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp, GLuint vs, GLuint fs);
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

/* A GL program's preshaders (after its registers are set up); what they read joins its reads. */
int hfx_rt_preshaders_setup(hfx_rt_program *p, const hfx_fx_effect *fx, const hfx_fx_program *fp);

/* Uploads the parameters whose version differs from the one this program holds, visiting only
 * the log entries written since the program last looked when it follows this instance; returns
 * HFX_OK (so Apply can end in it). */
int hfx_rt_upload_changed(hfx_effect *fx, hfx_rt_program *p);
/* The same for a program known to follow fx's log (the pass was the last one applied). */
int hfx_rt_upload_log(hfx_effect *fx, hfx_rt_program *p);

/* program_cache.c: link through the device's program cache when it has one (a hit loads the
 * driver's binary; a miss calls link and stores the result); hint before glLinkProgram. */
int hfx_rt_program_cached_link(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp, const char *vs_src,
                               const char *fs_src, int (*link)(hfx_shared *, hfx_rt_program *, const hfx_fx_program *,
                                                               const char *, const char *));
void hfx_rt_program_binary_hint(hfx_device *dev, GLuint program);
int hfx_rt_program_cache_usable(const hfx_device *dev); /* a folder, and a driver that hands out binaries */

/* spirv_load.c: programs from SPIR-V (HFX_TARGET_SPIRV), uniforms by the compiler's locations. */
void hfx_rt_spirv_init(hfx_device *dev, hfx_gl_loader load); /* at device creation */
int hfx_rt_spirv_check(hfx_device *dev, const hfx_fx_effect *fx); /* HFX_ERR_GL when GL cannot load SPIR-V */
int hfx_rt_spirv_program_build(hfx_shared *sh, uint32_t index);

/* sampler.c */
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
unsigned int hfx_gl_texture_target(const hfx_param *p); /* the table's texture_target */

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


#endif
