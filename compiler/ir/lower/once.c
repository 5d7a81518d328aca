/* once.c: operands a lowering reads more than once are evaluated once, as HLSL evaluates them.
 *
 * - pow(x, n) with a constant integral exponent that fxc expands into multiplications (the rule
 *   is hfx_ir_pow_products') becomes those products: x * (x * x) for 3, keeping x's sign, and
 *   1 / products for a negative n, as fxc's SM2/SM3 code computes them.
 * - tex*Dlod / tex*Dbias / tex*Dproj read their coordinate's .w apart from the rest: a
 *   coordinate with side effects or work in it (`float4(uv, 0, k++)`, a call) is computed once.
 * An operand that is not a variable (or a component of one) or a constant goes into a local of
 * the function, hfx_onceN, assigned in a comma expression at the place of the call:
 * `(hfx_once0 = 1.0 - d, hfx_once0 * (hfx_once0 * hfx_once0))`, which keeps the order of
 * evaluation wherever the call stands (conditions, loop steps, short-circuit operands).
 * Static globals' initialisers have no function to hold a local: there a pure operand is read
 * again, and one with side effects is left to the printer's helper (glsl_intrin.c). */
#include <math.h>

#include "eval.h"
#include "ir/ir.h"

typedef struct once {
    ir_ctx *c;
    ir_func *fn;
    ir_stmt **decls; uint32_t decl_count, decl_cap;
    unsigned next;
} once;

bool hfx_ir_pow_products(const ir_expr *y, unsigned comps, int *n) {
    if (!y || y->kind != IE_CONST || !hfx_type_is_numeric(y->type)) return false;
    double k = y->cval[0];
    for (unsigned i = 1; i < hfx_type_components(y->type) && i < 16; i++)
        if (y->cval[i] != k) return false; /* a splat only */
    if (!(k >= -2147483647.0 && k <= 2147483647.0) || k != trunc(k)) return false;
    /* fxc: the highest set bit of |n| plus the set bits, less one, multiplications at most
     * 2c + 1 for a positive n and c + 1 for a negative one (c: the components) */
    uint32_t m = hfx_ev_uint(fabs(k));
    int bits = 0, top = -1;
    for (int i = 0; i < 32; i++)
        if (m >> i & 1) bits++, top = i;
    int limit = k < 0 ? (int)comps + 1 : 2 * (int)comps + 1;
    if (top + bits - 1 > limit) return false;
    *n = hfx_ev_int(k);
    return true;
}

/* A variable, a component or member of one, or a constant: reading it again costs nothing
 * and changes nothing. */
static bool repeatable(const ir_expr *x) {
    while (x->kind == IE_SWIZZLE || x->kind == IE_FIELD) x = x->a[0];
    return x->kind == IE_VAR || x->kind == IE_CONST;
}

static ir_var *new_temp(once *o, const hfx_type *t, hfx_loc loc) {
    ir_var *v = HFX_NEW(o->c->arena, ir_var);
    ir_stmt *d = hfx_ir_new_stmt(o->c, IS_DECL, loc);
    if (!HFX_ARENA_GROW(o->c->arena, o->decls, o->decl_count, o->decl_cap, 4)) return NULL;
    v->kind = IRV_LOCAL;
    v->name = v->glsl = hfx_arena_printf(o->c->arena, "hfx_once%u", o->next++);
    v->type = t;
    v->param = HFX_NONE;
    d->var = v;
    o->decls[o->decl_count++] = d;
    return v;
}

static ir_expr *var_ref(ir_ctx *c, ir_var *v, hfx_loc loc) {
    ir_expr *r = hfx_ir_new_expr(c, IE_VAR, v->type, loc, 0);
    r->var = v;
    return r;
}

/* *x read once: a temporary when it is not repeatable; *set gets `tmp = x` (else NULL). In a
 * static initialiser (no function to hold the local) a pure x is read again instead. */
static ir_expr *read_once(once *o, ir_expr *x, ir_expr **set) {
    *set = NULL;
    if (repeatable(x) || !hfx_type_is_numeric(x->type) || (!o->fn && !hfx_ir_has_side_effects(x))) return x;
    ir_var *t = new_temp(o, x->type, x->loc);
    if (!t) return x;
    *set = hfx_ir_new_expr(o->c, IE_ASSIGN, x->type, x->loc, 2);
    (*set)->op = OP_NONE;
    (*set)->a[0] = var_ref(o->c, t, x->loc);
    (*set)->a[1] = x;
    return var_ref(o->c, t, x->loc);
}

/* (set, value), or value alone. */
static ir_expr *after(ir_ctx *c, ir_expr *set, ir_expr *value) {
    if (!set) return value;
    ir_expr *e = hfx_ir_new_expr(c, IE_COMMA, value->type, value->loc, 2);
    e->a[0] = set;
    e->a[1] = value;
    return e;
}

/* x^|n| by squaring, as fxc multiplies: the squares x, x^2, x^4... of |n|'s set bits, the
 * lowest first, each times the product so far. A square that is squared again goes into a
 * local (its assignment joins *sets), so the tree stays small. */
static ir_expr *products(once *o, ir_expr *x, const hfx_type *t, int n, ir_expr **sets) {
    ir_ctx *c = o->c;
    uint32_t m = (uint32_t)(n < 0 ? -(int64_t)n : n);
    if (m == 0) return hfx_ir_const_scalar(c, t, 1, x->loc);
    ir_expr *square = NULL, *result = NULL;
    int last = -1;
    for (int i = 0; i < 32 && m >> i; i++) {
        if (!(m >> i & 1)) continue;
        for (int j = i; j > last; j--) {
            if (!square) { square = x; continue; }
            ir_expr *set, *sq = hfx_ir_new_binary(c, OP_MUL, t, square, hfx_ir_clone_expr(c, square));
            square = m >> (i + 1) || j > last + 1 ? read_once(o, sq, &set) : sq;
            if (square != sq) *sets = after(c, *sets, set);
        }
        result = result ? hfx_ir_new_binary(c, OP_MUL, t, result, hfx_ir_clone_expr(c, square)) : hfx_ir_clone_expr(c, square);
        last = i;
    }
    if (n < 0) result = hfx_ir_new_binary(c, OP_DIV, t, hfx_ir_const_scalar(c, t, 1, x->loc), result);
    return result;
}

static bool float_base(hfx_base b) { return b == B_FLOAT || b == B_HALF || b == B_DOUBLE || b == B_MIN16FLOAT; }

static void expand_pow(once *o, ir_expr **slot) {
    ir_expr *e = *slot;
    int n;
    if (e->n != 2 || !float_base(e->type->base) || !hfx_type_equal(e->a[0]->type, e->type) ||
        !hfx_ir_pow_products(e->a[1], hfx_type_components(e->type), &n))
        return;
    if (!o->fn && hfx_ir_has_side_effects(e->a[0])) return;
    ir_expr *set, *x = read_once(o, e->a[0], &set);
    ir_expr *value = products(o, x, e->type, n, &set);
    *slot = after(o->c, set, value);
}

/* tex*Dlod / bias / proj: the printer reads the coordinate twice (.xy and .w). */
static void coordinate_once(once *o, ir_expr **slot) {
    ir_expr *e = *slot;
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of((int)e->intrin);
    if (!info || info->sig != SIG_TEX || e->n != 2) return;
    if (info->tex_form != TEXF_LOD && info->tex_form != TEXF_BIAS && info->tex_form != TEXF_PROJ) return;
    if (!o->fn) return;
    ir_expr *set;
    e->a[1] = read_once(o, e->a[1], &set);
    *slot = after(o->c, set, e);
}

static void visit(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    ir_expr *e = *slot;
    if (e->kind != IE_INTRIN) return;
    if (e->intrin == HFX_INTR_POW) expand_pow(data, slot);
    else coordinate_once(data, slot);
}

void hfx_ir_pass_once(ir_ctx *c, ir_shader *sh) {
    once g = {c, NULL, NULL, 0, 0, 0}; /* static initialisers: pow's products, no locals */
    for (uint32_t i = 0; i < sh->global_count; i++)
        if (sh->globals[i]->init) hfx_ir_walk_expr(c, &sh->globals[i]->init, visit, &g);
    for (uint32_t i = 0; i < sh->func_count; i++) {
        once o = {c, sh->funcs[i], NULL, 0, 0, 0};
        ir_stmt *body = sh->funcs[i]->body;
        if (!body || body->kind != IS_BLOCK) continue;
        hfx_ir_walk_stmt_exprs(c, body, visit, &o);
        if (o.decl_count) hfx_ir_insert_stmts(c, body, 0, o.decls, o.decl_count);
    }
}
