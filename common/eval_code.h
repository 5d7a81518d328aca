/* eval_code.h: expressions of parameters compiled for the runtime (state values such as
 * `AlphaRef = (Ref * 255);`): a small stack program of 32-bit words that common/eval runs, so
 * the runtime computes them without the compiler and with the compiler's arithmetic.
 *
 * An instruction is one word, op | a << 8 | b << 16, then its operand words:
 *   CONST   a = base, b = n     n words: the components (float bits, or int / uint bits)
 *   PARAM   a = base, b = n     1 word: offset of the parameter's first value word
 *   SWIZZLE a = n (1..4)        1 word: component i of the result is nibble i
 *   CONVERT a = base, b = n     to base, splatting a scalar or keeping the first n
 *   UNARY   a = hfx_ev_op       NEG, POS, NOT, BITNOT
 *   BINARY  a = hfx_ev_op       both operands first go to the larger base (bool < int < uint < float)
 *   CALL    a = hfx_ev_fn       its arguments go to one base as for BINARY (float when it needs it)
 *   TABLE   a = base, b = n     1 word count, then count * n words: pops an index, pushes element
 *                               index (truncated, clamped to [0, count - 1] as D3D9 does)
 *   SELECT                      pops c, y, x: x where c is true, else y (per component)
 *   ELEMENT a = base, b = n     3 words: offset, count, stride: pops an index, pushes the n words at
 *                               offset + index * stride of a parameter array (index clamped as TABLE)
 *   SHUFFLE a = n (1..16)       2 words: component i of the result is nibble i (word i / 8): a
 *                               matrix row, a truncated matrix, any pick of up to 16 components
 *   CONCAT  b = n               pops y, x: x's components then y's (to the larger base), n in all
 *   MATMUL  a = r | k << 4, b = c  pops y, x: mul(x, y) of an r x k and a k x c matrix (row-major;
 *                               a vector is 1 x k on the left, k x 1 on the right), r * c components
 * A program leaves one value. hfx_evc_validate checks everything a run relies on (opcodes,
 * operand words present, bases, counts, stack depth, parameter words in range), so a program
 * read from a hostile file can be run safely once it passes. */
#ifndef HFX_COMMON_EVAL_CODE_H
#define HFX_COMMON_EVAL_CODE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "eval.h"

typedef enum {
    HFX_EVC_CONST, HFX_EVC_PARAM, HFX_EVC_SWIZZLE, HFX_EVC_CONVERT, HFX_EVC_UNARY, HFX_EVC_BINARY,
    HFX_EVC_CALL, HFX_EVC_TABLE, HFX_EVC_SELECT, HFX_EVC_ELEMENT, HFX_EVC_SHUFFLE, HFX_EVC_CONCAT,
    HFX_EVC_MATMUL, HFX_EVC_OP_COUNT
} hfx_evc_op;

enum { HFX_EVC_MAX_DEPTH = 16, HFX_EVC_MAX_WORDS = 1u << 20 }; /* 16: fxc's preshaders (FXLVM trees) need more than 8 */

/* The instruction word. */
static inline uint32_t hfx_evc_word(hfx_evc_op op, uint32_t a, uint32_t b) {
    return (uint32_t)op | (a & 0xffu) << 8 | (b & 0xffu) << 16;
}

/* 0 when code[0 .. words) is a program that runs safely over value_words parameter words;
 * otherwise -1 and why in err (may be NULL). */
int hfx_evc_validate(const uint32_t *code, uint32_t words, uint32_t value_words, char *err, size_t err_size);
/* Where the instruction after the one at `at` starts (for walking a validated program). */
uint32_t hfx_evc_next(const uint32_t *code, uint32_t at, uint32_t words);
/* Component v of base b as a program or a parameter holds it: float bits, or int / uint bits. */
uint32_t hfx_evc_bits(hfx_ev_base b, double v);
/* The array entry a selector value (`PixelShader = (PSArray[i]);`) names, as D3D9 indexes: its
 * first component truncated by the rule of eval.h (NaN 0), clamped to [0, last]. */
uint32_t hfx_evc_index(const hfx_ev_value *v, uint32_t last);
/* Runs a validated program over the parameter words; false when the arithmetic does not fold
 * (an integer division by zero, shapes that do not combine): the caller keeps its last value. */
bool hfx_evc_run(const uint32_t *code, uint32_t words, const uint32_t *values, hfx_ev_value *out);

#endif
