/* check_expr.c: expressions: names, operators, swizzles, indexing, casts and the implicit
 * conversions between them. An erroneous expression gets the error type (c->err) and every
 * operation on it stays quiet, so one mistake gives one message. */
#include <string.h>

#include "check/check_ctx.h"

bool hfx_ck_is_err(const check_ctx *c, const hfx_type *t) { return !t || t == c->err; }

const char *hfx_ck_type_name(check_ctx *c, const hfx_type *t) { return hfx_type_name(c->arena, t); }

hfx_loc hfx_ck_start(const hfx_expr *e) {
    while (e) {
        switch (e->kind) {
        case EX_BINARY: case EX_ASSIGN: case EX_TERNARY: case EX_COMMA: case EX_INDEX: case EX_MEMBER:
        case EX_SWIZZLE: case EX_FIELD: case EX_METHOD:
            if (e->arg_count && e->args[0]) { e = e->args[0]; continue; }
            return e->loc;
        case EX_UNARY:
            if ((e->op == OP_POSTINC || e->op == OP_POSTDEC) && e->args[0]) { e = e->args[0]; continue; }
            return e->loc;
        case EX_CAST:
            if (e->implicit && e->args[0]) { e = e->args[0]; continue; }
            return e->loc;
        default:
            return e->loc;
        }
    }
    return (hfx_loc){0, 0, 0};
}

static const hfx_type *set_type(hfx_expr *e, const hfx_type *t) {
    e->type = t;
    return t;
}

static const hfx_type *fail(check_ctx *c, hfx_expr *e) { return set_type(e, c->err); }

hfx_expr *hfx_ck_implicit_cast(check_ctx *c, hfx_expr *e, const hfx_type *to) {
    if (!e || hfx_type_equal(e->type, to) || hfx_ck_is_err(c, e->type)) return e;
    /* objects pass as they are: a generic `sampler` feeds tex2D's sampler2D */
    if (e->type->kind == to->kind && (to->kind == TY_SAMPLER || to->kind == TY_TEXTURE)) return e;
    hfx_expr *cast = HFX_NEW(c->arena, hfx_expr);
    if (!cast) { c->oom = true; return e; }
    cast->kind = EX_CAST;
    cast->loc = e->loc;
    cast->type = to;
    cast->cast_type = to;
    cast->implicit = true;
    cast->intrinsic = -1;
    cast->args = HFX_NEW_ARRAY(c->arena, hfx_expr *, 1);
    if (!cast->args) { c->oom = true; return e; }
    cast->args[0] = e;
    cast->arg_count = 1;
    return cast;
}

hfx_expr *hfx_ck_convert_arg(check_ctx *c, hfx_expr *e, const hfx_type *to, bool warn, const hfx_expr *call) {
    if (!e || hfx_ck_is_err(c, e->type) || hfx_ck_is_err(c, to)) return e;
    hfx_conv conv = hfx_conv_classify(e->type, to, false);
    if (!conv.ok) {
        hfx_error(c->diags, hfx_ck_start(e), X_TYPE_MISMATCH, "cannot implicitly convert from '%s' to '%s'",
                  hfx_ck_type_name(c, e->type), hfx_ck_type_name(c, to));
        e->type = c->err;
        return e;
    }
    if (conv.truncates && warn) {
        /* fxc names the function and points at the call for a truncated argument */
        if (call)
            hfx_warning(c->diags, call->loc, X_IMPLICIT_TRUNCATION, "'%s': implicit truncation of vector type",
                        call->name ? call->name : "");
        else
            hfx_warning(c->diags, hfx_ck_start(e), X_IMPLICIT_TRUNCATION, "implicit truncation of vector type");
    }
    return hfx_ck_implicit_cast(c, e, to);
}

hfx_expr *hfx_ck_convert(check_ctx *c, hfx_expr *e, const hfx_type *to, bool warn) {
    return hfx_ck_convert_arg(c, e, to, warn, NULL);
}

void hfx_ck_cond(check_ctx *c, hfx_expr **pe, const char *what) {
    const hfx_type *t = hfx_ck_expr(c, *pe);
    if (hfx_ck_is_err(c, t)) return;
    if (!hfx_type_is_scalarlike(t)) {
        hfx_error(c->diags, hfx_ck_start(*pe), X_NO_IF_SCALAR, "%s statement conditional expressions must evaluate to a scalar", what);
        (*pe)->type = c->err;
        return;
    }
    *pe = hfx_ck_convert(c, *pe, hfx_type_scalar(c->types, B_BOOL), false);
}

/* ---- l-values ---- */

static bool swizzle_repeats(const hfx_expr *e) {
    for (unsigned i = 0; i < e->comp_count; i++)
        for (unsigned j = 0; j < i; j++)
            if (e->comps[i] == e->comps[j]) return true;
    return false;
}

bool hfx_ck_lvalue(check_ctx *c, hfx_expr *e) {
    hfx_expr *root = e;
    bool ok = true;
    while (root) {
        if (root->kind == EX_SWIZZLE) {
            if (swizzle_repeats(root)) ok = false;
            root = root->args[0];
        } else if (root->kind == EX_FIELD || root->kind == EX_INDEX) {
            root = root->args[0];
        } else {
            break;
        }
    }
    if (hfx_ck_is_err(c, e->type)) return false;
    if (!root || root->kind != EX_IDENT || !root->sym) ok = false;
    else if (root->sym->mods & MOD_CONST) ok = false;
    if (!ok) {
        hfx_error(c->diags, hfx_ck_start(e), X_NOT_LVALUE, "l-value specifies const object");
        return false;
    }
    if (root->sym->is_global) root->sym->assigned = true;
    return true;
}

/* ---- names ---- */

static const hfx_type *check_ident(check_ctx *c, hfx_expr *e) {
    hfx_decl *d = hfx_ck_lookup(c, e->name);
    if (d && (d->kind == DECL_VAR || d->kind == DECL_PARAM)) {
        e->sym = d;
        return set_type(e, d->type);
    }
    if (c->in_state) return set_type(e, hfx_type_void(c->types)); /* CLAMP, None, SrcAlpha... */
    hfx_error(c->diags, e->loc, X_UNDECLARED, "undeclared identifier '%s'", e->name);
    return fail(c, e);
}

static const hfx_type *check_state_ref(check_ctx *c, hfx_expr *e) {
    hfx_decl *d = hfx_ck_lookup(c, e->name);
    if (!d || (d->kind != DECL_VAR && d->kind != DECL_PARAM)) {
        hfx_error(c->diags, e->loc, X_UNDECLARED, "undeclared identifier '%s'", e->name);
        return fail(c, e);
    }
    e->sym = d;
    return set_type(e, d->type);
}

/* ---- operators ---- */

static bool is_arith(hfx_op op) { return op >= OP_ADD && op <= OP_MOD; }
static bool is_bitwise(hfx_op op) { return op >= OP_SHL && op <= OP_BITXOR; }
static bool is_compare(hfx_op op) { return op >= OP_LT && op <= OP_NE; }

/* An operand that is a state constant (in a state value): the builder folds `Red | Green`. */
static bool state_operand(const check_ctx *c, const hfx_type *t) {
    return c->in_state && t && t->kind == TY_VOID && t != c->err;
}

static bool require_numeric(check_ctx *c, hfx_expr *operand) {
    if (hfx_type_is_numeric(operand->type)) return true;
    hfx_error(c->diags, hfx_ck_start(operand), X_SCALAR_EXPECTED, "scalar, vector, or matrix expected");
    return false;
}

/* int with uint where neither is a literal (literals take the other side's type quietly). */
static bool signed_unsigned_mix(const hfx_expr *a, const hfx_expr *b) {
    hfx_base x = a->type->base, y = b->type->base;
    bool mix = (x == B_INT && y == B_UINT) || (x == B_UINT && y == B_INT);
    return mix && a->kind != EX_INT && b->kind != EX_INT;
}

/* The operand type both sides of a binary operator convert to; NULL after an error. */
static const hfx_type *binary_operand_type(check_ctx *c, hfx_expr *e, hfx_op op, hfx_expr *a, hfx_expr *b) {
    if (!require_numeric(c, a) || !require_numeric(c, b)) return NULL;
    hfx_base base = hfx_base_common(a->type->base, b->type->base);
    if (op == OP_AND || op == OP_OR) base = B_BOOL;
    else if (is_bitwise(op)) {
        if (hfx_base_is_float(base)) {
            hfx_error(c->diags, hfx_ck_start(e), X_INT_REQUIRED, "int or unsigned int type required");
            return NULL;
        }
        if (base == B_BOOL) base = B_INT;
    } else if (base == B_BOOL && is_arith(op)) {
        base = B_INT;
    }
    bool trunc = false;
    const hfx_type *t = hfx_common_shape(c->types, a->type, b->type, base, &trunc);
    if (!t) {
        hfx_error(c->diags, hfx_ck_start(e), X_TYPE_MISMATCH_OP, "type mismatch");
        return NULL;
    }
    if (trunc) hfx_warning(c->diags, hfx_ck_start(e), X_IMPLICIT_TRUNCATION, "implicit truncation of vector type");
    if (signed_unsigned_mix(a, b) && op != OP_SHL && op != OP_SHR && op != OP_AND && op != OP_OR)
        hfx_warning(c->diags, hfx_ck_start(e), X_SIGNED_UNSIGNED, "signed/unsigned mismatch, unsigned assumed");
    return t;
}

static const hfx_type *check_binary(check_ctx *c, hfx_expr *e) {
    const hfx_type *ta = hfx_ck_expr(c, e->args[0]), *tb = hfx_ck_expr(c, e->args[1]);
    if (hfx_ck_is_err(c, ta) || hfx_ck_is_err(c, tb)) return fail(c, e);
    if (state_operand(c, ta) || state_operand(c, tb)) return set_type(e, hfx_type_void(c->types));
    const hfx_type *t = binary_operand_type(c, e, e->op, e->args[0], e->args[1]);
    if (!t) return fail(c, e);
    e->args[0] = hfx_ck_implicit_cast(c, e->args[0], t);
    e->args[1] = hfx_ck_implicit_cast(c, e->args[1], t);
    if (is_compare(e->op)) return set_type(e, hfx_type_with_base(c->types, t, B_BOOL));
    return set_type(e, t);
}

static const hfx_type *check_unary(check_ctx *c, hfx_expr *e) {
    const hfx_type *t = hfx_ck_expr(c, e->args[0]);
    if (hfx_ck_is_err(c, t)) return fail(c, e);
    if (state_operand(c, t)) return set_type(e, t);
    if (!require_numeric(c, e->args[0])) return fail(c, e);
    switch (e->op) {
    case OP_NOT:
        t = hfx_type_with_base(c->types, t, B_BOOL);
        break;
    case OP_BITNOT:
        if (hfx_base_is_float(t->base)) {
            hfx_error(c->diags, hfx_ck_start(e), X_INT_REQUIRED, "int or unsigned int type required");
            return fail(c, e);
        }
        if (t->base == B_BOOL) t = hfx_type_with_base(c->types, t, B_INT);
        break;
    case OP_NEG: case OP_POS:
        if (t->base == B_BOOL) t = hfx_type_with_base(c->types, t, B_INT);
        break;
    default: /* ++ and -- */
        if (!hfx_ck_lvalue(c, e->args[0])) return fail(c, e);
        return set_type(e, t);
    }
    e->args[0] = hfx_ck_implicit_cast(c, e->args[0], t);
    return set_type(e, t);
}

/* `float4(dxSize, dx) = ddx(...);`: fxc writes each component back to the constructor's
 * arguments (DirectX SDK samples do this); every argument must be a vector or scalar l-value. */
static bool constructor_lvalue(check_ctx *c, hfx_expr *e) {
    bool ok = e->type && e->type->kind == TY_VECTOR;
    for (uint32_t i = 0; ok && i < e->arg_count; i++) {
        const hfx_type *t = e->args[i]->type;
        ok = t && (t->kind == TY_VECTOR || t->kind == TY_SCALAR) && hfx_ck_lvalue(c, e->args[i]);
    }
    if (!ok && e->type && e->type->kind != TY_VECTOR)
        hfx_error(c->diags, hfx_ck_start(e), X_NOT_LVALUE, "l-value specifies const object");
    return ok;
}

static const hfx_type *check_assign(check_ctx *c, hfx_expr *e) {
    const hfx_type *lt = hfx_ck_expr(c, e->args[0]), *rt = hfx_ck_expr(c, e->args[1]);
    if (hfx_ck_is_err(c, lt)) return fail(c, e);
    bool lv = e->args[0]->kind == EX_CONSTRUCT && e->op == OP_NONE ? constructor_lvalue(c, e->args[0])
                                                                    : hfx_ck_lvalue(c, e->args[0]);
    if (hfx_ck_is_err(c, rt)) return fail(c, e);
    if (e->op != OP_NONE) {
        if (!binary_operand_type(c, e, e->op, e->args[0], e->args[1])) return fail(c, e);
        e->args[1] = hfx_ck_convert(c, e->args[1], lt, false);
    } else {
        e->args[1] = hfx_ck_convert(c, e->args[1], lt, true);
    }
    if (!lv || hfx_ck_is_err(c, e->args[1]->type)) return fail(c, e);
    return set_type(e, lt);
}

static const hfx_type *check_ternary(check_ctx *c, hfx_expr *e) {
    const hfx_type *tc = hfx_ck_expr(c, e->args[0]);
    const hfx_type *ta = hfx_ck_expr(c, e->args[1]), *tb = hfx_ck_expr(c, e->args[2]);
    if (hfx_ck_is_err(c, tc) || hfx_ck_is_err(c, ta) || hfx_ck_is_err(c, tb)) return fail(c, e);
    if (!require_numeric(c, e->args[0])) return fail(c, e);
    const hfx_type *t;
    if (!hfx_type_is_numeric(ta) || !hfx_type_is_numeric(tb)) {
        if (!hfx_type_equal(ta, tb)) {
            hfx_error(c->diags, hfx_ck_start(e), X_TYPE_MISMATCH_OP, "type mismatch");
            return fail(c, e);
        }
        t = ta;
    } else {
        bool trunc = false, trunc2 = false;
        t = hfx_common_shape(c->types, ta, tb, hfx_base_common(ta->base, tb->base), &trunc);
        if (t && !hfx_type_is_scalarlike(tc)) t = hfx_common_shape(c->types, t, tc, t->base, &trunc2);
        if (!t) {
            hfx_error(c->diags, hfx_ck_start(e), X_TYPE_MISMATCH_OP, "type mismatch");
            return fail(c, e);
        }
        if (trunc || trunc2) hfx_warning(c->diags, hfx_ck_start(e), X_IMPLICIT_TRUNCATION, "implicit truncation of vector type");
    }
    const hfx_type *ct = hfx_type_is_scalarlike(tc) || !hfx_type_is_numeric(t) ? hfx_type_scalar(c->types, B_BOOL)
                                                                              : hfx_type_with_base(c->types, t, B_BOOL);
    e->args[0] = hfx_ck_implicit_cast(c, e->args[0], ct);
    e->args[1] = hfx_ck_implicit_cast(c, e->args[1], t);
    e->args[2] = hfx_ck_implicit_cast(c, e->args[2], t);
    return set_type(e, t);
}

/* ---- members, swizzles, indexing ---- */

static int swizzle_index(char ch, int *set) {
    static const char *const sets[2] = {"xyzw", "rgba"};
    for (int s = 0; s < 2; s++) {
        const char *p = strchr(sets[s], ch);
        if (ch && p) {
            if (*set >= 0 && *set != s) return -1;
            *set = s;
            return (int)(p - sets[s]);
        }
    }
    return -1;
}

/* .xyzw / .rgba on a scalar or vector; false when the name is no such swizzle. */
static bool vector_swizzle(hfx_expr *e, const char *name, unsigned count) {
    size_t n = strlen(name);
    int set = -1;
    if (n < 1 || n > 4) return false;
    for (size_t i = 0; i < n; i++) {
        int k = swizzle_index(name[i], &set);
        if (k < 0 || (unsigned)k >= count) return false;
        e->comps[i] = (uint8_t)k;
    }
    e->comp_count = (uint8_t)n;
    return true;
}

/* ._m00_m11 (zero-based) or ._11_22 (one-based), never mixed; false when invalid. */
static bool matrix_swizzle(hfx_expr *e, const char *name, unsigned rows, unsigned cols) {
    unsigned n = 0;
    int zero_based = -1;
    const char *p = name;
    while (*p) {
        if (*p != '_' || n == 4) return false;
        p++;
        int zb = *p == 'm';
        if (zb) p++;
        if (zero_based >= 0 && zero_based != zb) return false;
        zero_based = zb;
        if (p[0] < '0' || p[0] > '9' || p[1] < '0' || p[1] > '9') return false;
        unsigned r = (unsigned)(p[0] - '0'), col = (unsigned)(p[1] - '0');
        if (!zb) {
            if (r == 0 || col == 0) return false;
            r--, col--;
        }
        if (r >= rows || col >= cols) return false;
        e->comps[n++] = (uint8_t)(r * cols + col);
        p += 2;
    }
    if (!n) return false;
    e->comp_count = (uint8_t)n;
    return true;
}

static const hfx_type *check_member(check_ctx *c, hfx_expr *e) {
    const hfx_type *t = hfx_ck_expr(c, e->args[0]);
    if (hfx_ck_is_err(c, t)) return fail(c, e);
    if (t->kind == TY_STRUCT) {
        for (uint32_t i = 0; i < t->st->field_count; i++)
            if (t->st->fields[i].name && strcmp(t->st->fields[i].name, e->name) == 0) {
                e->kind = EX_FIELD;
                e->field = i;
                return set_type(e, t->st->fields[i].type);
            }
    } else if (t->kind == TY_SCALAR || t->kind == TY_VECTOR || t->kind == TY_MATRIX) {
        bool ok = t->kind == TY_MATRIX ? matrix_swizzle(e, e->name, t->rows, t->cols)
                                       : vector_swizzle(e, e->name, t->cols);
        if (ok) {
            e->kind = EX_SWIZZLE;
            return set_type(e, e->comp_count == 1 ? hfx_type_scalar(c->types, t->base)
                                                  : hfx_type_vector(c->types, t->base, e->comp_count));
        }
    }
    hfx_error(c->diags, hfx_ck_start(e), X_INVALID_SUBSCRIPT, "invalid subscript '%s'", e->name);
    return fail(c, e);
}

static const hfx_type *check_index(check_ctx *c, hfx_expr *e) {
    const hfx_type *t = hfx_ck_expr(c, e->args[0]), *it = hfx_ck_expr(c, e->args[1]);
    if (hfx_ck_is_err(c, t) || hfx_ck_is_err(c, it)) return fail(c, e);
    const hfx_type *result = NULL;
    uint32_t bound = 0;
    if (t->kind == TY_ARRAY) result = t->elem, bound = t->array_len;
    else if (t->kind == TY_VECTOR) result = hfx_type_scalar(c->types, t->base), bound = t->cols;
    else if (t->kind == TY_MATRIX) result = hfx_type_vector(c->types, t->base, t->cols), bound = t->rows;
    if (!result) {
        hfx_error(c->diags, hfx_ck_start(e), X_NOT_INDEXABLE,
                  "array, matrix, vector, or indexable object type expected in index expression");
        return fail(c, e);
    }
    if (c->in_state && state_operand(c, it)) return set_type(e, result);
    if (!hfx_type_is_scalarlike(it)) {
        hfx_error(c->diags, hfx_ck_start(e->args[1]), X_SCALAR_EXPECTED, "scalar, vector, or matrix expected");
        return fail(c, e);
    }
    int64_t k;
    if (hfx_ck_fold_int(c, e->args[1], &k) && bound && (k < 0 || k >= (int64_t)bound)) {
        hfx_error(c->diags, hfx_ck_start(e->args[1]), X_INDEX_RANGE, "array index out of bounds");
        return fail(c, e);
    }
    e->args[1] = hfx_ck_implicit_cast(c, e->args[1], hfx_type_scalar(c->types, it->base == B_UINT ? B_UINT : B_INT));
    return set_type(e, result);
}

/* Whether every leaf of ty is a number (a struct of floats, an array of vectors...). */
static bool numeric_leaves(const hfx_type *ty) {
    if (hfx_type_is_numeric(ty)) return true;
    if (ty->kind == TY_ARRAY) return numeric_leaves(ty->elem);
    if (ty->kind != TY_STRUCT) return false;
    for (uint32_t i = 0; i < ty->st->field_count; i++)
        if (!numeric_leaves(ty->st->fields[i].type)) return false;
    return true;
}

/* (S2)s1, (float4)s, (S)v, (float4)arr, (float2x2)arr, (float[2])v4: a cast to or from a struct
 * or an array takes the components in order when the source has at least as many (HLSL's
 * componentwise-compatible types). */
static bool restructure(const hfx_type *from, const hfx_type *to) {
    bool aggregate = from->kind == TY_STRUCT || to->kind == TY_STRUCT || from->kind == TY_ARRAY || to->kind == TY_ARRAY;
    if (!aggregate) return false;
    unsigned nf = hfx_type_components(from), nt = hfx_type_components(to);
    return numeric_leaves(from) && numeric_leaves(to) && nt > 0 && nf >= nt;
}

static const hfx_type *check_cast(check_ctx *c, hfx_expr *e) {
    const hfx_type *from = hfx_ck_expr(c, e->args[0]), *to = hfx_ck_resolve_type(c, e->cast_type, e->loc);
    if (hfx_ck_is_err(c, from)) return fail(c, e);
    e->cast_type = to;
    /* (VS_OUTPUT)0 and (float4[2])0: a scalar fills every component of a struct or array */
    bool fill = (to->kind == TY_STRUCT || to->kind == TY_ARRAY) && hfx_type_is_scalarlike(from);
    if (!fill && !restructure(from, to) && !hfx_conv_classify(from, to, true).ok) {
        hfx_error(c->diags, hfx_ck_start(e), X_TYPE_MISMATCH, "cannot convert from '%s' to '%s'",
                  hfx_ck_type_name(c, from), hfx_ck_type_name(c, to));
        return fail(c, e);
    }
    return set_type(e, to);
}

static const hfx_type *check_comma(check_ctx *c, hfx_expr *e) {
    const hfx_type *a = hfx_ck_expr(c, e->args[0]), *b = hfx_ck_expr(c, e->args[1]);
    if (hfx_ck_is_err(c, a) || hfx_ck_is_err(c, b)) return fail(c, e);
    return set_type(e, b);
}

static const hfx_type *check_sampler_state(check_ctx *c, hfx_expr *e) {
    for (uint32_t i = 0; i < e->state_count; i++) hfx_ck_state_value(c, &e->states[i]);
    return set_type(e, hfx_type_object(c->types, TY_SAMPLER, DIM_GENERIC));
}

const hfx_type *hfx_ck_expr(check_ctx *c, hfx_expr *e) {
    if (!e) return c->err;
    if (e->type) return e->type; /* shared subtrees (split initializers) are checked once */
    e->intrinsic = -1;
    switch (e->kind) {
    case EX_INT: return set_type(e, hfx_type_scalar(c->types, e->is_unsigned ? B_UINT : B_INT));
    case EX_FLOAT: return set_type(e, hfx_type_scalar(c->types, B_FLOAT));
    case EX_BOOL: return set_type(e, hfx_type_scalar(c->types, B_BOOL));
    case EX_STRING: return set_type(e, hfx_type_object(c->types, TY_STRING, DIM_GENERIC));
    case EX_IDENT: return check_ident(c, e);
    case EX_STATE_REF: return check_state_ref(c, e);
    case EX_UNARY: return check_unary(c, e);
    case EX_BINARY: return check_binary(c, e);
    case EX_ASSIGN: return check_assign(c, e);
    case EX_TERNARY: return check_ternary(c, e);
    case EX_COMMA: return check_comma(c, e);
    case EX_CALL: return hfx_ck_call(c, e);
    case EX_CONSTRUCT: return hfx_ck_construct(c, e);
    case EX_CAST: return check_cast(c, e);
    case EX_MEMBER: return check_member(c, e);
    case EX_INDEX: return check_index(c, e);
    case EX_COMPILE: return hfx_ck_compile(c, e);
    case EX_SAMPLER_STATE: return check_sampler_state(c, e);
    case EX_NULL: case EX_ASM: return set_type(e, hfx_type_void(c->types));
    case EX_METHOD:
        for (uint32_t i = 0; i < e->arg_count; i++) hfx_ck_expr(c, e->args[i]);
        hfx_error(c->diags, hfx_ck_start(e), X_UNSUPPORTED, "'%s': object methods are not supported in fx_2_0 effects", e->name);
        return fail(c, e);
    case EX_INIT_LIST:
        hfx_error(c->diags, e->loc, X_SYNTAX, "syntax error: unexpected token '{'");
        return fail(c, e);
    case EX_SWIZZLE: case EX_FIELD:
        return e->type ? e->type : fail(c, e);
    }
    return fail(c, e);
}
