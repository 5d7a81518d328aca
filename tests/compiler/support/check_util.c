/* check_util.c: see check_util.h. */
#include "check_util.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check/check.h"
#include "check/intrinsics.h"

ckt_result *ckt_run(const char *src) {
    ckt_result *r = calloc(1, sizeof *r);
    hfx_arena_init(&r->arena);
    hfx_diags_init(&r->diags, &r->arena, 0);
    r->types = hfx_types_new(&r->arena);
    hfx_pp_options pp;
    memset(&pp, 0, sizeof pp);
    hfx_token *toks = hfx_preprocess(&r->arena, &r->diags, "t.fx", src, (uint32_t)strlen(src), &pp);
    r->ast = hfx_parse(&r->arena, &r->diags, r->types, toks);
    if (!r->diags.errors) r->ok = hfx_check(&r->arena, &r->diags, r->types, r->ast);
    return r;
}

void ckt_free(ckt_result *r) {
    if (!r) return;
    hfx_arena_free(&r->arena);
    free(r);
}

char *ckt_text(const ckt_result *r) { return hfx_diags_format(&r->diags, 0); }

char *ckt_diags(const char *src) {
    ckt_result *r = ckt_run(src);
    char *s = ckt_text(r);
    ckt_free(r);
    return s;
}

hfx_decl *ckt_find(ckt_result *r, const char *name) {
    hfx_decl *found = NULL;
    for (uint32_t i = 0; r->ast && i < r->ast->decl_count; i++)
        if (r->ast->decls[i]->name && strcmp(r->ast->decls[i]->name, name) == 0) found = r->ast->decls[i];
    return found;
}

hfx_stmt *ckt_stmt(ckt_result *r, const char *fn, unsigned i) {
    hfx_decl *d = ckt_find(r, fn);
    if (!d || d->kind != DECL_FUNC || !d->func->body) return NULL;
    hfx_stmt *b = d->func->body;
    return i < b->body_count ? b->body[i] : NULL;
}

typedef struct buf {
    char *s;
    size_t len, cap;
} buf;

static void put(buf *b, const char *fmt, ...) {
    char tmp[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    if (n < 0) return;
    if (b->len + (size_t)n + 1 > b->cap) {
        b->cap = (b->len + (size_t)n + 1) * 2;
        b->s = realloc(b->s, b->cap);
    }
    memcpy(b->s + b->len, tmp, (size_t)n + 1);
    b->len += (size_t)n;
}

static const char *type_str(hfx_arena *a, const hfx_type *t) { return t ? hfx_type_name(a, t) : "?"; }

static const char *op_str(hfx_op op) {
    static const char *const names[] = {"=", "neg", "pos", "!", "~", "pre++", "pre--", "post++", "post--",
                                        "+", "-", "*", "/", "%", "<<", ">>", "&", "|", "^",
                                        "<", ">", "<=", ">=", "==", "!=", "&&", "||"};
    return (size_t)op < sizeof names / sizeof names[0] ? names[op] : "?";
}

static void dump(buf *b, hfx_arena *a, const hfx_expr *e);

static void dump_args(buf *b, hfx_arena *a, const hfx_expr *e, uint32_t from) {
    for (uint32_t i = from; i < e->arg_count; i++) {
        put(b, " ");
        dump(b, a, e->args[i]);
    }
    put(b, ")");
}

static void dump(buf *b, hfx_arena *a, const hfx_expr *e) {
    if (!e) { put(b, "null"); return; }
    const char *ty = type_str(a, e->type);
    switch (e->kind) {
    case EX_INT: put(b, "%lld:%s", (long long)e->ival, ty); return;
    case EX_FLOAT: put(b, "%g:%s", e->fval, ty); return;
    case EX_BOOL: put(b, "%s:%s", e->ival ? "true" : "false", ty); return;
    case EX_STRING: put(b, "\"%s\"", e->sval ? e->sval : ""); return;
    case EX_IDENT: put(b, "%s:%s%s", e->name, ty, e->sym ? "" : "!"); return;
    case EX_STATE_REF: put(b, "<%s>:%s", e->name, ty); return;
    case EX_UNARY: put(b, "(%s:%s", op_str(e->op), ty); break;
    case EX_BINARY: put(b, "(%s:%s", op_str(e->op), ty); break;
    case EX_ASSIGN: put(b, "(%s%s:%s", e->op ? op_str(e->op) : "", "=", ty); break;
    case EX_TERNARY: put(b, "(?:%s", ty); break;
    case EX_COMMA: put(b, "(,:%s", ty); break;
    case EX_CALL:
        if (e->fn) {
            put(b, "(%s(", e->name);
            for (uint32_t i = 0; i < e->fn->param_count; i++)
                put(b, "%s%s", i ? "," : "", type_str(a, e->fn->params[i]->type));
            put(b, "):%s", ty);
        } else {
            put(b, "(%s%s:%s", e->intrinsic >= 0 ? "#" : "?", e->name, ty);
        }
        break;
    case EX_CONSTRUCT: put(b, "(%s:%s", type_str(a, e->cast_type), ty); break;
    case EX_CAST: put(b, "(%s:%s", e->implicit ? "implicit" : "cast", ty); break;
    case EX_MEMBER: put(b, "(.%s?:%s", e->name, ty); break;
    case EX_SWIZZLE:
        put(b, "(.");
        for (unsigned i = 0; i < e->comp_count; i++) put(b, "%s%u", i ? "," : "", e->comps[i]);
        put(b, ":%s", ty);
        break;
    case EX_FIELD: put(b, "(.f%u:%s", e->field, ty); break;
    case EX_INDEX: put(b, "([]:%s", ty); break;
    case EX_INIT_LIST: put(b, "({}:%s", ty); break;
    case EX_COMPILE: put(b, "(compile %s %s:%s", e->profile, e->name, ty); break;
    default: put(b, "(kind%d:%s", (int)e->kind, ty); break;
    }
    dump_args(b, a, e, 0);
}

char *ckt_dump(const hfx_expr *e) {
    buf b = {0};
    hfx_arena a;
    hfx_arena_init(&a);
    put(&b, "");
    dump(&b, &a, e);
    hfx_arena_free(&a);
    return b.s;
}

char *ckt_dump_stmt(ckt_result *r, const char *fn, unsigned i) {
    hfx_stmt *s = ckt_stmt(r, fn, i);
    if (!s) return strdup("(no statement)");
    if (s->kind == ST_DECL) return ckt_dump(s->decl_count ? s->decls[0]->init : NULL);
    return ckt_dump(s->expr);
}

/* ---- ast.h's invariants, walked over every function body and initializer ---- */

typedef struct inv {
    int bad;
    char why[256];
} inv;

static void violation(inv *v, const hfx_expr *e, const char *what) {
    if (!v->bad++) snprintf(v->why, sizeof v->why, "line %u col %u: %s", e->loc.line, e->loc.col, what);
}

static bool is_bool_scalar(const hfx_type *t) { return t && t->kind == TY_SCALAR && t->base == B_BOOL; }

static void inv_expr(inv *v, const hfx_expr *e, bool state) {
    if (!e) return;
    for (uint32_t i = 0; i < e->arg_count; i++) inv_expr(v, e->args[i], state && e->kind != EX_COMPILE);
    if (!e->type) { violation(v, e, "untyped expression"); return; }
    switch (e->kind) {
    case EX_MEMBER: violation(v, e, "EX_MEMBER left"); break;
    case EX_IDENT: if (!e->sym && !state) violation(v, e, "unresolved name"); break;
    case EX_CALL:
        if (!e->fn && e->intrinsic < 0) violation(v, e, "unresolved call");
        if (e->fn)
            for (uint32_t i = 0; i < e->arg_count; i++)
                if (!hfx_type_equal(e->args[i]->type, e->fn->params[i]->type) &&
                    e->args[i]->type->kind != TY_SAMPLER && e->args[i]->type->kind != TY_TEXTURE)
                    violation(v, e, "argument not converted");
        break;
    case EX_BINARY:
        if (!state && !hfx_type_equal(e->args[0]->type, e->args[1]->type)) violation(v, e, "binary operands differ");
        break;
    case EX_ASSIGN:
        if (!hfx_type_equal(e->args[0]->type, e->args[1]->type)) violation(v, e, "assignment not converted");
        break;
    case EX_CONSTRUCT: {
        unsigned n = 0;
        for (uint32_t i = 0; i < e->arg_count; i++) n += hfx_type_components(e->args[i]->type);
        if (n != hfx_type_components(e->type)) violation(v, e, "constructor count");
        break;
    }
    case EX_INIT_LIST:
        if (e->arg_count != hfx_type_components(e->type) && hfx_type_components(e->type))
            violation(v, e, "init list not flattened");
        break;
    default: break;
    }
}

static void inv_stmt(inv *v, const hfx_stmt *s, const hfx_func *f) {
    if (!s) return;
    for (uint32_t i = 0; i < s->body_count; i++) inv_stmt(v, s->body[i], f);
    for (uint32_t i = 0; i < s->decl_count; i++) inv_expr(v, s->decls[i]->init, false);
    inv_stmt(v, s->init, f);
    inv_stmt(v, s->then_stmt, f);
    inv_stmt(v, s->else_stmt, f);
    inv_expr(v, s->step, false);
    inv_expr(v, s->expr, false);
    bool cond = s->kind == ST_IF || s->kind == ST_WHILE || s->kind == ST_DO || (s->kind == ST_FOR && s->expr);
    if (cond && !is_bool_scalar(s->expr->type)) violation(v, s->expr, "condition not bool");
    if (s->kind == ST_RETURN && s->expr && !hfx_type_equal(s->expr->type, f->ret)) violation(v, s->expr, "return not converted");
}

int ckt_invariants(ckt_result *r, char *why, size_t n) {
    inv v = {0, ""};
    for (uint32_t i = 0; r->ast && i < r->ast->decl_count; i++) {
        hfx_decl *d = r->ast->decls[i];
        if (d->kind == DECL_VAR) {
            if (d->init && d->init->kind != EX_SAMPLER_STATE) inv_expr(&v, d->init, false);
        } else if (d->kind == DECL_FUNC && d->func->body) {
            inv_stmt(&v, d->func->body, d->func);
        } else if (d->kind == DECL_TECHNIQUE) {
            for (uint32_t p = 0; p < d->technique->pass_count; p++)
                for (uint32_t k = 0; k < d->technique->passes[p].state_count; k++)
                    inv_expr(&v, d->technique->passes[p].states[k].value, true);
        }
    }
    snprintf(why, n, "%s", v.why);
    return v.bad;
}
