/* conv.h: HLSL's conversion rules between types (conv.c), shared by the checker and the
 * intrinsic table: which implicit and explicit conversions exist, what each costs in overload
 * ranking, which truncate (fxc's X3206), and the common type of a componentwise operation. */
#ifndef HFX_CONV_H
#define HFX_CONV_H

#include <stdbool.h>

#include "base/types.h"

/* Ranks of a conversion, compared field by field: the shape change first, then the base. */
typedef enum {
    CONV_SHAPE_EXACT,   /* same shape */
    CONV_SHAPE_RESHAPE, /* float4 <-> float1x4 / float4x1 / float2x2: same component count */
    CONV_SHAPE_SPLAT,   /* a scalar (or a 1-component vector/matrix) to a larger shape */
    CONV_SHAPE_TRUNC    /* float4 -> float3, float4x4 -> float3x3, float2 -> float (X3206) */
} hfx_conv_shape;

typedef enum {
    CONV_BASE_EXACT,    /* same element type */
    CONV_BASE_PROMOTE,  /* among half/float/double/min16float, or between int and uint */
    CONV_BASE_CONVERT,  /* int <-> float */
    CONV_BASE_BOOL      /* to or from bool */
} hfx_conv_base;

typedef struct hfx_conv {
    bool ok;
    bool truncates;     /* implicit ones warn X3206 */
    hfx_conv_shape shape;
    hfx_conv_base base;
} hfx_conv;

/* How `from` converts to `to`; explicit casts (`(float3)v`) allow more (any same-count reshape,
 * matrix to vector truncation, struct/array flattening is not supported). */
hfx_conv hfx_conv_classify(const hfx_type *from, const hfx_type *to, bool explicit_cast);

/* A total order on conversion quality for overload ranking: 0 is an exact match. */
unsigned hfx_conv_cost(hfx_conv c);

/* The element type of `a op b`: bool < int < uint < half < float < double. */
hfx_base hfx_base_common(hfx_base a, hfx_base b);

/* Whether a base is a floating type (half, float, double, min16float). */
bool hfx_base_is_float(hfx_base b);

/* The shape both operands of a componentwise operation convert to (scalars splat, vectors and
 * matrices truncate to the smaller), with element type `base`. NULL when the shapes do not
 * combine (float3 with float4x4). *truncates is set when an operand loses components. */
const hfx_type *hfx_common_shape(hfx_types *t, const hfx_type *a, const hfx_type *b, hfx_base base,
                                 bool *truncates);

/* The same shape as `ty` with element type `base`. */
const hfx_type *hfx_type_with_base(hfx_types *t, const hfx_type *ty, hfx_base base);

/* Scalars, 1-component vectors and 1x1 matrices: they splat like scalars. */
bool hfx_type_is_scalarlike(const hfx_type *ty);

#endif
