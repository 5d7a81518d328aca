/* types.h: HLSL types. Numeric types are interned (one object per base/rows/cols), so type
 * equality of numerics is pointer equality; arrays and structs are compared by hfx_type_equal.
 * Conventions: a scalar is 1x1, a vector is 1xN (rows = 1), a matrix RxC as declared:
 * float3x4 has 3 rows and 4 columns. */
#ifndef HFX_TYPES_H
#define HFX_TYPES_H

#include <stdbool.h>
#include <stdint.h>

#include "eval.h"

#include "base/arena.h"
#include "base/diag.h"

typedef enum {
    TY_VOID, TY_SCALAR, TY_VECTOR, TY_MATRIX, TY_ARRAY, TY_STRUCT,
    TY_TEXTURE, TY_SAMPLER, TY_STRING, TY_VERTEXSHADER, TY_PIXELSHADER,
    TY_FUNCTION /* only for diagnostics */
} hfx_type_kind;

typedef enum { B_BOOL, B_INT, B_UINT, B_HALF, B_FLOAT, B_DOUBLE, B_MIN16FLOAT, B_NONE } hfx_base;

typedef enum { DIM_GENERIC, DIM_1D, DIM_2D, DIM_3D, DIM_CUBE } hfx_dim;

enum { /* hfx_field.interp and declaration modifiers (hfx_decl.mods, hfx_param.mods) */
    MOD_IN = 1u << 0, MOD_OUT = 1u << 1, MOD_UNIFORM = 1u << 2, MOD_STATIC = 1u << 3,
    MOD_EXTERN = 1u << 4, MOD_SHARED = 1u << 5, MOD_CONST = 1u << 6, MOD_VOLATILE = 1u << 7,
    MOD_ROW_MAJOR = 1u << 8, MOD_COLUMN_MAJOR = 1u << 9, MOD_INLINE = 1u << 10,
    MOD_LINEAR = 1u << 11, MOD_CENTROID = 1u << 12, MOD_NOINTERPOLATION = 1u << 13,
    MOD_NOPERSPECTIVE = 1u << 14, MOD_SAMPLE = 1u << 15, MOD_PRECISE = 1u << 16,
    MOD_GROUPSHARED = 1u << 17
};

typedef struct hfx_type hfx_type;
typedef struct hfx_expr hfx_expr;

typedef struct hfx_field {
    const char *name;
    const hfx_type *type;
    const char *semantic;  /* NULL when none */
    uint32_t mods;         /* interpolation modifiers */
    hfx_loc loc;
} hfx_field;

typedef struct hfx_struct {
    const char *name;      /* NULL for an anonymous struct */
    hfx_field *fields;
    uint32_t field_count;
    hfx_loc loc;
} hfx_struct;

struct hfx_type {
    hfx_type_kind kind;
    hfx_base base;         /* scalar / vector / matrix element type */
    uint8_t rows, cols;
    hfx_dim dim;           /* textures and samplers */
    uint32_t array_len;    /* TY_ARRAY; 0 = unsized (`float a[] = {...}` before checking) */
    const hfx_type *elem;  /* TY_ARRAY element */
    hfx_struct *st;        /* TY_STRUCT */
    hfx_expr *array_len_expr; /* TY_ARRAY whose size the parser could not fold (a name, an expression) */
};

typedef struct hfx_types hfx_types; /* the interning table; one per compilation */

hfx_types *hfx_types_new(hfx_arena *arena);
const hfx_type *hfx_type_void(hfx_types *t);
const hfx_type *hfx_type_scalar(hfx_types *t, hfx_base b);
const hfx_type *hfx_type_vector(hfx_types *t, hfx_base b, unsigned n);           /* n = 1..4 */
const hfx_type *hfx_type_matrix(hfx_types *t, hfx_base b, unsigned rows, unsigned cols);
const hfx_type *hfx_type_numeric(hfx_types *t, hfx_type_kind k, hfx_base b, unsigned rows, unsigned cols);
const hfx_type *hfx_type_object(hfx_types *t, hfx_type_kind k, hfx_dim dim);     /* texture, sampler, string, shaders */
const hfx_type *hfx_type_array(hfx_types *t, const hfx_type *elem, uint32_t len);
const hfx_type *hfx_type_struct(hfx_types *t, hfx_struct *st);
/* Whether any array of arrays was made: when not, passes about them have nothing to do. */
bool hfx_types_nested_arrays(const hfx_types *t);

bool hfx_type_is_numeric(const hfx_type *ty);        /* scalar, vector or matrix */
bool hfx_type_equal(const hfx_type *a, const hfx_type *b);
unsigned hfx_type_components(const hfx_type *ty);    /* scalars in it (arrays and structs summed), 0 for objects */
const char *hfx_type_name(hfx_arena *a, const hfx_type *ty); /* "float4", "float4x4", "LuzSpot[2]" */
const char *hfx_base_name(hfx_base b);
/* The evaluator's base for b: half, double and min16float compute as float (SM2/SM3 do). */
hfx_ev_base hfx_base_ev(hfx_base b);

#endif
