/* The decorated tree the checker hands to codegen (ast.h's invariants): types, implicit
 * casts, resolved calls and overloads, swizzle components, flattened initializers. The
 * expected dumps are worked out by hand from HLSL's rules. */
#include <stdlib.h>
#include <string.h>

#include "check_util.h"
#include "test.h"

/* The dump of statement i of function fn in src, which must check without error. */
static char *stmt_of(const char *src, const char *fn, unsigned i) {
    ckt_result *r = ckt_run(src);
    if (!r->ok) {
        char *t = ckt_text(r);
        fprintf(stderr, "unexpected diagnostics:\n%s", t);
        free(t);
    }
    char *s = ckt_dump_stmt(r, fn, i);
    ckt_free(r);
    return s;
}

#define EXPECT_STMT(src, fn, i, expected) do { char *s_ = stmt_of(src, fn, i); CHECK_STR(s_, expected); free(s_); } while (0)

/* The first statement of function fn of a snippet, and its expected dump. */
typedef struct stmt_case {
    const char *fn, *expected;
} stmt_case;

static void expect_first_stmts(const char *src, const stmt_case *cases, size_t n) {
    for (size_t i = 0; i < n; i++) EXPECT_STMT(src, cases[i].fn, 0, cases[i].expected);
}

#define EXPECT_FIRST_STMTS(src, cases) expect_first_stmts(src, cases, sizeof cases / sizeof cases[0])

/* Compares the dump of e, and frees it. */
static void expect_dump(const hfx_expr *e, const char *expected) {
    char *s = ckt_dump(e);
    CHECK_STR(s, expected);
    free(s);
}

static const char *MUL_SRC =
    "float4x4 M; float3x4 N; float4x3 P; float3 v3; float4 v4; float s;\n"
    "float4 f1() { return mul(v3, M); }\n"
    "float3 f2() { return mul(v4, P); }\n"
    "float3 f3() { return mul(N, v4); }\n"
    "float f4() { return mul(v3, v3); }\n"
    "float4 f5() { return mul(s, v4); }\n"
    "float3x3 f6() { return mul(N, P); }\n"
    "float4 f7() { return mul(v4, N); }\n"
    "float3x4 f8() { return mul(2, N); }\n"
    "float4x4 f9() { return mul(M, M); }\n";

static const stmt_case MUL_SHAPES[] = {
    /* float3 * float4x4: the matrix is clamped to its first three rows, the result has 4 columns */
    {"f1", "(#mul:float4 v3:float3 (implicit:float3x4 M:float4x4))"},
    {"f2", "(#mul:float3 v4:float4 P:float4x3)"},
    {"f3", "(#mul:float3 N:float3x4 v4:float4)"},
    {"f4", "(#mul:float v3:float3 v3:float3)"},
    {"f5", "(#mul:float4 s:float v4:float4)"},
    {"f6", "(#mul:float3x3 N:float3x4 P:float4x3)"},
    /* float4 * float3x4: the vector is clamped to float3 */
    {"f7", "(#mul:float4 (implicit:float3 v4:float4) N:float3x4)"},
    {"f8", "(#mul:float3x4 (implicit:float 2:int) N:float3x4)"},
    {"f9", "(#mul:float4x4 M:float4x4 M:float4x4)"},
};

static void mul_shapes(void) {
    EXPECT_FIRST_STMTS(MUL_SRC, MUL_SHAPES);
    /* the seeds' pattern: mul into a float3 warns once, for the assignment */
    char *d = ckt_diags("float4x4 World;\nfloat3 f(float3 n) { float3 r = mul(n, World); return r; }\n");
    CHECK_STR(d, "t.fx(2,33): warning X3206: implicit truncation of vector type\n");
    free(d);
    EXPECT_STMT("float4x4 World;\nfloat3 f(float3 n) { float3 r = mul(n, World); return r; }\n", "f", 0,
                "(implicit:float3 (#mul:float4 n:float3 (implicit:float3x4 World:float4x4)))");
}

static const char *OPS_SRC =
    "float3 a; float4 b; int i;\n"
    "float3 g1() { return a - b; }\n"
    "float4 g2() { return b * 2; }\n"
    "float g3() { return i + 1.5; }\n"
    "bool3 g4() { return a < 1; }\n"
    "float4 g5() { return b.x ? b : 0; }\n"
    "bool g6() { return a.x && i; }\n"
    "float3 g7() { return -a; }\n"
    "int g8() { return -true; }\n"
    "float4 g9() { return b < 0.5 ? 0 : b; }\n"
    "int g10() { return i << 2; }\n";

static const stmt_case OPERATORS[] = {
    {"g1", "(-:float3 a:float3 (implicit:float3 b:float4))"},
    {"g2", "(*:float4 b:float4 (implicit:float4 2:int))"},
    {"g3", "(+:float (implicit:float i:int) 1.5:float)"},
    {"g4", "(<:bool3 a:float3 (implicit:float3 1:int))"},
    {"g5", "(?:float4 (implicit:bool (.0:float b:float4)) b:float4 (implicit:float4 0:int))"},
    {"g6", "(&&:bool (implicit:bool (.0:float a:float3)) (implicit:bool i:int))"},
    {"g7", "(neg:float3 a:float3)"},
    {"g8", "(neg:int (implicit:int true:bool))"},
    /* a componentwise ternary: the condition is a bool4 */
    {"g9", "(?:float4 (<:bool4 b:float4 (implicit:float4 0.5:float)) (implicit:float4 0:int) b:float4)"},
    {"g10", "(<<:int i:int 2:int)"},
};

static void operators(void) {
    EXPECT_FIRST_STMTS(OPS_SRC, OPERATORS);
}

static const char *MEMBER_SRC =
    "struct S { float3 p; float4 c[2]; };\n"
    "S s; float4x4 m; float4 v;\n"
    "float3 h1() { return s.p; }\n"
    "float4 h2() { return s.c[1]; }\n"
    "float4 h3() { return m[2]; }\n"
    "float h4() { return m._m12; }\n"
    "float2 h5() { return m._11_44; }\n"
    "float4 h6() { return v.wzyx; }\n"
    "float h7() { return v[3]; }\n"
    "float3 h8() { return v.rgb; }\n"
    "float h9() { return m[1][2]; }\n";

static const stmt_case MEMBERS_AND_INDEXING[] = {
    {"h1", "(.f0:float3 s:S)"},
    {"h2", "([]:float4 (.f1:float4[2] s:S) 1:int)"},
    {"h3", "([]:float4 m:float4x4 2:int)"}, /* a row */
    {"h4", "(.6:float m:float4x4)"},        /* row 1, col 2 */
    {"h5", "(.0,15:float2 m:float4x4)"},    /* one-based */
    {"h6", "(.3,2,1,0:float4 v:float4)"},
    {"h7", "([]:float v:float4 3:int)"},
    {"h8", "(.0,1,2:float3 v:float4)"},
    {"h9", "([]:float ([]:float4 m:float4x4 1:int) 2:int)"},
};

static void members_and_indexing(void) {
    EXPECT_FIRST_STMTS(MEMBER_SRC, MEMBERS_AND_INDEXING);
}

static const char *CALL_SRC =
    "float f(float x) { return x; }\n"
    "float f(float4 x) { return x.x; }\n"
    "float k(float a, float b = 2) { return a + b; }\n"
    "sampler s;\n"
    "float u1() { return f(1.0); }\n"
    "float u2() { return f(float4(1, 2, 3, 4.0)); }\n"
    "float u3() { return f(1); }\n"
    "float u4() { return k(1); }\n"
    "float4 u5(float2 uv) { return tex2D(s, uv); }\n"
    "float u6(float3 n) { return length(n) + dot(n, 2); }\n"
    "float3 u7(float3 a, float3 b) { return lerp(a, b, 0.5); }\n"
    "float u8(float x) { return pow(x, 2); }\n";

static const stmt_case CALLS_AND_OVERLOADS[] = {
    {"u1", "(f(float):float 1:float)"},
    {"u2", "(f(float4):float (float4:float4 (implicit:float 1:int) (implicit:float 2:int) (implicit:float 3:int) "
           "4:float))"},
    /* int -> float beats int -> float4 (a splat) */
    {"u3", "(f(float):float (implicit:float 1:int))"},
    /* a defaulted parameter may be left out: its default value becomes the argument */
    {"u4", "(k(float,float):float (implicit:float 1:int) (implicit:float 2:int))"},
    /* a generic sampler feeds tex2D as it is */
    {"u5", "(#tex2D:float4 s:sampler uv:float2)"},
    {"u6", "(+:float (#length:float n:float3) (#dot:float n:float3 (implicit:float3 2:int)))"},
    {"u7", "(#lerp:float3 a:float3 b:float3 (implicit:float3 0.5:float))"},
    {"u8", "(#pow:float x:float (implicit:float 2:int))"},
};

static void calls_and_overloads(void) {
    EXPECT_FIRST_STMTS(CALL_SRC, CALLS_AND_OVERLOADS);
    /* a float3 argument picks f(float) (a truncation) since float3 -> float4 is impossible */
    char *d = ckt_diags("float f(float x) { return x; }\nfloat f(float4 x) { return x.x; }\nfloat g(float3 v) { return f(v); }\n");
    CHECK_STR(d, "t.fx(3,28): warning X3206: 'f': implicit truncation of vector type\n");
    free(d);
}

static const char *RANK_SRC =
    "float p(half x) { return x; }\n"
    "float p(int x) { return x; }\n"
    "float q(float a, float4 b) { return a; }\n"
    "float q(float4 a, float b) { return b; }\n"
    "float3 saturate(float3 x) { return x * 0.5; }\n"
    "float r1(float x) { return p(x); }\n"
    "float r2(float4 v, float s) { return q(s, v) + q(v, s); }\n"
    "float3 r3(float3 v) { return saturate(v); }\n"
    "float r4(float s) { return saturate(s); }\n";

static const stmt_case OVERLOAD_RANKING[] = {
    /* float -> half is a promotion, float -> int a conversion: half wins */
    {"r1", "(p(half):float (implicit:half x:float))"},
    /* each call matches one overload exactly */
    {"r2", "(+:float (q(float,float4):float s:float v:float4) (q(float4,float):float v:float4 s:float))"},
    /* a user function named like an intrinsic competes with it: each takes what it matches best */
    {"r3", "(saturate(float3):float3 v:float3)"},
    {"r4", "(#saturate:float s:float)"},
};

static void overload_ranking(void) {
    EXPECT_FIRST_STMTS(RANK_SRC, OVERLOAD_RANKING);
}

static void sampler_parameters(void) {
    /* a generic sampler passed to a sampler2D parameter stays as it is (no cast node) */
    const char *src = "sampler s;\nfloat4 look(sampler2D t, float2 uv) { return tex2D(t, uv); }\n"
                      "float4 f(float2 uv) { return look(s, uv); }\n";
    EXPECT_STMT(src, "f", 0, "(look(sampler2D,float2):float4 s:sampler uv:float2)");
    ckt_result *r = ckt_run(src);
    char why[256];
    CHECK_INT(ckt_invariants(r, why, sizeof why), 0);
    ckt_free(r);
}

static void initializers(void) {
    ckt_result *r = ckt_run(
        "float4 c = {0.07F, 0.07F, 0.07F, 1};\n"
        "float ks = {0.05F};\n"
        "float2x2 m2 = {float2(1, 2), 3, 4};\n"
        "float a[] = {1, 2, 3};\n"
        "struct L { float3 d; int on; };\n"
        "L lights[2] = {{1, 2, 3, true}, {4, 5, 6, 0}};\n"
        "float4 z = 0;\n");
    CHECK(r->ok);
    expect_dump(ckt_find(r, "c")->init, "({}:float4 0.07:float 0.07:float 0.07:float (implicit:float 1:int))");
    expect_dump(ckt_find(r, "ks")->init, "({}:float 0.05:float)");
    expect_dump(ckt_find(r, "m2")->init,
                "({}:float2x2 (.0:float (float2:float2 (implicit:float 1:int) (implicit:float 2:int))) "
                "(.1:float (float2:float2 (implicit:float 1:int) (implicit:float 2:int))) "
                "(implicit:float 3:int) (implicit:float 4:int))");
    hfx_decl *a = ckt_find(r, "a");
    CHECK_INT(a->type->kind, TY_ARRAY);
    CHECK_INT(a->type->array_len, 3);
    expect_dump(ckt_find(r, "lights")->init,
                "({}:L[2] (implicit:float 1:int) (implicit:float 2:int) (implicit:float 3:int) "
                "(implicit:int true:bool) (implicit:float 4:int) (implicit:float 5:int) (implicit:float 6:int) 0:int)");
    expect_dump(ckt_find(r, "z")->init, "(implicit:float4 0:int)");
    ckt_free(r);
}

static void array_sizes(void) {
    ckt_result *r = ckt_run("static const int N = 3;\nfloat a[N * 2];\n#define MAX 5\nfloat b[MAX];\n");
    CHECK(r->ok);
    CHECK_INT(ckt_find(r, "a")->type->array_len, 6);
    CHECK_INT(ckt_find(r, "b")->type->array_len, 5);
    ckt_free(r);
}

static void statements(void) {
    const char *src =
        "int i; float4 v;\n"
        "float4 f()\n"
        "{\n"
        "    if (i) return v;\n"
        "    for (int k = 0; k < i; k++) v += 1;\n"
        "    while (v.x) v.x -= 1;\n"
        "    return 1;\n"
        "}\n";
    ckt_result *r = ckt_run(src);
    CHECK(r->ok);
    expect_dump(ckt_stmt(r, "f", 0)->expr, "(implicit:bool i:int)");
    hfx_stmt *loop = ckt_stmt(r, "f", 1);
    expect_dump(loop->expr, "(<:bool k:int i:int)"); /* already a bool: no cast */
    expect_dump(loop->then_stmt->expr, "(+=:float4 v:float4 (implicit:float4 1:int))");
    expect_dump(ckt_stmt(r, "f", 2)->expr, "(implicit:bool (.0:float v:float4))");
    expect_dump(ckt_stmt(r, "f", 3)->expr, "(implicit:float4 1:int)");
    /* the global written by a shader is marked */
    CHECK(ckt_find(r, "v")->assigned);
    CHECK(!ckt_find(r, "i")->assigned);
    CHECK(ckt_find(r, "v")->is_global);
    CHECK_INT(ckt_find(r, "i")->index, 0);
    CHECK_INT(ckt_find(r, "v")->index, 1);
    ckt_free(r);
}

static void entry_points_and_states(void) {
    ckt_result *r = ckt_run(
        "texture DiffuseTexture;\n"
        "sampler DiffuseSampler = sampler_state { Texture = (DiffuseTexture); AddressU = CLAMP; };\n"
        "struct O { float4 p : POSITION; };\n"
        "O vs() { O o = (O)0; return o; }\n"
        "float4 ps(uniform bool t) : COLOR { return t; }\n"
        "technique T { pass P { VertexShader = compile vs_2_0 vs(); PixelShader = compile ps_2_0 ps(1); } }\n");
    CHECK(r->ok);
    hfx_expr *ss = ckt_find(r, "DiffuseSampler")->init;
    CHECK_INT(ss->kind, EX_SAMPLER_STATE);
    expect_dump(ss->states[0].value, "DiffuseTexture:texture");
    expect_dump(ss->states[1].value, "CLAMP:void!"); /* a state constant, left for the builder */
    hfx_pass_ast *p = &ckt_find(r, "T")->technique->passes[0];
    expect_dump(p->states[1].value, "(compile ps_2_0 ps:pixelshader (implicit:bool 1:int))");
    CHECK(p->states[1].value->fn == ckt_find(r, "ps")->func);
    CHECK(p->states[0].value->fn == ckt_find(r, "vs")->func);
    char *s = ckt_dump_stmt(r, "vs", 0);
    CHECK_STR(s, "(cast:O 0:int)");
    free(s);
    ckt_free(r);
}

static void prototypes_resolve(void) {
    ckt_result *r = ckt_run("float g(float x);\nfloat f() { return g(1.0); }\nfloat g(float x) { return x * 2; }\n");
    CHECK(r->ok);
    hfx_expr *call = ckt_stmt(r, "f", 0)->expr;
    CHECK(call->fn != NULL);
    CHECK(call->fn->definition == ckt_find(r, "g")->func);
    CHECK(ckt_find(r, "g")->func->definition == ckt_find(r, "g")->func);
    ckt_free(r);
}

int main(void) {
    RUN(mul_shapes);
    RUN(operators);
    RUN(members_and_indexing);
    RUN(calls_and_overloads);
    RUN(overload_ranking);
    RUN(sampler_parameters);
    RUN(initializers);
    RUN(array_sizes);
    RUN(statements);
    RUN(entry_points_and_states);
    RUN(prototypes_resolve);
    return test_summary();
}
