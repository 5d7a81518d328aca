/* check_stmt.c: function declarations and bodies: parameters, local scopes, conditions, loops,
 * switch, returns (converted to the return type) and the all-paths-return rule. */
#include "check/check_ctx.h"

static void check_stmt(check_ctx *c, hfx_stmt *s);

static void check_local(check_ctx *c, hfx_decl *d) {
    d->type = hfx_ck_resolve_type(c, d->type, d->loc);
    if (d->type && d->type->kind == TY_VOID) {
        hfx_error(c->diags, d->loc, 3038, "'%s': variables cannot be declared 'void'", d->name);
        d->type = c->err;
    }
    if (d->init) hfx_ck_init(c, d);
    hfx_ck_scope_add(c, d);
}

static void check_block_items(check_ctx *c, hfx_stmt **body, uint32_t n) {
    for (uint32_t i = 0; i < n; i++) check_stmt(c, body[i]);
}

/* A sub-statement gets its own scope: `if (a) float x = 1;` declares nothing outside. */
static void check_scoped(check_ctx *c, hfx_stmt *s) {
    if (!s) return;
    hfx_ck_scope_push(c);
    check_stmt(c, s);
    hfx_ck_scope_pop(c);
}

static void check_loop_body(check_ctx *c, hfx_stmt *body) {
    c->loops++;
    check_scoped(c, body);
    c->loops--;
}

static void check_return(check_ctx *c, hfx_stmt *s) {
    hfx_func *f = c->func ? c->func->func : NULL;
    if (!f) return;
    bool is_void = f->ret->kind == TY_VOID;
    if (s->expr) {
        const hfx_type *t = hfx_ck_expr(c, s->expr);
        if (hfx_ck_is_err(c, t)) return;
        if (is_void) {
            if (t->kind != TY_VOID)
                hfx_error(c->diags, s->loc, X_VOID_RETURN, "'%s': void functions cannot return a value", f->name);
            return;
        }
        s->expr = hfx_ck_convert(c, s->expr, f->ret, true);
    } else if (!is_void) {
        hfx_error(c->diags, s->loc, X_MISSING_RETURN, "'%s': function must return a value", f->name);
    }
}

static bool is_label(const hfx_stmt *s) { return s->kind == ST_CASE || s->kind == ST_DEFAULT; }

/* Whether control cannot run past the end of s: break, continue, return, discard, or a block
 * ending in one. */
static bool ends_in_jump(const hfx_stmt *s) {
    switch (s->kind) {
    case ST_BREAK: case ST_CONTINUE: case ST_RETURN: case ST_DISCARD: return true;
    case ST_BLOCK: return s->body_count && ends_in_jump(s->body[s->body_count - 1]);
    case ST_IF: return s->else_stmt && ends_in_jump(s->then_stmt) && ends_in_jump(s->else_stmt);
    default: return false;
    }
}

/* fxc refuses `case 2: v += 2; case 3: ...`: a case with statements may not fall into the next
 * label (empty cases sharing a body are fine). */
static void check_fallthrough(check_ctx *c, const hfx_stmt *s) {
    bool open = false; /* statements since the last label that do not end in a jump */
    for (uint32_t i = 0; i < s->body_count; i++) {
        const hfx_stmt *st = s->body[i];
        if (is_label(st)) {
            if (open)
                hfx_error(c->diags, st->loc, X_CASE_FALLTHROUGH, "non-empty case statements must have break or return");
            open = false;
        } else if (st->kind != ST_EMPTY) {
            open = !ends_in_jump(st);
        }
    }
}

static void check_switch(check_ctx *c, hfx_stmt *s) {
    const hfx_type *t = hfx_ck_expr(c, s->expr);
    if (!hfx_ck_is_err(c, t)) {
        if (!hfx_type_is_scalarlike(t)) {
            hfx_error(c->diags, hfx_ck_start(s->expr), X_NO_IF_SCALAR,
                      "switch statement conditional expressions must evaluate to a scalar");
        } else {
            s->expr = hfx_ck_convert(c, s->expr, hfx_type_scalar(c->types, t->base == B_UINT ? B_UINT : B_INT), false);
        }
    }
    c->switches++;
    hfx_ck_scope_push(c);
    check_block_items(c, s->body, s->body_count);
    hfx_ck_scope_pop(c);
    c->switches--;
    check_fallthrough(c, s);
}

static void check_case(check_ctx *c, hfx_stmt *s) {
    int64_t v;
    if (!s->expr || hfx_ck_is_err(c, hfx_ck_expr(c, s->expr))) return;
    if (!hfx_ck_fold_int(c, s->expr, &v))
        hfx_error(c->diags, hfx_ck_start(s->expr), 3020, "case expressions must be literal scalar expressions");
    else
        s->expr = hfx_ck_convert(c, s->expr, hfx_type_scalar(c->types, B_INT), false);
}

/* fxc's loop scoping: `for (int i...)` declares i in the enclosing scope too, so i is usable
 * after the loop, and a second `for (int i...)` warns X3078 and takes over the name. */
static void check_for(check_ctx *c, hfx_stmt *s) {
    hfx_stmt *init = s->init;
    bool decl = init && init->kind == ST_DECL;
    for (uint32_t i = 0; decl && i < init->decl_count; i++)
        if (init->decls[i]->name && hfx_ck_declared_here(c, init->decls[i]->name))
            hfx_warning(c->diags, init->decls[i]->loc, X_LOOP_VAR_CONFLICT,
                        "loop control variable conflicts with a previous declaration in the outer scope; "
                        "most recent declaration will be used");
    hfx_ck_scope_push(c);
    check_stmt(c, init);
    if (s->expr) hfx_ck_cond(c, &s->expr, "for");
    if (s->step) hfx_ck_expr(c, s->step);
    check_loop_body(c, s->then_stmt);
    hfx_ck_scope_pop(c);
    for (uint32_t i = 0; decl && i < init->decl_count; i++) hfx_ck_scope_leak(c, init->decls[i]);
}

static void check_stmt(check_ctx *c, hfx_stmt *s) {
    if (!s) return;
    if (s->attr_count) hfx_ck_attributes(c, s);
    switch (s->kind) {
    case ST_BLOCK:
        hfx_ck_scope_push(c);
        check_block_items(c, s->body, s->body_count);
        hfx_ck_scope_pop(c);
        break;
    case ST_DECL:
        for (uint32_t i = 0; i < s->decl_count; i++) check_local(c, s->decls[i]);
        break;
    case ST_EXPR:
        if (s->expr) hfx_ck_expr(c, s->expr);
        break;
    case ST_IF:
        hfx_ck_cond(c, &s->expr, "if");
        check_scoped(c, s->then_stmt);
        check_scoped(c, s->else_stmt);
        break;
    case ST_FOR:
        check_for(c, s);
        break;
    case ST_WHILE:
        hfx_ck_cond(c, &s->expr, "while");
        check_loop_body(c, s->then_stmt);
        break;
    case ST_DO:
        check_loop_body(c, s->then_stmt);
        hfx_ck_cond(c, &s->expr, "do");
        break;
    case ST_SWITCH:
        check_switch(c, s);
        break;
    case ST_CASE:
        check_case(c, s);
        break;
    case ST_BREAK:
        if (!c->loops && !c->switches)
            hfx_error(c->diags, s->loc, X_BAD_JUMP, "break must be inside a loop or switch");
        break;
    case ST_CONTINUE:
        if (!c->loops) hfx_error(c->diags, s->loc, X_BAD_JUMP, "continue must be inside a loop");
        break;
    case ST_RETURN:
        check_return(c, s);
        break;
    case ST_ASM:
        hfx_error(c->diags, s->loc, X_UNSUPPORTED, "asm blocks are not supported");
        break;
    case ST_DEFAULT: case ST_DISCARD: case ST_EMPTY:
        break;
    }
}

static bool always_returns(const hfx_stmt *s);

/* Whether a break leaves s (breaks inside nested loops and switches leave those instead). */
static bool breaks_out(const hfx_stmt *s) {
    if (!s) return false;
    switch (s->kind) {
    case ST_BREAK: return true;
    case ST_FOR: case ST_WHILE: case ST_DO: case ST_SWITCH: return false;
    case ST_IF: return breaks_out(s->then_stmt) || breaks_out(s->else_stmt);
    case ST_BLOCK:
        for (uint32_t i = 0; i < s->body_count; i++)
            if (breaks_out(s->body[i])) return true;
        return false;
    default: return false;
    }
}

/* A switch returns when it has a default, nothing breaks out of it, and its last statement
 * returns (every case falls through to it or returns earlier). */
static bool switch_returns(const hfx_stmt *s) {
    bool has_default = false;
    for (uint32_t i = 0; i < s->body_count; i++) {
        if (s->body[i]->kind == ST_DEFAULT) has_default = true;
        if (breaks_out(s->body[i])) return false;
    }
    return has_default && s->body_count && always_returns(s->body[s->body_count - 1]);
}

/* Whether every path through s ends in a return (or a discard, which ends the shader). */
static bool always_returns(const hfx_stmt *s) {
    if (!s) return false;
    switch (s->kind) {
    case ST_RETURN: case ST_DISCARD: return true;
    case ST_BLOCK:
        for (uint32_t i = 0; i < s->body_count; i++)
            if (always_returns(s->body[i])) return true;
        return false;
    case ST_IF: return always_returns(s->then_stmt) && always_returns(s->else_stmt);
    case ST_DO: return always_returns(s->then_stmt);
    case ST_SWITCH: return switch_returns(s);
    default: return false;
    }
}

static bool has_uniform_param(const hfx_func *f) {
    for (uint32_t i = 0; i < f->param_count; i++)
        if (f->params[i]->mods & MOD_UNIFORM) return true;
    return false;
}

static void check_params(check_ctx *c, hfx_func *f) {
    for (uint32_t i = 0; i < f->param_count; i++) {
        hfx_decl *p = f->params[i];
        p->index = i;
        p->type = hfx_ck_resolve_type(c, p->type, p->loc);
        if (p->init) hfx_ck_init(c, p);
    }
}

void hfx_ck_function(check_ctx *c, hfx_decl *d) {
    hfx_func *f = d->func;
    if (!f) return;
    f->ret = hfx_ck_resolve_type(c, f->ret, f->loc);
    check_params(c, f);
    if (f->body && !f->definition) f->definition = f;
    hfx_ck_scope_add(c, d); /* before the body: a recursive call finds it (and codegen rejects it) */
    if (!f->body) return;
    c->func = d;
    hfx_ck_scope_push(c);
    for (uint32_t i = 0; i < f->param_count; i++) hfx_ck_scope_add(c, f->params[i]);
    if (f->body->kind == ST_BLOCK) check_block_items(c, f->body->body, f->body->body_count);
    else check_stmt(c, f->body);
    hfx_ck_scope_pop(c);
    if (f->ret->kind != TY_VOID && !always_returns(f->body)) {
        /* fxc decides after `compile ps_3_0 PS(1)` has fixed the uniform parameters */
        if (has_uniform_param(f)) f->returns_per_pass = true;
        else hfx_error(c->diags, f->loc, X_NOT_ALL_PATHS, "'%s': Not all control paths return a value", f->name);
    }
    c->func = NULL;
}
