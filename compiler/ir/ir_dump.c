/* ir_dump.c: the IR as indented text with S-expressions, for golden tests and hfxc debugging.
 * Types print in HLSL spelling; constants with %g. */
#include <stdio.h>
#include <stdlib.h>

#include "base/sbuf.h"
#include "ir/ir.h"

static const char *type_name(const hfx_type *t) {
    static const char *const scal[] = { "bool", "int", "uint", "half", "float", "double", "min16float", "?" };
    switch (t->kind) {
    case TY_VOID: return "void";
    case TY_SCALAR: return scal[t->base];
    case TY_STRUCT: return t->st->name ? t->st->name : "struct";
    case TY_SAMPLER: return "sampler";
    default: return NULL;
    }
}

static void put_type(sbuf *b, const hfx_type *t) {
    const char *n = type_name(t);
    if (n) { hfx_sb_put(b, n); return; }
    static const char *const scal[] = { "bool", "int", "uint", "half", "float", "double", "min16float", "?" };
    if (t->kind == TY_VECTOR) hfx_sb_printf(b, "%s%u", scal[t->base], t->cols);
    else if (t->kind == TY_MATRIX) hfx_sb_printf(b, "%s%ux%u", scal[t->base], t->rows, t->cols);
    else if (t->kind == TY_ARRAY) { put_type(b, t->elem); hfx_sb_printf(b, "[%u]", t->array_len); }
    else hfx_sb_put(b, "object");
}

static const char *op_name(hfx_op op) {
    static const char *const n[] = {
        [OP_NONE] = "=", [OP_NEG] = "neg", [OP_POS] = "pos", [OP_NOT] = "not", [OP_BITNOT] = "bitnot",
        [OP_PREINC] = "preinc", [OP_PREDEC] = "predec", [OP_POSTINC] = "postinc", [OP_POSTDEC] = "postdec",
        [OP_ADD] = "+", [OP_SUB] = "-", [OP_MUL] = "*", [OP_DIV] = "/", [OP_MOD] = "%", [OP_SHL] = "<<",
        [OP_SHR] = ">>", [OP_BITAND] = "&", [OP_BITOR] = "|", [OP_BITXOR] = "^", [OP_LT] = "<", [OP_GT] = ">",
        [OP_LE] = "<=", [OP_GE] = ">=", [OP_EQ] = "==", [OP_NE] = "!=", [OP_AND] = "&&", [OP_OR] = "||",
    };
    return op < sizeof n / sizeof *n && n[op] ? n[op] : "?";
}

static void put_expr(sbuf *b, const ir_expr *e) {
    if (!e) { hfx_sb_put(b, "null"); return; }
    switch (e->kind) {
    case IE_CONST: {
        hfx_sb_put(b, "(const ");
        put_type(b, e->type);
        unsigned n = hfx_type_is_numeric(e->type) ? hfx_type_components(e->type) : 0;
        for (unsigned i = 0; i < n && i < 16; i++) hfx_sb_printf(b, " %g", e->cval[i]);
        hfx_sb_put(b, ")");
        return;
    }
    case IE_VAR: {
        static const char *const kinds[] = { "local", "param", "uniform", "private", "sampler" };
        hfx_sb_printf(b, "(%s %s)", kinds[e->var->kind], e->var->name);
        return;
    }
    case IE_UNARY: case IE_BINARY: hfx_sb_printf(b, "(%s", op_name(e->op)); break;
    case IE_ASSIGN: hfx_sb_printf(b, "(assign%s%s", e->op ? " " : "", e->op ? op_name(e->op) : ""); break;
    case IE_SELECT: hfx_sb_put(b, "(select"); break;
    case IE_COMMA: hfx_sb_put(b, "(comma"); break;
    case IE_CALL: hfx_sb_printf(b, "(call %s", e->fn->name); break;
    case IE_INTRIN: hfx_sb_printf(b, "(%s", hfx_intrinsic_name((int)e->intrin) ? hfx_intrinsic_name((int)e->intrin) : "?"); break;
    case IE_CONSTRUCT: hfx_sb_put(b, "(construct "); put_type(b, e->type); break;
    case IE_CONVERT: hfx_sb_put(b, "(convert "); put_type(b, e->type); break;
    case IE_SWIZZLE:
        hfx_sb_put(b, "(swizzle ");
        for (unsigned i = 0; i < e->comp_count; i++) hfx_sb_printf(b, "%s%u", i ? "," : "", e->comps[i]);
        break;
    case IE_INDEX: hfx_sb_put(b, "(index"); break;
    case IE_FIELD: hfx_sb_printf(b, "(field %s", e->a[0]->type->st->fields[e->field].name); break;
    }
    for (uint32_t i = 0; i < e->n; i++) { hfx_sb_put(b, " "); put_expr(b, e->a[i]); }
    hfx_sb_put(b, ")");
}

static void indent(sbuf *b, int n) { for (int i = 0; i < n; i++) hfx_sb_put(b, "  "); }

static void put_stmt(sbuf *b, const ir_stmt *s, int depth) {
    static const char *const names[] = { "block", "decl", "expr", "if", "for", "while", "do", "switch", "case",
                                         "default", "break", "continue", "discard", "return" };
    indent(b, depth);
    hfx_sb_put(b, names[s->kind]);
    if (s->hint) hfx_sb_printf(b, " [%s]", s->hint);
    if (s->kind == IS_DECL) { hfx_sb_put(b, " "); put_type(b, s->var->type); hfx_sb_printf(b, " %s", s->var->name); }
    if (s->expr) { hfx_sb_put(b, " "); put_expr(b, s->expr); }
    hfx_sb_put(b, "\n");
    if (s->init) put_stmt(b, s->init, depth + 1);
    if (s->step) { indent(b, depth + 1); hfx_sb_put(b, "step "); put_expr(b, s->step); hfx_sb_put(b, "\n"); }
    for (uint32_t i = 0; i < s->count; i++) put_stmt(b, s->body[i], depth + 1);
    if (s->then_s) put_stmt(b, s->then_s, depth + 1);
    if (s->else_s) { indent(b, depth); hfx_sb_put(b, "else\n"); put_stmt(b, s->else_s, depth + 1); }
}

static void put_func(sbuf *b, const ir_func *f) {
    hfx_sb_printf(b, "function %s : ", f->name);
    put_type(b, f->ret);
    hfx_sb_put(b, "\n");
    for (uint32_t i = 0; i < f->param_count; i++) {
        const ir_var *v = f->params[i];
        hfx_sb_printf(b, "  param %s", (v->mods & MOD_OUT) ? ((v->mods & MOD_IN) ? "inout " : "out ") : "");
        put_type(b, v->type);
        hfx_sb_printf(b, " %s\n", v->name);
    }
    put_stmt(b, f->body, 1);
}

char *hfx_ir_dump_func(const ir_func *f) {
    sbuf b = {0};
    put_func(&b, f);
    return b.d;
}

char *hfx_ir_dump_shader(const ir_shader *sh) {
    sbuf b = {0};
    hfx_sb_printf(&b, "shader %s %s\n", sh->stage == IR_VERTEX ? "vertex" : "pixel", sh->entry->name);
    for (uint32_t i = 0; i < sh->global_count; i++) {
        static const char *const kinds[] = { "local", "param", "uniform", "private", "sampler" };
        const ir_var *v = sh->globals[i];
        hfx_sb_printf(&b, "global %s ", kinds[v->kind]);
        put_type(&b, v->type);
        hfx_sb_printf(&b, " %s\n", v->glsl);
    }
    for (uint32_t i = 0; i < sh->pre_count; i++) { /* what the CPU computes for it, in HLSL */
        const ir_var *v = sh->pres[i];
        hfx_sb_put(&b, "preshader ");
        put_type(&b, v->type);
        hfx_sb_printf(&b, " %s = %s\n", v->glsl, v->pre_text ? v->pre_text : "?");
    }
    for (uint32_t i = 0; i < sh->func_count; i++) put_func(&b, sh->funcs[i]);
    return b.d;
}
