/* conv.c: HLSL's conversion rules (see conv.h). Shapes follow fxc for SM2/SM3: scalars splat
 * everywhere, vectors and matrices truncate (with a warning when implicit), never grow. */
#include "check/conv.h"

bool hfx_base_is_float(hfx_base b) {
    return b == B_HALF || b == B_FLOAT || b == B_DOUBLE || b == B_MIN16FLOAT;
}

static int base_rank(hfx_base b) {
    switch (b) {
    case B_BOOL: return 0;
    case B_INT: return 1;
    case B_UINT: return 2;
    case B_HALF: case B_MIN16FLOAT: return 3;
    case B_FLOAT: return 4;
    case B_DOUBLE: return 5;
    default: return -1;
    }
}

hfx_base hfx_base_common(hfx_base a, hfx_base b) {
    return base_rank(a) >= base_rank(b) ? a : b;
}

bool hfx_type_is_scalarlike(const hfx_type *ty) {
    return hfx_type_is_numeric(ty) && ty->rows == 1 && ty->cols == 1;
}

static hfx_conv_base classify_base(hfx_base from, hfx_base to) {
    if (from == to) return CONV_BASE_EXACT;
    if (from == B_BOOL || to == B_BOOL) return CONV_BASE_BOOL;
    if (hfx_base_is_float(from) && hfx_base_is_float(to)) return CONV_BASE_PROMOTE;
    if (!hfx_base_is_float(from) && !hfx_base_is_float(to)) return CONV_BASE_PROMOTE;
    return CONV_BASE_CONVERT;
}

static hfx_conv fail(void) {
    hfx_conv c = {false, false, CONV_SHAPE_EXACT, CONV_BASE_EXACT};
    return c;
}

static hfx_conv shape(hfx_conv_shape s, hfx_conv_base b) {
    hfx_conv c = {true, s == CONV_SHAPE_TRUNC, s, b};
    return c;
}

/* A vector or a 1xN / Nx1 matrix: something that reads as a row of components. */
static bool is_linear(const hfx_type *ty) {
    return ty->kind == TY_VECTOR || (ty->kind == TY_MATRIX && (ty->rows == 1 || ty->cols == 1));
}

static hfx_conv classify_numeric(const hfx_type *from, const hfx_type *to, bool explicit_cast) {
    hfx_conv_base b = classify_base(from->base, to->base);
    unsigned fc = (unsigned)from->rows * from->cols, tc = (unsigned)to->rows * to->cols;
    if (from->kind == to->kind && from->rows == to->rows && from->cols == to->cols)
        return shape(CONV_SHAPE_EXACT, b);
    if (fc == 1) return shape(tc == 1 ? CONV_SHAPE_RESHAPE : CONV_SHAPE_SPLAT, b);
    if (tc == 1) return shape(CONV_SHAPE_TRUNC, b);
    if (from->kind == TY_MATRIX && to->kind == TY_MATRIX) {
        if (to->rows <= from->rows && to->cols <= from->cols) return shape(CONV_SHAPE_TRUNC, b);
        if (explicit_cast && tc == fc) return shape(CONV_SHAPE_RESHAPE, b);
        if (explicit_cast && tc < fc) return shape(CONV_SHAPE_TRUNC, b);
        return fail();
    }
    /* vector <-> vector, vector <-> matrix */
    if (tc == fc && (is_linear(from) || is_linear(to))) return shape(CONV_SHAPE_RESHAPE, b);
    if (tc < fc && is_linear(from) && is_linear(to)) return shape(CONV_SHAPE_TRUNC, b);
    if (explicit_cast && tc == fc) return shape(CONV_SHAPE_RESHAPE, b); /* (float2x2)v4, (float4)m2x2 */
    return fail(); /* (float4)float4x4: a matrix and a vector convert only at the same size */
}

/* `(float[4])v`: a cast from a vector or matrix to an array of as many scalars, in order. */
static hfx_conv numeric_to_array(const hfx_type *from, const hfx_type *to) {
    const hfx_type *e = to->elem;
    if (!e || e->kind != TY_SCALAR || to->array_len != hfx_type_components(from)) return fail();
    return shape(CONV_SHAPE_RESHAPE, from->base == e->base ? CONV_BASE_EXACT : CONV_BASE_CONVERT);
}

/* The numeric leaves of ty in order (fields, elements), up to cap; false when an object is
 * among them or there are more. */
static bool leaves_of(const hfx_type *ty, const hfx_type **out, unsigned *n, unsigned cap) {
    if (hfx_type_is_numeric(ty)) {
        if (*n == cap) return false;
        out[(*n)++] = ty;
        return true;
    }
    if (ty->kind == TY_ARRAY) {
        for (uint32_t i = 0; i < ty->array_len; i++)
            if (!leaves_of(ty->elem, out, n, cap)) return false;
        return true;
    }
    if (ty->kind != TY_STRUCT) return false;
    for (uint32_t i = 0; i < ty->st->field_count; i++)
        if (!leaves_of(ty->st->fields[i].type, out, n, cap)) return false;
    return true;
}

/* `VS_OUT o = input;`: two struct (or array) types whose members are the same types in the
 * same order convert implicitly, as fxc lets them (a struct of another name, same layout). */
static bool componentwise_equal(const hfx_type *from, const hfx_type *to) {
    enum { CAP = 64 };
    const hfx_type *a[CAP], *b[CAP];
    unsigned na = 0, nb = 0;
    if (!leaves_of(from, a, &na, CAP) || !leaves_of(to, b, &nb, CAP) || na != nb || !na) return false;
    for (unsigned i = 0; i < na; i++)
        if (a[i] != b[i]) return false; /* numeric types are interned: pointer equality */
    return true;
}

hfx_conv hfx_conv_classify(const hfx_type *from, const hfx_type *to, bool explicit_cast) {
    if (!from || !to) return fail();
    if (hfx_type_is_numeric(from) && hfx_type_is_numeric(to)) return classify_numeric(from, to, explicit_cast);
    if (explicit_cast && hfx_type_is_numeric(from) && !hfx_type_is_scalarlike(from) && to->kind == TY_ARRAY)
        return numeric_to_array(from, to);
    if (from->kind != to->kind) return fail();
    switch (from->kind) {
    case TY_TEXTURE: case TY_SAMPLER:
        if (from->dim == to->dim) return shape(CONV_SHAPE_EXACT, CONV_BASE_EXACT);
        /* `sampler s` feeds tex2D's sampler2D; texture2D feeds a generic `texture` */
        if (from->dim == DIM_GENERIC || to->dim == DIM_GENERIC) return shape(CONV_SHAPE_EXACT, CONV_BASE_PROMOTE);
        return fail();
    case TY_STRING: case TY_VERTEXSHADER: case TY_PIXELSHADER:
        return shape(CONV_SHAPE_EXACT, CONV_BASE_EXACT);
    case TY_STRUCT: case TY_ARRAY:
        if (hfx_type_equal(from, to)) return shape(CONV_SHAPE_EXACT, CONV_BASE_EXACT);
        return from->kind == TY_STRUCT && componentwise_equal(from, to) ? shape(CONV_SHAPE_RESHAPE, CONV_BASE_EXACT) : fail();
    default:
        return fail();
    }
}

unsigned hfx_conv_cost(hfx_conv c) {
    return c.ok ? (unsigned)c.shape * 4u + (unsigned)c.base : ~0u;
}

const hfx_type *hfx_type_with_base(hfx_types *t, const hfx_type *ty, hfx_base base) {
    return hfx_type_numeric(t, ty->kind, base, ty->rows, ty->cols);
}

static unsigned min_u(unsigned a, unsigned b) { return a < b ? a : b; }

const hfx_type *hfx_common_shape(hfx_types *t, const hfx_type *a, const hfx_type *b, hfx_base base,
                                 bool *truncates) {
    *truncates = false;
    if (!hfx_type_is_numeric(a) || !hfx_type_is_numeric(b)) return NULL;
    bool sa = hfx_type_is_scalarlike(a), sb = hfx_type_is_scalarlike(b);
    if (sa && sb) {
        if (a->kind == b->kind) return hfx_type_with_base(t, a, base);
        return hfx_type_scalar(t, base);
    }
    if (sa) return hfx_type_with_base(t, b, base);
    if (sb) return hfx_type_with_base(t, a, base);
    if (a->kind == TY_MATRIX && b->kind == TY_MATRIX) {
        unsigned r = min_u(a->rows, b->rows), c = min_u(a->cols, b->cols);
        *truncates = r != a->rows || r != b->rows || c != a->cols || c != b->cols;
        return hfx_type_matrix(t, base, r, c);
    }
    if (!is_linear(a) || !is_linear(b)) return NULL;
    unsigned na = (unsigned)a->rows * a->cols, nb = (unsigned)b->rows * b->cols;
    unsigned n = min_u(na, nb);
    *truncates = na != nb;
    if (a->kind == TY_VECTOR || b->kind == TY_VECTOR) return hfx_type_vector(t, base, n);
    return hfx_type_numeric(t, TY_MATRIX, base, a->rows == 1 ? 1 : n, a->rows == 1 ? n : 1);
}
