/* build_values.c: constant values of parameter defaults, annotations and state values. fxc
 * folds these at compile time; anything it cannot fold is not a literal expression. The value
 * is built as IR and folded by ir/lower/fold.c (the folder shader code uses too, on common/eval's
 * arithmetic); this file keeps the components, which may be more than a vector's (arrays,
 * structs), and stores them as value words. */
#include <string.h>

#include "effect/build_int.h"

/* The components live in the arena (nothing lost if an allocation failure escapes). */
void hfx_cvec_free(hfx_cvec *c) { memset(c, 0, sizeof *c); }

static bool push(hfx_builder *b, hfx_cvec *c, double v) {
    if (!HFX_ARENA_GROW(b->arena, c->v, c->n, c->cap, 8)) return !(b->failed_alloc = true);
    c->v[c->n++] = v;
    return true;
}

static bool is_integral_base(hfx_base base) { return base == B_BOOL || base == B_INT || base == B_UINT; }

/* The evaluator's base of a component list: ints (and bools) compute as int, the rest as float. */
static hfx_ev_base base_of(const hfx_cvec *c) { return c->integral ? HFX_EV_INT : HFX_EV_FLOAT; }

/* The components of a folded value in order: a constant's, or those of a constructor of
 * constants (an array or struct, which no one constant holds); false for anything else. */
static bool components(hfx_builder *b, const ir_expr *e, hfx_cvec *out) {
    if (e->kind == IE_CONSTRUCT && !hfx_type_is_numeric(e->type)) {
        for (uint32_t i = 0; i < e->n; i++)
            if (!components(b, e->a[i], out)) return false;
        return true;
    }
    if (!hfx_ir_is_const(e) || !hfx_type_is_numeric(e->type)) return false;
    out->integral = out->integral && is_integral_base(e->type->base);
    for (unsigned i = 0; i < hfx_type_components(e->type); i++)
        if (!push(b, out, e->cval[i])) return false;
    return true;
}

/* The value is built as IR and folded by ir/lower/fold.c, the one folder of constant
 * expressions (shader code's too); what is left is a constant or it is no literal. */
bool hfx_build_eval(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names) {
    out->n = 0;
    out->integral = true;
    ir_ctx c = {b->arena, b->diags, b->types, b->ast, b->fx};
    ir_value_src src = {names, NULL, NULL};
    ir_expr *v = e ? hfx_ir_build_value(&c, e, &src) : NULL;
    if (!v) return false;
    hfx_ir_fold_value(&c, &v);
    return components(b, v, out) && out->n > 0;
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
