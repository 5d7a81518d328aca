/* The parser on bad input: fxc's X3000 wording and positions, recovery at ';' and '}' so that
 * every error is reported and the rest of the file still parses, nesting limits that end in
 * an error instead of a stack overflow, and a 100 000-line file. */
#include <stdio.h>

#include "parse_util.h"
#include "test.h"

/* Parses src and checks the whole diagnostics text; the caller frees the result. */
static tp_result *parse_expecting(const char *src, const char *want) {
    tp_result *r = tp_parse(src);
    CHECK_STR(r->errors, want);
    return r;
}

static void expect_errors(const char *src, const char *want) {
    tp_free(parse_expecting(src, want));
}

/* A snippet and the whole diagnostics text it must give. */
typedef struct error_case {
    const char *src, *errors;
} error_case;

static void expect_each(const error_case *cases, size_t n) {
    for (size_t i = 0; i < n; i++) expect_errors(cases[i].src, cases[i].errors);
}

#define EXPECT_EACH(cases) expect_each(cases, sizeof cases / sizeof cases[0])

static void missing_semicolon(void) {
    tp_result *r = parse_expecting("float a\nfloat b;\nfloat c;\n",
                                   "t.fx(2,1): error X3000: syntax error: unexpected token 'float'\n");
    /* recovery skips to the ';' that ends b, so c is still declared */
    CHECK(tp_find(r, "c") != NULL);
    tp_free(r);
    expect_errors("void f() {\n  int i = 0\n  i = 2;\n}\n",
                  "t.fx(3,3): error X3000: syntax error: unexpected token 'i'\n");
}

static const error_case TOKEN_KINDS[] = {
    {"float a 1;", "t.fx(1,9): error X3000: syntax error: unexpected integer constant\n"},
    {"float a 1.5f;", "t.fx(1,9): error X3000: syntax error: unexpected float constant\n"},
    {"float a \"s\";", "t.fx(1,9): error X3000: syntax error: unexpected string constant\n"},
    {"float a = 1 @ 2;", "t.fx(1,13): error X3000: syntax error: unexpected token '@'\n"},
    {"float a = b->c;", "t.fx(1,12): error X3000: syntax error: unexpected token '->'\n"},
    {"float4 f() {", "t.fx(1,13): error X3000: syntax error: unexpected end of file\n"},
    {"float4 f() {\n", "t.fx(2,1): error X3000: syntax error: unexpected end of file\n"},
    {"Foo x;", "t.fx(1,1): error X3000: unrecognized identifier 'Foo'\n"},
    {"void f() { Foo x; }", "t.fx(1,12): error X3000: unrecognized identifier 'Foo'\n"},
    {"technique T { pass P { CullMode None; } }", "t.fx(1,33): error X3000: syntax error: unexpected token 'None'\n"},
};

static void token_kinds_in_messages(void) {
    EXPECT_EACH(TOKEN_KINDS);
}

static void every_error_reported(void) {
    tp_result *r = tp_parse("float a = ;\n"
                            "float4 f() {\n"
                            "  x = 1 +;\n"
                            "  y = );\n"
                            "  return 0;\n"
                            "}\n"
                            "technique T { pass P { CullMode = ; ZEnable = true; } }\n"
                            "float ok;\n");
    CHECK_STR(r->errors, "t.fx(1,11): error X3000: syntax error: unexpected token ';'\n"
                         "t.fx(3,10): error X3000: syntax error: unexpected token ';'\n"
                         "t.fx(4,7): error X3000: syntax error: unexpected token ')'\n"
                         "t.fx(7,35): error X3000: syntax error: unexpected token ';'\n");
    CHECK(tp_find(r, "ok") != NULL);
    hfx_decl *f = tp_find(r, "f");
    CHECK(f && f->kind == DECL_FUNC && f->func->body);
    if (f && f->func->body) {
        /* the two bad statements stay as empty ones, the return survives */
        CHECK_INT(f->func->body->body_count, 3);
        CHECK_INT(f->func->body->body[2]->kind, ST_RETURN);
    }
    hfx_decl *t = tp_find(r, "T");
    CHECK(t && t->technique->pass_count == 1 && t->technique->passes[0].state_count == 1);
    if (t && t->technique->pass_count == 1 && t->technique->passes[0].state_count == 1)
        CHECK_STR(t->technique->passes[0].states[0].name, "ZEnable");
    tp_free(r);
}

/* Recovery inside struct bodies and annotations keeps the rest of the declaration. */
static void recovery_in_structs_and_annotations(void) {
    tp_result *r = tp_parse("struct S { float a b; float c; };\n"
                            "float x < string n = ; int k = 1; > = 1;\n"
                            "float y;\n");
    CHECK_STR(r->errors, "t.fx(1,20): error X3000: syntax error: unexpected token 'b'\n"
                         "t.fx(2,22): error X3000: syntax error: unexpected token ';'\n");
    hfx_decl *s = tp_find(r, "S"), *x = tp_find(r, "x");
    CHECK(s && s->type->st->field_count == 1 && strcmp(s->type->st->fields[0].name, "c") == 0);
    CHECK(x && x->annotation_count == 1 && strcmp(x->annotations[0].name, "k") == 0);
    CHECK(x && x->init && x->init->ival == 1);
    CHECK(tp_find(r, "y") != NULL);
    tp_free(r);
}

static void unnamed_parameter_in_definition(void) {
    expect_errors("float f(float, int);\nfloat g(float a, int) { return a; }\n",
                  "t.fx(2,18): error X3000: 'g': parameter 2 has no name\n");
}

/* A missing ';' before a closing brace: the block still closes and what follows is kept. */
static void recovery_at_closing_braces(void) {
    tp_result *r = parse_expecting("technique T { pass P { CullMode = None } }\nfloat ok;\n",
                                   "t.fx(1,40): error X3000: syntax error: unexpected token '}'\n");
    hfx_decl *t = tp_find(r, "T");
    CHECK(t && t->kind == DECL_TECHNIQUE && t->technique->pass_count == 1);
    CHECK(tp_find(r, "ok") != NULL);
    tp_free(r);
    r = parse_expecting("sampler s = sampler_state { Texture = <t> };\nfloat ok;\n",
                        "t.fx(1,43): error X3000: syntax error: unexpected token '}'\n");
    hfx_decl *s = tp_find(r, "s");
    CHECK(s && s->init && s->init->kind == EX_SAMPLER_STATE && s->init->state_count == 0);
    CHECK(tp_find(r, "ok") != NULL);
    tp_free(r);
    r = parse_expecting("struct S { float a; float b }; float ok;\n",
                        "t.fx(1,29): error X3000: syntax error: unexpected token '}'\n");
    hfx_decl *st = tp_find(r, "S");
    CHECK(st && st->kind == DECL_STRUCT && st->type->st->field_count == 1);
    CHECK(tp_find(r, "ok") != NULL);
    tp_free(r);
}

static void struct_redefinition(void) {
    expect_errors("struct S { float a; };\nstruct S { int b; };\nstruct F;\nstruct F { float c; };\n",
                  "t.fx(2,8): error X3003: redefinition of 'S'\n");
}

static const error_case UNBALANCED[] = {
    {"void f() { if (x) { y = 1; }\n", "t.fx(2,1): error X3000: syntax error: unexpected end of file\n"},
    {"void f() { y = (1 + 2; }\nfloat z;\n", "t.fx(1,22): error X3000: syntax error: unexpected token ';'\n"},
    {"struct S { float a; \nfloat b;\n", "t.fx(3,1): error X3000: syntax error: unexpected end of file\n"},
    {"technique T { pass P { }\n", "t.fx(2,1): error X3000: syntax error: unexpected end of file\n"},
};

static void unbalanced_braces(void) {
    tp_result *r = parse_expecting("float a; }\nfloat b;\n",
                                   "t.fx(1,10): error X3000: syntax error: unexpected token '}'\n");
    CHECK(tp_find(r, "b") != NULL);
    tp_free(r);
    EXPECT_EACH(UNBALANCED);
}

static char *repeat(const char *head, const char *unit, int n, const char *mid, const char *unit2, int n2,
                    const char *tail) {
    size_t len = strlen(head) + strlen(unit) * n + strlen(mid) + strlen(unit2) * n2 + strlen(tail) + 1;
    char *s = malloc(len), *p = s;
    p += sprintf(p, "%s", head);
    for (int i = 0; i < n; i++) p += sprintf(p, "%s", unit);
    p += sprintf(p, "%s", mid);
    for (int i = 0; i < n2; i++) p += sprintf(p, "%s", unit2);
    sprintf(p, "%s", tail);
    return s;
}

/* A source of `head`, `unit` n times, `mid`, `unit2` n2 times, `tail` (see repeat), and what
 * parsing it must say: the whole text, or (contains) a part of it and how many errors. */
typedef struct nesting_case {
    const char *head, *unit;
    int n;
    const char *mid, *unit2;
    int n2;
    const char *tail, *errors;
    int contains, error_count;
} nesting_case;

static const nesting_case NESTING[] = {
    /* 10 000 parentheses: the 257th is too deep (the first is at column 11) */
    {"float a = ", "(", 10000, "1", ")", 10000, ";\nfloat b;\n",
     "t.fx(1,267): error X3000: nesting too deep: more than 256 levels of ( [ {\n", 0, 0},
    {"void f() ", "{", 10000, "", "}", 10000, "\n",
     "t.fx(1,266): error X3000: nesting too deep: more than 256 levels of ( [ {\n", 0, 0},
    /* 100 000 prefix operators overflow the parser's stack limit, reported once */
    {"float a = ", "-", 100000, "1;", "", 0, "\n", "error X3000: nesting too deep", 1, 1},
    /* 10 000 prefix operators fit the stack but not the expression depth limit (4096) */
    {"float a = ", "!", 10000, "1;", "", 0, "\n",
     "t.fx(1,5915): error X3000: nesting too deep: expression more than 4096 levels deep\n", 0, 0},
    /* a chain of 5000 additions is as deep */
    {"float a = 1", " + 1", 5000, ";", "", 0, "\n",
     "t.fx(1,16393): error X3000: nesting too deep: expression more than 4096 levels deep\n", 0, 0},
    /* 2000 nested unbraced ifs */
    {"void f() { ", "if (x) ", 2000, "y = 1;", "", 0, " }\n",
     "error X3000: nesting too deep: statements more than 1024 levels deep\n", 1, 1},
};

static void expect_nesting(const nesting_case *c) {
    char *src = repeat(c->head, c->unit, c->n, c->mid, c->unit2, c->n2, c->tail);
    tp_result *r = tp_parse(src);
    if (c->contains) {
        CHECK_CONTAINS(r->errors, c->errors);
        CHECK_INT(r->diags.errors, c->error_count);
    } else {
        CHECK_STR(r->errors, c->errors);
    }
    free(src);
    tp_free(r);
}

static void deep_nesting_is_an_error(void) {
    for (size_t i = 0; i < sizeof NESTING / sizeof NESTING[0]; i++) expect_nesting(&NESTING[i]);
}

static void long_but_shallow_is_fine(void) {
    /* 3000 terms, 3000 else-ifs would be too deep; 1000 of each are not */
    char *src = repeat("float a = 1", " + 1", 3000, ";\nvoid f() { if (x) y = 0;", " else if (x) y = 1;", 1000, " }\n");
    tp_result *r = tp_parse(src);
    CHECK_STR(r->errors, "");
    free(src);
    tp_free(r);
}

static void hundred_thousand_lines(void) {
    size_t cap = 4 * 1024 * 1024, len = 0;
    char *src = malloc(cap);
    for (int i = 0; i < 50000; i++) len += (size_t)snprintf(src + len, cap - len, "float g%d = %d.5;\n", i, i);
    len += (size_t)snprintf(src + len, cap - len, "float4 f(float x) : COLOR {\n");
    for (int i = 0; i < 49998; i++) len += (size_t)snprintf(src + len, cap - len, "  x += g%d * 2;\n", i);
    snprintf(src + len, cap - len, "  return x;\n}\n");
    tp_result *r = tp_parse(src);
    CHECK_STR(r->errors, "");
    CHECK_INT(r->ast->decl_count, 50001);
    hfx_decl *f = tp_find(r, "f");
    CHECK(f && f->func->body && f->func->body->body_count == 49999);
    CHECK(f && f->loc.line == 50001);
    hfx_decl *last = tp_find(r, "g49999");
    CHECK(last && last->init->kind == EX_FLOAT && last->init->fval == 49999.5);
    free(src);
    tp_free(r);
}

/* An integer literal past 32 bits keeps its low 32, with fxc's warning by base (Microsoft's list
 * of HLSL errors and warnings: 1002 hex, 1003 octal, 1004 decimal "value was truncated to 32
 * bits"); 4294967295 fits and warns nothing. */
static void literals_past_32_bits(void) {
    expect_errors("static const int a = 4294967297;\nstatic const int b = 0x1FFFFFFFF;\nstatic const int c = 0777777777777;\n"
                  "static const uint d = 4294967295;\nstatic const int e = 99999999999999999999999;\n",
                  "t.fx(1,22): warning X1004: decimal value truncated to 32 bits\n"
                  "t.fx(2,22): warning X1002: hex value truncated to 32 bits\n"
                  "t.fx(3,22): warning X1003: octal value truncated to 32 bits\n"
                  "t.fx(5,22): warning X1004: decimal value truncated to 32 bits\n");
    tp_result *r = tp_parse("static const int a = 4294967297;\n");
    const hfx_decl *a = tp_find(r, "a");
    CHECK(a && a->init && a->init->ival == 1);
    tp_free(r);
}

int main(void) {
    RUN(missing_semicolon);
    RUN(token_kinds_in_messages);
    RUN(every_error_reported);
    RUN(unbalanced_braces);
    RUN(struct_redefinition);
    RUN(recovery_at_closing_braces);
    RUN(unnamed_parameter_in_definition);
    RUN(recovery_in_structs_and_annotations);
    RUN(deep_nesting_is_an_error);
    RUN(long_but_shallow_is_fine);
    RUN(hundred_thousand_lines);
    RUN(literals_past_32_bits);
    return test_summary();
}
