/* intrinsics.h: the HLSL intrinsic functions (SM2/SM3 set plus asfloat/asint/asuint), listed
 * once in intrinsics.def: ids (the IR's too), names, argument counts, the rule that matches
 * argument types, the texture read, the back-end-neutral IR rewrite and the evaluator function.
 * The back ends' columns are read by the back ends themselves (glsl/glsl_intrin.c).
 *
 * Matching (intrinsics.c) follows fxc: the arguments of "same type" intrinsics combine like a
 * componentwise binary operator (scalars splat, longer vectors truncate with X3206), integer
 * arguments of float-only intrinsics become float, and the checker converts every argument to
 * the parameter type the rule picks, so codegen sees exact types. */
#ifndef HFX_INTRINSICS_H
#define HFX_INTRINSICS_H

#include <stdbool.h>
#include <stdint.h>

#include "base/types.h"
#include "eval.h"

/* Signature rules. T is the common type of the arguments (componentwise binary rules). */
typedef enum {
    SIG_SAME,        /* T f(T, ...): int or float */
    SIG_SAME_FLOAT,  /* T f(T, ...): T's element type made float when it is int/bool */
    SIG_CLIP,        /* void clip(T) */
    SIG_ALL_ANY,     /* bool f(T) */
    SIG_CLASSIFY,    /* bool-T f(T float): isnan, isinf, isfinite */
    SIG_DOT,         /* scalar dot(vT, vT) */
    SIG_LENGTH,      /* float length(vT) */
    SIG_DISTANCE,    /* float distance(vT, vT) */
    SIG_VEC_SAME,    /* vT f(vT, ...): normalize, reflect, faceforward */
    SIG_REFRACT,     /* vT refract(vT i, vT n, float eta) */
    SIG_CROSS,       /* float3 cross(float3, float3) */
    SIG_DETERMINANT, /* float determinant(floatNxN) */
    SIG_TRANSPOSE,   /* floatCxR transpose(floatRxC) */
    SIG_MUL,         /* the nine shapes of mul */
    SIG_LIT,         /* float4 lit(float, float, float): scalars only, fxc refuses vectors */
    SIG_DST,         /* float4 dst(float4, float4) */
    SIG_SINCOS,      /* void sincos(T, out T, out T) */
    SIG_OUT2,        /* T f(T, out T): modf, frexp */
    SIG_D3DCOLOR,    /* int4 D3DCOLORtoUBYTE4(float4) */
    SIG_NOISE,       /* float noise(floatN) */
    SIG_AS_FLOAT,    /* asfloat: same shape, float */
    SIG_AS_INT,      /* asint: same shape, int */
    SIG_AS_UINT,     /* asuint: same shape, uint */
    SIG_TEX          /* float4 texND[mode](samplerND, coords...) */
} hfx_sig;

/* Texture sampling forms (SIG_TEX rows; d3d9_ir_ops.c indexes by this order). */
typedef enum { TEXF_PLAIN, TEXF_BIAS, TEXF_LOD, TEXF_PROJ, TEXF_GRAD } hfx_tex_form;

/* The IR rewrite an intrinsic gets before any back end sees it (ir/lower/intrinsics.c): the
 * forms no target expresses directly, whatever the target. */
typedef enum {
    LOWER_NONE, /* the call stays as it is */
    LOWER_ROWS, /* componentwise: on a matrix, one call per row (targets have vector forms only) */
    LOWER_MUL   /* mul: a vector times a truncated matrix becomes a padded vector times the whole */
} hfx_intr_lower;

typedef enum {
#define HFX_INTRINSIC(id, name, mn, mx, sig, dim, texf, lower, ev, glsl_emit, glsl_fn) HFX_INTR_##id,
#include "check/intrinsics.def"
#undef HFX_INTRINSIC
    HFX_INTR_COUNT
} hfx_intrinsic_id;

typedef struct hfx_intrinsic_info {
    const char *name;
    uint8_t min_args, max_args;
    hfx_sig sig;
    hfx_dim dim;           /* the texture read's dimension; DIM_GENERIC: no texture read */
    hfx_tex_form tex_form; /* the texture read's form (SIG_TEX rows) */
    hfx_intr_lower lower;  /* the back-end-neutral IR rewrite */
    hfx_ev_fn fold;        /* how common/eval computes it on constants; HFX_EV_FN_NONE: left to the GPU */
} hfx_intrinsic_info;

/* Resolved parameter and return types of one call. */
typedef struct hfx_intrinsic_match {
    const hfx_type *params[4];  /* the type each argument converts to */
    const hfx_type *ret;
    bool out[4];                /* the argument is written (an l-value is required) */
    bool truncates;             /* some argument loses components (X3206) */
    unsigned cost;              /* sum of the argument conversion costs */
} hfx_intrinsic_match;

/* The id of an intrinsic by its (case-sensitive) name, or -1. */
int hfx_intrinsic_find(const char *name);
/* The entry of an id; NULL when out of range. */
const hfx_intrinsic_info *hfx_intrinsic_info_of(int id);
/* The HLSL name of an id ("tex2D"); NULL when out of range. */
const char *hfx_intrinsic_name(int id);
/* Matches argument types against an intrinsic's rule; false when no form of it fits. */
bool hfx_intrinsic_match_args(hfx_types *t, int id, const hfx_type *const *args, unsigned n,
                              hfx_intrinsic_match *out);

#endif
