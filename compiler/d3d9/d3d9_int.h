/* d3d9_int.h: what the files of compiler/d3d9/ share. d3d9.c: the table, the decoder loop;
 * d3d9_operands.c: operand tokens and register checks; d3d9_ctab.c: the constant table;
 * d3d9_dis.c: fxc's listing; d3d9_ir.c: the translator to the IR. */
#ifndef HFX_D3D9_INT_H
#define HFX_D3D9_INT_H

#include <stdarg.h>
#include <string.h>

#include "d3d9/d3d9.h"

#define D3D9_FOURCC_CTAB 0x42415443u /* "CTAB" */
#define D3D9_MAX_DEPTH 64

typedef struct d3d9_reader {
    hfx_arena *arena;
    hfx_diags *diags;
    const d3d9_input *in;
    const unsigned char *bytes;
    uint32_t words;
    d3d9_shader *sh;
    uint32_t inst_cap, comment_cap;
    uint16_t stack[D3D9_MAX_DEPTH]; /* open flow-control blocks: D3D9_IF, _LOOP, _REP */
    uint32_t depth, loops;
} d3d9_reader;

/* --- d3d9.c --- */
uint32_t hfx_d3d9_word(const d3d9_reader *r, uint32_t i);             /* little-endian word i of the blob */
void hfx_d3d9_fail(d3d9_reader *r, uint32_t word, unsigned code, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));                      /* a located error at word `word` */
void hfx_d3d9_operand_counts(const d3d9_op_info *op, uint8_t model, unsigned *dst, unsigned *src);

/* --- d3d9_operands.c --- */
/* Reads the operands of the instruction at word i (len words follow it) into in, checking counts
 * and register types for the model. */
void hfx_d3d9_read_operands(d3d9_reader *r, d3d9_inst *in, const d3d9_op_info *op, uint32_t i, uint32_t len);
/* The model's read ports (hfx_d3d9_port_excess): an error at word `at` naming the registers. */
void hfx_d3d9_check_ports(d3d9_reader *r, const d3d9_inst *in, const d3d9_op_info *op, uint32_t at);
void hfx_d3d9_check_scalar_sources(d3d9_reader *r, const d3d9_inst *in, const d3d9_op_info *op, uint32_t at);

/* --- d3d9_ctab.c --- */
void hfx_d3d9_read_ctab(d3d9_reader *r, const d3d9_comment *c, uint32_t at);

#endif
