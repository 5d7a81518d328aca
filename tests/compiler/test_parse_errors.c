/* The parser on bad input: fxc's X3000 wording and positions, recovery at ';' and '}' so that
 * every error is reported and the rest of the file still parses, nesting limits that end in
 * an error instead of a stack overflow, and a 100 000-line file. */
#include <stdio.h>

#include "parse_util.h"
#include "test.h"

static void expect_errors(const char *src, const char *want) {
    tp_result *r = tp_parse(src);
    CHECK_STR(r->errors, want);
    tp_free(r);
}

static void missing_semicolon(void) {
    tp_result *r = tp_parse("float a\nfloat b;\nfloat c;\n");
    CHECK_STR(r->errors, "t.fx(2,1): error X3000: syntax error: unexpected token 'float'\n");
    /* recovery skips to the ';' that ends b, so c is still declared */
    CHECK(tp_find(r, "c") != NULL);
    tp_free(r);
    expect_errors("void f() {\n  int i = 0\n  i = 2;\n}\n",
                  "t.fx(3,3): error X3000: syntax error: unexpected token 'i'\n");
}

static void token_kinds_in_messages(void) {
    expect_errors("float a 1;", "t.fx(1,9): error X3000: syntax error: unexpected integer constant\n");
    expect_errors("float a 1.5f;", "t.fx(1,9): error X3000: syntax error: unexpected float constant\n");
    expect_errors("float a \"s\";", "t.fx(1,9): error X3000: syntax error: unexpected string constant\n");
    expect_errors("float a = 1 @ 2;", "t.fx(1,13): error X3000: syntax error: unexpected token '@'\n");
    expect_errors("float a = b->c;", "t.fx(1,12): error X3000: syntax error: unexpected token '->'\n");
    expect_errors("float4 f() {", "t.fx(1,13): error X3000: syntax error: unexpected end of file\n");
    expect_errors("float4 f() {\n", "t.fx(2,1): error X3000: syntax error: unexpected end of file\n");
    expect_errors("Foo x;", "t.fx(1,1): error X3000: unrecognized identifier 'Foo'\n");
    expect_errors("void f() { Foo x; }", "t.fx(1,12): error X3000: unrecognized identifier 'Foo'\n");
    expect_errors("technique T { pass P { CullMode None; } }",
                  "t.fx(1,33): error X3000: syntax error: unexpected token 'None'\n");
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
    tp_result *r = tp_parse("technique T { pass P { CullMode = None } }\nfloat ok;\n");
    CHECK_STR(r->errors, "t.fx(1,40): error X3000: syntax error: unexpected token '}'\n");
    hfx_decl *t = tp_find(r, "T");
    CHECK(t && t->kind == DECL_TECHNIQUE && t->technique->pass_count == 1);
    CHECK(tp_find(r, "ok") != NULL);
    tp_free(r);
    r = tp_parse("sampler s = sampler_state { Texture = <t> };\nfloat ok;\n");
    CHECK_STR(r->errors, "t.fx(1,43): error X3000: syntax error: unexpected token '}'\n");
    hfx_decl *s = tp_find(r, "s");
    CHECK(s && s->init && s->init->kind == EX_SAMPLER_STATE && s->init->state_count == 0);
    CHECK(tp_find(r, "ok") != NULL);
    tp_free(r);
    r = tp_parse("struct S { float a; float b }; float ok;\n");
    CHECK_STR(r->errors, "t.fx(1,29): error X3000: syntax error: unexpected token '}'\n");
    hfx_decl *st = tp_find(r, "S");
    CHECK(st && st->kind == DECL_STRUCT && st->type->st->field_count == 1);
    CHECK(tp_find(r, "ok") != NULL);
    tp_free(r);
}

static void struct_redefinition(void) {
    expect_errors("struct S { float a; };\nstruct S { int b; };\nstruct F;\nstruct F { float c; };\n",
                  "t.fx(2,8): error X3003: redefinition of 'S'\n");
}

static void unbalanced_braces(void) {
    tp_result *r = tp_parse("float a; }\nfloat b;\n");
    CHECK_STR(r->errors, "t.fx(1,10): error X3000: syntax error: unexpected token '}'\n");
    CHECK(tp_find(r, "b") != NULL);
    tp_free(r);
    expect_errors("void f() { if (x) { y = 1; }\n",
                  "t.fx(2,1): error X3000: syntax error: unexpected end of file\n");
    expect_errors("void f() { y = (1 + 2; }\nfloat z;\n",
                  "t.fx(1,22): error X3000: syntax error: unexpected token ';'\n");
    expect_errors("struct S { float a; \nfloat b;\n",
                  "t.fx(3,1): error X3000: syntax error: unexpected end of file\n");
    expect_errors("technique T { pass P { }\n", "t.fx(2,1): error X3000: syntax error: unexpected end of file\n");
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

static void deep_nesting_is_an_error(void) {
    /* 10 000 parentheses: the 257th is too deep (the first is at column 11) */
    char *src = repeat("float a = ", "(", 10000, "1", ")", 10000, ";\nfloat b;\n");
    tp_result *r = tp_parse(src);
    CHECK_STR(r->errors, "t.fx(1,267): error X3000: nesting too deep: more than 256 levels of ( [ {\n");
    free(src);
    tp_free(r);
    src = repeat("void f() ", "{", 10000, "", "}", 10000, "\n");
    r = tp_parse(src);
    CHECK_STR(r->errors, "t.fx(1,266): error X3000: nesting too deep: more than 256 levels of ( [ {\n");
    free(src);
    tp_free(r);
    /* 100 000 prefix operators overflow the parser's stack limit, reported once */
    src = repeat("float a = ", "-", 100000, "1;", "", 0, "\n");
    r = tp_parse(src);
    CHECK_INT(r->diags.errors, 1);
    CHECK_CONTAINS(r->errors, "error X3000: nesting too deep");
    free(src);
    tp_free(r);
    /* 10 000 prefix operators fit the stack but not the expression depth limit (4096) */
    src = repeat("float a = ", "!", 10000, "1;", "", 0, "\n");
    r = tp_parse(src);
    CHECK_STR(r->errors, "t.fx(1,5915): error X3000: nesting too deep: expression more than 4096 levels deep\n");
    free(src);
    tp_free(r);
    /* a chain of 5000 additions is as deep */
    src = repeat("float a = 1", " + 1", 5000, ";", "", 0, "\n");
    r = tp_parse(src);
    CHECK_STR(r->errors, "t.fx(1,16393): error X3000: nesting too deep: expression more than 4096 levels deep\n");
    free(src);
    tp_free(r);
    /* 2000 nested unbraced ifs */
    src = repeat("void f() { ", "if (x) ", 2000, "y = 1;", "", 0, " }\n");
    r = tp_parse(src);
    CHECK_CONTAINS(r->errors, "error X3000: nesting too deep: statements more than 1024 levels deep\n");
    CHECK_INT(r->diags.errors, 1);
    free(src);
    tp_free(r);
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
    return test_summary();
}
