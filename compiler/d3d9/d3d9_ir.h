/* d3d9_ir.h: the translator's shared state (d3d9_ir.c: registers and the interface;
 * d3d9_ir_ops.c: instructions; d3d9_ir_runs.c: scalar runs). */
#ifndef HFX_D3D9_IR_H
#define HFX_D3D9_IR_H

#include "d3d9/d3d9_int.h"
#include "ir/ir.h"

typedef struct d3d9_tx {
    ir_ctx *c;
    const d3d9_shader *s;
    ir_shader *sh;
    ir_func *fn;
    hfx_func *src;
    const hfx_type *f1, *f2, *f3, *f4, *i1, *i4, *b4;
    ir_var *temps[32], *a0, *regfile, *p0, *aL;
    ir_stmt *open[D3D9_MAX_DEPTH + 2]; /* the if or for statement of each open block */
    uint32_t loop_count;      /* counters made so far (for their names) */
    ir_var *inputs[3][16];    /* by register type: [0] v, [1] t, [2] vPos / vFace */
    ir_var *outputs[5][12];   /* [0] oPos/oFog/oPts, [1] oD, [2] oT / o, [3] oC, [4] oDepth */
    ir_var **consts;          /* per CTAB constant: its parameter's uniform (lazy) */
    ir_var *samplers[16];
    ir_var *texregs[8];       /* ps_1_1..1_3: t registers, written by tex / texcoord (locals) */
    ir_var **pres;            /* per d3d9_shader.pres entry: its private register variable (lazy) */
    ir_stmt *prologue;        /* declarations and setup, before the instructions */
    struct { ir_stmt *s; uint32_t cap; } blocks[D3D9_MAX_DEPTH + 2]; /* [0] the prologue, [1] the body, then open ifs / loops */
    uint32_t depth;           /* blocks[depth] receives the next statement */
    ir_var **params; uint32_t param_count, param_cap;
    hfx_loc loc;              /* the instruction being translated */
    uint32_t regfile_size;
    unsigned held_count;      /* locals made by held(), for unique names */
    bool failed, pack;
} d3d9_tx;

/* --- d3d9_ir.c --- */
void hfx_d3d9_tx_fail(d3d9_tx *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
ir_expr *hfx_d3d9_tx_var(d3d9_tx *t, ir_var *v);                      /* a read (or l-value) of v */
ir_expr *hfx_d3d9_tx_swizzle(d3d9_tx *t, ir_expr *x, const uint8_t *comps, unsigned n);
ir_expr *hfx_d3d9_tx_float4(d3d9_tx *t, ir_expr *x);                  /* x padded (or splat, for a scalar) to float4 */
ir_expr *hfx_d3d9_tx_const4(d3d9_tx *t, const float v[4]);
ir_expr *hfx_d3d9_tx_read(d3d9_tx *t, const d3d9_src *x);            /* a source register, swizzled and modified */
ir_expr *hfx_d3d9_tx_reg(d3d9_tx *t, unsigned type, unsigned num);   /* a register as float4, no swizzle */
ir_var *hfx_d3d9_tx_sampler(d3d9_tx *t, unsigned num);
ir_expr *hfx_d3d9_tx_bool(d3d9_tx *t, unsigned num);                 /* b register: defb or its parameter */
ir_expr *hfx_d3d9_tx_int4(d3d9_tx *t, unsigned num);                 /* i register: defi or its parameter */
ir_var *hfx_d3d9_tx_local(d3d9_tx *t, const char *name, const hfx_type *ty); /* a zeroed local of the entry */
ir_var *hfx_d3d9_tx_texcoord(d3d9_tx *t, unsigned n);                /* the TEXCOORDn input parameter */
bool hfx_d3d9_tx_ps1(const d3d9_tx *t);                              /* ps_1_1 .. ps_1_4 */
void hfx_d3d9_tx_write(d3d9_tx *t, const d3d9_dst *d, ir_expr *value); /* dst.mask = value.mask, with _sat */
/* mul of source v (width components) by the matrix parameter whose registers m .. m + count - 1
 * are, from its first (m4x4 family), as float4; NULL (no error) when they are not such a whole
 * parameter: the caller then reads register by register. */
ir_expr *hfx_d3d9_tx_matrix_mul(d3d9_tx *t, const d3d9_src *v, const d3d9_src *m, unsigned width, unsigned count);
void hfx_d3d9_tx_add(d3d9_tx *t, uint32_t block, ir_stmt *s);        /* appends s to blocks[block] */
void hfx_d3d9_tx_emit(d3d9_tx *t, ir_expr *e);                        /* e as a statement of the current block */

/* --- d3d9_ir_ops.c --- */
void hfx_d3d9_tx_inst(d3d9_tx *t, const d3d9_inst *in);

/* --- d3d9_ir_runs.c --- */
/* A run of one scalar operation (exp, log, rcp, rsq) over components of one register from
 * instruction i, translated as one vector operation: the instructions it took, 0 for none. */
unsigned hfx_d3d9_tx_scalar_run(d3d9_tx *t, uint32_t i);

/* --- d3d9_ir_flow.c --- */
bool hfx_d3d9_tx_flow(d3d9_tx *t, const d3d9_inst *in);             /* if / else / loops / break: translated, true */
ir_expr *hfx_d3d9_tx_predicate(d3d9_tx *t, const d3d9_inst *in, ir_expr *value); /* (p0) value: select with the old dst */

#endif
