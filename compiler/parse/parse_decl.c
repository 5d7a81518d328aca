/* parse_decl.c: declarations, functions, techniques and statements for parser.y. One
 * hfx_decl per declarator; lists collected in parse_vec become exact arrays here. */
#include <string.h>
#include <strings.h>

#include "parse/parse_ctx.h"

/* ---- declarators ---- */

parse_declarator *hfx_pb_declarator(parse_ctx *ctx, const char *name, hfx_loc loc) {
    parse_declarator *d = HFX_NEW(ctx->arena, parse_declarator);
    if (!d) {
        hfx_parse_fatal(ctx, loc, "out of memory");
        return NULL;
    }
    d->name = name;
    d->loc = loc;
    return d;
}

parse_declarator *hfx_pb_decl_dims(parse_ctx *ctx, parse_declarator *d, parse_vec dims) {
    if (d) d->dims = dims;
    return d;
}

parse_declarator *hfx_pb_decl_semantic(parse_declarator *d, const char *semantic) {
    if (d) d->semantic = semantic;
    return d;
}

/* Every reservation is kept (`: register(vs, c13) : register(ps, c14)`, FNA's stock effects):
 * each shader takes its own profile's (hfx_register_for). */
parse_declarator *hfx_pb_decl_register(parse_ctx *ctx, parse_declarator *d, const char *reg) {
    if (d) d->reg = d->reg && reg ? hfx_arena_printf(ctx->arena, "%s;%s", d->reg, reg) : reg;
    return d;
}

const char *hfx_register_for(const char *reg, const char *profile, char *buf, size_t cap) {
    const char *any = NULL, *mine = NULL;
    size_t any_n = 0, mine_n = 0;
    for (const char *e = reg; e && *e;) {
        const char *end = strchr(e, ';'), *comma = strchr(e, ',');
        if (!end) end = e + strlen(e);
        if (!comma || comma > end) any = e, any_n = (size_t)(end - e);
        else {
            size_t n = (size_t)(comma - e);
            if (profile && strncasecmp(e, profile, n) == 0 && (!profile[n] || profile[n] == '_')) {
                for (mine = comma + 1; *mine == ' '; mine++) {}
                mine_n = (size_t)(end - mine);
            }
        }
        e = *end ? end + 1 : end;
    }
    const char *pick = mine ? mine : any;
    size_t n = mine ? mine_n : any_n;
    if (!pick || n >= cap) return NULL;
    memcpy(buf, pick, n);
    buf[n] = 0;
    return buf;
}

parse_declarator *hfx_pb_decl_annotations(parse_ctx *ctx, parse_declarator *d, parse_vec annotations) {
    if (!d) return d;
    for (uint32_t i = 0; i < annotations.count; i++)
        d->annotations = hfx_parse_vec_push(ctx, d->annotations, annotations.items[i]);
    return d;
}

parse_declarator *hfx_pb_decl_init(parse_declarator *d, hfx_expr *init) {
    if (d) d->init = init;
    return d;
}

static hfx_annotation_ast *annotation_array(parse_ctx *ctx, parse_vec v, uint32_t *count) {
    *count = 0;
    if (!v.count) return NULL;
    hfx_annotation_ast *a = HFX_NEW_ARRAY(ctx->arena, hfx_annotation_ast, v.count);
    if (!a) return NULL;
    for (uint32_t i = 0; i < v.count; i++) a[i] = *(hfx_annotation_ast *)v.items[i];
    *count = v.count;
    return a;
}

static hfx_decl *new_decl(parse_ctx *ctx, hfx_decl_kind kind, const char *name, hfx_loc loc) {
    hfx_decl *d = HFX_NEW(ctx->arena, hfx_decl);
    if (!d) {
        hfx_parse_fatal(ctx, loc, "out of memory");
        return NULL;
    }
    d->kind = kind;
    d->name = name;
    d->loc = loc;
    return d;
}

/* A declaration's variable from its specifiers and one declarator. */
static hfx_decl *var_decl(parse_ctx *ctx, hfx_decl_kind kind, parse_specs *specs, parse_declarator *dt) {
    hfx_decl *d = new_decl(ctx, kind, dt->name, dt->loc);
    if (!d) return NULL;
    d->type = hfx_pb_array_type(ctx, specs->type, dt->dims);
    d->mods = specs->mods;
    d->semantic = dt->semantic;
    d->reg = dt->reg;
    d->annotations = annotation_array(ctx, dt->annotations, &d->annotation_count);
    d->init = dt->init;
    return d;
}

/* The DECL_STRUCT a declaration introduces with `struct S {...}`, or NULL. */
hfx_decl *hfx_pb_struct_decl(parse_ctx *ctx, parse_specs *specs) {
    if (!specs->defines) return NULL;
    hfx_decl *d = new_decl(ctx, DECL_STRUCT, specs->defines->name, specs->defines->loc);
    if (d) d->type = specs->type;
    specs->defines = NULL;
    return d;
}

parse_vec hfx_pb_vars(parse_ctx *ctx, parse_specs *specs, parse_vec declarators, bool global) {
    parse_vec out = hfx_parse_vec_new();
    hfx_decl *st = hfx_pb_struct_decl(ctx, specs);
    if (st) out = hfx_parse_vec_push(ctx, out, st);
    for (uint32_t i = 0; i < declarators.count; i++) {
        parse_declarator *dt = declarators.items[i];
        hfx_decl *d = dt ? var_decl(ctx, DECL_VAR, specs, dt) : NULL;
        if (!d) continue;
        d->is_global = global;
        out = hfx_parse_vec_push(ctx, out, d);
    }
    return out;
}

parse_vec hfx_pb_typedefs(parse_ctx *ctx, parse_specs *specs, parse_vec declarators) {
    parse_vec out = hfx_parse_vec_new();
    hfx_decl *st = hfx_pb_struct_decl(ctx, specs);
    if (st) out = hfx_parse_vec_push(ctx, out, st);
    for (uint32_t i = 0; i < declarators.count; i++) {
        parse_declarator *dt = declarators.items[i];
        hfx_decl *d = dt ? var_decl(ctx, DECL_TYPEDEF, specs, dt) : NULL;
        if (!d) continue;
        parse_typename *e = hfx_parse_find_typename(ctx, d->name);
        if (e && !e->type && !e->st) {
            e->type = d->type;
            e->mods = d->mods;
        }
        out = hfx_parse_vec_push(ctx, out, d);
    }
    return out;
}

parse_vec hfx_pb_fields(parse_ctx *ctx, parse_vec fields, parse_specs *specs, parse_vec declarators) {
    for (uint32_t i = 0; i < declarators.count; i++) {
        parse_declarator *dt = declarators.items[i];
        hfx_field *f = dt ? HFX_NEW(ctx->arena, hfx_field) : NULL;
        if (!f) continue;
        f->name = dt->name;
        f->type = hfx_pb_array_type(ctx, specs->type, dt->dims);
        f->semantic = dt->semantic;
        f->mods = specs->mods;
        f->loc = dt->loc;
        fields = hfx_parse_vec_push(ctx, fields, f);
    }
    return fields;
}

/* ---- functions ---- */

hfx_decl *hfx_pb_param(parse_ctx *ctx, parse_specs *specs, parse_declarator *dt, hfx_loc loc) {
    if (!dt) {
        hfx_decl *d = new_decl(ctx, DECL_PARAM, NULL, loc);
        if (!d) return NULL;
        d->type = specs->type;
        d->mods = specs->mods;
        return d;
    }
    return var_decl(ctx, DECL_PARAM, specs, dt);
}

/* `f(void)` declares no parameter. */
static bool is_void_list(parse_vec params) {
    if (params.count != 1 || !params.items[0]) return false;
    const hfx_decl *p = params.items[0];
    return !p->name && p->type && p->type->kind == TY_VOID;
}

hfx_decl *hfx_pb_function(parse_ctx *ctx, parse_specs *specs, const char *name, hfx_loc loc, parse_vec params,
                      const char *semantic) {
    hfx_decl *d = new_decl(ctx, DECL_FUNC, name, loc);
    hfx_func *f = HFX_NEW(ctx->arena, hfx_func);
    if (!d || !f) return NULL;
    d->func = f;
    d->type = specs->type;
    d->mods = specs->mods;
    d->is_global = true;
    f->ret = specs->type;
    f->name = name;
    f->loc = loc;
    f->ret_semantic = semantic;
    if (is_void_list(params)) params.count = 0;
    uint32_t n = 0;
    for (uint32_t i = 0; i < params.count; i++)
        if (params.items[i]) params.items[n++] = params.items[i];
    f->params = (hfx_decl **)params.items;
    f->param_count = n;
    for (uint32_t i = 0; i < n; i++) f->params[i]->index = i;
    return d;
}

static hfx_attribute *attribute_array(parse_ctx *ctx, parse_vec v, uint32_t *count) {
    *count = 0;
    if (!v.count) return NULL;
    hfx_attribute *a = HFX_NEW_ARRAY(ctx->arena, hfx_attribute, v.count);
    if (!a) return NULL;
    for (uint32_t i = 0; i < v.count; i++) a[i] = *(hfx_attribute *)v.items[i];
    *count = v.count;
    return a;
}

hfx_decl *hfx_pb_function_body(parse_ctx *ctx, hfx_decl *fn, parse_vec attrs, hfx_stmt *body) {
    if (!fn) return NULL;
    fn->func->body = body;
    /* a prototype may leave parameters unnamed (as C does); a definition may not */
    for (uint32_t i = 0; body && i < fn->func->param_count; i++)
        if (!fn->func->params[i]->name)
            hfx_error(ctx->diags, fn->func->params[i]->loc, X_SYNTAX, "'%s': parameter %u has no name", fn->name,
                      i + 1);
    fn->func->attrs = attribute_array(ctx, attrs, &fn->func->attr_count);
    return fn;
}

hfx_annotation_ast *hfx_pb_annotation(parse_ctx *ctx, const hfx_type *type, parse_declarator *dt) {
    hfx_annotation_ast *a = HFX_NEW(ctx->arena, hfx_annotation_ast);
    if (!a || !dt) return a;
    a->type = hfx_pb_array_type(ctx, type, dt->dims);
    a->name = dt->name;
    a->value = dt->init;
    a->loc = dt->loc;
    return a;
}

hfx_attribute *hfx_pb_attribute(parse_ctx *ctx, const char *name, parse_vec args, hfx_loc loc) {
    hfx_attribute *a = HFX_NEW(ctx->arena, hfx_attribute);
    if (!a) return NULL;
    a->name = name;
    a->args = (hfx_expr **)args.items;
    a->arg_count = args.count;
    a->loc = loc;
    return a;
}

/* ---- techniques ---- */

hfx_state_assign *hfx_pb_state(parse_ctx *ctx, const char *name, hfx_expr *index, hfx_expr *value, hfx_loc loc) {
    hfx_state_assign *s = HFX_NEW(ctx->arena, hfx_state_assign);
    if (!s) return NULL;
    s->name = name;
    s->index = index;
    s->value = value;
    s->loc = loc;
    return s;
}

static hfx_state_assign *state_array(parse_ctx *ctx, parse_vec v, uint32_t *count) {
    *count = 0;
    hfx_state_assign *a = HFX_NEW_ARRAY(ctx->arena, hfx_state_assign, v.count ? v.count : 1);
    if (!a) return NULL;
    for (uint32_t i = 0; i < v.count; i++)
        if (v.items[i]) a[(*count)++] = *(hfx_state_assign *)v.items[i];
    return a;
}

hfx_pass_ast *hfx_pb_pass(parse_ctx *ctx, const char *name, parse_vec annotations, parse_vec states, hfx_loc loc) {
    hfx_pass_ast *p = HFX_NEW(ctx->arena, hfx_pass_ast);
    if (!p) return NULL;
    p->name = name;
    p->loc = loc;
    p->annotations = annotation_array(ctx, annotations, &p->annotation_count);
    p->states = state_array(ctx, states, &p->state_count);
    return p;
}

hfx_decl *hfx_pb_technique(parse_ctx *ctx, const char *keyword, const char *name, parse_vec annotations,
                       parse_vec passes, hfx_loc loc) {
    hfx_decl *d = new_decl(ctx, DECL_TECHNIQUE, name, loc);
    hfx_technique_ast *t = HFX_NEW(ctx->arena, hfx_technique_ast);
    hfx_pass_ast *p = HFX_NEW_ARRAY(ctx->arena, hfx_pass_ast, passes.count ? passes.count : 1);
    if (!d || !t || !p) return NULL;
    d->technique = t;
    d->is_global = true;
    t->name = name;
    t->keyword = keyword;
    t->annotations = annotation_array(ctx, annotations, &t->annotation_count);
    t->passes = p;
    for (uint32_t i = 0; i < passes.count; i++)
        if (passes.items[i]) t->passes[t->pass_count++] = *(hfx_pass_ast *)passes.items[i];
    return d;
}

void hfx_pb_global(parse_ctx *ctx, hfx_decl *d) {
    if (!d) return;
    d->is_global = true;
    ctx->globals = hfx_parse_vec_push(ctx, ctx->globals, d);
}

void hfx_pb_d3d10_ignored(parse_ctx *ctx, const char *what, const char *name, hfx_loc loc) {
    hfx_warning(ctx->diags, loc, X_UNSUPPORTED, "'%s': %s is Direct3D 10 effect syntax, ignored in fx_2_0", name ? name : "",
                what);
}

void hfx_pb_globals(parse_ctx *ctx, parse_vec decls) {
    for (uint32_t i = 0; i < decls.count; i++) hfx_pb_global(ctx, decls.items[i]);
}

/* ---- statements ---- */

typedef parse_stmt_node stmt_node;

static uint32_t stmt_depth(const hfx_stmt *s) { return s ? ((const stmt_node *)s)->depth : 0; }

hfx_stmt *hfx_pb_stmt(parse_ctx *ctx, hfx_stmt_kind kind, hfx_loc loc) {
    stmt_node *n = HFX_NEW(ctx->arena, stmt_node);
    if (!n) {
        hfx_parse_fatal(ctx, loc, "out of memory");
        n = ctx->oom_stmt;
    }
    n->s.kind = kind;
    n->s.loc = loc;
    n->depth = 1;
    return &n->s;
}

/* Records s's depth from its children; too deep is fatal (recursive passes must not overflow). */
static hfx_stmt *deepen(parse_ctx *ctx, hfx_stmt *s, const hfx_stmt *a, const hfx_stmt *b, const hfx_stmt *c) {
    uint32_t d = stmt_depth(a);
    if (stmt_depth(b) > d) d = stmt_depth(b);
    if (stmt_depth(c) > d) d = stmt_depth(c);
    if (((stmt_node *)s)->depth < d + 1) ((stmt_node *)s)->depth = d + 1;
    if (d + 1 > PARSE_MAX_STMT_DEPTH)
        hfx_parse_fatal(ctx, s->loc, "nesting too deep: statements more than 1024 levels deep");
    return s;
}

hfx_stmt *hfx_pb_block(parse_ctx *ctx, parse_vec stmts, hfx_loc loc) {
    hfx_stmt *s = hfx_pb_stmt(ctx, ST_BLOCK, loc);
    uint32_t n = 0;
    for (uint32_t i = 0; i < stmts.count; i++)
        if (stmts.items[i]) {
            stmts.items[n++] = stmts.items[i];
            deepen(ctx, s, stmts.items[i], NULL, NULL);
        }
    s->body = (hfx_stmt **)stmts.items;
    s->body_count = n;
    return s;
}

hfx_stmt *hfx_pb_decl_stmt(parse_ctx *ctx, parse_vec decls, hfx_loc loc) {
    uint32_t n = 0;
    for (uint32_t i = 0; i < decls.count; i++)
        if (decls.items[i]) decls.items[n++] = decls.items[i];
    hfx_stmt *s = hfx_pb_stmt(ctx, n ? ST_DECL : ST_EMPTY, loc);
    s->decls = (hfx_decl **)decls.items;
    s->decl_count = n;
    return s;
}

hfx_stmt *hfx_pb_expr_stmt(parse_ctx *ctx, hfx_stmt_kind kind, hfx_expr *e, hfx_loc loc) {
    hfx_stmt *s = hfx_pb_stmt(ctx, kind, loc);
    s->expr = e;
    return s;
}

hfx_stmt *hfx_pb_if(parse_ctx *ctx, hfx_expr *cond, hfx_stmt *then_stmt, hfx_stmt *else_stmt, hfx_loc loc) {
    hfx_stmt *s = hfx_pb_stmt(ctx, ST_IF, loc);
    s->expr = cond;
    s->then_stmt = then_stmt;
    s->else_stmt = else_stmt;
    return deepen(ctx, s, then_stmt, else_stmt, NULL);
}

hfx_stmt *hfx_pb_loop(parse_ctx *ctx, hfx_stmt_kind kind, hfx_expr *cond, hfx_stmt *body, hfx_loc loc) {
    hfx_stmt *s = hfx_pb_stmt(ctx, kind, loc);
    s->expr = cond;
    s->then_stmt = body;
    return deepen(ctx, s, body, NULL, NULL);
}

hfx_stmt *hfx_pb_for(parse_ctx *ctx, hfx_stmt *init, hfx_expr *cond, hfx_expr *step, hfx_stmt *body, hfx_loc loc) {
    hfx_stmt *s = hfx_pb_stmt(ctx, ST_FOR, loc);
    s->init = init;
    s->expr = cond;
    s->step = step;
    s->then_stmt = body;
    return deepen(ctx, s, init, body, NULL);
}

hfx_stmt *hfx_pb_switch(parse_ctx *ctx, hfx_expr *e, parse_vec body, hfx_loc loc) {
    hfx_stmt *s = hfx_pb_block(ctx, body, loc);
    s->kind = ST_SWITCH;
    s->expr = e;
    return s;
}

hfx_stmt *hfx_pb_attributed(parse_ctx *ctx, hfx_attribute *attr, hfx_stmt *s) {
    if (!attr) return s;
    hfx_attribute *a = HFX_NEW_ARRAY(ctx->arena, hfx_attribute, s->attr_count + 1);
    if (!a) return s;
    a[0] = *attr;
    if (s->attr_count) memcpy(a + 1, s->attrs, sizeof *a * s->attr_count);
    s->attrs = a;
    s->attr_count++;
    return s;
}

hfx_stmt *hfx_pb_asm_stmt(parse_ctx *ctx, const char *text, hfx_loc loc) {
    return hfx_pb_expr_stmt(ctx, ST_ASM, hfx_pb_asm(ctx, text, loc), loc);
}
