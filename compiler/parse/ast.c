/* ast.c: hfx_ast_dump, the readable tree behind `hfxc --ast` and the parser tests. One node
 * a line, two spaces of indent a level; expressions print inline in source-like form with
 * every operator parenthesized, so precedence is visible. Recursion is bounded (the parser
 * bounds tree depth; the dump stops at DUMP_MAX_DEPTH anyway). */
#include "parse/ast.h"

#include "base/sbuf.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { DUMP_MAX_DEPTH = 4500 }; /* just above the parser's own limits (ast.h trees from hfx_parse) */

typedef struct dump {
    sbuf out;
    hfx_arena arena;  /* for type names */
} dump;

static void put(dump *d, const char *s, size_t n) { hfx_sb_putn(&d->out, s, n); }

static void puts_(dump *d, const char *s) { put(d, s, strlen(s)); }

__attribute__((format(printf, 2, 3))) static void putf(dump *d, const char *fmt, ...) {
    char tmp[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    if (n > 0) put(d, tmp, (size_t)n < sizeof tmp ? (size_t)n : sizeof tmp - 1);
}

static void indent(dump *d, int level) {
    for (int i = 0; i < level; i++) put(d, "  ", 2);
}

/* ---- types and modifiers ---- */

static void dump_expr(dump *d, const hfx_expr *e, int depth);

static void dump_type(dump *d, const hfx_type *t) {
    if (!t) {
        puts_(d, "?");
        return;
    }
    if (t->kind != TY_ARRAY) {
        puts_(d, hfx_type_name(&d->arena, t));
        return;
    }
    const hfx_type *elem = t;
    while (elem->kind == TY_ARRAY) elem = elem->elem;
    puts_(d, hfx_type_name(&d->arena, elem));
    for (; t->kind == TY_ARRAY; t = t->elem) {
        puts_(d, "[");
        if (t->array_len_expr) dump_expr(d, t->array_len_expr, 0);
        else if (t->array_len) putf(d, "%u", t->array_len);
        puts_(d, "]");
    }
}

static void dump_mods(dump *d, uint32_t mods) {
    static const char *const names[] = {
        "in", "out", "uniform", "static", "extern", "shared", "const", "volatile", "row_major",
        "column_major", "inline", "linear", "centroid", "nointerpolation", "noperspective", "sample",
        "precise", "groupshared",
    };
    for (unsigned i = 0; i < sizeof names / sizeof *names; i++)
        if (mods & (1u << i)) putf(d, "%s ", names[i]);
}

/* ---- expressions ---- */

static const char *op_text(hfx_op op) {
    static const char *const ops[] = {
        "", "-", "+", "!", "~", "++", "--", "++", "--",
        "+", "-", "*", "/", "%", "<<", ">>", "&", "|", "^",
        "<", ">", "<=", ">=", "==", "!=", "&&", "||",
    };
    return (unsigned)op < sizeof ops / sizeof *ops ? ops[op] : "?";
}

static void dump_string(dump *d, const char *s) {
    puts_(d, "\"");
    for (; s && *s; s++) {
        if (*s == '"' || *s == '\\') putf(d, "\\%c", *s);
        else if (*s == '\n') puts_(d, "\\n");
        else if ((unsigned char)*s < 32) putf(d, "\\x%02x", (unsigned char)*s);
        else put(d, s, 1);
    }
    puts_(d, "\"");
}

static void dump_args(dump *d, const hfx_expr *e, uint32_t from, int depth) {
    puts_(d, "(");
    for (uint32_t i = from; i < e->arg_count; i++) {
        if (i > from) puts_(d, ", ");
        dump_expr(d, e->args[i], depth + 1);
    }
    puts_(d, ")");
}

static void dump_float(dump *d, double v) {
    char tmp[64];
    snprintf(tmp, sizeof tmp, "%.9g", v);
    puts_(d, tmp);
    if (!strpbrk(tmp, ".eni")) puts_(d, ".0"); /* keeps 1.0 apart from the integer 1 */
}

static void dump_state_list(dump *d, const hfx_state_assign *s, uint32_t n, int depth);

static void dump_operator(dump *d, const hfx_expr *e, int depth) {
    const hfx_expr *a = e->arg_count > 0 ? e->args[0] : NULL, *b = e->arg_count > 1 ? e->args[1] : NULL;
    puts_(d, "(");
    switch (e->kind) {
    case EX_UNARY:
        if (e->op == OP_POSTINC || e->op == OP_POSTDEC) {
            dump_expr(d, a, depth + 1);
            puts_(d, op_text(e->op));
        } else {
            puts_(d, op_text(e->op));
            dump_expr(d, a, depth + 1);
        }
        break;
    case EX_BINARY:
    case EX_ASSIGN:
    case EX_COMMA:
        dump_expr(d, a, depth + 1);
        if (e->kind == EX_COMMA) puts_(d, ", ");
        else putf(d, " %s%s ", op_text(e->op), e->kind == EX_ASSIGN ? "=" : "");
        dump_expr(d, b, depth + 1);
        break;
    case EX_TERNARY:
        dump_expr(d, a, depth + 1);
        puts_(d, " ? ");
        dump_expr(d, b, depth + 1);
        puts_(d, " : ");
        dump_expr(d, e->arg_count > 2 ? e->args[2] : NULL, depth + 1);
        break;
    default: break;
    }
    puts_(d, ")");
}

static void dump_expr_inner(dump *d, const hfx_expr *e, int depth) {
    switch (e->kind) {
    case EX_INT: putf(d, "%lld", (long long)e->ival); break;
    case EX_FLOAT: dump_float(d, e->fval); break;
    case EX_BOOL: puts_(d, e->ival ? "true" : "false"); break;
    case EX_STRING: dump_string(d, e->sval); break;
    case EX_IDENT: puts_(d, e->name); break;
    case EX_UNARY: case EX_BINARY: case EX_ASSIGN: case EX_TERNARY: case EX_COMMA:
        dump_operator(d, e, depth);
        break;
    case EX_CALL:
        puts_(d, e->name);
        dump_args(d, e, 0, depth);
        break;
    case EX_METHOD:
        dump_expr(d, e->arg_count ? e->args[0] : NULL, depth + 1);
        putf(d, ".%s", e->name);
        dump_args(d, e, 1, depth);
        break;
    case EX_CONSTRUCT:
        dump_type(d, e->cast_type);
        dump_args(d, e, 0, depth);
        break;
    case EX_CAST:
        puts_(d, e->implicit ? "implicit(" : "(");
        dump_type(d, e->cast_type);
        puts_(d, ")");
        dump_expr(d, e->arg_count ? e->args[0] : NULL, depth + 1);
        break;
    case EX_MEMBER: case EX_SWIZZLE: case EX_FIELD:
        dump_expr(d, e->arg_count ? e->args[0] : NULL, depth + 1);
        putf(d, ".%s", e->name ? e->name : "?");
        break;
    case EX_INDEX:
        dump_expr(d, e->arg_count ? e->args[0] : NULL, depth + 1);
        puts_(d, "[");
        dump_expr(d, e->arg_count > 1 ? e->args[1] : NULL, depth + 1);
        puts_(d, "]");
        break;
    case EX_INIT_LIST:
        puts_(d, "{");
        for (uint32_t i = 0; i < e->arg_count; i++) {
            if (i) puts_(d, ", ");
            dump_expr(d, e->args[i], depth + 1);
        }
        puts_(d, "}");
        break;
    case EX_COMPILE:
        putf(d, "compile %s %s", e->profile, e->name);
        dump_args(d, e, 0, depth);
        break;
    case EX_SAMPLER_STATE:
        puts_(d, "sampler_state {");
        dump_state_list(d, e->states, e->state_count, depth);
        puts_(d, " }");
        break;
    case EX_STATE_REF: putf(d, "<%s>", e->name); break;
    case EX_ASM: puts_(d, "asm { "); puts_(d, e->sval ? e->sval : ""); puts_(d, " }"); break;
    case EX_NULL: puts_(d, "NULL"); break;
    }
}

static void dump_expr(dump *d, const hfx_expr *e, int depth) {
    if (!e) {
        puts_(d, "<null>");
        return;
    }
    if (depth > DUMP_MAX_DEPTH) {
        puts_(d, "...");
        return;
    }
    bool parens = e->parenthesized && e->kind != EX_UNARY && e->kind != EX_BINARY && e->kind != EX_ASSIGN &&
                  e->kind != EX_TERNARY && e->kind != EX_COMMA;
    if (parens) puts_(d, "(");
    dump_expr_inner(d, e, depth);
    if (parens) puts_(d, ")");
}

static void dump_state(dump *d, const hfx_state_assign *s, int depth) {
    puts_(d, s->name);
    if (s->index) {
        puts_(d, "[");
        dump_expr(d, s->index, depth + 1);
        puts_(d, "]");
    }
    puts_(d, " = ");
    dump_expr(d, s->value, depth + 1);
}

static void dump_state_list(dump *d, const hfx_state_assign *s, uint32_t n, int depth) {
    for (uint32_t i = 0; i < n; i++) {
        puts_(d, " ");
        dump_state(d, &s[i], depth);
        puts_(d, ";");
    }
}

/* ---- declarations ---- */

static void dump_annotations(dump *d, const hfx_annotation_ast *a, uint32_t n, int level) {
    for (uint32_t i = 0; i < n; i++) {
        indent(d, level);
        puts_(d, "annotation ");
        dump_type(d, a[i].type);
        putf(d, " %s = ", a[i].name);
        dump_expr(d, a[i].value, 0);
        puts_(d, "\n");
    }
}

static void dump_var_line(dump *d, const hfx_decl *v) {
    dump_mods(d, v->mods);
    dump_type(d, v->type);
    putf(d, " %s", v->name ? v->name : "<unnamed>");
    if (v->semantic) putf(d, " : %s", v->semantic);
    for (const char *r = v->reg; r && *r;) { /* one `: register(...)` for each written */
        const char *end = strchr(r, ';');
        int n = end ? (int)(end - r) : (int)strlen(r);
        putf(d, " : register(%.*s)", n, r);
        r += n + (end != NULL);
    }
}

static void dump_var(dump *d, const char *what, const hfx_decl *v, int level) {
    indent(d, level);
    putf(d, "%s ", what);
    dump_var_line(d, v);
    if (v->init) {
        puts_(d, " = ");
        dump_expr(d, v->init, 0);
    }
    puts_(d, "\n");
    dump_annotations(d, v->annotations, v->annotation_count, level + 1);
}

static void dump_struct(dump *d, const hfx_decl *s, int level) {
    indent(d, level);
    putf(d, "struct %s\n", s->name ? s->name : "<anonymous>");
    const hfx_struct *st = s->type && s->type->kind == TY_STRUCT ? s->type->st : NULL;
    for (uint32_t i = 0; st && i < st->field_count; i++) {
        const hfx_field *f = &st->fields[i];
        indent(d, level + 1);
        puts_(d, "field ");
        dump_mods(d, f->mods);
        dump_type(d, f->type);
        putf(d, " %s", f->name);
        if (f->semantic) putf(d, " : %s", f->semantic);
        puts_(d, "\n");
    }
}

static void dump_attributes(dump *d, const hfx_attribute *a, uint32_t n) {
    for (uint32_t i = 0; i < n; i++) {
        putf(d, "[%s", a[i].name);
        if (a[i].arg_count) {
            puts_(d, "(");
            for (uint32_t j = 0; j < a[i].arg_count; j++) {
                if (j) puts_(d, ", ");
                dump_expr(d, a[i].args[j], 0);
            }
            puts_(d, ")");
        }
        puts_(d, "] ");
    }
}

static void dump_stmt(dump *d, const hfx_stmt *s, int level);

static void dump_decl(dump *d, const hfx_decl *decl, int level) {
    switch (decl->kind) {
    case DECL_VAR: dump_var(d, "var", decl, level); break;
    case DECL_PARAM: dump_var(d, "param", decl, level); break;
    case DECL_TYPEDEF: dump_var(d, "typedef", decl, level); break;
    case DECL_STRUCT: dump_struct(d, decl, level); break;
    case DECL_FUNC: {
        const hfx_func *f = decl->func;
        indent(d, level);
        puts_(d, "function ");
        dump_attributes(d, f->attrs, f->attr_count);
        dump_mods(d, decl->mods);
        dump_type(d, f->ret);
        putf(d, " %s", f->name);
        if (f->ret_semantic) putf(d, " : %s", f->ret_semantic);
        puts_(d, f->body ? "\n" : " (prototype)\n");
        for (uint32_t i = 0; i < f->param_count; i++) dump_var(d, "param", f->params[i], level + 1);
        if (f->body) dump_stmt(d, f->body, level + 1);
        break;
    }
    case DECL_TECHNIQUE: {
        const hfx_technique_ast *t = decl->technique;
        indent(d, level);
        putf(d, "technique %s", t->name ? t->name : "<anonymous>");
        if (t->keyword && strcmp(t->keyword, "technique") != 0) putf(d, " (%s)", t->keyword);
        puts_(d, "\n");
        dump_annotations(d, t->annotations, t->annotation_count, level + 1);
        for (uint32_t i = 0; i < t->pass_count; i++) {
            const hfx_pass_ast *p = &t->passes[i];
            indent(d, level + 1);
            putf(d, "pass %s\n", p->name ? p->name : "<anonymous>");
            dump_annotations(d, p->annotations, p->annotation_count, level + 2);
            for (uint32_t j = 0; j < p->state_count; j++) {
                indent(d, level + 2);
                puts_(d, "state ");
                dump_state(d, &p->states[j], 0);
                puts_(d, "\n");
            }
        }
        break;
    }
    }
}

/* ---- statements ---- */

static void dump_stmt_line(dump *d, const char *head, const hfx_expr *e, int level) {
    indent(d, level);
    puts_(d, head);
    if (e) {
        puts_(d, " ");
        dump_expr(d, e, 0);
    }
    puts_(d, "\n");
}

static void dump_stmt(dump *d, const hfx_stmt *s, int level) {
    if (!s) return;
    if (level > DUMP_MAX_DEPTH) {
        indent(d, 1);
        puts_(d, "...\n");
        return;
    }
    if (s->attr_count) {
        indent(d, level);
        dump_attributes(d, s->attrs, s->attr_count);
        puts_(d, "\n");
    }
    switch (s->kind) {
    case ST_BLOCK:
        dump_stmt_line(d, "block", NULL, level);
        for (uint32_t i = 0; i < s->body_count; i++) dump_stmt(d, s->body[i], level + 1);
        break;
    case ST_DECL:
        for (uint32_t i = 0; i < s->decl_count; i++) dump_decl(d, s->decls[i], level);
        break;
    case ST_EXPR: dump_stmt_line(d, "expr", s->expr, level); break;
    case ST_IF:
        dump_stmt_line(d, "if", s->expr, level);
        dump_stmt(d, s->then_stmt, level + 1);
        if (s->else_stmt) {
            dump_stmt_line(d, "else", NULL, level);
            dump_stmt(d, s->else_stmt, level + 1);
        }
        break;
    case ST_FOR:
        dump_stmt_line(d, "for", NULL, level);
        if (s->init) dump_stmt(d, s->init, level + 2);
        dump_stmt_line(d, "  cond", s->expr, level);
        dump_stmt_line(d, "  step", s->step, level);
        dump_stmt(d, s->then_stmt, level + 1);
        break;
    case ST_WHILE:
        dump_stmt_line(d, "while", s->expr, level);
        dump_stmt(d, s->then_stmt, level + 1);
        break;
    case ST_DO:
        dump_stmt_line(d, "do", NULL, level);
        dump_stmt(d, s->then_stmt, level + 1);
        dump_stmt_line(d, "while", s->expr, level);
        break;
    case ST_SWITCH:
        dump_stmt_line(d, "switch", s->expr, level);
        for (uint32_t i = 0; i < s->body_count; i++) dump_stmt(d, s->body[i], level + 1);
        break;
    case ST_CASE: dump_stmt_line(d, "case", s->expr, level); break;
    case ST_DEFAULT: dump_stmt_line(d, "default", NULL, level); break;
    case ST_BREAK: dump_stmt_line(d, "break", NULL, level); break;
    case ST_CONTINUE: dump_stmt_line(d, "continue", NULL, level); break;
    case ST_DISCARD: dump_stmt_line(d, "discard", NULL, level); break;
    case ST_RETURN: dump_stmt_line(d, "return", s->expr, level); break;
    case ST_EMPTY: dump_stmt_line(d, "empty", NULL, level); break;
    case ST_ASM: dump_stmt_line(d, "asm", s->expr, level); break;
    }
}

char *hfx_ast_dump(const hfx_ast *ast) {
    dump d;
    memset(&d, 0, sizeof d);
    hfx_arena_init(&d.arena);
    puts_(&d, "");
    for (uint32_t i = 0; ast && i < ast->decl_count; i++) dump_decl(&d, ast->decls[i], 0);
    hfx_arena_free(&d.arena);
    return hfx_sb_take(&d.out);
}

_Static_assert(OP_BITNOT - OP_NEG == HFX_EV_BITNOT - HFX_EV_NEG && OP_OR - OP_ADD == HFX_EV_OR - HFX_EV_ADD,
               "hfx_op and hfx_ev_op list their operators in the same order");

bool hfx_op_ev(hfx_op op, hfx_ev_op *out) {
    if (op >= OP_NEG && op <= OP_BITNOT) *out = (hfx_ev_op)(HFX_EV_NEG + (op - OP_NEG));
    else if (op >= OP_ADD && op <= OP_OR) *out = (hfx_ev_op)(HFX_EV_ADD + (op - OP_ADD));
    else return false;
    return true;
}
