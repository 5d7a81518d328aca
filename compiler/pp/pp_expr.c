/* pp_expr.c: #if and #elif. `defined` is resolved first, then macros are expanded, then the
 * line is evaluated as a C integer constant expression in 64 bits (unsigned when an operand
 * is, as C's usual conversions say); identifiers left over are 0. Operands that are not
 * evaluated (after && / || / ?: decided) may divide by zero without an error. */
#include <stdlib.h>
#include <string.h>

#include "pp/pp_internal.h"

typedef struct pp_value {
    uint64_t v;
    bool is_unsigned;
} pp_value;

typedef struct expr {
    hfx_pp *pp;
    hfx_token *tok;
    hfx_loc directive;
    bool failed;
    uint32_t depth;
} expr;

static bool is_punct(const hfx_token *t, hfx_punct p) { return t->kind == TK_PUNCT && t->punct == p; }

static void fail_code(expr *e, const hfx_token *at, unsigned code, const char *msg) {
    if (!e->failed)
        hfx_pp_error(e->pp, at->kind == TK_EOF ? e->directive : at->loc, code, "%s", msg);
    e->failed = true;
}

static void fail(expr *e, const hfx_token *at, const char *msg) {
    if (!e->failed)
        hfx_pp_error(e->pp, at->kind == TK_EOF ? e->directive : at->loc, X_PP_INVALID_INT_EXPR, "%s", msg);
    e->failed = true;
}

/* Replaces "defined X" and "defined ( X )" by 1 or 0 before macros are expanded. */
static hfx_token *resolve_defined(hfx_pp *pp, hfx_token *line, expr *e) {
    hfx_token head = {0}, *cur = &head;
    for (hfx_token *t = line;;) {
        if (t->kind == TK_EOF) {
            cur->next = t;
            return head.next;
        }
        if (t->kind != TK_IDENT || strcmp(t->text, "defined") != 0) {
            cur = cur->next = t;
            t = t->next;
            continue;
        }
        hfx_token *name = t->next;
        bool paren = is_punct(name, P_LPAREN);
        if (paren) name = name->next;
        if (name->kind != TK_IDENT) {
            fail(e, name, "'defined' expects an identifier");
            return line;
        }
        hfx_token *after = name->next;
        if (paren) {
            if (!is_punct(after, P_RPAREN)) {
                fail(e, after, "missing ')' after 'defined'");
                return line;
            }
            after = after->next;
        }
        hfx_token *value = hfx_pp_copy_token(pp, t);
        value->kind = TK_INT;
        value->text = hfx_pp_find_macro(pp, name->text) ? "1" : "0";
        value->len = 1;
        cur = cur->next = value;
        t = after;
    }
}

/* The value of an integer literal: decimal, octal or hex with u/l suffixes. */
static pp_value int_literal(expr *e, const hfx_token *t) {
    const char *s = t->text;
    int base = 10;
    if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) { base = 16; s += 2; }
    else if (s[0] == '0') base = 8;
    uint64_t v = 0;
    bool overflow = false;
    for (; *s; s++) {
        int d = *s >= '0' && *s <= '9' ? *s - '0' : *s >= 'a' && *s <= 'f' ? *s - 'a' + 10
              : *s >= 'A' && *s <= 'F' ? *s - 'A' + 10 : -1;
        if (d < 0 || (base == 16 && d >= 16) || (base != 16 && (d >= base || (*s > '9')))) break;
        if (v > (UINT64_MAX - (uint64_t)d) / (uint64_t)base) overflow = true;
        v = v * (uint64_t)base + (uint64_t)d;
    }
    pp_value r = {v, v > (uint64_t)INT64_MAX};
    for (; *s; s++) {
        if (*s == 'u' || *s == 'U') r.is_unsigned = true;
        else if (*s != 'l' && *s != 'L') { fail(e, t, "invalid integer constant in preprocessor expression"); break; }
    }
    if (overflow) fail(e, t, "integer constant is too large");
    return r;
}

/* "defined X" that a macro expansion produced (C leaves it undefined; GCC and MSVC evaluate it). */
static pp_value defined_operator(expr *e, hfx_token *t) {
    hfx_token *name = t->next;
    bool paren = is_punct(name, P_LPAREN);
    if (paren) name = name->next;
    if (name->kind != TK_IDENT) {
        fail(e, name, "'defined' expects an identifier");
        return (pp_value){0, false};
    }
    e->tok = name->next;
    if (paren) {
        if (!is_punct(e->tok, P_RPAREN)) fail(e, e->tok, "missing ')' after 'defined'");
        else e->tok = e->tok->next;
    }
    return (pp_value){hfx_pp_find_macro(e->pp, name->text) != NULL, false};
}

static pp_value parse_expr(expr *e, bool eval);
static pp_value parse_binary(expr *e, int min_prec, bool eval);

static pp_value parse_unary(expr *e, bool eval) {
    hfx_token *t = e->tok;
    pp_value r = {0, false};
    if (++e->depth > PP_MAX_EXPR_DEPTH) {
        fail(e, t, "preprocessor expression nested too deeply");
        return r;
    }
    if (t->kind == TK_PUNCT && (t->punct == P_PLUS || t->punct == P_MINUS || t->punct == P_TILDE ||
                                t->punct == P_BANG)) {
        e->tok = t->next;
        r = parse_unary(e, eval);
        if (t->punct == P_MINUS) r.v = 0 - r.v;
        else if (t->punct == P_TILDE) r.v = ~r.v;
        else if (t->punct == P_BANG) r = (pp_value){r.v == 0, false};
    } else if (is_punct(t, P_LPAREN)) {
        e->tok = t->next;
        r = parse_expr(e, eval);
        if (!is_punct(e->tok, P_RPAREN)) fail(e, e->tok, "missing ')' in preprocessor expression");
        else e->tok = e->tok->next;
    } else if (t->kind == TK_INT) {
        r = int_literal(e, t);
        e->tok = t->next;
    } else if (t->kind == TK_IDENT && strcmp(t->text, "defined") == 0) {
        r = defined_operator(e, t);
    } else if (t->kind == TK_IDENT) {
        /* An identifier that is not a macro (true and false included) is 0, as in C. */
        e->tok = t->next;
    } else if (t->kind == TK_FLOAT) {
        fail(e, t, "floating-point constant in preprocessor expression");
    } else if (t->kind == TK_EOF) {
        fail(e, t, "expected a value in preprocessor expression");
    } else {
        fail(e, t, "invalid integer constant expression");
    }
    e->depth--;
    return r;
}

static int precedence(const hfx_token *t) {
    if (t->kind != TK_PUNCT) return -1;
    switch (t->punct) {
    case P_STAR: case P_SLASH: case P_PERCENT: return 10;
    case P_PLUS: case P_MINUS: return 9;
    case P_SHL: case P_SHR: return 8;
    case P_LT: case P_GT: case P_LE: case P_GE: return 7;
    case P_EQEQ: case P_NE: return 6;
    case P_AMP: return 5;
    case P_CARET: return 4;
    case P_PIPE: return 3;
    case P_ANDAND: return 2;
    case P_OROR: return 1;
    default: return -1;
    }
}

static bool is_negative(pp_value a) { return !a.is_unsigned && (int64_t)a.v < 0; }

static pp_value compare(hfx_punct op, pp_value a, pp_value b, bool uns) {
    bool lt = uns ? a.v < b.v : (int64_t)a.v < (int64_t)b.v;
    bool gt = uns ? a.v > b.v : (int64_t)a.v > (int64_t)b.v;
    bool r = op == P_LT ? lt : op == P_GT ? gt : op == P_LE ? !gt : op == P_GE ? !lt
           : op == P_EQEQ ? a.v == b.v : a.v != b.v;
    return (pp_value){r, false};
}

static pp_value divide(expr *e, const hfx_token *op, pp_value a, pp_value b, bool uns, bool eval) {
    if (b.v == 0) {
        if (eval)
            fail_code(e, op, X_PP_DIVIDE_BY_ZERO, op->punct == P_SLASH ? "division by zero in preprocessor expression"
                                                                       : "modulus by zero in preprocessor expression");
        return (pp_value){0, uns};
    }
    if (uns) return (pp_value){op->punct == P_SLASH ? a.v / b.v : a.v % b.v, true};
    int64_t x = (int64_t)a.v, y = (int64_t)b.v;
    if (x == INT64_MIN && y == -1) return (pp_value){op->punct == P_SLASH ? a.v : 0, false};
    return (pp_value){(uint64_t)(op->punct == P_SLASH ? x / y : x % y), false};
}

static pp_value shift(hfx_punct op, pp_value a, pp_value b) {
    bool neg = is_negative(a);
    uint64_t n = b.v;
    if (is_negative(b) || n >= 64) return (pp_value){op == P_SHR && neg ? UINT64_MAX : 0, a.is_unsigned};
    if (op == P_SHL) return (pp_value){a.v << n, a.is_unsigned};
    if (a.is_unsigned || !neg) return (pp_value){a.v >> n, a.is_unsigned};
    return (pp_value){~(~a.v >> n), false}; /* arithmetic shift of a negative value */
}

static pp_value apply(expr *e, const hfx_token *op, pp_value a, pp_value b, bool eval) {
    bool uns = a.is_unsigned || b.is_unsigned;
    switch (op->punct) {
    case P_STAR: return (pp_value){a.v * b.v, uns};
    case P_SLASH: case P_PERCENT: return divide(e, op, a, b, uns, eval);
    case P_PLUS: return (pp_value){a.v + b.v, uns};
    case P_MINUS: return (pp_value){a.v - b.v, uns};
    case P_SHL: case P_SHR: return shift(op->punct, a, b);
    case P_AMP: return (pp_value){a.v & b.v, uns};
    case P_CARET: return (pp_value){a.v ^ b.v, uns};
    case P_PIPE: return (pp_value){a.v | b.v, uns};
    default: return compare(op->punct, a, b, uns);
    }
}

/* Precedence climbing over the binary operators; && and || only evaluate what they need. */
static pp_value parse_binary(expr *e, int min_prec, bool eval) {
    pp_value a = parse_unary(e, eval);
    for (;;) {
        hfx_token *op = e->tok;
        int prec = precedence(op);
        if (prec < min_prec || e->failed) return a;
        e->tok = op->next;
        if (op->punct == P_ANDAND || op->punct == P_OROR) {
            bool decided = op->punct == P_ANDAND ? a.v == 0 : a.v != 0;
            pp_value b = parse_binary(e, prec + 1, eval && !decided);
            a = (pp_value){decided ? op->punct == P_OROR : b.v != 0, false};
            continue;
        }
        pp_value b = parse_binary(e, prec + 1, eval);
        a = apply(e, op, a, b, eval);
    }
}

static pp_value parse_conditional(expr *e, bool eval) {
    if (++e->depth > PP_MAX_EXPR_DEPTH) {
        fail(e, e->tok, "preprocessor expression nested too deeply");
        return (pp_value){0, false};
    }
    pp_value c = parse_binary(e, 1, eval);
    if (is_punct(e->tok, P_QUESTION) && !e->failed) {
        e->tok = e->tok->next;
        pp_value a = parse_expr(e, eval && c.v != 0);
        if (!is_punct(e->tok, P_COLON)) {
            fail(e, e->tok, "expected ':' in preprocessor expression");
        } else {
            e->tok = e->tok->next;
            pp_value b = parse_conditional(e, eval && c.v == 0);
            bool uns = a.is_unsigned || b.is_unsigned;
            c = c.v ? (pp_value){a.v, uns} : (pp_value){b.v, uns};
        }
    }
    e->depth--;
    return c;
}

static pp_value parse_expr(expr *e, bool eval) {
    pp_value v = parse_conditional(e, eval);
    while (is_punct(e->tok, P_COMMA) && !e->failed) {
        e->tok = e->tok->next;
        v = parse_conditional(e, eval);
    }
    return v;
}

/* Expands the macros of a #if line, leaving the operand of a "defined" that an expansion
 * produced unexpanded, as GCC and MSVC do. */
static hfx_token *expand_condition(hfx_pp *pp, hfx_token *tok) {
    hfx_token head = {0}, *cur = &head;
    while (tok->kind != TK_EOF) {
        if (hfx_pp_expand_macro(pp, &tok, tok)) continue;
        cur = cur->next = tok;
        tok = tok->next;
        if (cur->kind != TK_IDENT || strcmp(cur->text, "defined") != 0) continue;
        int keep = is_punct(tok, P_LPAREN) ? 3 : 1;
        for (int i = 0; i < keep && tok->kind != TK_EOF; i++) {
            cur = cur->next = tok;
            tok = tok->next;
        }
    }
    cur->next = tok;
    return head.next;
}

bool hfx_pp_eval_condition(hfx_pp *pp, hfx_token *line, hfx_loc directive) {
    expr e = {pp, NULL, directive, false, 0};
    if (line->kind == TK_EOF) {
        hfx_pp_error(pp, directive, X_PP_INVALID_INT_EXPR, "#if with no expression");
        return false;
    }
    line = resolve_defined(pp, line, &e);
    if (e.failed) return false;
    pp->expansion_tokens = 0;
    e.tok = expand_condition(pp, line);
    pp_value v = parse_expr(&e, true);
    if (!e.failed && e.tok->kind != TK_EOF) fail(&e, e.tok, "invalid integer constant expression");
    return !e.failed && v.v != 0;
}
