/* check.c: the checker's driver: scopes, top-level declarations in source order (HLSL, like
 * C, sees only what is declared above), array sizes, annotations and techniques. Expressions
 * are in check_expr.c, calls and initializers in check_call.c, statements in check_stmt.c. */
#include "check/check.h"

#include <stdlib.h>
#include <string.h>

#include "check/check_ctx.h"

/* ---- scopes: one hash table of entries; popping a scope unlinks its entries ---- */

static uint32_t hash_name(const char *s) {
    uint32_t h = 2166136261u;
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 16777619u;
    return h % CHECK_BUCKETS;
}

void hfx_ck_scope_push(check_ctx *c) { c->depth++; }

void hfx_ck_scope_pop(check_ctx *c) {
    while (c->entry_count && c->entries[c->entry_count - 1].depth == c->depth) {
        check_entry *e = &c->entries[--c->entry_count];
        c->buckets[hash_name(e->name)] = e->next;
    }
    c->depth--;
}

hfx_decl *hfx_ck_lookup(check_ctx *c, const char *name) {
    for (int32_t i = c->buckets[hash_name(name)]; i >= 0; i = c->entries[i].next)
        if (strcmp(c->entries[i].name, name) == 0) return c->entries[i].decl;
    return NULL;
}

uint32_t hfx_ck_lookup_funcs(check_ctx *c, const char *name, hfx_decl **out, uint32_t max) {
    uint32_t n = 0;
    for (int32_t i = c->buckets[hash_name(name)]; i >= 0; i = c->entries[i].next) {
        check_entry *e = &c->entries[i];
        if (e->decl->kind == DECL_FUNC && strcmp(e->name, name) == 0 && n < max) out[n++] = e->decl;
    }
    for (uint32_t i = 0; i < n / 2; i++) { /* the chain runs newest first */
        hfx_decl *t = out[i];
        out[i] = out[n - 1 - i];
        out[n - 1 - i] = t;
    }
    return n;
}

static void push_entry(check_ctx *c, hfx_decl *d) {
    if (!HFX_ARENA_GROW(c->arena, c->entries, c->entry_count, c->entry_cap, 256)) { c->oom = true; return; }
    uint32_t h = hash_name(d->name);
    c->entries[c->entry_count] = (check_entry){d->name, d, c->depth, c->buckets[h]};
    c->buckets[h] = (int32_t)c->entry_count++;
}

static bool same_params(const hfx_func *a, const hfx_func *b) {
    if (a->param_count != b->param_count) return false;
    for (uint32_t i = 0; i < a->param_count; i++)
        if (!hfx_type_equal(a->params[i]->type, b->params[i]->type)) return false;
    return true;
}

/* A function with the signature of an earlier one: a prototype and its definition link up,
 * two bodies are a redefinition. Returns true when `d` must not get its own entry. */
static bool merge_function(check_ctx *c, hfx_decl *d) {
    for (int32_t i = c->buckets[hash_name(d->name)]; i >= 0; i = c->entries[i].next) {
        check_entry *e = &c->entries[i];
        if (e->depth != c->depth || strcmp(e->name, d->name) != 0 || e->decl->kind != DECL_FUNC) continue;
        hfx_func *old = e->decl->func, *f = d->func;
        if (!same_params(old, f)) continue;
        if (old->body && f->body) {
            hfx_error(c->diags, d->loc, X_REDEFINITION, "redefinition of '%s'", d->name);
            return true;
        }
        if (f->body) {
            old->definition = f;
            e->decl = d; /* calls from here on find the definition */
        } else {
            f->definition = old->definition;
        }
        return true;
    }
    return false;
}

void hfx_ck_scope_add(check_ctx *c, hfx_decl *d) {
    if (!d->name) return;
    if (d->kind == DECL_FUNC && merge_function(c, d)) return;
    for (int32_t i = c->buckets[hash_name(d->name)]; i >= 0; i = c->entries[i].next) {
        check_entry *e = &c->entries[i];
        if (e->depth != c->depth || strcmp(e->name, d->name) != 0) continue;
        if (d->kind == DECL_FUNC && e->decl->kind == DECL_FUNC) continue; /* an overload */
        hfx_error(c->diags, d->loc, X_REDEFINITION, "redefinition of '%s'", d->name);
        return;
    }
    push_entry(c, d);
}

void hfx_ck_scope_leak(check_ctx *c, hfx_decl *d) {
    if (d->name) push_entry(c, d);
}

bool hfx_ck_declared_here(check_ctx *c, const char *name) {
    for (int32_t i = c->buckets[hash_name(name)]; i >= 0; i = c->entries[i].next)
        if (c->entries[i].depth == c->depth && strcmp(c->entries[i].name, name) == 0) return true;
    return false;
}

/* ---- constants and types ---- */

/* An operator on folded ints, with int's rules (common/eval). */
static bool fold_op(hfx_op op, int64_t a, const int64_t *b, int64_t *out) {
    hfx_ev_op ev;
    double r;
    if (!hfx_op_ev(op, &ev)) return false;
    if (b ? !hfx_ev_binary(ev, HFX_EV_INT, (double)a, (double)*b, &r) : !hfx_ev_unary(ev, HFX_EV_INT, (double)a, &r))
        return false;
    *out = hfx_ev_int(r);
    return true;
}

bool hfx_ck_fold_int(check_ctx *c, hfx_expr *e, int64_t *out) {
    int64_t a, b;
    if (!e) return false;
    switch (e->kind) {
    case EX_INT: case EX_BOOL: *out = hfx_ev_int(hfx_ev_normalise(HFX_EV_INT, (double)e->ival)); return true;
    case EX_FLOAT: *out = hfx_ev_int(e->fval); return true;
    case EX_IDENT: {
        hfx_decl *d = e->sym ? e->sym : hfx_ck_lookup(c, e->name);
        if (!d || d->kind != DECL_VAR || !(d->mods & MOD_CONST) || !d->init) return false;
        if (d->init->kind == EX_INIT_LIST) return d->init->arg_count == 1 && hfx_ck_fold_int(c, d->init->args[0], out);
        return hfx_ck_fold_int(c, d->init, out);
    }
    case EX_CAST: case EX_CONSTRUCT:
        return e->arg_count == 1 && hfx_ck_fold_int(c, e->args[0], out);
    case EX_UNARY: return hfx_ck_fold_int(c, e->args[0], &a) && fold_op(e->op, a, NULL, out);
    case EX_BINARY: return hfx_ck_fold_int(c, e->args[0], &a) && hfx_ck_fold_int(c, e->args[1], &b) && fold_op(e->op, a, &b, out);
    default: return false;
    }
}

/* The first name in e that nothing declares (fxc reports it, X3004, rather than X3058). */
static const hfx_expr *undeclared_in(check_ctx *c, const hfx_expr *e, int depth) {
    if (!e || depth > 64) return NULL;
    if (e->kind == EX_IDENT) return e->sym || !e->name || hfx_ck_lookup(c, e->name) ? NULL : e;
    for (uint32_t i = 0; i < e->arg_count; i++) {
        const hfx_expr *u = undeclared_in(c, e->args[i], depth + 1);
        if (u) return u;
    }
    return NULL;
}

const hfx_type *hfx_ck_resolve_type(check_ctx *c, const hfx_type *ty, hfx_loc loc) {
    if (!ty || ty->kind != TY_ARRAY) return ty;
    const hfx_type *elem = hfx_ck_resolve_type(c, ty->elem, loc);
    if (!ty->array_len_expr) return elem == ty->elem ? ty : hfx_type_array(c->types, elem, ty->array_len);
    int64_t n = 0;
    hfx_expr *len = ty->array_len_expr;
    if (!hfx_ck_fold_int(c, len, &n) || n <= 0 || n > 65536) {
        const hfx_expr *u = undeclared_in(c, len, 0);
        if (u) hfx_error(c->diags, u->loc, X_UNDECLARED, "undeclared identifier '%s'", u->name);
        else hfx_error(c->diags, hfx_ck_start(len), X_ARRAY_DIM, "array dimensions must be literal scalar expressions");
        n = 1;
    }
    return hfx_type_array(c->types, elem, (uint32_t)n);
}

void hfx_ck_annotations(check_ctx *c, hfx_annotation_ast *a, uint32_t n) {
    for (uint32_t i = 0; i < n; i++) {
        if (!a[i].value || !a[i].type) continue;
        hfx_decl tmp;
        memset(&tmp, 0, sizeof tmp);
        tmp.kind = DECL_VAR;
        tmp.name = a[i].name;
        tmp.type = a[i].type;
        tmp.init = a[i].value;
        tmp.loc = a[i].loc;
        hfx_ck_init(c, &tmp);
        a[i].value = tmp.init;
    }
}

/* ---- the call graph: HLSL has no recursion (every call is inlined) ---- */

static hfx_func *defined(hfx_func *f) { return f && f->definition ? f->definition : f; }

void hfx_ck_record_call(check_ctx *c, hfx_func *to, hfx_loc loc, bool compile) {
    if (!HFX_ARENA_GROW(c->arena, c->edges, c->edge_count, c->edge_cap, 64)) { c->oom = true; return; }
    c->edges[c->edge_count++] = (check_edge){c->func ? c->func->func : NULL, to, loc, compile};
}

/* Calls and compiles of functions that were declared but never given a body. */
static void check_undefined(check_ctx *c) {
    for (uint32_t i = 0; i < c->edge_count; i++) {
        check_edge *e = &c->edges[i];
        if (defined(e->to)->body) continue;
        bool first = true;
        for (uint32_t j = 0; j < i && first; j++) first = c->edges[j].to != e->to;
        if (!first) continue;
        if (!e->compile)
            hfx_error(c->diags, e->loc, X_UNDEFINED, "'%s': function is declared but not defined", e->to->name);
        else
            hfx_error(c->diags, e->loc, X_UNDEFINED, "'%s': entrypoint not found", e->to->name);
    }
}

/* The call graph in compressed rows: node i calls dst[first[i] .. first[i + 1]). Nodes are
 * function definitions, found through a pointer hash (no field in hfx_func to number them). */
typedef struct call_graph {
    hfx_func **keys; uint32_t *ids; uint32_t cap;  /* open addressing, cap a power of two */
    uint32_t nodes;
    uint32_t *first, *dst, *edge;                  /* edge: the index in c->edges of each dst */
} call_graph;

static uint32_t node_of(call_graph *g, hfx_func *f) {
    uint32_t h = (uint32_t)(((uintptr_t)f >> 4) * 2654435761u) & (g->cap - 1);
    while (g->keys[h] && g->keys[h] != f) h = (h + 1) & (g->cap - 1);
    if (!g->keys[h]) {
        g->keys[h] = f;
        g->ids[h] = g->nodes++;
    }
    return g->ids[h];
}

static bool build_graph(check_ctx *c, call_graph *g, uint32_t *src, uint32_t *to) {
    uint32_t ne = c->edge_count;
    g->cap = 16;
    while (g->cap < ne * 4 + 16) g->cap *= 2;
    g->keys = HFX_NEW_ARRAY(c->arena, hfx_func *, g->cap);
    g->ids = HFX_NEW_ARRAY(c->arena, uint32_t, g->cap);
    g->first = HFX_NEW_ARRAY(c->arena, uint32_t, ne * 2 + 2);
    g->dst = HFX_NEW_ARRAY(c->arena, uint32_t, ne + 1);
    g->edge = HFX_NEW_ARRAY(c->arena, uint32_t, ne + 1);
    if (!g->keys || !g->ids || !g->first || !g->dst || !g->edge) return false;
    for (uint32_t i = 0; i < ne; i++) {
        src[i] = c->edges[i].from ? node_of(g, defined(c->edges[i].from)) : UINT32_MAX;
        to[i] = node_of(g, defined(c->edges[i].to));
        if (src[i] != UINT32_MAX) g->first[src[i] + 1]++;
    }
    for (uint32_t i = 0; i < g->nodes; i++) g->first[i + 1] += g->first[i];
    uint32_t *fill = HFX_NEW_ARRAY(c->arena, uint32_t, g->nodes + 1);
    if (!fill) return false;
    for (uint32_t i = 0; i < ne; i++) {
        if (src[i] == UINT32_MAX) continue;
        uint32_t k = g->first[src[i]] + fill[src[i]]++;
        g->dst[k] = to[i];
        g->edge[k] = i;
    }
    return true;
}

/* Depth-first search from every node; a call to a function still on the stack closes a
 * cycle and is reported (once per calling function). O(functions + calls). */
static void find_cycles(check_ctx *c, const call_graph *g) {
    enum { WHITE, GREY, BLACK };
    unsigned char *color = HFX_NEW_ARRAY(c->arena, unsigned char, g->nodes + 1);
    unsigned char *reported = HFX_NEW_ARRAY(c->arena, unsigned char, g->nodes + 1);
    uint32_t *stack = HFX_NEW_ARRAY(c->arena, uint32_t, g->nodes + 1), *cursor = HFX_NEW_ARRAY(c->arena, uint32_t, g->nodes + 1);
    for (uint32_t root = 0; color && reported && stack && cursor && root < g->nodes; root++) {
        if (color[root] != WHITE) continue;
        uint32_t top = 0;
        stack[top++] = root;
        cursor[root] = g->first[root];
        color[root] = GREY;
        while (top) {
            uint32_t n = stack[top - 1];
            if (cursor[n] == g->first[n + 1]) {
                color[n] = BLACK;
                top--;
                continue;
            }
            uint32_t k = cursor[n]++, m = g->dst[k];
            if (color[m] == GREY && !reported[n]) {
                const check_edge *e = &c->edges[g->edge[k]];
                reported[n] = 1;
                hfx_error(c->diags, e->loc, X_RECURSION, "'%s': recursive function calls are not allowed", e->to->name);
            } else if (color[m] == WHITE) {
                color[m] = GREY;
                cursor[m] = g->first[m];
                stack[top++] = m;
            }
        }
    }
}

static void check_recursion(check_ctx *c) {
    call_graph g;
    memset(&g, 0, sizeof g);
    uint32_t *src = HFX_NEW_ARRAY(c->arena, uint32_t, c->edge_count + 1), *to = HFX_NEW_ARRAY(c->arena, uint32_t, c->edge_count + 1);
    if (src && to && build_graph(c, &g, src, to)) find_cycles(c, &g);
}

/* ---- top-level declarations ---- */

static void check_struct(check_ctx *c, hfx_decl *d) {
    hfx_struct *st = d->type && d->type->kind == TY_STRUCT ? d->type->st : NULL;
    if (!st) return;
    for (uint32_t i = 0; i < st->field_count; i++) {
        st->fields[i].type = hfx_ck_resolve_type(c, st->fields[i].type, st->fields[i].loc);
        for (uint32_t j = 0; j < i; j++)
            if (st->fields[i].name && st->fields[j].name && strcmp(st->fields[i].name, st->fields[j].name) == 0)
                hfx_error(c->diags, st->fields[i].loc, X_REDEFINITION, "redefinition of '%s'", st->fields[i].name);
    }
}

static void check_global_var(check_ctx *c, hfx_decl *d) {
    d->is_global = true;
    d->index = c->global_count++;
    d->type = hfx_ck_resolve_type(c, d->type, d->loc);
    hfx_ck_annotations(c, d->annotations, d->annotation_count);
    if (d->init) hfx_ck_init(c, d);
    hfx_ck_scope_add(c, d);
}

static void check_pass(check_ctx *c, hfx_pass_ast *p) {
    hfx_ck_annotations(c, p->annotations, p->annotation_count);
    for (uint32_t i = 0; i < p->state_count; i++) hfx_ck_state_value(c, &p->states[i]);
}

static void check_technique(check_ctx *c, hfx_decl *d) {
    hfx_technique_ast *t = d->technique;
    if (!t) return;
    hfx_ck_annotations(c, t->annotations, t->annotation_count);
    for (uint32_t i = 0; i < t->pass_count; i++) check_pass(c, &t->passes[i]);
}

static void check_decl(check_ctx *c, hfx_decl *d) {
    switch (d->kind) {
    case DECL_VAR: check_global_var(c, d); break;
    case DECL_FUNC: hfx_ck_function(c, d); break;
    case DECL_STRUCT: check_struct(c, d); break;
    case DECL_TYPEDEF: d->type = hfx_ck_resolve_type(c, d->type, d->loc); break;
    case DECL_TECHNIQUE: check_technique(c, d); break;
    case DECL_PARAM: break;
    }
}

bool hfx_check(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast) {
    check_ctx c;
    memset(&c, 0, sizeof c);
    c.arena = arena;
    c.diags = diags;
    c.types = types;
    hfx_type *err = HFX_NEW(arena, hfx_type);
    if (!err) return false;
    err->kind = TY_VOID;
    err->base = B_NONE;
    c.err = err;
    for (int i = 0; i < CHECK_BUCKETS; i++) c.buckets[i] = -1;
    for (uint32_t i = 0; ast && i < ast->decl_count; i++)
        if (ast->decls[i]) check_decl(&c, ast->decls[i]);
    check_undefined(&c);
    if (!diags->errors) check_recursion(&c);
    return diags->errors == 0 && !c.oom;
}
