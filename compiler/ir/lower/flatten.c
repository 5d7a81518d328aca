/* flatten.c: a small if / else that only picks a variable's value becomes a select, as fxc
 * flattens such branches (unless [branch] asks for one):
 *     if (d <= range) k = min(1 / (c1 + c2 * d), 1); else k = 0;
 * is `k = d <= range ? min(1 / (c1 + c2 * d), 1) : 0;`. A GPU running pixels in lockstep pays
 * for both sides of a divergent branch anyway, and the branch's bookkeeping on top (llvmpipe:
 * 1.3 % of point.fx's pixel-bound frame). Only when each branch is one plain assignment to the
 * same local (or there is no else: the local keeps its value), both values are pure and small,
 * without sampling or derivatives, and the condition is one bool. */
#include <strings.h>

#include "ir/ir.h"

enum { MAX_NODES = 24 }; /* both values together: small enough that computing both is cheaper */

static unsigned nodes(const ir_expr *e, unsigned budget) {
    if (!e || budget == 0) return 0;
    unsigned n = 1;
    for (uint32_t i = 0; i < e->n && n <= budget; i++) n += nodes(e->a[i], budget - n);
    return n;
}

static bool pure(const ir_expr *e) {
    if (!e) return true;
    if (e->kind == IE_CALL || e->kind == IE_ASSIGN || e->kind == IE_COMMA) return false;
    if (e->kind == IE_UNARY && e->op != OP_NEG && e->op != OP_POS && e->op != OP_NOT && e->op != OP_BITNOT) return false;
    if ((e->kind == IE_INTRIN && !hfx_ir_intrinsic_movable(e->intrin)) || hfx_ir_integer_division(e))
        return false; /* an integer division the branch guards may trap */
    for (uint32_t i = 0; i < e->n; i++)
        if (!pure(e->a[i])) return false;
    return true;
}

/* The assignment `local = value` a branch consists of, or NULL. */
static ir_expr *sole_assignment(const ir_stmt *s) {
    if (s && s->kind == IS_BLOCK && s->count == 1) s = s->body[0];
    const ir_expr *e = s && s->kind == IS_EXPR ? s->expr : NULL;
    if (!e || e->kind != IE_ASSIGN || e->op != OP_NONE || e->a[0]->kind != IE_VAR) return NULL;
    const ir_var *v = e->a[0]->var;
    if (v->kind != IRV_LOCAL || !hfx_type_is_numeric(v->type) || !pure(e->a[1])) return NULL;
    return (ir_expr *)e;
}

/* if statement s as `x = c ? a : b;`, when it qualifies. */
static void flatten_if(ir_ctx *c, ir_stmt *s) {
    const ir_expr *cond = s->expr;
    if ((s->hint && strcasecmp(s->hint, "branch") == 0) || !cond || cond->type->kind != TY_SCALAR || cond->type->base != B_BOOL || !pure(cond)) return;
    ir_expr *then_a = sole_assignment(s->then_s), *else_a = s->else_s ? sole_assignment(s->else_s) : NULL;
    if (!then_a || (s->else_s && (!else_a || else_a->a[0]->var != then_a->a[0]->var))) return;
    ir_expr *target = then_a->a[0], *other = else_a ? else_a->a[1] : target;
    if (nodes(then_a->a[1], MAX_NODES + 1) + nodes(other, MAX_NODES + 1) > MAX_NODES) return;
    ir_expr *sel = hfx_ir_new_expr(c, IE_SELECT, target->type, s->loc, 3);
    sel->a[0] = s->expr;
    sel->a[1] = then_a->a[1];
    sel->a[2] = else_a ? other : hfx_ir_clone_expr(c, target);
    ir_expr *as = hfx_ir_new_expr(c, IE_ASSIGN, target->type, s->loc, 2);
    as->op = OP_NONE;
    as->a[0] = target;
    as->a[1] = sel;
    s->kind = IS_EXPR;
    s->expr = as;
    s->then_s = s->else_s = NULL;
}

static void flatten_stmt(ir_ctx *c, ir_stmt *s) {
    if (!s) return;
    flatten_stmt(c, s->init);
    for (uint32_t i = 0; i < s->count; i++) flatten_stmt(c, s->body[i]);
    flatten_stmt(c, s->then_s);
    flatten_stmt(c, s->else_s);
    if (s->kind == IS_IF) flatten_if(c, s);
}

void hfx_ir_pass_flatten(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) flatten_stmt(c, sh->funcs[i]->body);
}
