/* glsl_int.h: what glsl.c (declarations, statements, main) and hfx_glsl_expr.c (expressions,
 * intrinsics, helper functions) share. */
#ifndef HFX_GLSL_INT_H
#define HFX_GLSL_INT_H

#include "base/sbuf.h"
#include "glsl/glsl.h"
#include "ir/ir.h"


typedef struct gp {
    ir_ctx *c;
    const ir_shader *sh;
    ir_stage stage;
    const glsl_iface *io;
    hfx_target target;
    bool legacy;              /* GLSL 110. Nothing is decided on ES 300 against GLSL 330 but the
                                 header: codegen makes one text from the other (hfx_glsl_retarget) */
    sbuf *out;
    int indent;
    unsigned loop_counters;     /* hfx_iterK variables of [unroll(n)] loops so far */
    sbuf helpers;             /* helper functions, in first-use order */
    const char **helper_keys; uint32_t helper_count, helper_cap;
    const hfx_type **structs; uint32_t struct_count, struct_cap; /* in dependency order */
    sbuf structs_text;
    bool failed;
    bool lvalue;              /* printing the target of a write: no guarded reads */
    ir_leaf *in, *outv;       /* the entry's interface (NULL for a fixed-function stand-in) */
    int in_count, out_count;
    bool uses_fixup;          /* the pixel shader reads hfx_pos_fixup (ddy, VPOS) */
    bool nonsquare;           /* GLSL 110 met a non-square matrix type */
    bool spirv;               /* HFX_TARGET_SPIRV or HFX_TARGET_SPIRV_VK: glslang makes SPIR-V of it */
    bool vulkan;              /* HFX_TARGET_SPIRV_VK */
    const ir_var **bools; uint32_t bool_count, bool_cap; /* SPIR-V (GL): bool uniforms declared as int */
    size_t block_at; bool has_block; /* Vulkan: where the uniform block goes in the declarations */
    const ir_var **padded; uint32_t padded_count, padded_cap; /* hfx_glsl_find_padded */
} gp;

/* Expression precedence, GLSL's: lower binds tighter. */
enum { PREC_PRIMARY = 1, PREC_POSTFIX, PREC_UNARY, PREC_MUL, PREC_ADD, PREC_SHIFT, PREC_REL, PREC_EQ,
       PREC_BITAND, PREC_BITXOR, PREC_BITOR, PREC_AND, PREC_XOR, PREC_OR, PREC_SELECT, PREC_ASSIGN, PREC_COMMA };

const char *hfx_glsl_type(gp *p, const hfx_type *t);        /* "vec4", "mat3x4", "LuzSpot"; arrays: the element */
const char *hfx_glsl_ctor_type(gp *p, const hfx_type *t);   /* arrays as "float[3]" */
void hfx_glsl_decl(gp *p, sbuf *out, const hfx_type *t, const char *name); /* appends "float a[3]" */
bool hfx_glsl_is_matrix(const hfx_type *t);                 /* a matrix GLSL keeps as one (no 1xN / Nx1) */
void hfx_glsl_zero(gp *p, const hfx_type *t);               /* a zero value of t */
void hfx_glsl_expr(gp *p, const ir_expr *e, int max_prec);
void hfx_glsl_lvalue(gp *p, const ir_expr *e, int max_prec); /* an expression that is written */
bool hfx_glsl_helper(gp *p, const char *key);
/* Uniform arrays the stage reads at an index that may leave them (GLSL 330 / ES 300, arrays
 * declared on their own): each is declared one element longer, that element is never uploaded
 * and so stays zero (GL zeroes uniforms at link), and a read is arr[min(uint(i), len)]: D3D9's
 * zero past either end in one instruction, where a compare and a select of every component of
 * the element cost 0.5% of SkinnedEffect's four-bone frame on llvmpipe (issue 37). */
void hfx_glsl_find_padded(gp *p);
bool hfx_glsl_is_padded(const gp *p, const ir_var *v);               /* true when key is new: print its text into p->helpers */
void hfx_glsl_error(gp *p, hfx_loc loc, const char *msg);
/* glsl_ps1.c: ps_1_1..ps_1_3 read a TEXCOORD input used only as a value clamped to [0, 1]. */
bool hfx_glsl_ps1_value_only(ir_ctx *c, const ir_shader *sh, const ir_leaf *l); /* l is such an input */

/* glsl_pack.c: HFXC_PACK_UNIFORMS (packed parameters read from `uniform vec4 hfx_c[K]`). */
uint32_t hfx_glsl_packed_reg(const gp *p, const ir_var *v); /* v's first register, or HFX_NONE */
void hfx_glsl_declare_regs(gp *p);                          /* hfx_c, when the stage reads a packed parameter */
void hfx_glsl_declare_packed(gp *p, const ir_var *v, uint32_t reg); /* its private global */
void hfx_glsl_init_packed(gp *p);                           /* main's first lines: each from its registers */

/* glsl_spirv.c: what the SPIR-V targets print differently. Every top-level uniform declaration
 * goes through hfx_glsl_uniform (v NULL for the code generator's own); reads of a uniform through
 * hfx_glsl_uniform_read; hfx_glsl_spirv_decls appends the declarations with Vulkan's block in place. */
void hfx_glsl_uniform(gp *p, const ir_var *v, const char *name, const char *decl, bool sampler);
void hfx_glsl_uniform_read(gp *p, sbuf *out, const ir_var *v);
void hfx_glsl_record_struct(gp *p, const char *name, size_t text_from);
void hfx_glsl_spirv_decls(gp *p, sbuf *all, const sbuf *decls);

#endif
