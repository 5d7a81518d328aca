/* check.h: type checking (check.c, check_expr.c, check_call.c, check_stmt.c, with conv.c and
 * intrinsics.c): resolves names, overloads and intrinsics, inserts implicit conversions,
 * reports fxc's errors and warnings.
 *
 * Beyond the invariants at the top of ast.h, a successful check also guarantees:
 * - EX_CALL of an intrinsic: `intrinsic` is an id of intrinsics.h (name: hfx_intrinsic_name),
 *   every argument has the exact parameter type the rule picked (mul's inner dimension is
 *   already clamped: mul(float3, float4x4) has the matrix cast to float3x4, no warning), and
 *   out arguments (sincos, modf, frexp) are l-values of exactly that type;
 * - sampler and texture arguments are never cast: a generic `sampler` reaches tex2D or a
 *   sampler2D parameter as it is;
 * - EX_CALL of a user function: `fn` may be a prototype; fn->definition is the body (every
 *   definition points to itself); EX_COMPILE has `fn` set too (the definition), and its args
 *   are converted to the entry's uniform parameters, in order;
 * - EX_CONSTRUCT arguments keep their shape but take the constructed element type;
 * - EX_CAST (explicit) from a scalar to a struct or array: `(VS_OUT)0` fills every component;
 *   numeric casts (explicit or implicit) keep the leading components in row-major order
 *   (float4x4 -> float3x3 keeps the top-left block; (float3)m keeps m._11_12_13) and reshape
 *   equal counts row-major (float4 <-> float2x2); a scalar source splats;
 * - EX_INIT_LIST args are the scalar leaves in memory order (row-major), each converted to its
 *   leaf's scalar type; a vector/matrix/struct item is split into EX_SWIZZLE/EX_FIELD/EX_INDEX
 *   nodes sharing the item (so it is evaluated once per component: items are pure values);
 *   unsized arrays (`float a[] = {...}`) get their length;
 * - array types sized by constant expressions (`float a[N]`) are folded: array_len is set;
 * - EX_INDEX indexes are int (uint stays uint); swizzles never repeat a component in an
 *   l-value; EX_UNARY OP_NOT has a bool operand, OP_NEG/OP_BITNOT an int one for bools;
 * - binary operands are converted to the operation type (comparisons give bool of it;
 *   && and || work on bool of the common shape);
 * - ternary: the condition is a bool scalar, or a bool vector of the result's shape;
 * - a for-init variable stays visible after its loop (fxc's scoping, codegen hoists it);
 * - globals: is_global set, index = declaration order (build.c renumbers), `assigned` set on
 *   any global a function writes (directly, through a swizzle/field/element, or as an out
 *   argument);
 * - state values (passes, sampler_state): names that are no variable are EX_IDENT with sym NULL
 *   and void type (CLAMP, None...), operators over them are void too; names that are variables
 *   resolve (Texture = (tex)); EX_STATE_REF always resolves;
 * - technique10 passes: `CompileShader(vs_4_0, VS(args))` is rewritten to an EX_COMPILE (loc at
 *   the entry's name); other unknown calls in state values (SetVertexShader(...),
 *   SetBlendState(...)) keep their state-checked arguments and take the first one's type;
 * - no recursion (X3500), no call of a function without a body (X3501).
 * Diagnostics point at the start of the offending expression (a binary operator's left
 * operand, an assignment's right-hand side); a truncated argument warns at the call, naming
 * the function ("'dot': implicit truncation of vector type"), as fxc does. */
#ifndef HFX_CHECK_H
#define HFX_CHECK_H

#include <stdbool.h>

#include "parse/ast.h"

/* Decorates the tree in place (see the invariants in ast.h). Returns true when no error. */
bool hfx_check(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast);

#endif
