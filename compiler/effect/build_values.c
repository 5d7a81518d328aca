/* build_values.c: constant evaluation for parameter defaults, annotations and state values.
 * fxc folds these at compile time; anything it cannot fold is not a literal expression. The
 * arithmetic is common/eval's (Direct3D's rules); this file walks the tree and keeps the
 * components, which may be more than a vector's (arrays, structs). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect/build_int.h"

enum { MAX_DEPTH = 64 };

/* The components live in the arena (nothing lost if an allocation failure escapes). */
void hfx_cvec_free(hfx_cvec *c) { memset(c, 0, sizeof *c); }

static bool push(hfx_builder *b, hfx_cvec *c, double v) {
    if (!HFX_ARENA_GROW(b->arena, c->v, c->n, c->cap, 8)) return !(b->failed_alloc = true);
    c->v[c->n++] = v;
    return true;
}

static bool append(hfx_builder *b, hfx_cvec *dst, const hfx_cvec *src) {
    for (uint32_t i = 0; i < src->n; i++)
        if (!push(b, dst, src->v[i])) return false;
    dst->integral = dst->integral && src->integral;
    return true;
}

static bool is_integral_base(hfx_base base) { return base == B_BOOL || base == B_INT || base == B_UINT; }

/* The evaluator's base of a component list: ints (and bools) compute as int, the rest as float. */
static hfx_ev_base base_of(const hfx_cvec *c) { return c->integral ? HFX_EV_INT : HFX_EV_FLOAT; }

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
    for (uint32_t i = 0; i < out->n; i++) out->v[i] = hfx_ev_convert(base_of(out), hfx_base_ev(ty->base), out->v[i]);
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
    hfx_ev_op op;
    if (e->arg_count < 1 || !hfx_op_ev(e->op, &op) || !eval(b, e->args[0], out, names, depth + 1)) return false;
    hfx_ev_base base = base_of(out);
    for (uint32_t i = 0; i < out->n; i++)
        if (!hfx_ev_unary(op, base, out->v[i], &out->v[i])) return false;
    out->integral = hfx_ev_result_base(op, base) != HFX_EV_FLOAT;
    return true;
}

static bool binary(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    hfx_cvec l = {0}, r = {0};
    hfx_ev_op op;
    bool ok = e->arg_count == 2 && hfx_op_ev(e->op, &op) && eval(b, e->args[0], &l, names, depth + 1) &&
              eval(b, e->args[1], &r, names, depth + 1);
    uint32_t n = l.n > r.n ? l.n : r.n;
    ok = ok && n > 0 && fit(b, &l, n) && fit(b, &r, n);
    hfx_ev_base base = l.integral && r.integral ? HFX_EV_INT : HFX_EV_FLOAT;
    for (uint32_t i = 0; ok && i < n; i++) {
        double v;
        ok = hfx_ev_binary(op, base, l.v[i], r.v[i], &v) && push(b, out, v);
    }
    out->integral = ok && hfx_ev_result_base(op, base) != HFX_EV_FLOAT;
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

/* A component list as an evaluator value of base `base`; false past 16 components. */
static bool to_value(const hfx_cvec *c, hfx_ev_base base, hfx_ev_value *v) {
    if (!c->n || c->n > HFX_EV_MAX_COMPONENTS) return false;
    v->base = base;
    v->n = (uint8_t)c->n;
    for (uint32_t i = 0; i < c->n; i++) v->c[i] = hfx_ev_convert(base_of(c), base, c->v[i]);
    return true;
}

/* The arguments as one base: int when all are and the function computes on ints (abs, min,
 * max, clamp, sign, dot...), else float. */
static bool call_values(hfx_ev_fn fn, const hfx_cvec *args, unsigned n, hfx_ev_value *out) {
    hfx_ev_value v[3];
    bool integral = true;
    for (unsigned i = 0; i < n; i++) integral = integral && args[i].integral;
    for (int pass = integral ? 0 : 1; pass < 2; pass++) {
        hfx_ev_base base = pass == 0 ? HFX_EV_INT : HFX_EV_FLOAT;
        bool ok = true;
        for (unsigned i = 0; i < n; i++) ok = ok && to_value(&args[i], base, &v[i]);
        if (ok && hfx_ev_call(fn, v, n, out)) return true;
    }
    return false;
}

/* Intrinsics fxc folds in initializers, by their row of intrinsics.def. */
static bool call(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names, int depth) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of(e->intrinsic);
    if (!info || info->fold == HFX_EV_FN_NONE || e->arg_count > 3) return false;
    hfx_cvec args[3] = {{0}, {0}, {0}};
    hfx_ev_value r;
    bool ok = true;
    for (uint32_t i = 0; ok && i < e->arg_count; i++) ok = eval(b, e->args[i], &args[i], names, depth + 1);
    ok = ok && call_values(info->fold, args, e->arg_count, &r);
    for (uint32_t i = 0; ok && i < r.n; i++) ok = push(b, out, r.c[i]);
    out->integral = ok && r.base != HFX_EV_FLOAT;
    for (int i = 0; i < 3; i++) hfx_cvec_free(&args[i]);
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

static uint32_t word_of(double v, hfx_ev_base from, hfx_base base) {
    v = hfx_ev_convert(from, hfx_base_ev(base), v);
    if (base == B_UINT) return hfx_ev_uint(v);
    if (is_integral_base(base)) return (uint32_t)hfx_ev_int(v);
    float f = (float)v;
    uint32_t w;
    memcpy(&w, &f, sizeof w);
    return w;
}

static void store(const hfx_type *ty, const hfx_cvec *c, uint32_t *words, uint32_t *pos, uint32_t *w) {
    switch (ty->kind) {
    case TY_SCALAR: case TY_VECTOR: case TY_MATRIX:
        for (uint32_t i = 0; i < (uint32_t)ty->rows * ty->cols; i++, (*pos)++, (*w)++)
            words[*w] = word_of(*pos < c->n ? c->v[*pos] : 0.0, base_of(c), ty->base);
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
        for (uint32_t i = 0; i < n; i++) words[i] = word_of(c->v[0], base_of(c), ty->base);
        return;
    }
    store(ty, c, words, &pos, &w);
}
