/* bytecode.h: the D3D9 shader bytecode back end. A lowered stage (hfx_ir_lower) becomes the token
 * stream fxc writes for a shader model: registers allocated (r, c / i / b after the effect's
 * parameters and register(cN) reservations, v / t / o / oPos / oD / oT / oC / oDepth, s), a CTAB
 * comment naming the parameters, `def` constants, instructions selected as fxc does (mad, dp3 /
 * dp4, nrm, lrp, pow, rcp / rsq, sincos, cmp / slt / sge selects, texkill, texld...), flow flattened
 * and loops unrolled. Every shader written is decoded and validated by compiler/d3d9's reader and
 * checked against the model's limits before it is returned. */
#ifndef HFX_BYTECODE_H
#define HFX_BYTECODE_H

#include <stdint.h>

#include "ir/ir.h"

/* The bytecode of sh for `profile` ("vs_3_0", "ps_2_0"...): *count words in the arena, or NULL
 * with located errors (fxc's X3xxx / X5xxx codes at the HLSL position; X5006 for what the writer
 * does not handle yet). vs_1_1 and ps_1_x are written as 2_0 with a warning. */
const uint32_t *hfx_bc_write(ir_ctx *c, const ir_shader *sh, const char *profile, uint32_t *count);

#endif
