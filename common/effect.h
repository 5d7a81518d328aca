/* effect.h: the compiled effect, as plain data. The compiler builds it, hfxo.c writes and reads
 * it, the runtime loads GL objects from it. It knows neither HLSL nor GL, so the runtime can
 * load a .hfxo without the compiler.
 *
 * Layout rules (everything is an index into the arrays of hfx_fx_effect; HFX_NONE = absent):
 * - params: the top-level parameters are params[0 .. top_param_count), in declaration order.
 *   Each param's children (array elements for an array, members for a struct) are contiguous:
 *   params[first_child .. first_child + child_count). An array's elements are not arrays.
 * - values: one buffer of 32-bit words holding every numeric parameter (default values from the
 *   initializers, zero otherwise). A param owns words [offset, offset + words): scalars 1 word,
 *   vectors N, matrices rows*cols in row-major order (XNA's order; translation of a 4x4 at
 *   12..14), arrays element after element, structs member after member; no padding.
 *   bool and int are int32 (bool 0/1), float is IEEE float. Objects own no words.
 * - annotations, states: contiguous ranges [first, first + count). An empty range has
 *   first <= the array's length (the builder writes 0), so first + count never overflows. */
#ifndef HFX_COMMON_EFFECT_H
#define HFX_COMMON_EFFECT_H

#include <stddef.h>
#include <stdint.h>

#include "hfx/hfx.h"

#define HFX_NONE 0xffffffffu

typedef struct hfx_fx_annotation {
    char *name;
    hfx_param_type type;   /* BOOL, INT, FLOAT or STRING */
    hfx_param_class klass; /* SCALAR, VECTOR, MATRIX, or OBJECT for a string */
    uint32_t rows, cols;
    uint32_t count;        /* number of words in data (rows*cols; 0 for strings) */
    uint32_t *data;        /* int32 or float bits by type */
    char *string;          /* for strings */
} hfx_fx_annotation;

typedef struct hfx_fx_code {
    char *data;             /* GLSL text (NUL-terminated), SPIR-V words or Direct3D 9 bytecode */
    size_t size;            /* bytes, without the NUL */
} hfx_fx_code;

enum { /* hfx_fx_param.flags */
    HFX_FX_PARAM_SHARED = 1u << 0,
    HFX_FX_PARAM_ROW_MAJOR = 1u << 1,
    HFX_FX_PARAM_COLUMN_MAJOR = 1u << 2
};

typedef struct hfx_fx_param {
    char *name;
    char *semantic;        /* NULL when none */
    char *glsl_name;       /* name in the emitted GLSL (a member's own name for members); NULL if never a uniform */
    hfx_param_class klass;
    hfx_param_type type;
    uint32_t rows, cols;   /* scalar 1x1, vector 1xN, matrix RxC as declared (float3x4: 3 rows, 4 cols) */
    uint32_t elements;     /* array length, 0 when not an array */
    uint32_t parent;       /* HFX_NONE for top level */
    uint32_t first_child, child_count;
    uint32_t offset, words;
    uint32_t first_annotation, annotation_count;
    uint32_t sampler;      /* index into samplers for a sampler parameter, else HFX_NONE */
    uint32_t flags;
    char *string;          /* a string parameter's initial value (`string s = "..."`); NULL otherwise */
    char *file;            /* top level: the file that declares it, as the #include named it; NULL when unknown */
    uint32_t line, col;    /* ... and where (the name); 0 when unknown (a .hfxo from before they were kept) */
    hfx_fx_code d3d9;      /* a vertexshader / pixelshader leaf: its Direct3D 9 bytecode as an fx_2_0
                            * binary carried it (what hfx's fx_2_0 writer writes back); size 0 when unknown */
} hfx_fx_param;

/* How a state's value is given. */
typedef enum {
    HFX_FX_VALUE_INT,      /* int32 (enums, DWORDs, bools as 0/1) */
    HFX_FX_VALUE_FLOAT,    /* up to 4 floats (colours as float4) */
    HFX_FX_VALUE_PARAM,    /* taken from a parameter at apply time (`ZEnable = <p>;`, `Texture = <t>;`) */
    HFX_FX_VALUE_PROGRAM,  /* VertexShader / PixelShader: index into programs (HFX_NONE for NULL) */
    HFX_FX_VALUE_UNSUPPORTED, /* parsed but not expressible (asm, non-constant shader array index) */
    HFX_FX_VALUE_EXPR      /* computed from parameters at apply time: exprs[ref .. ref + count), eval_code.h */
} hfx_fx_value_kind;

typedef struct hfx_fx_state {
    uint32_t id;           /* hfx_state_id from states.h */
    uint32_t index;        /* the [n] of `MinFilter[1] = ...`, 0 otherwise */
    hfx_fx_value_kind kind;
    uint32_t count;        /* components in f (1..4); words of the program for EXPR */
    int32_t i;
    float f[4];
    uint32_t ref;          /* param index for PARAM, program index for PROGRAM, first word for EXPR */
    uint32_t line, col;    /* where the state was written, for load-time reports */
    uint32_t source;       /* VertexShader / PixelShader: 1 + the shader parameter the value names (the array an
                            * EXPR picks from, `= <vs>`); 0 when the shader is given inline (fx_2_0's writer) */
} hfx_fx_state;

typedef enum { HFX_FX_DIM_2D, HFX_FX_DIM_1D, HFX_FX_DIM_3D, HFX_FX_DIM_CUBE } hfx_fx_dim;

typedef struct hfx_fx_sampler {
    uint32_t param;         /* the sampler parameter */
    uint32_t texture_param; /* from `Texture = <t>`; HFX_NONE if the sampler names no texture */
    hfx_fx_dim dim;         /* what the shaders sample it as */
    uint32_t first_state, state_count; /* the sampler_state block, less Texture */
    uint32_t texture_slot;  /* how many of those states came before Texture (an fx_2_0 binary's order, which
                             * its writer keeps; 0 otherwise) */
} hfx_fx_sampler;

typedef struct hfx_fx_attribute {
    char *semantic;         /* canonical upper case with index: "POSITION0", "TEXCOORD3" */
    char *glsl_name;        /* the vertex shader's input variable */
    int32_t location;       /* fixed by the Cg / NVIDIA aliasing convention */
} hfx_fx_attribute;

typedef struct hfx_fx_sampler_use {
    char *glsl_name;        /* the sampler uniform in the GLSL */
    uint32_t sampler;       /* index into samplers */
    int32_t unit;           /* texture unit this program samples it on */
} hfx_fx_sampler_use;

/* HFXC_PACK_UNIFORMS: the program's packable parameters (hfx_fx_param_packable) live in one
 * `uniform vec4 hfx_c[reg_count];`, as D3D9's constant registers, so a runtime sets all the
 * changed ones with one glUniform4fv. A scalar or vector takes one register (.x, .xy, .xyz,
 * .xyzw); a floatRxC matrix R registers, register reg + i holding HLSL row i in its first C
 * components (the parameter's row-major words, row after row, each row padded to 4). */
#define HFX_FX_REGS_NAME "hfx_c"
#define HFX_FX_MAX_REGS 4096u    /* what a reader accepts; the compiler packs at most 256 */

/* A switch: a scalar bool parameter that both stages declare as
 *     #ifdef HFX_SWITCH_k / const bool NAME = HFX_SWITCH_k; / #else / uniform bool NAME; / #endif
 * k counting the program's switches in uniform order. A GL runtime may link a variant of the
 * program per combination of the switches' values (defining each HFX_SWITCH_k true or false
 * after the #version line), so that `if (NAME)` costs the shader nothing, as an #ifdef would in
 * hand-written GLSL; the text with nothing defined reads the uniform as any other. */
#define HFX_FX_MAX_SWITCHES 4u
enum { /* hfx_fx_uniform_use.flags */
    HFX_FX_USE_SWITCH = 1u << 0
};

typedef struct hfx_fx_uniform_use {
    uint32_t param;         /* top-level parameter the program reads */
    uint32_t reg;           /* its first register in hfx_c; HFX_NONE: its own GLSL uniform */
    uint32_t flags;         /* HFX_FX_USE_SWITCH */
} hfx_fx_uniform_use;

enum { HFX_STAGE_VERTEX, HFX_STAGE_FRAGMENT, HFX_STAGE_COUNT };

enum { /* hfx_fx_program.flags */
    HFX_FX_PROGRAM_ALPHA_TEST = 1u << 0 /* fragment shader has hfx_alpha_func / hfx_alpha_ref uniforms */
};

/* A preshader (HFXC_PACK_UNIFORMS): work a shader did on parameters alone, moved to the CPU as
 * fxc does. Its common/eval_code program (words first .. first + words of the program's
 * pre_code) runs over the effect's parameter values when one it reads changed; the result goes
 * into registers reg .. reg + rows - 1 of hfx_c, cols components each, laid out as a packed
 * parameter of its type (HLSL row i in register reg + i). */
typedef struct hfx_fx_preshader {
    uint32_t first, words;
    uint32_t reg, rows, cols;
} hfx_fx_preshader;

/* One GLSL program: the vertex + pixel shader pair of a pass, specialised for it. */
typedef struct hfx_fx_program {
    hfx_fx_code code[HFX_STAGE_COUNT][HFX_TARGET_COUNT];
    hfx_fx_attribute *attributes; uint32_t attribute_count;
    hfx_fx_sampler_use *samplers; uint32_t sampler_count;
    hfx_fx_uniform_use *uniforms; uint32_t uniform_count;
    uint32_t flags;
    uint32_t reg_count;     /* vec4 registers of hfx_c (0: nothing packed) */
    hfx_fx_preshader *preshaders; uint32_t preshader_count; /* registers after the parameters' */
    uint32_t *pre_code; uint32_t pre_words;
    /* The pass's shaders as Direct3D 9 bytecode (vs_* / ps_* tokens; size 0: none or not made): an
     * fx_2_0 binary's own, or the D3D9 back end's for a compiled source. fx_2_0's writer writes
     * them; the .hfxo does not carry them. */
    hfx_fx_code d3d9[HFX_STAGE_COUNT];
} hfx_fx_program;

typedef struct hfx_fx_pass {
    char *name;             /* "" for an anonymous pass */
    uint32_t first_annotation, annotation_count;
    uint32_t first_state, state_count; /* render, sampler and shader states in source order */
    uint32_t program;       /* HFX_NONE if the pass sets no shaders */
} hfx_fx_pass;

/* A pass whose shaders come from shader arrays indexed by parameters (`VertexShader =
 * (VSArray[VSIndices[ShaderIndex]]);`, XNA's stock effects): one variant per pair of array
 * indices the compiler found reachable. Apply runs the pass's VertexShader / PixelShader EXPR
 * states (the indices, clamped into the arrays) and uses the variant's program. */
typedef struct hfx_fx_variant {
    uint32_t pass;
    uint32_t vs, ps;        /* shader array indices; HFX_NONE for a stage that is not selected */
    uint32_t program;
} hfx_fx_variant;

typedef struct hfx_fx_technique {
    char *name;             /* "" for an anonymous technique */
    uint32_t first_annotation, annotation_count;
    uint32_t first_pass, pass_count;
} hfx_fx_technique;

typedef struct hfx_fx_effect {
    char *source_name;      /* file the effect came from, for messages */
    hfx_fx_param *params; uint32_t param_count, top_param_count;
    uint32_t *values; uint32_t value_words;
    uint32_t *exprs; uint32_t expr_words; /* the programs of EXPR states, one after another */
    hfx_fx_variant *variants; uint32_t variant_count; /* by pass, in pass order */
    hfx_fx_annotation *annotations; uint32_t annotation_count;
    hfx_fx_state *states; uint32_t state_count;
    hfx_fx_sampler *samplers; uint32_t sampler_count;
    hfx_fx_program *programs; uint32_t program_count;
    hfx_fx_pass *passes; uint32_t pass_count;
    hfx_fx_technique *techniques; uint32_t technique_count;
    uint32_t targets;       /* bit (1 << hfx_target) for each target whose code is present */
} hfx_fx_effect;

void hfx_fx_effect_free(hfx_fx_effect *fx);                 /* frees fx and everything it owns */
void hfx_fx_program_clear(hfx_fx_program *p);               /* frees what p owns, zeroes it */
hfx_fx_effect *hfx_fx_effect_copy(const hfx_fx_effect *fx); /* deep copy; NULL when out of memory */
uint32_t hfx_fx_param_find(const hfx_fx_effect *fx, const char *name); /* top-level by name, or HFX_NONE */
/* The top-level parameter that the eval_code instruction at code[at] reads (PARAM, ELEMENT), else HFX_NONE. */
uint32_t hfx_fx_param_read_at(const hfx_fx_effect *fx, const uint32_t *code, uint32_t at);
/* A numeric value of 1..16 words: what eval_code reads whole (a parameter, or an array's element). */
int hfx_fx_param_evaluable(const hfx_fx_param *p);
/* Registers parameter i would take in hfx_c (rows for a matrix, else 1); 0 when it cannot be
 * packed: only a top-level, non-array float scalar, vector or matrix (up to 4x4) with a GLSL name. */
uint32_t hfx_fx_param_packable(const hfx_fx_effect *fx, uint32_t i);
/* Whether parameter i can be a switch (HFX_FX_USE_SWITCH): a top-level scalar bool, not an array, with a GLSL name. */
int hfx_fx_param_switchable(const hfx_fx_effect *fx, uint32_t i);
/* Whether program p reads use u from hfx_c (a register inside reg_count) rather than its own uniform. */
static inline int hfx_fx_use_packed(const hfx_fx_program *p, const hfx_fx_uniform_use *u) {
    return u->reg != HFX_NONE && u->reg < p->reg_count;
}

/* .hfxo: see docs/hfxo-format.md. */
int hfx_fx_write_hfxo(const hfx_fx_effect *fx, void **out, size_t *out_size); /* 0 on success */
hfx_fx_effect *hfx_fx_read_hfxo(const void *data, size_t size, char *err, size_t err_size);
int hfx_fx_is_hfxo(const void *data, size_t size);          /* checks the magic number */

#endif
