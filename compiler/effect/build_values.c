/* build_values.c: constant evaluation for parameter defaults, annotations and state values.
 * fxc folds these at compile time; anything it cannot fold is not a literal expression. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect/build_int.h"

enum { MAX_DEPTH = 64 };

void hfx_cvec_free(hfx_cvec *c) {
    free(c->v);
    memset(c, 0, sizeof *c);
}

static bool push(hfx_builder *b, hfx_cvec *c, double v) {
    if (!HFX_BUILD_GROW(b, c->v, c->n, c->cap)) return false;
    c->v[c->n++] = v;
    return true;
}

static bool append(hfx_builder *b, hfx_cvec *dst, const hfx_cvec *src) {
    for (uint32_t i = 0; i < src->n; i++)
        if (!push(b, dst, src->v[i])) return false;
    dst->integral = dst->integral && src->integral;
    return true;
}

static int32_t to_i32(double v);

static bool is_integral_base(hfx_base base) { return base == B_BOOL || base == B_INT || base == B_UINT; }

/* Converts one component to a base type, as a cast does. */
static double convert(double v, hfx_base base) {
    switch (base) {
    case B_BOOL: return v != 0.0;
    case B_INT: return (double)to_i32(v);
    case B_UINT: return isfinite(v) && v > 0 ? (double)(uint32_t)fmin(trunc(v), 4294967295.0) : 0;
    default: return v;
    }
}

/* Resizes c to n components the way HLSL converts: a scalar splats, a longer list truncates. */
static bool fit(hfx_builder *b, hfx_cvec *c, uint32_t n) {
    if (c->n == 1 && n > 1) {
        double v = c->v[0];
        while (c->n < n)
            if (!push(b, c, v)) return false;
    }
    if (c->n > n) c->n = n;
    return c->n == n;
}

static bool eval(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth);

static bool eval_args(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    out->integral = true;
    for (uint32_t i = 0; i < e->arg_count; i++) {
        hfx_cvec c = {0};
        bool ok = eval(b, e->args[i], &c, names, depth + 1) && append(b, out, &c);
        hfx_cvec_free(&c);
        if (!ok) return false;
    }
    return true;
}

static bool eval_cast(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    const hfx_type *ty = e->cast_type ? e->cast_type : e->type;
    if (!eval_args(b, e, out, names, depth)) return false;
    if (!ty || !hfx_type_is_numeric(ty)) return ty == NULL;
    if (!fit(b, out, (uint32_t)ty->rows * ty->cols)) return false;
    for (uint32_t i = 0; i < out->n; i++) out->v[i] = convert(out->v[i], ty->base);
    out->integral = is_integral_base(ty->base);
    return true;
}

static bool eval_ident(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    int32_t named;
    if (names && e->name && hfx_state_value_lookup(names, e->name, &named) == 0) {
        out->integral = true;
        return push(b, out, named);
    }
    const hfx_decl *d = e->sym;
    /* Only constants fold: a static const global or local with a literal initializer. */
    if (!d || d->kind != DECL_VAR || !d->init || !(d->mods & MOD_CONST)) return false;
    return eval(b, d->init, out, names, depth + 1);
}

static bool unary(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    if (e->arg_count < 1 || !eval(b, e->args[0], out, names, depth + 1)) return false;
    for (uint32_t i = 0; i < out->n; i++) {
        double v = out->v[i];
        switch (e->op) {
        case OP_NEG: out->v[i] = -v; break;
        case OP_POS: break;
        case OP_NOT: out->v[i] = v == 0.0; out->integral = true; break;
        case OP_BITNOT: out->v[i] = (double)~to_i32(v); break;
        default: return false;
        }
    }
    return true;
}

static int32_t to_i32(double v) {
    if (!(v == v)) return 0;
    if (v >= 2147483647.0) return INT32_MAX;
    if (v <= -2147483648.0) return INT32_MIN;
    return (int32_t)v;
}

/* 32-bit integer arithmetic that wraps as the GPU does, never overflowing in C. */
static double integer_op(hfx_op op, double dx, double dy, bool *ok) {
    int32_t x = to_i32(dx), y = to_i32(dy);
    uint32_t ux = (uint32_t)x, uy = (uint32_t)y;
    switch (op) {
    case OP_ADD: return (double)(int32_t)(ux + uy);
    case OP_SUB: return (double)(int32_t)(ux - uy);
    case OP_MUL: return (double)(int32_t)(ux * uy);
    case OP_DIV:
        if (y == 0 || (x == INT32_MIN && y == -1)) { *ok = false; return 0; }
        return (double)(x / y);
    case OP_MOD:
        if (y == 0 || (x == INT32_MIN && y == -1)) { *ok = false; return 0; }
        return (double)(x % y);
    case OP_SHL: return (double)(int32_t)(ux << (uy & 31));
    case OP_SHR: return (double)(x < 0 ? (int32_t)~(~ux >> (uy & 31)) : (int32_t)(ux >> (uy & 31)));
    case OP_BITAND: return (double)(int32_t)(ux & uy);
    case OP_BITOR: return (double)(int32_t)(ux | uy);
    case OP_BITXOR: return (double)(int32_t)(ux ^ uy);
    default: *ok = false; return 0;
    }
}

static double float_op(hfx_op op, double x, double y, bool integral, bool *ok) {
    switch (op) {
    case OP_ADD: return x + y;
    case OP_SUB: return x - y;
    case OP_MUL: return x * y;
    case OP_DIV: return x / y;
    case OP_MOD: return fmod(x, y);
    case OP_LT: return x < y;
    case OP_GT: return x > y;
    case OP_LE: return x <= y;
    case OP_GE: return x >= y;
    case OP_EQ: return x == y;
    case OP_NE: return x != y;
    case OP_AND: return x != 0 && y != 0;
    case OP_OR: return x != 0 || y != 0;
    default:
        if (integral) return integer_op(op, x, y, ok);
        *ok = false;
        return 0;
    }
}

static bool binary(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    hfx_cvec l = {0}, r = {0};
    bool ok = e->arg_count == 2 && eval(b, e->args[0], &l, names, depth + 1) && eval(b, e->args[1], &r, names, depth + 1);
    uint32_t n = l.n > r.n ? l.n : r.n;
    ok = ok && n > 0 && fit(b, &l, n) && fit(b, &r, n);
    bool integral = l.integral && r.integral;
    bool compare = e->op >= OP_LT;
    for (uint32_t i = 0; ok && i < n; i++) {
        double v = integral && !compare && e->op != OP_AND && e->op != OP_OR
                       ? integer_op(e->op, l.v[i], r.v[i], &ok)
                       : float_op(e->op, l.v[i], r.v[i], integral, &ok);
        ok = ok && push(b, out, v);
    }
    out->integral = integral || compare;
    hfx_cvec_free(&l);
    hfx_cvec_free(&r);
    return ok;
}

static bool swizzle(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    hfx_cvec src = {0};
    bool ok = e->arg_count == 1 && eval(b, e->args[0], &src, names, depth + 1);
    for (uint32_t i = 0; ok && i < e->comp_count; i++) {
        ok = e->comps[i] < src.n && push(b, out, src.v[e->comps[i]]);
    }
    out->integral = src.integral;
    hfx_cvec_free(&src);
    return ok;
}

/* Intrinsics fxc folds in initializers: componentwise math on constants. */
static double unary_math(const char *n, double x, bool *ok) {
    static const struct { const char *name; double (*fn)(double); } table[] = {
        {"abs", fabs}, {"sqrt", sqrt}, {"sin", sin}, {"cos", cos}, {"tan", tan}, {"asin", asin},
        {"acos", acos}, {"atan", atan}, {"exp", exp}, {"exp2", exp2}, {"log", log}, {"log2", log2},
        {"log10", log10}, {"floor", floor}, {"ceil", ceil}, {"round", round}, {"trunc", trunc},
        {"sinh", sinh}, {"cosh", cosh}, {"tanh", tanh}};
    for (size_t i = 0; i < sizeof table / sizeof *table; i++)
        if (strcmp(n, table[i].name) == 0) return table[i].fn(x);
    if (strcmp(n, "rsqrt") == 0) return 1.0 / sqrt(x);
    if (strcmp(n, "frac") == 0) return x - floor(x);
    if (strcmp(n, "saturate") == 0) return x < 0 ? 0 : x > 1 ? 1 : x;
    if (strcmp(n, "radians") == 0) return x * (3.14159265358979323846 / 180.0);
    if (strcmp(n, "degrees") == 0) return x * (180.0 / 3.14159265358979323846);
    if (strcmp(n, "sign") == 0) return (x > 0) - (x < 0);
    *ok = false;
    return 0;
}

static double binary_math(const char *n, double x, double y, bool *ok) {
    if (strcmp(n, "pow") == 0) return pow(x, y);
    if (strcmp(n, "min") == 0) return x < y ? x : y;
    if (strcmp(n, "max") == 0) return x > y ? x : y;
    if (strcmp(n, "fmod") == 0) return fmod(x, y);
    if (strcmp(n, "atan2") == 0) return atan2(x, y);
    if (strcmp(n, "step") == 0) return y >= x;
    *ok = false;
    return 0;
}

static bool call(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    if (e->intrinsic < 0 || !e->name || e->arg_count < 1 || e->arg_count > 2) return false;
    hfx_cvec x = {0}, y = {0};
    bool ok = eval(b, e->args[0], &x, names, depth + 1);
    if (ok && e->arg_count == 2) {
        ok = eval(b, e->args[1], &y, names, depth + 1);
        uint32_t n = x.n > y.n ? x.n : y.n;
        ok = ok && fit(b, &x, n) && fit(b, &y, n);
    }
    for (uint32_t i = 0; ok && i < x.n; i++) {
        double v = e->arg_count == 1 ? unary_math(e->name, x.v[i], &ok) : binary_math(e->name, x.v[i], y.v[i], &ok);
        ok = ok && push(b, out, v);
    }
    const hfx_type *ty = e->type;
    out->integral = ty && hfx_type_is_numeric(ty) && is_integral_base(ty->base);
    hfx_cvec_free(&x);
    hfx_cvec_free(&y);
    return ok;
}

static bool eval(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    if (!e || depth > MAX_DEPTH) return false;
    switch (e->kind) {
    case EX_INT: case EX_BOOL:
        out->integral = true;
        return push(b, out, (double)e->ival);
    case EX_FLOAT:
        out->integral = false;
        return push(b, out, e->fval);
    case EX_IDENT: return eval_ident(b, e, out, names, depth);
    case EX_UNARY: return unary(b, e, out, names, depth);
    case EX_BINARY: return binary(b, e, out, names, depth);
    case EX_CAST: case EX_CONSTRUCT: return eval_cast(b, e, out, names, depth);
    case EX_INIT_LIST: return eval_args(b, e, out, names, depth);
    case EX_SWIZZLE: return swizzle(b, e, out, names, depth);
    case EX_CALL: return call(b, e, out, names, depth);
    case EX_COMMA: return e->arg_count == 2 && eval(b, e->args[1], out, names, depth + 1);
    case EX_TERNARY: {
        hfx_cvec c = {0};
        bool ok = e->arg_count == 3 && eval(b, e->args[0], &c, names, depth + 1) && c.n == 1;
        const hfx_expr *pick = ok ? e->args[c.v[0] != 0 ? 1 : 2] : NULL;
        hfx_cvec_free(&c);
        return ok && eval(b, pick, out, names, depth + 1);
    }
    default: return false;
    }
}

bool hfx_build_eval(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names) {
    out->n = 0;
    out->integral = true;
    return eval(b, e, out, names, 0) && out->n > 0;
}

/* --- storing into value words ------------------------------------------------------------- */

static uint32_t word_of(double v, hfx_base base) {
    if (base == B_UINT) return (uint32_t)convert(v, B_UINT);
    if (is_integral_base(base)) return (uint32_t)to_i32(convert(v, base));
    float f = (float)v;
    uint32_t w;
    memcpy(&w, &f, sizeof w);
    return w;
}

static void store(const hfx_type *ty, const hfx_cvec *c, uint32_t *words, uint32_t *pos, uint32_t *w) {
    switch (ty->kind) {
    case TY_SCALAR: case TY_VECTOR: case TY_MATRIX:
        for (uint32_t i = 0; i < (uint32_t)ty->rows * ty->cols; i++, (*pos)++, (*w)++)
            words[*w] = word_of(*pos < c->n ? c->v[*pos] : 0.0, ty->base);
        break;
    case TY_ARRAY:
        for (uint32_t i = 0; ty->elem && i < ty->array_len; i++) store(ty->elem, c, words, pos, w);
        break;
    case TY_STRUCT:
        for (uint32_t i = 0; ty->st && i < ty->st->field_count; i++) store(ty->st->fields[i].type, c, words, pos, w);
        break;
    default:
        break;
    }
}

void hfx_build_store(const hfx_type *ty, const hfx_cvec *c, uint32_t *words) {
    uint32_t pos = 0, w = 0;
    /* `float4 c = 0.5;` and `float ks = {0.05F};` both fill every component. */
    if (c->n == 1 && hfx_type_is_numeric(ty)) {
        uint32_t n = (uint32_t)ty->rows * ty->cols;
        for (uint32_t i = 0; i < n; i++) words[i] = word_of(c->v[0], ty->base);
        return;
    }
    store(ty, c, words, &pos, &w);
}
