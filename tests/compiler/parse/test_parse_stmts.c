/* The parser on statements and expressions: every statement form with its attributes, C
 * precedence and associativity (visible in the dump, which parenthesizes every operator),
 * casts versus parentheses, constructors, members, methods, and node locations. */
#include <stdio.h>

#include "parse_util.h"
#include "test.h"

/* The dump of the body of `void f() { <body> }` without the function header lines. */
static void expect_body(const char *body, const char *want) {
    char src[4096];
    snprintf(src, sizeof src, "struct MyStruct { float a; };\nvoid f() {\n%s\n}\n", body);
    tp_result *r = tp_parse(src);
    CHECK_STR(r->errors, "");
    const char *head = "struct MyStruct\n  field float a\nfunction void f\n  block\n";
    size_t n = strlen(head);
    CHECK(strncmp(r->dump, head, n) == 0);
    if (strncmp(r->dump, head, n) == 0) CHECK_STR(r->dump + n, want);
    else fprintf(stderr, "%s", r->dump);
    tp_free(r);
}

static void statement_forms(void) {
    expect_body("int i = 0, j;\n"
                "if (i) i = 1; else if (j) j = 2; else { }\n"
                "for (i = 0; i < 4; ++i) { continue; }\n"
                "for (int k = 0; ; ) break;\n"
                "for (;;) discard;\n"
                "while (i--) ;\n"
                "do { i += 2; } while (i < 10);\n"
                "switch (i) { case 1: i = 0; break; case 2+1: default: break; }\n"
                "return;\n",
                "    var int i = 0\n"
                "    var int j\n"
                "    if i\n"
                "      expr (i = 1)\n"
                "    else\n"
                "      if j\n"
                "        expr (j = 2)\n"
                "      else\n"
                "        block\n"
                "    for\n"
                "        expr (i = 0)\n"
                "      cond (i < 4)\n"
                "      step (++i)\n"
                "      block\n"
                "        continue\n"
                "    for\n"
                "        var int k = 0\n"
                "      cond\n"
                "      step\n"
                "      break\n"
                "    for\n"
                "      cond\n"
                "      step\n"
                "      discard\n"
                "    while (i--)\n"
                "      empty\n"
                "    do\n"
                "      block\n"
                "        expr (i += 2)\n"
                "    while (i < 10)\n"
                "    switch i\n"
                "      case 1\n"
                "      expr (i = 0)\n"
                "      break\n"
                "      case (2 + 1)\n"
                "      default\n"
                "      break\n"
                "    return\n");
}

static void loop_attributes(void) {
    expect_body("[unroll] for (int i = 0; i < 2; i++) { }\n"
                "[unroll(4)] while (true) { }\n"
                "[loop] [fastopt] do { } while (false);\n"
                "[branch] if (1) { } \n"
                "[flatten] if (0) { }\n",
                "    [unroll] \n"
                "    for\n"
                "        var int i = 0\n"
                "      cond (i < 2)\n"
                "      step (i++)\n"
                "      block\n"
                "    [unroll(4)] \n"
                "    while true\n"
                "      block\n"
                "    [loop] [fastopt] \n"
                "    do\n"
                "      block\n"
                "    while false\n"
                "    [branch] \n"
                "    if 1\n"
                "      block\n"
                "    [flatten] \n"
                "    if 0\n"
                "      block\n");
    tp_result *r = tp_parse("void f() { [unroll(4)] for (;;) { } }");
    hfx_stmt *loop = r->ast->decls[0]->func->body->body[0];
    CHECK_INT(loop->kind, ST_FOR);
    CHECK_INT(loop->attr_count, 1);
    CHECK_STR(loop->attrs[0].name, "unroll");
    CHECK_INT(loop->attrs[0].arg_count, 1);
    CHECK_INT(loop->attrs[0].args[0]->ival, 4);
    CHECK_INT(loop->attrs[0].loc.col, 13);
    tp_free(r);
}

static void asm_blocks(void) {
    tp_result *r = tp_parse("void f() {\n  asm { mov r0, c0 { nested } }\n  int i;\n}\n"
                            "technique T { pass P { PixelShader = asm { ps_1_1\n tex t0 }; } }\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "function void f\n"
                       "  block\n"
                       "    asm asm { mov r0 , c0 { nested } }\n"
                       "    var int i\n"
                       "technique T\n"
                       "  pass P\n"
                       "    state PixelShader = asm { ps_1_1\ntex t0 }\n");
    hfx_stmt *a = r->ast->decls[0]->func->body->body[0];
    CHECK_INT(a->kind, ST_ASM);
    CHECK(a->expr && a->expr->kind == EX_ASM);
    CHECK_INT(a->loc.line, 2);
    CHECK_INT(a->loc.col, 3);
    tp_free(r);
}

static void precedence(void) {
    expect_body("a = b + c * d - e / f % g;\n"
                "a = b << 1 + 2 < c == d & e ^ f | g && h || k;\n"
                "a = b ? c : d ? e : f;\n"
                "a = b = c;\n"
                "a += b -= c;\n"
                "a *= 2, b /= 3, c %= 4;\n"
                "a <<= 1; a >>= 2; a &= 3; a |= 4; a ^= 5;\n"
                "a = -b++ + !c - ~d * --e;\n"
                "a = b > c >= d <= e != f;\n"
                "a = (b + c) * d;\n"
                "a = b >> 2;\n",
                "    expr (a = ((b + (c * d)) - ((e / f) % g)))\n"
                "    expr (a = ((((((((b << (1 + 2)) < c) == d) & e) ^ f) | g) && h) || k))\n"
                "    expr (a = (b ? c : (d ? e : f)))\n"
                "    expr (a = (b = c))\n"
                "    expr (a += (b -= c))\n"
                "    expr (((a *= 2), (b /= 3)), (c %= 4))\n"
                "    expr (a <<= 1)\n"
                "    expr (a >>= 2)\n"
                "    expr (a &= 3)\n"
                "    expr (a |= 4)\n"
                "    expr (a ^= 5)\n"
                "    expr (a = (((-(b++)) + (!c)) - ((~d) * (--e))))\n"
                "    expr (a = ((((b > c) >= d) <= e) != f))\n"
                "    expr (a = ((b + c) * d))\n"
                "    expr (a = (b >> 2))\n");
}

static void postfix_casts_and_constructors(void) {
    expect_body("x = float4(v.xyz, 1).wzyx;\n"
                "x = (float3)y;\n"
                "x = (MyStruct)0;\n"
                "x = (float3x3)World;\n"
                "x = (y);\n"
                "x = (float4(1,2,3,4));\n"
                "x = a[i].b.c[2];\n"
                "x = m._m00 + m._11;\n"
                "x = t.Sample(s, uv);\n"
                "x = vector<float, 2>(1, 2) + matrix<int,1,1>(3);\n"
                "x = (int[2])k;\n"
                "x = -mul(a, b)[0];\n"
                "x = 1.5.xx;\n"
                "x = s.sample + s.texture + s.in;\n",
                "    expr (x = float4(v.xyz, 1).wzyx)\n"
                "    expr (x = (float3)y)\n"
                "    expr (x = (MyStruct)0)\n"
                "    expr (x = (float3x3)World)\n"
                "    expr (x = (y))\n"
                "    expr (x = (float4(1, 2, 3, 4)))\n"
                "    expr (x = a[i].b.c[2])\n"
                "    expr (x = (m._m00 + m._11))\n"
                "    expr (x = t.Sample(s, uv))\n"
                "    expr (x = (float2(1, 2) + int(3)))\n" /* types.c interns 1x1 as the scalar */
                "    expr (x = (int[2])k)\n"
                "    expr (x = (-mul(a, b)[0]))\n"
                "    expr (x = 1.5.xx)\n"
                "    expr (x = ((s.sample + s.texture) + s.in))\n");
}

/* An expression's loc is its operator or first token; a call's is the callee name. */
static void expression_locations(void) {
    tp_result *r = tp_parse("void f() {\n"
                            "  x = a + foo(b)[2] * c.y;\n"
                            "}\n");
    CHECK_STR(r->errors, "");
    hfx_expr *as = r->ast->decls[0]->func->body->body[0]->expr;
    CHECK_INT(as->kind, EX_ASSIGN);
    CHECK_INT(as->loc.col, 5);            /* = */
    hfx_expr *add = as->args[1];
    CHECK_INT(add->op, OP_ADD);
    CHECK_INT(add->loc.col, 9);           /* + */
    CHECK_INT(add->args[0]->loc.col, 7);  /* a */
    hfx_expr *mul = add->args[1];
    CHECK_INT(mul->op, OP_MUL);
    CHECK_INT(mul->loc.col, 21);          /* * */
    hfx_expr *index = mul->args[0];
    CHECK_INT(index->kind, EX_INDEX);
    CHECK_INT(index->loc.col, 17);        /* [ */
    hfx_expr *call = index->args[0];
    CHECK_INT(call->kind, EX_CALL);
    CHECK_STR(call->name, "foo");
    CHECK_INT(call->loc.line, 2);
    CHECK_INT(call->loc.col, 11);         /* foo */
    hfx_expr *member = mul->args[1];
    CHECK_INT(member->kind, EX_MEMBER);
    CHECK_STR(member->name, "y");
    CHECK_INT(member->loc.col, 24);       /* . */
    CHECK_INT(member->args[0]->loc.col, 23);
    CHECK_INT(call->intrinsic, -1);
    tp_free(r);
}

int main(void) {
    RUN(statement_forms);
    RUN(loop_attributes);
    RUN(asm_blocks);
    RUN(precedence);
    RUN(postfix_casts_and_constructors);
    RUN(expression_locations);
    return test_summary();
}
