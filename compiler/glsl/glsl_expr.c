/* hfx_glsl_expr.c: IR expressions as GLSL text, with HLSL's meaning. The matrix convention
 * (docs/conventions.md): HLSL floatRxC is GLSL mat{R}x{C} whose column i holds HLSL row i, so
 * mul(v, M) prints `M * v`, mul(M, v) `v * M`, mul(A, B) `B * A`, M[i] is m[i], M._m01 m[0][1]. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glsl/glsl_int.h"

void hfx_glsl_error(gp *p, hfx_loc loc, const char *msg) {
    hfx_error(p->c->diags, loc, X_UNSUPPORTED, "%s", msg);
    p->failed = true;
}

bool hfx_glsl_is_matrix(const hfx_type *t) { return t->kind == TY_MATRIX && t->rows > 1 && t->cols > 1; }

static bool is_float(hfx_base b) { return b == B_FLOAT || b == B_HALF || b == B_DOUBLE || b == B_MIN16FLOAT; }
static unsigned ncomp(const hfx_type *t) { return hfx_type_is_numeric(t) ? hfx_type_components(t) : 0; }

static const char *scalar_name(gp *p, hfx_base b) {
    switch (b) {
    case B_BOOL: return "bool";
    case B_INT: return "int";
    case B_UINT: return p && p->legacy ? "int" : "uint";
    default: return "float";
    }
}

/* Type names from tables: the printer asks for one per declaration and constructor. */
static const char *vec_name(gp *p, hfx_base b, unsigned n) {
    static const char *const names[4][5] = {
        {"", "float", "vec2", "vec3", "vec4"},
        {"", "bool", "bvec2", "bvec3", "bvec4"},
        {"", "int", "ivec2", "ivec3", "ivec4"},
        {"", "uint", "uvec2", "uvec3", "uvec4"},
    };
    int row = b == B_BOOL ? 1 : b == B_INT ? 2 : b == B_UINT ? (p->legacy ? 2 : 3) : 0;
    return n <= 4 ? names[row][n] : "float";
}

static const char *mat_name(unsigned rows, unsigned cols) {
    static const char *const names[3][3] = {
        {"mat2", "mat2x3", "mat2x4"}, {"mat3x2", "mat3", "mat3x4"}, {"mat4x2", "mat4x3", "mat4"},
    };
    return rows >= 2 && rows <= 4 && cols >= 2 && cols <= 4 ? names[rows - 2][cols - 2] : "float";
}

static void add_struct(gp *p, const hfx_type *t) {
    for (uint32_t i = 0; i < p->struct_count; i++)
        if (p->structs[i]->st == t->st) return;
    for (uint32_t i = 0; i < t->st->field_count; i++) {
        const hfx_type *f = t->st->fields[i].type;
        while (f->kind == TY_ARRAY) f = f->elem;
        if (f->kind == TY_STRUCT) add_struct(p, f);
    }
    if (!HFX_ARENA_GROW(p->c->arena, p->structs, p->struct_count, p->struct_cap, 8)) return;
    p->structs[p->struct_count++] = t;
    size_t from = p->structs_text.len;
    const char *name = hfx_glsl_type(p, t);
    hfx_sb_printf(&p->structs_text, "struct %s\n{\n", name);
    for (uint32_t i = 0; i < t->st->field_count; i++) {
        const hfx_field *f = &t->st->fields[i];
        hfx_sb_put(&p->structs_text, "    ");
        hfx_glsl_decl(p, &p->structs_text, f->type, hfx_glsl_name(p->c->arena, f->name));
        hfx_sb_put(&p->structs_text, ";\n");
    }
    hfx_sb_put(&p->structs_text, "};\n\n");
    hfx_glsl_record_struct(p, name, from);
}

const char *hfx_glsl_type(gp *p, const hfx_type *t) {
    hfx_arena *a = p->c->arena;
    switch (t->kind) {
    case TY_VOID: return "void";
    case TY_SCALAR: return scalar_name(p, t->base);
    case TY_VECTOR: return t->cols == 1 ? scalar_name(p, t->base) : vec_name(p, t->base, t->cols);
    case TY_MATRIX:
        if (t->rows == 1 && t->cols == 1) return scalar_name(p, t->base);
        if (t->rows == 1 || t->cols == 1) return vec_name(p, t->base, t->rows * t->cols);
        if (t->rows != t->cols && p->legacy) p->nonsquare = true; /* reported once, by hfx_glsl_print */
        return mat_name(t->rows, t->cols);
    case TY_ARRAY: return hfx_glsl_type(p, t->elem);
    case TY_STRUCT: {
        const char *name = t->st->name ? hfx_glsl_name(a, t->st->name)
                                       : hfx_arena_printf(a, "hfx_struct_%u_%u", t->st->loc.line, t->st->loc.col);
        return name;
    }
    case TY_SAMPLER:
        switch (t->dim) {
        case DIM_3D: return "sampler3D";
        case DIM_CUBE: return "samplerCube";
        default: return "sampler2D";
        }
    default: return "float";
    }
}

static void use_type(gp *p, const hfx_type *t) {
    while (t->kind == TY_ARRAY) t = t->elem;
    if (t->kind == TY_STRUCT) add_struct(p, t);
}

const char *hfx_glsl_ctor_type(gp *p, const hfx_type *t) {
    use_type(p, t);
    if (t->kind != TY_ARRAY) return hfx_glsl_type(p, t);
    return hfx_arena_printf(p->c->arena, "%s[%u]", hfx_glsl_ctor_type(p, t->elem), t->array_len);
}

void hfx_glsl_decl(gp *p, sbuf *out, const hfx_type *t, const char *name) {
    use_type(p, t);
    const hfx_type *e = t;
    while (e->kind == TY_ARRAY) e = e->elem;
    hfx_sb_put(out, hfx_glsl_type(p, e));
    hfx_sb_putn(out, " ", 1);
    hfx_sb_put(out, name);
    for (e = t; e->kind == TY_ARRAY; e = e->elem) hfx_sb_printf(out, "[%u]", e->array_len);
}

static void put_float(gp *p, double v) {
    char buf[48];
    if (isnan(v)) { hfx_sb_put(p->out, "(0.0 / 0.0)"); return; }
    if (isinf(v)) { hfx_sb_put(p->out, v > 0 ? "3.40282347e+38" : "-3.40282347e+38"); return; }
    float f = (float)v;
    if (f == truncf(f) && fabsf(f) < 1e9f) { /* what %.9g prints for integers, without snprintf */
        hfx_sb_printf(p->out, "%s%lld.0", signbit(f) && f == 0 ? "-" : "", (long long)hfx_ev_int(f));
        return;
    }
    snprintf(buf, sizeof buf, "%.9g", (double)f);
    if (!strpbrk(buf, ".e")) strcat(buf, ".0");
    hfx_sb_put(p->out, buf);
}

static void put_scalar(gp *p, hfx_base b, double v) {
    switch (b) {
    case B_BOOL: hfx_sb_put(p->out, v != 0 ? "true" : "false"); break;
    case B_INT:
        if (v <= -2147483648.0) hfx_sb_put(p->out, "(-2147483647 - 1)"); /* 2147483648 is no int literal */
        else hfx_sb_printf(p->out, "%lld", (long long)hfx_ev_int(v));
        break;
    case B_UINT: hfx_sb_printf(p->out, p->legacy ? "%lld" : "%lldu", (long long)hfx_ev_uint(v)); break;
    default: put_float(p, v);
    }
}

static void put_const(gp *p, const ir_expr *e) {
    unsigned n = ncomp(e->type);
    if (n <= 1) { put_scalar(p, e->type->base, e->cval[0]); return; }
    bool same = true;
    for (unsigned i = 1; i < n; i++) same = same && e->cval[i] == e->cval[0];
    hfx_sb_printf(p->out, "%s(", hfx_glsl_type(p, e->type));
    if (same && !hfx_glsl_is_matrix(e->type)) n = 1; /* mat4(x) would be a diagonal */
    for (unsigned i = 0; i < n; i++) {
        if (i) hfx_sb_put(p->out, ", ");
        put_scalar(p, e->type->base, e->cval[i]);
    }
    hfx_sb_put(p->out, ")");
}

void hfx_glsl_zero(gp *p, const hfx_type *t) {
    if (t->kind == TY_ARRAY || t->kind == TY_STRUCT) {
        hfx_sb_printf(p->out, "%s(", hfx_glsl_ctor_type(p, t));
        uint32_t n = t->kind == TY_ARRAY ? t->array_len : t->st->field_count;
        for (uint32_t i = 0; i < n; i++) {
            if (i) hfx_sb_put(p->out, ", ");
            hfx_glsl_zero(p, t->kind == TY_ARRAY ? t->elem : t->st->fields[i].type);
        }
        hfx_sb_put(p->out, ")");
        return;
    }
    if (ncomp(t) <= 1) { put_scalar(p, t->base, 0); return; }
    hfx_sb_printf(p->out, "%s(", hfx_glsl_type(p, t));
    put_scalar(p, t->base, 0);
    hfx_sb_put(p->out, ")");
}

bool hfx_glsl_helper(gp *p, const char *key) {
    for (uint32_t i = 0; i < p->helper_count; i++)
        if (strcmp(p->helper_keys[i], key) == 0) return false;
    if (!HFX_ARENA_GROW(p->c->arena, p->helper_keys, p->helper_count, p->helper_cap, 16)) return false;
    p->helper_keys[p->helper_count++] = hfx_arena_strdup(p->c->arena, key);
    return true;
}

static void open_paren(gp *p, bool wrap) { if (wrap) hfx_sb_put(p->out, "("); }
static void close_paren(gp *p, bool wrap) { if (wrap) hfx_sb_put(p->out, ")"); }

static void call_args(gp *p, const char *fn, ir_expr *const *a, uint32_t n) {
    hfx_sb_printf(p->out, "%s(", fn);
    for (uint32_t i = 0; i < n; i++) {
        if (i) hfx_sb_put(p->out, ", ");
        hfx_glsl_expr(p, a[i], PREC_ASSIGN);
    }
    hfx_sb_put(p->out, ")");
}

/* An expression that is written (assignment target, out argument). */
void hfx_glsl_lvalue(gp *p, const ir_expr *e, int max) {
    bool saved = p->lvalue;
    p->lvalue = true;
    hfx_glsl_expr(p, e, max);
    p->lvalue = saved;
}

static void user_call(gp *p, const ir_expr *e) {
    hfx_sb_printf(p->out, "%s(", e->fn->glsl);
    for (uint32_t i = 0; i < e->n; i++) {
        if (i) hfx_sb_put(p->out, ", ");
        if (i < e->fn->param_count && (e->fn->params[i]->mods & MOD_OUT)) hfx_glsl_lvalue(p, e->a[i], PREC_ASSIGN);
        else hfx_glsl_expr(p, e->a[i], PREC_ASSIGN);
    }
    hfx_sb_put(p->out, ")");
}

static void binary(gp *p, const char *op, const ir_expr *x, const ir_expr *y, int prec, int max) {
    bool wrap = prec > max;
    open_paren(p, wrap);
    hfx_glsl_expr(p, x, prec);
    hfx_sb_printf(p->out, " %s ", op);
    hfx_glsl_expr(p, y, prec - 1);
    close_paren(p, wrap);
}

/* Helpers per GLSL type, overloaded by name. */
static void helper_fmod(gp *p, const char *ty) {
    if (hfx_glsl_helper(p, hfx_arena_printf(p->c->arena, "fmod %s", ty)))
        hfx_sb_printf(&p->helpers, p->legacy ? "%s hfx_fmod(%s x, %s y) { %s q = x / y; return x - y * sign(q) * floor(abs(q)); }\n"
                                         : "%s hfx_fmod(%s x, %s y) { return x - y * trunc(x / y); }\n", ty, ty, ty, ty);
}

static void helper_imod(gp *p, const char *ty) {
    if (hfx_glsl_helper(p, hfx_arena_printf(p->c->arena, "imod %s", ty)))
        hfx_sb_printf(&p->helpers, "%s hfx_imod(%s x, %s y) { return x - y * (x / y); }\n", ty, ty, ty);
}

static const char *bvec(gp *p, unsigned n) { return n == 1 ? "bool" : hfx_arena_printf(p->c->arena, "bvec%u", n); }

static void helper_logic(gp *p, unsigned n, bool is_and) {
    const char *ty = bvec(p, n), *name = is_and ? "hfx_and" : "hfx_or", *op = is_and ? "&&" : "||";
    if (!hfx_glsl_helper(p, hfx_arena_printf(p->c->arena, "%s %s", name, ty))) return;
    hfx_sb_printf(&p->helpers, "%s %s(%s a, %s b) { return %s(", ty, name, ty, ty, ty);
    for (unsigned i = 0; i < n; i++) hfx_sb_printf(&p->helpers, "%sa[%u] %s b[%u]", i ? ", " : "", i, op, i);
    hfx_sb_put(&p->helpers, "); }\n");
}

static void helper_select(gp *p, const hfx_type *t) {
    const char *ty = hfx_glsl_type(p, t);
    unsigned n = ncomp(t);
    if (!hfx_glsl_helper(p, hfx_arena_printf(p->c->arena, "select %s", ty))) return;
    hfx_sb_printf(&p->helpers, "%s hfx_select(%s c, %s a, %s b) { return %s(", ty, bvec(p, n), ty, ty, ty);
    for (unsigned i = 0; i < n; i++) hfx_sb_printf(&p->helpers, "%sc[%u] ? a[%u] : b[%u]", i ? ", " : "", i, i, i);
    hfx_sb_put(&p->helpers, "); }\n");
}

static void helper_splat_matrix(gp *p, const hfx_type *t) {
    const char *ty = hfx_glsl_type(p, t);
    if (!hfx_glsl_helper(p, hfx_arena_printf(p->c->arena, "splat %s", ty))) return;
    hfx_sb_printf(&p->helpers, "%s hfx_splat_%s(float s) { return %s(", ty, ty, ty);
    for (unsigned i = 0; i < t->rows; i++) hfx_sb_printf(&p->helpers, "%svec%u(s)", i ? ", " : "", t->cols);
    hfx_sb_put(&p->helpers, "); }\n");
}

static void print_unary(gp *p, const ir_expr *e, int max) {
    const ir_expr *x = e->a[0];
    bool vec = ncomp(e->type) > 1;
    if (e->op == OP_NOT && vec) { call_args(p, "not", e->a, 1); return; }
    if (e->op == OP_POSTINC || e->op == OP_POSTDEC) {
        bool wrap = PREC_POSTFIX > max;
        open_paren(p, wrap);
        hfx_glsl_lvalue(p, x, PREC_POSTFIX);
        hfx_sb_put(p->out, e->op == OP_POSTINC ? "++" : "--");
        close_paren(p, wrap);
        return;
    }
    const char *op = e->op == OP_NEG ? "-" : e->op == OP_NOT ? "!" : e->op == OP_BITNOT ? "~" :
                     e->op == OP_PREINC ? "++" : "--";
    bool wrap = PREC_UNARY > max;
    open_paren(p, wrap);
    hfx_sb_put(p->out, op);
    if (e->op == OP_PREINC || e->op == OP_PREDEC) hfx_glsl_lvalue(p, x, PREC_POSTFIX);
    else hfx_glsl_expr(p, x, PREC_POSTFIX); /* "- -x" would read as "--x" */
    close_paren(p, wrap);
}

/* A scalar converted to a vector or matrix of the same element type. */
static bool is_splat(const ir_expr *e) {
    if (e->kind != IE_CONVERT && !(e->kind == IE_CONSTRUCT && e->n == 1)) return false;
    const hfx_type *from = e->a[0]->type;
    return ncomp(from) == 1 && ncomp(e->type) > 1 && strcmp(scalar_name(NULL, from->base), scalar_name(NULL, e->type->base)) == 0 &&
           (e->type->kind == TY_VECTOR || hfx_glsl_is_matrix(e->type));
}

static const char *rel_fn(hfx_op op) {
    switch (op) {
    case OP_LT: return "lessThan";
    case OP_GT: return "greaterThan";
    case OP_LE: return "lessThanEqual";
    case OP_GE: return "greaterThanEqual";
    case OP_EQ: return "equal";
    default: return "notEqual";
    }
}

static void print_binary(gp *p, const ir_expr *e, int max) {
    const ir_expr *x = e->a[0], *y = e->a[1];
    unsigned n = ncomp(x->type);
    hfx_op op = e->op;
    if (op >= OP_LT && op <= OP_NE && n > 1) {
        if (hfx_glsl_is_matrix(x->type)) hfx_glsl_error(p, e->loc, "comparison of matrices is not supported");
        call_args(p, rel_fn(op), e->a, 2);
        return;
    }
    if ((op == OP_AND || op == OP_OR) && n > 1) {
        helper_logic(p, n, op == OP_AND);
        call_args(p, op == OP_AND ? "hfx_and" : "hfx_or", e->a, 2);
        return;
    }
    if (op == OP_MUL && hfx_glsl_is_matrix(x->type) && hfx_glsl_is_matrix(y->type)) {
        call_args(p, "matrixCompMult", e->a, 2);
        return;
    }
    if (op == OP_MOD) {
        const char *ty = hfx_glsl_type(p, e->type);
        if (is_float(e->type->base)) { helper_fmod(p, ty); call_args(p, "hfx_fmod", e->a, 2); }
        else { helper_imod(p, ty); call_args(p, "hfx_imod", e->a, 2); }
        return;
    }
    static const struct { const char *s; int prec; } ops[] = {
        [OP_ADD] = {"+", PREC_ADD}, [OP_SUB] = {"-", PREC_ADD}, [OP_MUL] = {"*", PREC_MUL},
        [OP_DIV] = {"/", PREC_MUL}, [OP_SHL] = {"<<", PREC_SHIFT}, [OP_SHR] = {">>", PREC_SHIFT},
        [OP_BITAND] = {"&", PREC_BITAND}, [OP_BITOR] = {"|", PREC_BITOR}, [OP_BITXOR] = {"^", PREC_BITXOR},
        [OP_LT] = {"<", PREC_REL}, [OP_GT] = {">", PREC_REL}, [OP_LE] = {"<=", PREC_REL}, [OP_GE] = {">=", PREC_REL},
        [OP_EQ] = {"==", PREC_EQ}, [OP_NE] = {"!=", PREC_EQ}, [OP_AND] = {"&&", PREC_AND}, [OP_OR] = {"||", PREC_OR},
    };
    if (op >= sizeof ops / sizeof *ops || !ops[op].s) { hfx_glsl_error(p, e->loc, "unknown operator"); return; }
    if (p->legacy && op >= OP_SHL && op <= OP_BITXOR) {
        hfx_glsl_error(p, e->loc, "integer bit operations are not available in GLSL 110");
        return;
    }
    if (op >= OP_ADD && op <= OP_DIV) { /* GLSL mixes scalars and vectors here: drop the splat */
        if (is_splat(y) && !is_splat(x)) y = y->a[0];
        else if (is_splat(x) && !is_splat(y)) x = x->a[0];
    }
    binary(p, ops[op].s, x, y, ops[op].prec, max);
}

static void print_select(gp *p, const ir_expr *e, int max) {
    const ir_expr *c = e->a[0];
    if (ncomp(c->type) > 1) {
        /* mix(b, a, c) evaluates b first: with side effects, hfx_select keeps HLSL's order */
        bool effects = hfx_ir_has_side_effects(c) || hfx_ir_has_side_effects(e->a[1]) || hfx_ir_has_side_effects(e->a[2]);
        if (is_float(e->type->base) && !p->legacy && !effects) {
            const ir_expr *args[3] = { e->a[2], e->a[1], c }; /* mix picks y where the bool is true */
            call_args(p, "mix", (ir_expr *const *)args, 3);
        } else {
            helper_select(p, e->type);
            call_args(p, "hfx_select", e->a, 3);
        }
        return;
    }
    if (hfx_ir_has_side_effects(e->a[1]) || hfx_ir_has_side_effects(e->a[2])) {
        /* before SM6, HLSL evaluates both operands of ?: (the effects of both happen); a
         * function's arguments are all evaluated, GLSL's ?: evaluates one */
        const char *ty = hfx_glsl_type(p, e->type);
        if (hfx_glsl_helper(p, hfx_arena_printf(p->c->arena, "select1 %s", ty)))
            hfx_sb_printf(&p->helpers, "%s hfx_select1(bool c, %s a, %s b) { return c ? a : b; }\n", ty, ty, ty);
        call_args(p, "hfx_select1", e->a, 3);
        return;
    }
    bool wrap = PREC_SELECT > max;
    open_paren(p, wrap);
    hfx_glsl_expr(p, c, PREC_OR);
    hfx_sb_put(p->out, " ? ");
    hfx_glsl_expr(p, e->a[1], PREC_ASSIGN);
    hfx_sb_put(p->out, " : ");
    hfx_glsl_expr(p, e->a[2], PREC_SELECT);
    close_paren(p, wrap);
}

/* `float4(a, b) = v`: a helper with an out parameter per argument takes v's components in
 * order and returns v, so the assignment stays an expression. */
static void print_scatter(gp *p, const ir_expr *e) {
    const ir_expr *ctor = e->a[0];
    const char *vt = hfx_glsl_type(p, ctor->type);
    sbuf sig = {.arena = p->c->arena}, body = {.arena = p->c->arena};
    unsigned at = 0;
    for (uint32_t i = 0; i < ctor->n; i++) {
        unsigned n = ncomp(ctor->a[i]->type);
        hfx_sb_printf(&sig, "out %s a%u, ", hfx_glsl_type(p, ctor->a[i]->type), i);
        hfx_sb_printf(&body, "a%u = v.%.*s; ", i, (int)n, &"xyzw"[at]);
        at += n;
    }
    const char *key = hfx_arena_printf(p->c->arena, "scatter %s%s", sig.d ? sig.d : "", vt);
    if (hfx_glsl_helper(p, key))
        hfx_sb_printf(&p->helpers, "%s hfx_scatter(%s%s v) { %sreturn v; }\n", vt, sig.d ? sig.d : "", vt, body.d ? body.d : "");
    hfx_sb_put(p->out, "hfx_scatter(");
    for (uint32_t i = 0; i < ctor->n; i++) {
        hfx_glsl_lvalue(p, ctor->a[i], PREC_ASSIGN);
        hfx_sb_put(p->out, ", ");
    }
    hfx_glsl_expr(p, e->a[1], PREC_ASSIGN);
    hfx_sb_put(p->out, ")");
}

static void print_assign(gp *p, const ir_expr *e, int max) {
    const ir_expr *x = e->a[0], *y = e->a[1];
    if (x->kind == IE_CONSTRUCT && e->op == OP_NONE) { print_scatter(p, e); return; }
    bool wrap = PREC_ASSIGN > max;
    open_paren(p, wrap);
    hfx_glsl_lvalue(p, x, PREC_UNARY);
    if (e->op == OP_NONE) {
        hfx_sb_put(p->out, " = ");
        hfx_glsl_expr(p, y, PREC_ASSIGN);
    } else if (e->op == OP_MOD || (e->op == OP_MUL && hfx_glsl_is_matrix(x->type))) {
        /* no GLSL compound form with HLSL's meaning: x = f(x, y) */
        ir_expr tmp = *e;
        tmp.kind = IE_BINARY;
        hfx_sb_put(p->out, " = ");
        print_binary(p, &tmp, PREC_ASSIGN);
    } else {
        static const char *const ops[] = {
            [OP_ADD] = "+=", [OP_SUB] = "-=", [OP_MUL] = "*=", [OP_DIV] = "/=", [OP_SHL] = "<<=",
            [OP_SHR] = ">>=", [OP_BITAND] = "&=", [OP_BITOR] = "|=", [OP_BITXOR] = "^=",
        };
        const char *op = e->op < sizeof ops / sizeof *ops ? ops[e->op] : NULL;
        if (!op) { hfx_glsl_error(p, e->loc, "unknown assignment operator"); op = "="; }
        if (e->op >= OP_ADD && e->op <= OP_DIV && is_splat(y) && x->type->kind == TY_VECTOR) y = y->a[0]; /* v *= s */
        hfx_sb_printf(p->out, " %s ", op);
        hfx_glsl_expr(p, y, PREC_ASSIGN);
    }
    close_paren(p, wrap);
}

/* Constructor arguments: GLSL forbids matrices among several matrix-constructor arguments,
 * so such a matrix is passed row by row (HLSL rows are GLSL columns). */
static void print_construct(gp *p, const ir_expr *e) {
    if (p->legacy && e->type->kind == TY_ARRAY) { /* 110 has no array constructors (found by fuzz/fuzz_diff.c) */
        hfx_glsl_error(p, e->loc, "array initializers and constructors need GLSL 330 or ES 300");
        return;
    }
    const char *ty = hfx_glsl_ctor_type(p, e->type);
    if (hfx_glsl_is_matrix(e->type) && e->n == 1 && ncomp(e->a[0]->type) == 1) { /* a scalar spread */
        helper_splat_matrix(p, e->type);
        hfx_sb_printf(p->out, "hfx_splat_%s", ty);
        call_args(p, "", e->a, 1);
        return;
    }
    hfx_sb_printf(p->out, "%s(", ty);
    for (uint32_t i = 0; i < e->n; i++) {
        if (i) hfx_sb_put(p->out, ", ");
        const ir_expr *a = e->a[i];
        if (hfx_glsl_is_matrix(e->type) && e->n > 1 && hfx_glsl_is_matrix(a->type)) {
            for (unsigned r = 0; r < a->type->rows; r++) {
                if (r) hfx_sb_put(p->out, ", ");
                hfx_glsl_expr(p, a, PREC_POSTFIX);
                hfx_sb_printf(p->out, "[%u]", r);
            }
        } else {
            hfx_glsl_expr(p, a, PREC_ASSIGN);
        }
    }
    hfx_sb_put(p->out, ")");
}

static void print_convert(gp *p, const ir_expr *e, int max);

/* The upper-left part of a matrix as column vectors, `m[0].xyz, m[1].xyz, m[2].xyz`, for GLSL
 * 110, which builds matrices from vectors only (found by fuzz/fuzz_diff.c). */
static void print_submatrix_columns(gp *p, const hfx_type *to, const ir_expr *x) {
    for (unsigned c = 0; c < to->rows; c++) {
        if (c) hfx_sb_put(p->out, ", ");
        hfx_glsl_expr(p, x, PREC_POSTFIX);
        hfx_sb_printf(p->out, "[%u].%.*s", c, (int)to->cols, "xyzw");
    }
}

/* A scalar cast to a struct or an array fills every component: `(VS_OUTPUT)0` zeroes each
 * member (nested structs, arrays and matrices too), as HLSL defines the cast. */
static void print_fill(gp *p, const hfx_type *to, ir_expr *x) {
    if (hfx_type_is_numeric(to)) {
        ir_expr conv = {.kind = IE_CONVERT, .type = to, .loc = x->loc, .a = &x, .n = 1};
        print_convert(p, &conv, PREC_ASSIGN);
        return;
    }
    if (p->legacy) { hfx_glsl_error(p, x->loc, "a cast to a struct or an array needs GLSL 330 or ES 300"); return; }
    hfx_sb_printf(p->out, "%s(", hfx_glsl_ctor_type(p, to));
    uint32_t n = to->kind == TY_ARRAY ? to->array_len : to->st ? to->st->field_count : 0;
    for (uint32_t i = 0; i < n; i++) {
        if (i) hfx_sb_put(p->out, ", ");
        print_fill(p, to->kind == TY_ARRAY ? to->elem : to->st->fields[i].type, x);
    }
    hfx_sb_put(p->out, ")");
}

/* `(float[4])v`: each component of a vector or matrix (row by row) becomes an element. */
static void print_to_array(gp *p, const hfx_type *to, const ir_expr *x) {
    unsigned n = ncomp(x->type);
    const char *elem = scalar_name(p, to->elem->base);
    if (p->legacy) { hfx_glsl_error(p, x->loc, "a cast to an array needs GLSL 330 or ES 300"); return; }
    hfx_sb_printf(p->out, "%s(", hfx_glsl_ctor_type(p, to));
    for (unsigned i = 0; i < n; i++) {
        hfx_sb_printf(p->out, "%s%s(", i ? ", " : "", elem);
        hfx_glsl_expr(p, x, PREC_POSTFIX);
        if (hfx_glsl_is_matrix(x->type)) hfx_sb_printf(p->out, "[%u][%u])", i / x->type->cols, i % x->type->cols);
        else hfx_sb_printf(p->out, ".%c)", "xyzw"[i]);
    }
    hfx_sb_put(p->out, ")");
}

static void print_convert(gp *p, const ir_expr *e, int max) {
    const ir_expr *x = e->a[0];
    const hfx_type *to = e->type, *from = x->type;
    unsigned nt = ncomp(to), nf = ncomp(from);
    if (nf == 1 && (to->kind == TY_STRUCT || to->kind == TY_ARRAY)) { print_fill(p, to, e->a[0]); return; }
    if (nf > 1 && to->kind == TY_ARRAY) { print_to_array(p, to, x); return; }
    if (!nt || !nf) { hfx_glsl_expr(p, x, max); return; }
    const char *tty = hfx_glsl_type(p, to), *fty = hfx_glsl_type(p, from);
    if (hfx_glsl_is_matrix(to)) {
        if (nf == 1) {
            helper_splat_matrix(p, to);
            hfx_sb_printf(p->out, "hfx_splat_%s(", tty);
            if (!is_float(from->base)) hfx_sb_put(p->out, "float(");
            hfx_glsl_expr(p, x, PREC_ASSIGN);
            hfx_sb_put(p->out, is_float(from->base) ? ")" : "))");
            return;
        }
        hfx_sb_printf(p->out, "%s(", tty); /* submatrix, or components in order from a vector */
        if (p->legacy && hfx_glsl_is_matrix(from)) print_submatrix_columns(p, to, x); /* 110: no mat3(mat4) */
        else hfx_glsl_expr(p, x, PREC_ASSIGN);
        hfx_sb_put(p->out, ")");
        return;
    }
    if (nt == 1 && nf > 1) { /* the first component */
        bool same = strcmp(tty, scalar_name(p, from->base)) == 0;
        if (!same) hfx_sb_printf(p->out, "%s(", tty);
        hfx_glsl_expr(p, x, PREC_POSTFIX);
        hfx_sb_put(p->out, hfx_glsl_is_matrix(from) ? "[0][0]" : ".x");
        if (!same) hfx_sb_put(p->out, ")");
        return;
    }
    if (to->kind == TY_MATRIX && to->cols == 1 && hfx_glsl_is_matrix(from)) { /* Nx1: column 0, a GLSL vector */
        hfx_sb_printf(p->out, "%s(", tty);
        for (unsigned r = 0; r < nt; r++) {
            if (r) hfx_sb_put(p->out, ", ");
            hfx_glsl_expr(p, x, PREC_POSTFIX);
            hfx_sb_printf(p->out, "[%u][0]", r);
        }
        hfx_sb_put(p->out, ")");
        return;
    }
    if (strcmp(tty, fty) == 0) { hfx_glsl_expr(p, x, max); return; }
    if (nt < nf && !hfx_glsl_is_matrix(from) && strcmp(scalar_name(p, to->base), scalar_name(p, from->base)) == 0) {
        hfx_glsl_expr(p, x, PREC_POSTFIX);
        hfx_sb_printf(p->out, ".%.*s", (int)nt, "xyzw");
        return;
    }
    hfx_sb_printf(p->out, "%s(", tty);
    hfx_glsl_expr(p, x, PREC_ASSIGN);
    hfx_sb_put(p->out, ")");
}

static void print_swizzle(gp *p, const ir_expr *e, int max) {
    const ir_expr *x = e->a[0];
    unsigned n = e->comp_count;
    if (ncomp(x->type) == 1) {
        if (n == 1) { hfx_glsl_expr(p, x, max); return; }
        hfx_sb_printf(p->out, "%s(", hfx_glsl_type(p, e->type));
        hfx_glsl_expr(p, x, PREC_ASSIGN);
        hfx_sb_put(p->out, ")");
        return;
    }
    if (hfx_glsl_is_matrix(x->type)) {
        unsigned cols = x->type->cols, row = e->comps[0] / cols, same = 1;
        while (same < n && e->comps[same] / cols == row) same++;
        if (same == n && n > 1) { /* one HLSL row, which is one GLSL column: m[r] and its components (a
                            translated D3D9 register is one, and drivers compile a gather slower) */
            hfx_glsl_expr(p, x, PREC_POSTFIX);
            hfx_sb_printf(p->out, "[%u]", row);
            bool whole = n == cols;
            for (unsigned i = 0; i < n && whole; i++) whole = e->comps[i] % cols == i;
            if (!whole) {
                hfx_sb_put(p->out, ".");
                for (unsigned i = 0; i < n; i++) hfx_sb_printf(p->out, "%c", "xyzw"[e->comps[i] % cols]);
            }
            return;
        }
        if (n > 1) hfx_sb_printf(p->out, "%s(", hfx_glsl_type(p, e->type));
        for (unsigned i = 0; i < n; i++) {
            if (i) hfx_sb_put(p->out, ", ");
            hfx_glsl_expr(p, x, PREC_POSTFIX);
            hfx_sb_printf(p->out, "[%u][%u]", e->comps[i] / cols, e->comps[i] % cols);
        }
        if (n > 1) hfx_sb_put(p->out, ")");
        return;
    }
    hfx_glsl_expr(p, x, PREC_POSTFIX);
    hfx_sb_put(p->out, ".");
    for (unsigned i = 0; i < n; i++) hfx_sb_printf(p->out, "%c", "xyzw"[e->comps[i] & 3]);
}

/* The test that sends a guarded read to zero: only the upper end for an index known not to be
 * negative; else one unsigned compare for both ends, or two in GLSL 110, which has no uint. */
static const char *guard_test(const gp *p, const ir_expr *e, const char **suffix) {
    uint32_t len = e->a[0]->var->type->array_len;
    *suffix = "";
    if (e->range == IR_RANGE_NONNEG) {
        *suffix = "below"; /* hfx_readbelow_X: no "hfx_read_" + name can spell it */
        return hfx_arena_printf(p->c->arena, "i >= %u", len);
    }
    if (!p->legacy) return hfx_arena_printf(p->c->arena, "uint(i) >= %uu", len);
    return hfx_arena_printf(p->c->arena, "i < 0 || i >= %u", len);
}

/* e reads a uniform array declared on its own at an index not proved inside it: the reads
 * hfx_glsl_find_padded pads, where GLSL has uint and the text is not SPIR-V's. */
static bool paddable_read(const gp *p, const ir_expr *e) {
    if (!e || e->kind != IE_INDEX || p->legacy || p->spirv) return false;
    const ir_expr *x = e->a[0];
    return x->kind == IE_VAR && x->var->kind == IRV_UNIFORM &&
           x->type->kind == TY_ARRAY && !hfx_ir_is_const(e->a[1]) && e->range != IR_RANGE_IN_BOUNDS &&
           hfx_glsl_packed_reg(p, x->var) == HFX_NONE;
}

static int32_t padded_index(const gp *p, const ir_var *v) {
    for (uint32_t i = 0; i < p->padded_count; i++)
        if (p->padded[i] == v) return (int32_t)i;
    return -1;
}

static void note_padded(ir_ctx *c, ir_expr **slot, void *data) {
    gp *p = data;
    if (!paddable_read(p, *slot) || padded_index(p, (*slot)->a[0]->var) >= 0) return;
    if (HFX_ARENA_GROW(c->arena, p->padded, p->padded_count, p->padded_cap, 4)) p->padded[p->padded_count++] = (*slot)->a[0]->var;
}

/* uses[2k] counts every read of padded[k], uses[2k + 1] those that index it. */
typedef struct { gp *p; uint32_t *uses; } use_count;

static void count_uses(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    use_count *u = data;
    const ir_expr *e = *slot;
    int32_t k;
    if (e && e->kind == IE_VAR && (k = padded_index(u->p, e->var)) >= 0) u->uses[2 * k]++;
    if (e && e->kind == IE_INDEX && e->a[0]->kind == IE_VAR && (k = padded_index(u->p, e->a[0]->var)) >= 0) u->uses[2 * k + 1]++;
}

/* The program's other stage declares the uniform too: GL links the two declarations only when
 * they agree, so an array both stages read keeps its length (and its guarded reads). */
static bool other_stage_reads(const gp *p, const ir_var *v) {
    const ir_shader *other = p->io ? p->io->stages[p->stage == IR_VERTEX ? 1 : 0] : NULL;
    for (uint32_t i = 0; other && i < other->global_count; i++)
        if (other->globals[i]->kind == IRV_UNIFORM && strcmp(other->globals[i]->glsl, v->glsl) == 0) return true;
    return false;
}

/* Only arrays read element by element: one passed whole to a function, or copied, keeps its
 * type (and its guarded reads); so does one the other stage reads. */
void hfx_glsl_find_padded(gp *p) {
    for (uint32_t i = 0; p->sh && i < p->sh->func_count; i++) hfx_ir_walk_stmt_exprs(p->c, p->sh->funcs[i]->body, note_padded, p);
    if (!p->padded_count) return;
    use_count u = {p, hfx_arena_alloc(p->c->arena, (size_t)p->padded_count * 2 * sizeof *u.uses)};
    if (!u.uses) { p->padded_count = 0; return; }
    memset(u.uses, 0, (size_t)p->padded_count * 2 * sizeof *u.uses);
    for (uint32_t i = 0; i < p->sh->func_count; i++) hfx_ir_walk_stmt_exprs(p->c, p->sh->funcs[i]->body, count_uses, &u);
    for (uint32_t i = 0; i < p->sh->global_count; i++) /* static initialisers, run in main */
        if (p->sh->globals[i]->init) hfx_ir_walk_expr(p->c, &p->sh->globals[i]->init, count_uses, &u);
    uint32_t kept = 0;
    for (uint32_t k = 0; k < p->padded_count; k++)
        if (u.uses[2 * k] == u.uses[2 * k + 1] && !other_stage_reads(p, p->padded[k])) p->padded[kept++] = p->padded[k];
    p->padded_count = kept;
}

bool hfx_glsl_is_padded(const gp *p, const ir_var *v) { return padded_index(p, v) >= 0; }

/* arr[min(uint(i), len)] (arr[min(i, len)] for an index known not to be negative): the element
 * past the end is the padding's zero. */
static void print_padded_read(gp *p, const ir_expr *e) {
    uint32_t len = e->a[0]->type->array_len;
    bool nonneg = e->range == IR_RANGE_NONNEG && e->a[1]->type->base == B_INT;
    hfx_glsl_expr(p, e->a[0], PREC_POSTFIX);
    hfx_sb_put(p->out, nonneg ? "[min(" : "[min(uint(");
    bool conv = e->a[1]->type->base != B_INT;
    if (conv) hfx_sb_put(p->out, "int(");
    hfx_glsl_expr(p, e->a[1], PREC_ASSIGN);
    hfx_sb_printf(p->out, nonneg ? "%s, %u)]" : "%s), %uu)]", conv ? ")" : "", len);
}

/* Reads of a uniform array at a dynamic (or out of range) index return zero past the end,
 * as D3D9's unset constant registers do in practice, instead of GLSL's undefined value. */
static void print_guarded_read(gp *p, const ir_expr *e) {
    const ir_var *v = e->a[0]->var;
    const hfx_type *at = v->type;
    const char *suffix, *test = guard_test(p, e, &suffix);
    const char *fn = hfx_arena_printf(p->c->arena, "hfx_read%s_%s", suffix, v->glsl);
    if (hfx_glsl_helper(p, fn)) {
        sbuf *saved = p->out;
        sbuf tmp = {.arena = p->c->arena};
        p->out = &tmp;
        hfx_glsl_zero(p, at->elem);
        p->out = saved;
        /* an if, not ?: (glslang's SPIR-V for a ?: of a uniform block's struct and a local one
         * stores mismatched types) */
        sbuf name = {.arena = p->c->arena};
        hfx_glsl_uniform_read(p, &name, v);
        hfx_sb_printf(&p->helpers, "%s %s(int i)\n{\n    if (%s) return %s;\n    return %s[i];\n}\n", hfx_glsl_ctor_type(p, at->elem),
                  fn, test, tmp.d ? tmp.d : "0", name.d ? name.d : v->glsl);
    }
    hfx_sb_printf(p->out, "%s(", fn);
    if (e->a[1]->type->base != B_INT) hfx_sb_put(p->out, "int(");
    hfx_glsl_expr(p, e->a[1], PREC_ASSIGN);
    hfx_sb_put(p->out, e->a[1]->type->base != B_INT ? "))" : ")");
}

static void print_index(gp *p, const ir_expr *e, int max) {
    const ir_expr *x = e->a[0], *i = e->a[1];
    if (!p->lvalue && x->type->kind == TY_ARRAY && x->kind == IE_VAR &&
        (x->var->kind == IRV_UNIFORM || x->var->kind == IRV_PRIVATE) &&
        (!hfx_ir_is_const(i) ? e->range != IR_RANGE_IN_BOUNDS : i->cval[0] < 0 || i->cval[0] >= x->type->array_len)) {
        bool saved = p->lvalue;
        p->lvalue = false;
        if (paddable_read(p, e) && hfx_glsl_is_padded(p, x->var)) print_padded_read(p, e);
        else print_guarded_read(p, e);
        p->lvalue = saved;
        return;
    }
    if (x->type->kind == TY_MATRIX && x->type->rows == 1) { hfx_glsl_expr(p, x, max); return; } /* float1xN: its row */
    if (hfx_type_is_numeric(x->type) && ncomp(x->type) == 1) { hfx_glsl_expr(p, x, max); return; } /* float1[0] */
    hfx_glsl_expr(p, x, PREC_POSTFIX);
    hfx_sb_put(p->out, "[");
    bool conv = i->type->base != B_INT && !hfx_ir_is_const(i), saved = p->lvalue;
    if (conv) hfx_sb_put(p->out, "int(");
    p->lvalue = false; /* the index itself is read */
    if (hfx_ir_is_const(i)) hfx_sb_printf(p->out, "%lld", (long long)hfx_ev_int(i->cval[0]));
    else hfx_glsl_expr(p, i, PREC_COMMA - 1);
    p->lvalue = saved;
    if (conv) hfx_sb_put(p->out, ")");
    hfx_sb_put(p->out, "]");
}

void hfx_glsl_intrinsic(gp *p, const ir_expr *e, int max);

void hfx_glsl_expr(gp *p, const ir_expr *e, int max) {
    if (!e) { hfx_glsl_error(p, (hfx_loc){0, 0, 0}, "missing expression"); return; }
    switch (e->kind) {
    case IE_CONST: {
        bool neg = ncomp(e->type) == 1 && e->cval[0] < 0;
        open_paren(p, neg && PREC_UNARY > max);
        put_const(p, e);
        close_paren(p, neg && PREC_UNARY > max);
        break;
    }
    case IE_VAR: hfx_glsl_uniform_read(p, p->out, e->var); break;
    case IE_UNARY: print_unary(p, e, max); break;
    case IE_BINARY: print_binary(p, e, max); break;
    case IE_SELECT: print_select(p, e, max); break;
    case IE_ASSIGN: print_assign(p, e, max); break;
    case IE_COMMA: binary(p, ",", e->a[0], e->a[1], PREC_COMMA, max); break;
    case IE_CALL: user_call(p, e); break;
    case IE_INTRIN: hfx_glsl_intrinsic(p, e, max); break;
    case IE_CONSTRUCT: print_construct(p, e); break;
    case IE_CONVERT: print_convert(p, e, max); break;
    case IE_SWIZZLE: print_swizzle(p, e, max); break;
    case IE_INDEX: print_index(p, e, max); break;
    case IE_FIELD:
        hfx_glsl_expr(p, e->a[0], PREC_POSTFIX);
        hfx_sb_printf(p->out, ".%s", hfx_glsl_name(p->c->arena, e->a[0]->type->st->fields[e->field].name));
        break;
    }
}
