#include "base/types.h"

#include <stdio.h>
#include <string.h>

enum { BASE_COUNT = B_NONE + 1 };

struct hfx_types {
    hfx_arena *arena;
    hfx_type void_type;
    hfx_type numeric[BASE_COUNT][5][5]; /* [base][rows][cols]; scalars at [1][1] */
    hfx_type vectors[BASE_COUNT][5];    /* vectors are 1xN, kept apart from 1xN matrices */
    hfx_type objects[TY_FUNCTION + 1][DIM_CUBE + 1];
    bool nested_arrays; /* some array type has arrays for elements (every array type is made here) */
};

hfx_types *hfx_types_new(hfx_arena *arena) {
    hfx_types *t = HFX_NEW(arena, hfx_types);
    if (!t) return NULL;
    t->arena = arena;
    t->void_type.kind = TY_VOID;
    t->void_type.base = B_NONE;
    for (int b = 0; b < BASE_COUNT; b++) {
        for (int r = 1; r <= 4; r++)
            for (int c = 1; c <= 4; c++) {
                hfx_type *ty = &t->numeric[b][r][c];
                ty->kind = (r == 1 && c == 1) ? TY_SCALAR : TY_MATRIX;
                ty->base = (hfx_base)b;
                ty->rows = (uint8_t)r;
                ty->cols = (uint8_t)c;
            }
        for (int n = 1; n <= 4; n++) {
            hfx_type *ty = &t->vectors[b][n];
            ty->kind = TY_VECTOR;
            ty->base = (hfx_base)b;
            ty->rows = 1;
            ty->cols = (uint8_t)n;
        }
    }
    for (int k = 0; k <= TY_FUNCTION; k++)
        for (int d = 0; d <= DIM_CUBE; d++) {
            t->objects[k][d].kind = (hfx_type_kind)k;
            t->objects[k][d].base = B_NONE;
            t->objects[k][d].dim = (hfx_dim)d;
        }
    return t;
}

const hfx_type *hfx_type_void(hfx_types *t) { return &t->void_type; }
const hfx_type *hfx_type_scalar(hfx_types *t, hfx_base b) { return &t->numeric[b][1][1]; }

const hfx_type *hfx_type_vector(hfx_types *t, hfx_base b, unsigned n) {
    if (n < 1 || n > 4) return NULL;
    return &t->vectors[b][n];
}

const hfx_type *hfx_type_matrix(hfx_types *t, hfx_base b, unsigned rows, unsigned cols) {
    if (rows < 1 || rows > 4 || cols < 1 || cols > 4) return NULL;
    return &t->numeric[b][rows][cols];
}

const hfx_type *hfx_type_numeric(hfx_types *t, hfx_type_kind k, hfx_base b, unsigned rows, unsigned cols) {
    switch (k) {
    case TY_SCALAR: return hfx_type_scalar(t, b);
    case TY_VECTOR: return hfx_type_vector(t, b, cols);
    case TY_MATRIX: return hfx_type_matrix(t, b, rows, cols);
    default: return NULL;
    }
}

const hfx_type *hfx_type_object(hfx_types *t, hfx_type_kind k, hfx_dim dim) { return &t->objects[k][dim]; }

const hfx_type *hfx_type_array(hfx_types *t, const hfx_type *elem, uint32_t len) {
    hfx_type *ty = HFX_NEW(t->arena, hfx_type);
    ty->kind = TY_ARRAY;
    ty->base = elem->base;
    ty->elem = elem;
    ty->array_len = len;
    if (elem->kind == TY_ARRAY) t->nested_arrays = true;
    return ty;
}

bool hfx_types_nested_arrays(const hfx_types *t) { return t->nested_arrays; }

const hfx_type *hfx_type_struct(hfx_types *t, hfx_struct *st) {
    hfx_type *ty = HFX_NEW(t->arena, hfx_type);
    ty->kind = TY_STRUCT;
    ty->base = B_NONE;
    ty->st = st;
    return ty;
}

bool hfx_type_is_numeric(const hfx_type *ty) {
    return ty && (ty->kind == TY_SCALAR || ty->kind == TY_VECTOR || ty->kind == TY_MATRIX);
}

bool hfx_type_equal(const hfx_type *a, const hfx_type *b) {
    if (a == b) return true;
    if (!a || !b || a->kind != b->kind) return false;
    switch (a->kind) {
    case TY_ARRAY: return a->array_len == b->array_len && hfx_type_equal(a->elem, b->elem);
    case TY_STRUCT: return a->st == b->st;
    case TY_SCALAR: case TY_VECTOR: case TY_MATRIX:
        return a->base == b->base && a->rows == b->rows && a->cols == b->cols;
    case TY_TEXTURE: case TY_SAMPLER: return a->dim == b->dim;
    default: return true;
    }
}

unsigned hfx_type_components(const hfx_type *ty) {
    switch (ty->kind) {
    case TY_SCALAR: case TY_VECTOR: case TY_MATRIX: return (unsigned)ty->rows * ty->cols;
    case TY_ARRAY: return ty->array_len * hfx_type_components(ty->elem);
    case TY_STRUCT: {
        unsigned n = 0;
        for (uint32_t i = 0; i < ty->st->field_count; i++) n += hfx_type_components(ty->st->fields[i].type);
        return n;
    }
    default: return 0;
    }
}

const char *hfx_base_name(hfx_base b) {
    static const char *const names[] = {"bool", "int", "uint", "half", "float", "double", "min16float", "none"};
    return names[b];
}

const char *hfx_type_name(hfx_arena *a, const hfx_type *ty) {
    static const char *const dims[] = {"", "1D", "2D", "3D", "CUBE"};
    switch (ty->kind) {
    case TY_VOID: return "void";
    case TY_SCALAR: return hfx_base_name(ty->base);
    case TY_VECTOR: return hfx_arena_printf(a, "%s%u", hfx_base_name(ty->base), ty->cols);
    case TY_MATRIX: return hfx_arena_printf(a, "%s%ux%u", hfx_base_name(ty->base), ty->rows, ty->cols);
    case TY_ARRAY: return hfx_arena_printf(a, "%s[%u]", hfx_type_name(a, ty->elem), ty->array_len);
    case TY_STRUCT: return ty->st->name ? ty->st->name : "struct";
    case TY_TEXTURE: return hfx_arena_printf(a, "texture%s", dims[ty->dim]);
    case TY_SAMPLER: return hfx_arena_printf(a, "sampler%s", dims[ty->dim]);
    case TY_STRING: return "string";
    case TY_VERTEXSHADER: return "vertexshader";
    case TY_PIXELSHADER: return "pixelshader";
    case TY_FUNCTION: return "function";
    }
    return "?";
}

hfx_ev_base hfx_base_ev(hfx_base b) {
    switch (b) {
    case B_BOOL: return HFX_EV_BOOL;
    case B_INT: return HFX_EV_INT;
    case B_UINT: return HFX_EV_UINT;
    default: return HFX_EV_FLOAT;
    }
}
