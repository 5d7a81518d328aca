/* glsl_names.c: keeping HLSL names in the GLSL where GLSL allows them. */
#include <stdlib.h>
#include <string.h>

#include "codegen.h"

/* GLSL keywords and reserved words (4.60 and ES 3.00), and built-in function names a user
 * global could shadow. Sorted for bsearch. */
static const char *const reserved[] = {
    "abs", "acos", "active", "all", "any", "asin", "asm", "atan", "atomic_uint", "attribute",
    "break", "buffer", "bvec2", "bvec3", "bvec4", "case", "cast", "ceil", "centroid", "clamp",
    "class", "coherent", "common", "const", "continue", "cos", "cross", "default", "degrees",
    "discard", "distance", "dmat2", "dmat3", "dmat4", "do", "dot", "double", "dvec2", "dvec3",
    "dvec4", "else", "enum", "exp", "exp2", "extern", "external", "false", "filter", "fixed",
    "flat", "float", "floor", "for", "fract", "fvec2", "fvec3", "fvec4", "goto", "half", "highp",
    "hvec2", "hvec3", "hvec4", "if", "iimage2D", "image2D", "in", "inline", "inout", "input",
    "int", "interface", "invariant", "isampler2D", "isampler3D", "isamplerCube", "ivec2", "ivec3",
    "ivec4", "layout", "length", "log", "log2", "long", "lowp", "main", "mat2", "mat2x2",
    "mat2x3", "mat2x4", "mat3", "mat3x2", "mat3x3", "mat3x4", "mat4", "mat4x2", "mat4x3",
    "mat4x4", "max", "mediump", "min", "mix", "mod", "namespace", "noinline", "noise",
    "noperspective", "normalize", "out", "output", "partition", "patch", "pow", "precise",
    "precision", "public", "radians", "readonly", "reflect", "refract", "resource", "restrict",
    "return", "round", "sample", "sampler1D", "sampler1DShadow", "sampler2D", "sampler2DArray",
    "sampler2DRect", "sampler2DShadow", "sampler3D", "sampler3DRect", "samplerBuffer",
    "samplerCube", "samplerCubeShadow", "shared", "short", "sign", "sin", "sizeof", "smooth",
    "smoothstep", "sqrt", "static", "step", "struct", "subroutine", "superp", "switch", "tan",
    "template", "texture", "texture1D", "texture2D", "texture3D", "textureCube", "textureLod",
    "this", "true", "typedef", "uimage2D", "uint", "union", "unsigned", "usampler2D",
    "usampler3D", "usamplerCube", "using", "uvec2", "uvec3", "uvec4", "varying", "vec2", "vec3",
    "vec4", "void", "volatile", "while", "writeonly",
};

static int cmp(const void *a, const void *b) { return strcmp(*(const char *const *)a, *(const char *const *)b); }

const char *hfx_glsl_name(hfx_arena *arena, const char *name) {
    int clash = strncmp(name, "gl_", 3) == 0 || strstr(name, "__") != NULL || strncmp(name, "hfx_", 4) == 0 ||
                bsearch(&name, reserved, sizeof reserved / sizeof *reserved, sizeof *reserved, cmp) != NULL;
    return clash ? hfx_arena_printf(arena, "hfx_%s", name) : name;
}
