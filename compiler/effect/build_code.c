/* build_code.c: a state value that reads parameters (`AlphaRef = (Ref * 255);`,
 * `CullMode = (Cull ? 2 : 1);`, `FillMode = (Modes[Index]);`) compiled to a common/eval_code
 * program in fx->exprs, which the runtime runs at Apply with the compiler's arithmetic.
 * Constant parts fold first; parameters become PARAM reads, static const arrays indexed by a
 * parameter become TABLEs (clamped as D3D9 clamps). Anything else is not compiled. */
#include <string.h>

#include "effect/build_int.h"
#include "eval_code.h"

enum { MAX_DEPTH = 64 };

typedef struct code {
    hfx_builder *b;
    const hfx_state_info *names;
    uint32_t start;
    bool ok;
} code;

static void emit(code *c, uint32_t w) {
    hfx_fx_effect *fx = c->b->fx;
    if (!c->ok || !HFX_BUILD_GROW(c->b, fx->exprs, fx->expr_words, c->b->expr_cap)) {
        c->ok = false;
        return;
    }
    fx->exprs[fx->expr_words++] = w;
}

/* Constant components as CONST: int when they all came from ints, else float. */
static void emit_const(code *c, const hfx_cvec *v) {
    hfx_ev_base base = v->integral ? HFX_EV_INT : HFX_EV_FLOAT;
    emit(c, hfx_evc_word(HFX_EVC_CONST, base, v->n));
    for (uint32_t i = 0; i < v->n; i++) emit(c, hfx_evc_bits(base, v->v[i]));
}

static bool fold(code *c, const hfx_expr *e) {
    hfx_cvec v = {0};
    bool folded = hfx_build_eval(c->b, e, &v, c->names) && v.n >= 1 && v.n <= HFX_EV_MAX_COMPONENTS;
    if (folded) emit_const(c, &v);
    hfx_cvec_free(&v);
    return folded;
}

static hfx_ev_base param_base(hfx_param_type t) {
    return t == HFX_TYPE_FLOAT ? HFX_EV_FLOAT : t == HFX_TYPE_BOOL ? HFX_EV_BOOL : HFX_EV_INT;
}

/* A numeric parameter (not an array, at most 16 words) read as a whole. */
static bool param(code *c, const hfx_expr *e) {
    uint32_t p = hfx_build_param_of(c->b, e);
    if (p == HFX_NONE) return false;
    const hfx_fx_param *fp = &c->b->fx->params[p];
    if (fp->elements || !hfx_fx_param_evaluable(fp)) return false;
    emit(c, hfx_evc_word(HFX_EVC_PARAM, param_base(fp->type), fp->words));
    emit(c, fp->offset);
    return true;
}

static void expr(code *c, const hfx_expr *e, int depth);

/* table[index] where table is a static const array: the index first, then its elements. */
static bool table(code *c, const hfx_expr *e, int depth) {
    const hfx_expr *t = e->args[0];
    const hfx_decl *d = t->kind == EX_IDENT ? t->sym : NULL;
    if (!d || d->kind != DECL_VAR || !(d->mods & MOD_CONST) || !d->init || !d->type || d->type->kind != TY_ARRAY ||
        !d->type->array_len)
        return false;
    hfx_cvec v = {0};
    uint32_t count = d->type->array_len;
    bool ok = hfx_build_eval(c->b, d->init, &v, NULL) && v.n % count == 0 && v.n / count >= 1 &&
              v.n / count <= HFX_EV_MAX_COMPONENTS;
    if (ok) {
        hfx_ev_base base = v.integral ? HFX_EV_INT : HFX_EV_FLOAT;
        expr(c, e->args[1], depth + 1);
        emit(c, hfx_evc_word(HFX_EVC_TABLE, base, v.n / count));
        emit(c, count);
        for (uint32_t i = 0; i < v.n; i++) emit(c, hfx_evc_bits(base, v.v[i]));
    }
    hfx_cvec_free(&v);
    return ok;
}

/* array[index] where array is a parameter array read with a non-constant index: ELEMENT. */
static bool element(code *c, const hfx_expr *e, int depth) {
    uint32_t p = hfx_build_param_of(c->b, e->args[0]);
    const hfx_fx_effect *fx = c->b->fx;
    if (p == HFX_NONE || !fx->params[p].elements || fx->params[p].first_child == HFX_NONE) return false;
    const hfx_fx_param *el = &fx->params[fx->params[p].first_child];
    if (!hfx_fx_param_evaluable(el)) return false;
    expr(c, e->args[1], depth + 1);
    emit(c, hfx_evc_word(HFX_EVC_ELEMENT, param_base(el->type), el->words));
    emit(c, el->offset);
    emit(c, fx->params[p].elements);
    emit(c, fx->params[p].words / fx->params[p].elements);
    return true;
}

static bool swizzle(code *c, const hfx_expr *e, int depth) {
    if (e->comp_count < 1 || e->comp_count > 4) return false;
    uint32_t comps = 0;
    for (uint32_t i = 0; i < e->comp_count; i++) comps |= (uint32_t)(e->comps[i] & 15u) << (4 * i);
    expr(c, e->args[0], depth + 1);
    emit(c, hfx_evc_word(HFX_EVC_SWIZZLE, e->comp_count, 0));
    emit(c, comps);
    return true;
}

static bool cast(code *c, const hfx_expr *e, int depth) {
    const hfx_type *ty = e->cast_type ? e->cast_type : e->type;
    if (e->arg_count != 1 || !ty || !hfx_type_is_numeric(ty)) return false;
    expr(c, e->args[0], depth + 1);
    emit(c, hfx_evc_word(HFX_EVC_CONVERT, hfx_base_ev(ty->base), (uint32_t)ty->rows * ty->cols));
    return true;
}

static bool call(code *c, const hfx_expr *e, int depth) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of(e->intrinsic);
    if (!info || info->fold == HFX_EV_FN_NONE || (int)e->arg_count != hfx_ev_fn_args(info->fold)) return false;
    for (uint32_t i = 0; i < e->arg_count; i++) expr(c, e->args[i], depth + 1);
    emit(c, hfx_evc_word(HFX_EVC_CALL, (uint32_t)info->fold, 0));
    return true;
}

static bool operation(code *c, const hfx_expr *e, int depth) {
    hfx_ev_op op;
    if (!hfx_op_ev(e->op, &op)) return false;
    for (uint32_t i = 0; i < e->arg_count; i++) expr(c, e->args[i], depth + 1);
    emit(c, hfx_evc_word(e->kind == EX_UNARY ? HFX_EVC_UNARY : HFX_EVC_BINARY, op, 0));
    return true;
}

static bool parts(code *c, const hfx_expr *e, int depth) {
    switch (e->kind) {
    case EX_IDENT: case EX_STATE_REF: return param(c, e);
    case EX_INDEX: return e->arg_count == 2 && (param(c, e) || table(c, e, depth) || element(c, e, depth));
    case EX_UNARY: return e->arg_count == 1 && operation(c, e, depth);
    case EX_BINARY: return e->arg_count == 2 && operation(c, e, depth);
    case EX_SWIZZLE: return e->arg_count == 1 && swizzle(c, e, depth);
    case EX_CAST: case EX_CONSTRUCT: return cast(c, e, depth);
    case EX_CALL: return call(c, e, depth);
    case EX_TERNARY:
        if (e->arg_count != 3) return false;
        expr(c, e->args[1], depth + 1);
        expr(c, e->args[2], depth + 1);
        expr(c, e->args[0], depth + 1);
        emit(c, hfx_evc_word(HFX_EVC_SELECT, 0, 0));
        return true;
    default: return false;
    }
}

static void expr(code *c, const hfx_expr *e, int depth) {
    if (!c->ok) return;
    if (!e || depth > MAX_DEPTH) c->ok = false;
    else if (!fold(c, e) && !parts(c, e, depth)) c->ok = false;
}

/* The program of e, then (clamp > 0) a table 0 .. clamp - 1 that clamps it into an array. */
static bool compile(hfx_builder *b, const hfx_expr *e, const hfx_state_info *names, uint32_t clamp, uint32_t *first,
                    uint32_t *words) {
    hfx_fx_effect *fx = b->fx;
    code c = {b, names, fx->expr_words, true};
    expr(&c, e, 0);
    if (clamp) {
        emit(&c, hfx_evc_word(HFX_EVC_TABLE, HFX_EV_INT, 1));
        emit(&c, clamp);
        for (uint32_t i = 0; i < clamp; i++) emit(&c, i);
    }
    uint32_t n = fx->expr_words - c.start;
    if (c.ok && hfx_evc_validate(fx->exprs + c.start, n, fx->value_words, NULL, 0) == 0) {
        *first = c.start;
        *words = n;
        return true;
    }
    fx->expr_words = c.start; /* nothing of a program that could not be made */
    return false;
}

bool hfx_build_code(hfx_builder *b, const hfx_expr *e, const hfx_state_info *names, uint32_t *first, uint32_t *words) {
    return compile(b, e, names, 0, first, words);
}

bool hfx_build_selector(hfx_builder *b, const hfx_expr *index, uint32_t count, uint32_t *first, uint32_t *words) {
    return count && compile(b, index, NULL, count, first, words);
}
