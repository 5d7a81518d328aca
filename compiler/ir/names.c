/* names.c: keeping HLSL names in the GLSL where GLSL allows them. */
#include <stdlib.h>
#include <string.h>

#include "ir/ir.h"

/* GLSL keywords and reserved words (4.60 and ES 3.00), and built-in function names a user
 * global could shadow. Sorted for bsearch. */
static const char *const reserved[] = {
    "EmitVertex", "EndPrimitive", "abs", "acos", "acosh", "active", "all", "any", "asin", "asinh",
    "asm", "atan", "atanh", "atomicAdd", "atomic_uint", "attribute", "barrier", "bitCount",
    "bitfieldExtract", "bitfieldInsert", "bitfieldReverse", "break", "buffer", "bvec2", "bvec3",
    "bvec4", "case", "cast", "ceil", "centroid", "clamp", "class", "coherent", "common", "const",
    "continue", "cos", "cosh", "cross", "dFdx", "dFdy", "default", "degrees", "determinant", "discard",
    "distance", "dmat2", "dmat3", "dmat4", "do", "dot", "double", "dvec2", "dvec3", "dvec4", "else",
    "emitVertex", "enum", "equal", "exp", "exp2", "extern", "external", "faceforward", "false",
    "filter", "findLSB", "findMSB", "fixed", "flat", "float", "floatBitsToInt", "floatBitsToUint",
    "floor", "fma", "for", "fract", "frexp", "ftransform", "fvec2", "fvec3", "fvec4", "fwidth", "goto",
    "greaterThan", "greaterThanEqual", "half", "highp", "hvec2", "hvec3", "hvec4", "if", "iimage2D",
    "image2D", "imageLoad", "imageStore", "imulExtended", "in", "inline", "inout", "input", "int",
    "intBitsToFloat", "interface", "interpolateAtCentroid", "interpolateAtOffset",
    "interpolateAtSample", "invariant", "inverse", "inversesqrt", "isampler1D", "isampler2D",
    "isampler2DArray", "isampler3D", "isamplerCube", "isinf", "isnan", "ivec2", "ivec3", "ivec4",
    "layout", "ldexp", "length", "lessThan", "lessThanEqual", "log", "log2", "long", "lowp", "main",
    "mat2", "mat2x2", "mat2x3", "mat2x4", "mat3", "mat3x2", "mat3x3", "mat3x4", "mat4", "mat4x2",
    "mat4x3", "mat4x4", "matrixCompMult", "max", "mediump", "memoryBarrier", "min", "mix", "mod",
    "modf", "namespace", "noinline", "noise", "noise1", "noise2", "noise3", "noise4", "noperspective",
    "normalize", "not", "notEqual", "out", "outerProduct", "output", "packHalf2x16", "packSnorm2x16",
    "packUnorm2x16", "packUnorm4x8", "partition", "patch", "pow", "precise", "precision", "public",
    "radians", "readonly", "reflect", "refract", "resource", "restrict", "return", "round", "roundEven",
    "sample", "sampler1D", "sampler1DArray", "sampler1DShadow", "sampler2D", "sampler2DArray",
    "sampler2DArrayShadow", "sampler2DRect", "sampler2DShadow", "sampler3D", "sampler3DRect",
    "samplerBuffer", "samplerCube", "samplerCubeShadow", "samplerExternalOES", "shadow1D", "shadow2D",
    "shadow2DProj", "shared", "short", "sign", "sin", "sinh", "sizeof", "smooth", "smoothstep", "sqrt",
    "static", "step", "struct", "subroutine", "superp", "switch", "tan", "tanh", "template",
    "texelFetch", "texelFetchOffset", "texture", "texture1D", "texture1DLod", "texture1DProj",
    "texture2D", "texture2DLod", "texture2DProj", "texture2DProjLod", "texture3D", "texture3DLod",
    "texture3DProj", "textureCube", "textureCubeLod", "textureGather", "textureGatherOffset",
    "textureGrad", "textureLod", "textureLodOffset", "textureOffset", "textureProj", "textureProjLod",
    "textureQueryLevels", "textureQueryLod", "textureSize", "this", "transpose", "true", "trunc",
    "typedef", "uaddCarry", "uimage2D", "uint", "uintBitsToFloat", "umulExtended", "union",
    "unpackHalf2x16", "unpackSnorm2x16", "unpackUnorm2x16", "unpackUnorm4x8", "unsigned", "usampler1D",
    "usampler2D", "usampler2DArray", "usampler3D", "usamplerCube", "using", "usubBorrow", "uvec2",
    "uvec3", "uvec4", "varying", "vec2", "vec3", "vec4", "void", "volatile", "while", "writeonly",
};

/* Binary search deciding on the first byte where it can: every declaration, field and struct
 * name the printer writes comes here. */
static bool is_reserved(const char *name) {
    size_t lo = 0, hi = sizeof reserved / sizeof *reserved;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const char *r = reserved[mid];
        int c = (unsigned char)name[0] - (unsigned char)r[0];
        if (c == 0) c = strcmp(name, r);
        if (c == 0) return true;
        if (c < 0) hi = mid;
        else lo = mid + 1;
    }
    return false;
}

const char *hfx_glsl_name(hfx_arena *arena, const char *name) {
    int clash = strncmp(name, "gl_", 3) == 0 || strstr(name, "__") != NULL || strncmp(name, "hfx_", 4) == 0 ||
                is_reserved(name);
    return clash ? hfx_arena_printf(arena, "hfx_%s", name) : name;
}
