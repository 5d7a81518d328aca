/* glsl.h: the GLSL printer's interface: one stage of a program, for one target. */
#ifndef HFX_GLSL_H
#define HFX_GLSL_H

#include "ir/ir.h"

/* A stage's top-level uniforms and struct types as its GLSL 330 printed them, in order: what the
 * SPIR-V targets of the program need from both stages (glsl_spirv.c). Arena memory. */
typedef struct glsl_record {
    struct glsl_rec_uniform { const char *name, *decl; bool sampler; } *uniforms; /* decl: "vec4 a[3]" */
    uint32_t uniform_count, uniform_cap;
    struct glsl_rec_struct { const char *name, *text; } *structs;
    uint32_t struct_count, struct_cap;
} glsl_record;

/* What the two stages of a program share. */
typedef struct glsl_iface {
    const char **varyings; uint32_t varying_count; /* canonical semantics, sorted */
    const char **vs_writes; uint32_t vs_write_count; /* varyings the vertex shader writes */
    const hfx_fx_attribute *attrs; uint32_t attr_count;
    const char **flat; uint32_t flat_count; /* varyings without interpolation (nointerpolation) */
    /* Derived varyings (ir/lower/varyings.c): outputs the pixel entry computes itself; the
     * vertex stage does not write them, the pixel stage does not read them, neither declares them. */
    const char **derived; uint32_t derived_count;
    const ir_shader *stages[2]; /* the program's vertex and pixel shaders (either NULL) */
    bool clamp_vs_colors;    /* vs_1_1 / vs_2_x COLOR outputs saturate as D3D9's oD0/oD1 */
    bool clamp_ps1_texcoords; /* ps_1_1..ps_1_3: TEXCOORD inputs read as values saturate (texcoord tN) */
    const hfx_fx_uniform_use *uniforms; uint32_t uniform_count; /* the program's, with their registers */
    uint32_t reg_count;      /* HFXC_PACK_UNIFORMS: size of hfx_c in both stages (0: nothing packed) */
    bool alpha_test;         /* some pass of the effect enables D3D9's alpha test: COLOR0 carries it */
    const ir_var **pre_vars; const uint32_t *pre_regs; uint32_t pre_count; /* preshaders' registers */
    /* The SPIR-V targets (HFX_TARGET_SPIRV, HFX_TARGET_SPIRV_VK): the program (its uniforms' and
     * samplers' locations, common/spirv_loc.c) and both stages' records; `record` is filled by a
     * GLSL 330 print when set. */
    const hfx_fx_effect *fx; const hfx_fx_program *prog;
    const glsl_record *records[2];
    glsl_record *record;
} glsl_iface;

/* ps_1_1, ps_1_2 or ps_1_3, whose texcoord instruction clamps (glsl_ps1.c). */
bool hfx_glsl_ps1_clamps(const char *profile);

/* sem is one of io's derived varyings. */
bool hfx_glsl_iface_derived(const glsl_iface *io, const char *sem);

/* Prints one stage for one target (sh NULL: the fixed-function stand-in); malloc'ed text,
 * NULL with errors in diags. glsl.c */
char *hfx_glsl_print(ir_ctx *c, const ir_shader *sh, ir_stage stage, const glsl_iface *io, hfx_target target);
/* A GLSL 330 text as ES 300, or the reverse (only the header differs); malloc'ed, NULL when the
 * text does not start with from's header or memory runs out. */
char *hfx_glsl_retarget(const char *text, hfx_target from, hfx_target to);

#endif
