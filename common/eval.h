/* eval.h: the one expression evaluator. Constant folding in the compiler (parser, checker,
 * effect builder, IR lowering) and the runtime's state expressions compute with these
 * functions, so a value is the same wherever hfx computes it, and it is Direct3D's:
 * - int and uint are 32 bits and wrap; shifts use the low 5 bits of the count; >> is
 *   arithmetic on int, logical on uint; integer division truncates toward zero, and a division
 *   or remainder by zero (or INT_MIN / -1) is not folded (the GPU decides).
 * - float is single precision: every float result is rounded to float; x / 0.0 is IEEE's.
 * - float to int / uint truncates toward zero, NaN gives 0, out-of-range values clamp (uint:
 *   negatives give 0); int <-> uint keep the bits; to bool is != 0; bool is 0 or 1.
 * - pow(x, y) is |x|^y, as D3D9's pow instruction computes it (the absolute value of x).
 * - round(x) is floor(x + 0.5) as the SM2/SM3 code fxc emits computes it; % on floats is
 *   fmod (truncating); step(a, x) is x >= a.
 * Values are up to 16 components held as doubles already in their base's range (an int is an
 * integral double in int32 range), so any base converts exactly. GL-free, no state. */
#ifndef HFX_COMMON_EVAL_H
#define HFX_COMMON_EVAL_H

#include <stdbool.h>
#include <stdint.h>

typedef enum { HFX_EV_BOOL, HFX_EV_INT, HFX_EV_UINT, HFX_EV_FLOAT, HFX_EV_BASE_COUNT } hfx_ev_base;

/* Operators. Unary: NEG, POS, NOT, BITNOT; the rest are binary. */
#define HFX_EV_OPS(X) \
    X(NEG) X(POS) X(NOT) X(BITNOT) X(ADD) X(SUB) X(MUL) X(DIV) X(MOD) X(SHL) X(SHR) X(BITAND) X(BITOR) \
    X(BITXOR) X(LT) X(GT) X(LE) X(GE) X(EQ) X(NE) X(AND) X(OR)

typedef enum {
#define HFX_EV_OP_ENUM_(name) HFX_EV_##name,
    HFX_EV_OPS(HFX_EV_OP_ENUM_)
#undef HFX_EV_OP_ENUM_
    HFX_EV_OP_COUNT
} hfx_ev_op;

/* The intrinsics the evaluator computes: common/eval_funcs.def, in the order of the numbers
 * stored in files (eval.c asserts each row's number is its place). */
typedef enum {
#define HFX_EV_FUNC(name, number, args) HFX_EV_FN_##name,
#include "eval_funcs.def"
#undef HFX_EV_FUNC
    HFX_EV_FN_COUNT,
    HFX_EV_FN_NONE = -1 /* an intrinsic the evaluator leaves to the GPU */
} hfx_ev_fn;

enum { HFX_EV_MAX_COMPONENTS = 16 };

typedef struct hfx_ev_value {
    hfx_ev_base base;
    uint8_t n; /* components, 1..16 */
    double c[HFX_EV_MAX_COMPONENTS];
} hfx_ev_value;

/* THE float -> integer conversion: every one in hfx's libraries goes through these (C11 6.3.1.4
 * leaves a cast of an out-of-range value undefined; docs/conventions.md, "Float to integer";
 * tests/common/float_casts.cmake finds a raw one). Truncates toward zero, NaN gives 0, out of range clamps
 * (uint: negatives give 0): Direct3D's rule above. */
int32_t hfx_ev_int(double v);
uint32_t hfx_ev_uint(double v);
/* v of base `from` as base `to`, by the conversion rules above. */
double hfx_ev_convert(hfx_ev_base from, hfx_ev_base to, double v);
/* A value of base b from any double (a literal): converted as from float, or kept when integral in range. */
double hfx_ev_normalise(hfx_ev_base b, double v);
/* The base of `op`'s result on operands of base b (comparisons and && || give bool). */
hfx_ev_base hfx_ev_result_base(hfx_ev_op op, hfx_ev_base b);
/* One component of a unary or binary operator on operands of base b; false when it is not
 * folded (not defined on b, or an integer division by zero). */
bool hfx_ev_unary(hfx_ev_op op, hfx_ev_base b, double x, double *out);
bool hfx_ev_binary(hfx_ev_op op, hfx_ev_base b, double x, double y, double *out);
/* The whole operation on values of one base, a scalar operand splatting over the other's
 * components; false when some component is not folded or the counts differ. */
bool hfx_ev_apply(hfx_ev_op op, const hfx_ev_value *x, const hfx_ev_value *y, hfx_ev_value *out);
/* An intrinsic on n arguments already of one base (the checker's choice); false when not folded. */
bool hfx_ev_call(hfx_ev_fn fn, const hfx_ev_value *args, unsigned n, hfx_ev_value *out);
int hfx_ev_fn_args(hfx_ev_fn fn);            /* its argument count, 0 when out of range */
const char *hfx_ev_fn_name(hfx_ev_fn fn);    /* "NORMALIZE"; NULL when out of range */
/* x converted to base b and n components: a scalar splats, a longer value keeps its first n. */
bool hfx_ev_fit(const hfx_ev_value *x, hfx_ev_base b, unsigned n, hfx_ev_value *out);

#endif
