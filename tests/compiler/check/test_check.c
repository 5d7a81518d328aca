/* The checker's diagnostics, one test per rule: exact fxc-style text with positions counted
 * by hand from the snippets (columns are 1-based bytes). */
#include <stdlib.h>

#include "check_util.h"
#include "test.h"

#define EXPECT_DIAGS(src, expected) do { char *t_ = ckt_diags(src); CHECK_STR(t_, expected); free(t_); } while (0)

static void undeclared_identifier(void) {
    EXPECT_DIAGS("float4 f() : COLOR { return x; }\n",
                 "t.fx(1,29): error X3004: undeclared identifier 'x'\n");
    /* a call of an unknown function is reported at its name */
    EXPECT_DIAGS("float f() {\n    return g(1);\n}\n",
                 "t.fx(2,12): error X3004: undeclared identifier 'g'\n");
    /* globals are visible only below their declaration, as in fxc */
    EXPECT_DIAGS("float f() { return later; }\nfloat later;\n",
                 "t.fx(1,20): error X3004: undeclared identifier 'later'\n");
}

static void redefinition(void) {
    EXPECT_DIAGS("float a;\nfloat4 a;\n", "t.fx(2,8): error X3003: redefinition of 'a'\n");
    EXPECT_DIAGS("float f(float x) { return x; }\nfloat f(float y) { return y; }\n",
                 "t.fx(2,7): error X3003: redefinition of 'f'\n");
    EXPECT_DIAGS("float f(float x, float x) { return x; }\n", "t.fx(1,24): error X3003: redefinition of 'x'\n");
    EXPECT_DIAGS("void f() { float a; int a; }\n", "t.fx(1,25): error X3003: redefinition of 'a'\n");
    /* shadowing in an inner scope, overloads and prototypes are fine */
    EXPECT_DIAGS("float a;\nfloat f(float x);\nfloat f(float x) { float a = x; { float a = 2; } return a; }\n"
                 "float f(float2 x) { return x.x; }\n",
                 "");
}

static void no_matching_function(void) {
    const char *src =
        "float4 Phong(float3 a, float3 b, float3 c, float4 d, float4 e) { return d * e; }\n"
        "float4 g()\n"
        "{\n"
        "    float4 color = Phong(\n"
        "    float3(1, 0, 0),\n"
        "    float3(0, 1, 0),\n"
        "    float4(1, 1, 1, 1),\n"
        "    float4(1, 1, 1, 1));\n"
        "    return color;\n"
        "}\n";
    EXPECT_DIAGS(src, "t.fx(4,20): error X3013: 'Phong': no matching 4 parameter function\n");
    /* the right count with an argument that cannot convert (float to a struct) */
    EXPECT_DIAGS("struct S { float a; };\nfloat h(S s) { return s.a; }\nfloat k() { return h(1.0); }\n",
                 "t.fx(3,20): error X3013: 'h': no matching 1 parameter function\n");
    /* intrinsics say so */
    EXPECT_DIAGS("float k(float3 v) { return dot(v); }\n",
                 "t.fx(1,28): error X3013: 'dot': no matching 1 parameter intrinsic function\n");
    EXPECT_DIAGS("sampler3D s;\nfloat4 k(float2 uv) { return tex2D(s, uv); }\n",
                 "t.fx(2,30): error X3013: 'tex2D': no matching 2 parameter intrinsic function\n");
}

static void ambiguous_call(void) {
    /* (int, float) against (float, int) for f(1, 1): each wins one argument */
    EXPECT_DIAGS("float f(float a, int b) { return a; }\nfloat f(int a, float b) { return b; }\n"
                 "float g() { return f(1, 1); }\n",
                 "t.fx(3,20): error X3067: 'f': ambiguous function call\n");
}

static void truncation_warnings(void) {
    /* assignment, initializer, return and binary operator: each at the start of the truncated
     * expression; an argument: at the call, naming the function (fxc's wording) */
    const char *src =
        "float4 w;\n"
        "float h(float2 a) { return a.x; }\n"
        "float3 f()\n"
        "{\n"
        "    float3 v = w;\n"
        "    v = w * 2;\n"
        "    float r = h(w);\n"
        "    float3 d = v - w;\n"
        "    return w;\n"
        "}\n";
    EXPECT_DIAGS(src,
                 "t.fx(5,16): warning X3206: implicit truncation of vector type\n"
                 "t.fx(6,9): warning X3206: implicit truncation of vector type\n"
                 "t.fx(7,15): warning X3206: 'h': implicit truncation of vector type\n"
                 "t.fx(8,16): warning X3206: implicit truncation of vector type\n"
                 "t.fx(9,12): warning X3206: implicit truncation of vector type\n");
    /* explicit casts and swizzles do not warn; matrices truncate too */
    EXPECT_DIAGS("float4x4 m;\nfloat4 w;\nfloat3 f() { float3x3 n = (float3x3)m; float3 v = (float3)w; return w.xyz; }\n", "");
    EXPECT_DIAGS("float4x4 m;\nfloat3x3 f() { return m; }\n",
                 "t.fx(2,23): warning X3206: implicit truncation of vector type\n");
    /* intrinsic arguments too; mul clamps its inner dimension silently */
    EXPECT_DIAGS("sampler s;\nfloat4 f(float3 a, float4 b) { return dot(a, b) + tex2D(s, a) + mul(a, (float4x4)0); }\n",
                 "t.fx(2,39): warning X3206: 'dot': implicit truncation of vector type\n"
                 "t.fx(2,51): warning X3206: 'tex2D': implicit truncation of vector type\n");
}

static void signed_unsigned(void) {
    /* a literal adapts; an int variable against a uint one warns */
    EXPECT_DIAGS("uint u; int i;\nbool f() { return u < 3 && i + u > 1; }\n",
                 "t.fx(2,28): warning X3203: signed/unsigned mismatch, unsigned assumed\n");
}

static void cannot_convert(void) {
    EXPECT_DIAGS("float3 v;\nfloat4 f() { return v; }\n",
                 "t.fx(2,21): error X3017: cannot implicitly convert from 'float3' to 'float4'\n");
    EXPECT_DIAGS("float4x4 m;\nfloat4 f() { return m; }\n",
                 "t.fx(2,21): error X3017: cannot implicitly convert from 'float4x4' to 'float4'\n");
    EXPECT_DIAGS("float3 v;\nfloat4 f() { return (float4)v; }\n",
                 "t.fx(2,21): error X3017: cannot convert from 'float3' to 'float4'\n");
    /* float3 times float4x4 componentwise does not combine */
    EXPECT_DIAGS("float3 v;\nfloat4x4 m;\nfloat3 f() { return v * m; }\n", "t.fx(3,21): error X3020: type mismatch\n");
}

static void swizzle_errors(void) {
    EXPECT_DIAGS("float4 v;\nfloat f() { return v.xyzq.x; }\n", "t.fx(2,20): error X3018: invalid subscript 'xyzq'\n");
    EXPECT_DIAGS("float4 v;\nfloat2 f() { return v.xg; }\n", "t.fx(2,21): error X3018: invalid subscript 'xg'\n");
    EXPECT_DIAGS("float4 v;\nfloat4 f() { return v.xyzwx; }\n", "t.fx(2,21): error X3018: invalid subscript 'xyzwx'\n");
    EXPECT_DIAGS("float2 v;\nfloat f() { return v.z; }\n", "t.fx(2,20): error X3018: invalid subscript 'z'\n");
    EXPECT_DIAGS("float4x4 m;\nfloat2 f() { return m._m00_11; }\n",
                 "t.fx(2,21): error X3018: invalid subscript '_m00_11'\n");
    EXPECT_DIAGS("float3x3 m;\nfloat f() { return m._m33; }\n", "t.fx(2,20): error X3018: invalid subscript '_m33'\n");
    /* legal ones */
    EXPECT_DIAGS("float s;\nfloat4 v;\nfloat4x4 m;\n"
                 "float4 f() { float3 a = s.xxx; float b = s.x; float2 c = m._m00_m11 + m._11_22; return v.bgra + v.xxyy; }\n",
                 "");
}

static void lvalue_errors(void) {
    EXPECT_DIAGS("static const float c = 1;\nvoid f() { c = 2; }\n",
                 "t.fx(2,12): error X3025: l-value specifies const object\n");
    EXPECT_DIAGS("float4 v;\nvoid f() { v.xx = float2(1, 2); }\n",
                 "t.fx(2,12): error X3025: l-value specifies const object\n");
    EXPECT_DIAGS("float a;\nvoid f() { (a + 1) = 2; }\n", "t.fx(2,13): error X3025: l-value specifies const object\n");
    EXPECT_DIAGS("void f() { 5++; }\n", "t.fx(1,12): error X3025: l-value specifies const object\n");
    EXPECT_DIAGS("float4 v;\nvoid f() { float s, c; sincos(v.x, s, 1.0); }\n",
                 "t.fx(2,39): error X3025: l-value specifies const object\n");
    /* writable: locals, swizzles without repeats, fields, elements, uniforms (a private copy) */
    EXPECT_DIAGS("struct S { float4 p; };\nfloat4 u;\nfloat arr[2];\n"
                 "void f(S s, out float4 o) { s.p.xz = 1; arr[1] += 2; u *= 2; o = u; o.w++; }\n", "");
}

static void condition_errors(void) {
    EXPECT_DIAGS("float4 v;\nfloat f() { if (v) return 1; return 0; }\n",
                 "t.fx(2,17): error X3019: if statement conditional expressions must evaluate to a scalar\n");
}

static void return_errors(void) {
    EXPECT_DIAGS("float f(float x) { if (x > 0) return 1; }\n",
                 "t.fx(1,7): error X3507: 'f': Not all control paths return a value\n");
    EXPECT_DIAGS("void f() { return 1; }\n", "t.fx(1,12): error X3079: 'f': void functions cannot return a value\n");
    EXPECT_DIAGS("float f() { return; }\n", "t.fx(1,13): error X3080: 'f': function must return a value\n");
    EXPECT_DIAGS("float f(float x) { if (x > 0) return 1; else return 2; }\n", "");
    EXPECT_DIAGS("float f(int i) { switch (i) { case 0: return 1; default: return 2; } }\n", "");
    EXPECT_DIAGS("float f(int i) { switch (i) { case 0: break; default: return 2; } }\n",
                 "t.fx(1,7): error X3507: 'f': Not all control paths return a value\n");
    EXPECT_DIAGS("float4 f(float4 c) : COLOR { if (c.a > 0) return c; else discard; }\n", "");
}

static void constructor_errors(void) {
    EXPECT_DIAGS("float4 f() { return float4(1, 2); }\n",
                 "t.fx(1,21): error X3014: incorrect number of arguments to numeric-type constructor\n");
    EXPECT_DIAGS("float3 v;\nfloat4 f() { return float4(v, 1, 2); }\n",
                 "t.fx(2,21): error X3014: incorrect number of arguments to numeric-type constructor\n");
}

static void cascades_are_suppressed(void) {
    /* one unknown name, one error: nothing about the operator, the call or the assignment */
    EXPECT_DIAGS("float3 f() { float3 v = normalize(nothing * 2) + 1; return v; }\n",
                 "t.fx(1,35): error X3004: undeclared identifier 'nothing'\n");
    /* every independent error is reported */
    EXPECT_DIAGS("float f() { float a = b; float c = d; return a + c; }\n",
                 "t.fx(1,23): error X3004: undeclared identifier 'b'\n"
                 "t.fx(1,36): error X3004: undeclared identifier 'd'\n");
}

static void indexing_errors(void) {
    EXPECT_DIAGS("float a[3];\nfloat f() { return a[3]; }\n", "t.fx(2,22): error X3504: array index out of bounds\n");
    EXPECT_DIAGS("float a;\nfloat f() { return a[0]; }\n",
                 "t.fx(2,20): error X3121: array, matrix, vector, or indexable object type expected in index expression\n");
    EXPECT_DIAGS("int n;\nfloat f() { float a[n]; return a[0]; }\n",
                 "t.fx(2,21): error X3058: array dimensions must be literal scalar expressions\n");
    /* a constructor as a target needs an l-value for every argument */
    EXPECT_DIAGS("float f() { float3 t; float4(1, t) = 2; return t.x; }\n", "t.fx(1,30): error X3025: l-value specifies const object\n");
    /* a name nothing declares is that, as fxc says it (real effects: a size macro left undefined) */
    EXPECT_DIAGS("float f() { float a[N + 1]; return a[0]; }\n", "t.fx(1,21): error X3004: undeclared identifier 'N'\n");
}

static void entry_points(void) {
    const char *head = "float4 ps(float2 uv : TEXCOORD0, uniform bool tex, uniform float k) : COLOR { return tex ? k : 0; }\n";
    char src[1024];
    snprintf(src, sizeof src, "%stechnique T { pass P { PixelShader = compile ps_2_0 ps(true, 2); } }\n", head);
    EXPECT_DIAGS(src, "");
    snprintf(src, sizeof src, "%stechnique T { pass P { PixelShader = compile ps_2_0 ps(true); } }\n", head);
    EXPECT_DIAGS(src, "t.fx(2,53): error X3013: 'ps': no matching 1 parameter function\n");
    EXPECT_DIAGS("technique T { pass P { VertexShader = compile vs_2_0 nothere(); } }\n",
                 "t.fx(1,54): error X3004: undeclared identifier 'nothere'\n");
    /* an argument of a compile is an expression: unknown names are errors there */
    snprintf(src, sizeof src, "%stechnique T { pass P { PixelShader = compile ps_2_0 ps(true, what); } }\n", head);
    EXPECT_DIAGS(src, "t.fx(2,62): error X3004: undeclared identifier 'what'\n");
}

static void state_values(void) {
    /* state names and values stay for the builder; <name> must exist */
    EXPECT_DIAGS("texture t;\nsampler s = sampler_state { Texture = <t>; AddressU = CLAMP; MinFilter = LINEAR; };\n"
                 "technique T { pass P { CullMode = None; ZEnable = true; SrcBlend = SrcAlpha; ColorWriteEnable = Red | Green; } }\n",
                 "");
    EXPECT_DIAGS("sampler s = sampler_state { Texture = <missing>; };\n",
                 "t.fx(1,40): error X3004: undeclared identifier 'missing'\n");
}

static void technique10_passes(void) {
    /* SM4 pass syntax is accepted (the builder decides what to do with it) */
    EXPECT_DIAGS("float4 VS(float4 p : POSITION, uniform float k) : POSITION { return p * k; }\n"
                 "float4 PS() : COLOR { return 1; }\n"
                 "technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS(2))); SetGeometryShader(NULL);\n"
                 "    SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                 "");
    EXPECT_DIAGS("technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, Missing())); } }\n",
                 "t.fx(1,64): error X3004: undeclared identifier 'Missing'\n");
}

static void initializer_errors(void) {
    EXPECT_DIAGS("float4 v = {1, 2, 3};\n", "t.fx(1,12): error X3017: 'v': cannot implicitly convert from 'float3' to 'float4'\n");
    EXPECT_DIAGS("float4 v = {1, 2, 3, 4};\nfloat2x2 m = {v};\nfloat a[] = {1, 2, 3};\nfloat ks = {0.05F};\n", "");
}

static void recursion(void) {
    EXPECT_DIAGS("float f(float x) { return f(x - 1); }\n",
                 "t.fx(1,27): error X3500: 'f': recursive function calls are not allowed\n");
    /* through a prototype: g calls h calls g; reported once, at the call that closes the cycle */
    EXPECT_DIAGS("float h(float x);\nfloat g(float x) { return h(x); }\nfloat h(float x) { return g(x); }\n",
                 "t.fx(3,27): error X3500: 'g': recursive function calls are not allowed\n");
    /* declared, never defined */
    EXPECT_DIAGS("float h(float x);\nfloat g(float x) { return h(x) + h(2 * x); }\n"
                 "float4 ps() : COLOR { return g(1); }\nfloat4 vs() : POSITION;\n"
                 "technique T { pass P { VertexShader = compile vs_2_0 vs(); PixelShader = compile ps_2_0 ps(); } }\n",
                 "t.fx(2,27): error X3501: 'h': function is declared but not defined\n"
                 "t.fx(5,54): error X3501: 'vs': entrypoint not found\n");
    /* a diamond is no cycle */
    EXPECT_DIAGS("float a(float x) { return x; }\nfloat b(float x) { return a(x); }\nfloat c(float x) { return a(x) + b(x); }\n", "");
}

static void unsupported(void) {
    EXPECT_DIAGS("PixelShader p = asm { ps_2_0 mov oC0, c0 };\n",
                 "t.fx(1,17): error X3094: asm shaders are not supported\n");
    EXPECT_DIAGS("texture2D t;\nfloat4 f(float2 uv) { return t.Sample(uv); }\n",
                 "t.fx(2,30): error X3094: 'Sample': object methods are not supported in fx_2_0 effects\n");
}

static void loop_scoping(void) {
    /* fxc keeps a for-init variable after its loop; a second loop with the same name warns */
    EXPECT_DIAGS("float f()\n{\n    float s = 0;\n    for (int i = 0; i < 3; i++) s += i;\n"
                 "    for (int i = 0; i < 2; i++) s += i;\n    return s + i;\n}\n",
                 "t.fx(5,14): warning X3078: loop control variable conflicts with a previous declaration in the "
                 "outer scope; most recent declaration will be used\n");
    ckt_result *r = ckt_run("float f() { for (int i = 0; i < 2; i++) {} for (int i = 0; i < 3; i++) {} return i; }\n");
    hfx_stmt *second = ckt_stmt(r, "f", 1), *ret = ckt_stmt(r, "f", 2);
    CHECK(r->ok);
    CHECK(ret->expr->args[0]->sym == second->init->decls[0]); /* the most recent i, converted to float */
    ckt_free(r);
}

int main(void) {
    RUN(loop_scoping);
    RUN(recursion);
    RUN(unsupported);
    RUN(undeclared_identifier);
    RUN(redefinition);
    RUN(no_matching_function);
    RUN(ambiguous_call);
    RUN(truncation_warnings);
    RUN(signed_unsigned);
    RUN(cannot_convert);
    RUN(swizzle_errors);
    RUN(lvalue_errors);
    RUN(condition_errors);
    RUN(return_errors);
    RUN(constructor_errors);
    RUN(cascades_are_suppressed);
    RUN(indexing_errors);
    RUN(entry_points);
    RUN(state_values);
    RUN(technique10_passes);
    RUN(initializer_errors);
    return test_summary();
}
