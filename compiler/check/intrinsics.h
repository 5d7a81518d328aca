/* intrinsics.h: the HLSL intrinsic functions (SM2/SM3 set plus asfloat/asint/asuint): ids,
 * names, argument counts, the rule that matches argument types, and the GLSL each lowers to
 * (a note for the code generator, which maps them by name: hfx_intrinsic_name).
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
    SIG_LIT,         /* float4 lit(float, float, float) */
    SIG_SINCOS,      /* void sincos(T, out T, out T) */
    SIG_OUT2,        /* T f(T, out T): modf, frexp */
    SIG_D3DCOLOR,    /* int4 D3DCOLORtoUBYTE4(float4) */
    SIG_NOISE,       /* float noise(floatN) */
    SIG_REINTERPRET, /* asfloat / asint / asuint: same shape, new element type */
    SIG_TEX          /* float4 texND[mode](samplerND, coords...) */
} hfx_sig;

/* Texture sampling forms (SIG_TEX). */
typedef enum { TEXF_PLAIN, TEXF_BIAS, TEXF_LOD, TEXF_PROJ, TEXF_GRAD } hfx_tex_form;

/* X(id, "name", min args, max args, rule, dim (textures), form (textures), GLSL lowering) */
#define HFX_INTRINSIC_LIST(X) \
    X(ABS, "abs", 1, 1, SIG_SAME, 0, 0, "abs(x)") \
    X(ACOS, "acos", 1, 1, SIG_SAME_FLOAT, 0, 0, "acos(x)") \
    X(ALL, "all", 1, 1, SIG_ALL_ANY, 0, 0, "all(bvec(x)) (scalar: bool(x))") \
    X(ANY, "any", 1, 1, SIG_ALL_ANY, 0, 0, "any(bvec(x)) (scalar: bool(x))") \
    X(ASFLOAT, "asfloat", 1, 1, SIG_REINTERPRET, 0, B_FLOAT, "intBitsToFloat / uintBitsToFloat") \
    X(ASIN, "asin", 1, 1, SIG_SAME_FLOAT, 0, 0, "asin(x)") \
    X(ASINT, "asint", 1, 1, SIG_REINTERPRET, 0, B_INT, "floatBitsToInt(x)") \
    X(ASUINT, "asuint", 1, 1, SIG_REINTERPRET, 0, B_UINT, "floatBitsToUint(x)") \
    X(ATAN, "atan", 1, 1, SIG_SAME_FLOAT, 0, 0, "atan(x)") \
    X(ATAN2, "atan2", 2, 2, SIG_SAME_FLOAT, 0, 0, "atan(y, x)") \
    X(CEIL, "ceil", 1, 1, SIG_SAME_FLOAT, 0, 0, "ceil(x)") \
    X(CLAMP, "clamp", 3, 3, SIG_SAME, 0, 0, "clamp(x, a, b)") \
    X(CLIP, "clip", 1, 1, SIG_CLIP, 0, 0, "if (any(lessThan(x, 0))) discard;") \
    X(COS, "cos", 1, 1, SIG_SAME_FLOAT, 0, 0, "cos(x)") \
    X(COSH, "cosh", 1, 1, SIG_SAME_FLOAT, 0, 0, "cosh(x)") \
    X(CROSS, "cross", 2, 2, SIG_CROSS, 0, 0, "cross(a, b)") \
    X(D3DCOLORTOUBYTE4, "D3DCOLORtoUBYTE4", 1, 1, SIG_D3DCOLOR, 0, 0, "ivec4(x.zyxw * 255.001953)") \
    X(DDX, "ddx", 1, 1, SIG_SAME_FLOAT, 0, 0, "dFdx(x)") \
    X(DDY, "ddy", 1, 1, SIG_SAME_FLOAT, 0, 0, "dFdy(x) (negated when rendering flipped)") \
    X(DEGREES, "degrees", 1, 1, SIG_SAME_FLOAT, 0, 0, "degrees(x)") \
    X(DETERMINANT, "determinant", 1, 1, SIG_DETERMINANT, 0, 0, "determinant(m) (1x1: m)") \
    X(DISTANCE, "distance", 2, 2, SIG_DISTANCE, 0, 0, "distance(a, b)") \
    X(DOT, "dot", 2, 2, SIG_DOT, 0, 0, "dot(a, b) (ints: sum of products)") \
    X(EXP, "exp", 1, 1, SIG_SAME_FLOAT, 0, 0, "exp(x)") \
    X(EXP2, "exp2", 1, 1, SIG_SAME_FLOAT, 0, 0, "exp2(x)") \
    X(FACEFORWARD, "faceforward", 3, 3, SIG_VEC_SAME, 0, 0, "faceforward(n, i, ng)") \
    X(FLOOR, "floor", 1, 1, SIG_SAME_FLOAT, 0, 0, "floor(x)") \
    X(FMOD, "fmod", 2, 2, SIG_SAME_FLOAT, 0, 0, "x - y * trunc(x / y)") \
    X(FRAC, "frac", 1, 1, SIG_SAME_FLOAT, 0, 0, "fract(x)") \
    X(FREXP, "frexp", 2, 2, SIG_OUT2, 0, 0, "frexp(x, e) (e written as float)") \
    X(FWIDTH, "fwidth", 1, 1, SIG_SAME_FLOAT, 0, 0, "fwidth(x)") \
    X(ISFINITE, "isfinite", 1, 1, SIG_CLASSIFY, 0, 0, "!(isnan(x) || isinf(x))") \
    X(ISINF, "isinf", 1, 1, SIG_CLASSIFY, 0, 0, "isinf(x)") \
    X(ISNAN, "isnan", 1, 1, SIG_CLASSIFY, 0, 0, "isnan(x)") \
    X(LDEXP, "ldexp", 2, 2, SIG_SAME_FLOAT, 0, 0, "x * exp2(e)") \
    X(LENGTH, "length", 1, 1, SIG_LENGTH, 0, 0, "length(x)") \
    X(LERP, "lerp", 3, 3, SIG_SAME_FLOAT, 0, 0, "mix(a, b, t)") \
    X(LIT, "lit", 3, 3, SIG_LIT, 0, 0, "vec4(1, max(n_dot_l, 0), (n_dot_l < 0 || n_dot_h < 0) ? 0 : pow(n_dot_h, m), 1)") \
    X(LOG, "log", 1, 1, SIG_SAME_FLOAT, 0, 0, "log(x)") \
    X(LOG10, "log10", 1, 1, SIG_SAME_FLOAT, 0, 0, "log2(x) * 0.30103") \
    X(LOG2, "log2", 1, 1, SIG_SAME_FLOAT, 0, 0, "log2(x)") \
    X(MAX, "max", 2, 2, SIG_SAME, 0, 0, "max(a, b)") \
    X(MIN, "min", 2, 2, SIG_SAME, 0, 0, "min(a, b)") \
    X(MODF, "modf", 2, 2, SIG_OUT2, 0, 0, "modf(x, ip)") \
    X(MUL, "mul", 2, 2, SIG_MUL, 0, 0, "row vectors: mul(v, M) = v * M, mul(M, v) = M * v with HLSL's row-major layout; scalars: a * b; vector.vector: dot") \
    X(NOISE, "noise", 1, 1, SIG_NOISE, 0, 0, "a Perlin noise helper function") \
    X(NORMALIZE, "normalize", 1, 1, SIG_VEC_SAME, 0, 0, "normalize(x)") \
    X(POW, "pow", 2, 2, SIG_SAME_FLOAT, 0, 0, "pow(x, y)") \
    X(RADIANS, "radians", 1, 1, SIG_SAME_FLOAT, 0, 0, "radians(x)") \
    X(REFLECT, "reflect", 2, 2, SIG_VEC_SAME, 0, 0, "reflect(i, n)") \
    X(REFRACT, "refract", 3, 3, SIG_REFRACT, 0, 0, "refract(i, n, eta)") \
    X(ROUND, "round", 1, 1, SIG_SAME_FLOAT, 0, 0, "round(x)") \
    X(RSQRT, "rsqrt", 1, 1, SIG_SAME_FLOAT, 0, 0, "inversesqrt(x)") \
    X(SATURATE, "saturate", 1, 1, SIG_SAME_FLOAT, 0, 0, "clamp(x, 0.0, 1.0)") \
    X(SIGN, "sign", 1, 1, SIG_SAME, 0, 0, "sign(x)") \
    X(SIN, "sin", 1, 1, SIG_SAME_FLOAT, 0, 0, "sin(x)") \
    X(SINCOS, "sincos", 3, 3, SIG_SINCOS, 0, 0, "s = sin(x); c = cos(x);") \
    X(SINH, "sinh", 1, 1, SIG_SAME_FLOAT, 0, 0, "sinh(x)") \
    X(SMOOTHSTEP, "smoothstep", 3, 3, SIG_SAME_FLOAT, 0, 0, "smoothstep(a, b, x)") \
    X(SQRT, "sqrt", 1, 1, SIG_SAME_FLOAT, 0, 0, "sqrt(x)") \
    X(STEP, "step", 2, 2, SIG_SAME_FLOAT, 0, 0, "step(a, x)") \
    X(TAN, "tan", 1, 1, SIG_SAME_FLOAT, 0, 0, "tan(x)") \
    X(TANH, "tanh", 1, 1, SIG_SAME_FLOAT, 0, 0, "tanh(x)") \
    X(TRANSPOSE, "transpose", 1, 1, SIG_TRANSPOSE, 0, 0, "transpose(m)") \
    X(TRUNC, "trunc", 1, 1, SIG_SAME_FLOAT, 0, 0, "trunc(x)") \
    X(TEX1D, "tex1D", 2, 4, SIG_TEX, DIM_1D, TEXF_PLAIN, "texture(s, vec2(t, 0.5)); 4 args: textureGrad") \
    X(TEX1DBIAS, "tex1Dbias", 2, 2, SIG_TEX, DIM_1D, TEXF_BIAS, "texture(s, t.x, t.w)") \
    X(TEX1DGRAD, "tex1Dgrad", 4, 4, SIG_TEX, DIM_1D, TEXF_GRAD, "textureGrad(s, t, ddx, ddy)") \
    X(TEX1DLOD, "tex1Dlod", 2, 2, SIG_TEX, DIM_1D, TEXF_LOD, "textureLod(s, t.x, t.w)") \
    X(TEX1DPROJ, "tex1Dproj", 2, 2, SIG_TEX, DIM_1D, TEXF_PROJ, "texture(s, t.x / t.w)") \
    X(TEX2D, "tex2D", 2, 4, SIG_TEX, DIM_2D, TEXF_PLAIN, "texture(s, t); 4 args: textureGrad") \
    X(TEX2DBIAS, "tex2Dbias", 2, 2, SIG_TEX, DIM_2D, TEXF_BIAS, "texture(s, t.xy, t.w)") \
    X(TEX2DGRAD, "tex2Dgrad", 4, 4, SIG_TEX, DIM_2D, TEXF_GRAD, "textureGrad(s, t, ddx, ddy)") \
    X(TEX2DLOD, "tex2Dlod", 2, 2, SIG_TEX, DIM_2D, TEXF_LOD, "textureLod(s, t.xy, t.w)") \
    X(TEX2DPROJ, "tex2Dproj", 2, 2, SIG_TEX, DIM_2D, TEXF_PROJ, "textureProj(s, t) (t.xyw)") \
    X(TEX3D, "tex3D", 2, 4, SIG_TEX, DIM_3D, TEXF_PLAIN, "texture(s, t); 4 args: textureGrad") \
    X(TEX3DBIAS, "tex3Dbias", 2, 2, SIG_TEX, DIM_3D, TEXF_BIAS, "texture(s, t.xyz, t.w)") \
    X(TEX3DGRAD, "tex3Dgrad", 4, 4, SIG_TEX, DIM_3D, TEXF_GRAD, "textureGrad(s, t, ddx, ddy)") \
    X(TEX3DLOD, "tex3Dlod", 2, 2, SIG_TEX, DIM_3D, TEXF_LOD, "textureLod(s, t.xyz, t.w)") \
    X(TEX3DPROJ, "tex3Dproj", 2, 2, SIG_TEX, DIM_3D, TEXF_PROJ, "textureProj(s, t)") \
    X(TEXCUBE, "texCUBE", 2, 4, SIG_TEX, DIM_CUBE, TEXF_PLAIN, "texture(s, t); 4 args: textureGrad") \
    X(TEXCUBEBIAS, "texCUBEbias", 2, 2, SIG_TEX, DIM_CUBE, TEXF_BIAS, "texture(s, t.xyz, t.w)") \
    X(TEXCUBEGRAD, "texCUBEgrad", 4, 4, SIG_TEX, DIM_CUBE, TEXF_GRAD, "textureGrad(s, t, ddx, ddy)") \
    X(TEXCUBELOD, "texCUBElod", 2, 2, SIG_TEX, DIM_CUBE, TEXF_LOD, "textureLod(s, t.xyz, t.w)") \
    X(TEXCUBEPROJ, "texCUBEproj", 2, 2, SIG_TEX, DIM_CUBE, TEXF_PROJ, "texture(s, t.xyz / t.w)")

typedef enum {
#define HFX_INTRINSIC_ENUM_(id, name, mn, mx, sig, dim, form, glsl) HFX_INTR_##id,
    HFX_INTRINSIC_LIST(HFX_INTRINSIC_ENUM_)
#undef HFX_INTRINSIC_ENUM_
    HFX_INTR_COUNT
} hfx_intrinsic_id;

typedef struct hfx_intrinsic_info {
    const char *name;
    uint8_t min_args, max_args;
    hfx_sig sig;
    hfx_dim dim;         /* SIG_TEX */
    int form;            /* SIG_TEX: hfx_tex_form; SIG_REINTERPRET: the hfx_base produced */
    const char *glsl;    /* how it lowers, for the code generator */
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
