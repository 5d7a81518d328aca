/* arrays.c: arrays of arrays, which GLSL 330 and ES 300 lack, become flat arrays: the type
 * float[2][3] is float[6], a[i][j] is a[i * 3 + j], and a nested initializer is spliced into
 * one list. Local and static variables and function parameters only; a uniform array of arrays, or an inner array used
 * as a value (a[i] passed on whole), is reported at its HLSL position. */
#include "ir/ir.h"

static bool nested(const hfx_type *t) { return t && t->kind == TY_ARRAY && t->elem->kind == TY_ARRAY; }

/* float[2][3] -> float[6]. */
static const hfx_type *flat_type(ir_ctx *c, const hfx_type *t) {
    uint32_t n = 1;
    while (t->kind == TY_ARRAY) n *= t->array_len, t = t->elem;
    return hfx_type_array(c->types, t, n);
}

static ir_expr *int_const(ir_ctx *c, uint32_t v, hfx_loc loc) {
    return hfx_ir_const_scalar(c, hfx_type_scalar(c->types, B_INT), v, loc);
}

static ir_expr *binary(ir_ctx *c, hfx_op op, ir_expr *x, ir_expr *y) {
    ir_expr *r = hfx_ir_new_expr(c, IE_BINARY, x->type, x->loc, 2);
    r->op = op;
    r->a[0] = x;
    r->a[1] = y;
    return r;
}

/* a[i][j] -> a[i * len + j]; the inner index was already rewritten when it was nested deeper. */
static void flatten_index(ir_ctx *c, ir_expr *e) {
    ir_expr *inner = e->a[0];
    if (inner->kind != IE_INDEX || inner->type->kind != TY_ARRAY || inner->a[0]->type->kind != TY_ARRAY) return;
    ir_expr *i = inner->a[1], *j = e->a[1];
    const hfx_type *it = hfx_type_scalar(c->types, B_INT);
    if (i->type != it) { ir_expr *cv = hfx_ir_new_expr(c, IE_CONVERT, it, i->loc, 1); cv->a[0] = i; i = cv; }
    if (j->type != it) { ir_expr *cv = hfx_ir_new_expr(c, IE_CONVERT, it, j->loc, 1); cv->a[0] = j; j = cv; }
    e->a[0] = inner->a[0];
    e->a[1] = binary(c, OP_ADD, binary(c, OP_MUL, i, int_const(c, inner->type->array_len, e->loc)), j);
}

/* {{1, 2, 3}, {4, 5, 6}} -> {1, 2, 3, 4, 5, 6}. */
static void splice_construct(ir_ctx *c, ir_expr **slot, int *bad) {
    ir_expr *e = *slot;
    const hfx_type *ft = flat_type(c, e->type);
    ir_expr *r = hfx_ir_new_expr(c, IE_CONSTRUCT, ft, e->loc, ft->array_len);
    uint32_t k = 0;
    for (uint32_t i = 0; i < e->n; i++) {
        ir_expr *part = e->a[i];
        if (part->kind != IE_CONSTRUCT || part->type->kind != TY_ARRAY || k + part->n > ft->array_len) {
            hfx_error(c->diags, part->loc, X_UNSUPPORTED, "an array of arrays built from a whole inner array is not supported");
            (*bad)++;
            return;
        }
        for (uint32_t j = 0; j < part->n; j++) r->a[k++] = part->a[j];
    }
    *slot = r;
}

static void flatten_expr(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    if (e->kind == IE_INDEX) flatten_index(c, e);
    else if (e->kind == IE_CONSTRUCT && nested(e->type)) splice_construct(c, slot, data);
    else if (e->kind == IE_VAR && nested(e->type)) e->type = flat_type(c, e->type);
}

/* What is left: an index yielding a whole inner array. */
static void check_left(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    if (e->kind == IE_INDEX && e->type->kind == TY_ARRAY && e->a[0]->type->kind == TY_ARRAY && !nested(e->a[0]->type)) {
        hfx_error(c->diags, e->loc, X_UNSUPPORTED, "an inner array of an array of arrays used whole is not supported");
        (*(int *)data)++;
    }
}

static void flatten_decls(ir_ctx *c, ir_stmt *s) {
    if (!s) return;
    if (s->kind == IS_DECL && nested(s->var->type)) s->var->type = flat_type(c, s->var->type);
    flatten_decls(c, s->init);
    for (uint32_t i = 0; i < s->count; i++) flatten_decls(c, s->body[i]);
    flatten_decls(c, s->then_s);
    flatten_decls(c, s->else_s);
}

void hfx_ir_pass_arrays(ir_ctx *c, ir_shader *sh) {
    if (!hfx_types_nested_arrays(c->types)) return; /* no such type, nothing to flatten or report */
    int bad = 0;
    for (uint32_t i = 0; i < sh->global_count; i++) {
        ir_var *v = sh->globals[i];
        if (!nested(v->type)) continue;
        if (v->kind != IRV_PRIVATE) {
            hfx_error(c->diags, v->decl ? v->decl->loc : (hfx_loc){0}, X_UNSUPPORTED,
                      "'%s': a parameter that is an array of arrays is not supported", v->name);
            continue;
        }
        hfx_ir_walk_expr(c, &v->init, flatten_expr, &bad);
        v->type = flat_type(c, v->type);
    }
    for (uint32_t i = 0; i < sh->func_count; i++) {
        ir_func *f = sh->funcs[i];
        for (uint32_t k = 0; k < f->param_count; k++) /* float f(float a[2][2]): a float[4] parameter */
            if (nested(f->params[k]->type)) f->params[k]->type = flat_type(c, f->params[k]->type);
        flatten_decls(c, sh->funcs[i]->body);
        hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, flatten_expr, &bad);
        hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, check_left, &bad);
    }
}
