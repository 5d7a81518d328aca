/* The parser on declarations: storage classes, semantics, registers, annotations,
 * initializers, arrays, every type spelling, typedef, struct, objects, functions. Expected
 * dumps are written by hand from the sources (see ast.c for the dump's form). */
#include <stdio.h>

#include "parse_util.h"
#include "test.h"

/* Parses src, expects no diagnostic and the given dump. */
static void expect_dump(const char *src, const char *want) {
    tp_result *r = tp_parse(src);
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, want);
    tp_free(r);
}

static void storage_classes_and_modifiers(void) {
    expect_dump("static const float a = 1;\n"
                "row_major float4x4 m : WORLD;\n"
                "shared uniform float3 v;\n"
                "extern volatile float e;\n"
                "column_major float3x4 cm;\n"
                "inline float f() { return 0; }\n",
                "var static const float a = 1\n"
                "var row_major float4x4 m : WORLD\n"
                "var uniform shared float3 v\n"
                "var extern volatile float e\n"
                "var column_major float3x4 cm\n"
                "function inline float f\n"
                "  block\n"
                "    return 0\n");
}

static void semantics_and_registers(void) {
    tp_result *r = tp_parse("sampler s : register(s0);\n"
                            "float4 c : register(c12);\n"
                            "float4 k : register(vs, c3);\n"
                            "float4 x : COLOR : register(c1);\n"
                            "float3 e : register(vs, c13) : register(ps, c14);\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "var sampler s : register(s0)\n"
                       "var float4 c : register(c12)\n"
                       "var float4 k : register(vs,c3)\n" /* the profile kept: lower/registers.c checks it */
                       "var float4 x : COLOR : register(c1)\n"
                       "var float3 e : register(vs,c13) : register(ps,c14)\n"); /* both kept (FNA's stock effects) */
    /* each shader takes its own profile's reservation, else the unqualified one */
    char buf[16];
    hfx_decl *e = tp_find(r, "e"), *k = tp_find(r, "k"), *c = tp_find(r, "c");
    CHECK(e && k && c);
    if (e && k && c) {
        CHECK_STR(hfx_register_for(e->reg, "vs_2_0", buf, sizeof buf), "c13");
        CHECK_STR(hfx_register_for(e->reg, "ps_3_0", buf, sizeof buf), "c14");
        CHECK(hfx_register_for(k->reg, "ps_2_0", buf, sizeof buf) == NULL);
        CHECK_STR(hfx_register_for(k->reg, "vs_3_0", buf, sizeof buf), "c3");
        CHECK_STR(hfx_register_for(c->reg, "ps_2_0", buf, sizeof buf), "c12");
        CHECK(hfx_register_for(c->reg, "ps_2_0", buf, 3) == NULL); /* "c12" does not fit in 3 bytes */
    }
    hfx_decl *x = tp_find(r, "x");
    CHECK(x && x->semantic && x->reg);
    if (x) {
        CHECK_STR(x->semantic, "COLOR");
        CHECK_STR(x->reg, "c1");
        CHECK_INT(x->loc.line, 4);
        CHECK_INT(x->loc.col, 8);
    }
    tp_free(r);
}

static void annotations(void) {
    tp_result *r = tp_parse("float f < string UIName = \"a\" \"b\"; float UIMin = 0; float3 v = {1,2,3};\n"
                            "          int i = -1; string Esc = \"q\\\"\\n\"; > = 0.5;\n"
                            "texture t < string ResourceName = \"x.dds\"; >;\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "var float f = 0.5\n"
                       "  annotation string UIName = \"ab\"\n"
                       "  annotation float UIMin = 0\n"
                       "  annotation float3 v = {1, 2, 3}\n"
                       "  annotation int i = (-1)\n"
                       "  annotation string Esc = \"q\\\"\\n\"\n"
                       "var texture t\n"
                       "  annotation string ResourceName = \"x.dds\"\n");
    hfx_decl *f = tp_find(r, "f");
    CHECK(f && f->annotation_count == 5);
    if (f && f->annotation_count == 5) {
        CHECK_STR(f->annotations[0].value->sval, "ab");
        CHECK_STR(f->annotations[4].value->sval, "q\"\n");
        CHECK_INT(f->annotations[2].type->kind, TY_VECTOR);
        CHECK_INT(f->annotations[1].loc.line, 1);
        CHECK_INT(f->annotations[1].loc.col, 42); /* UIMin */
    }
    tp_free(r);
}

static void initializers(void) {
    tp_result *r = tp_parse("float2x2 m = {{1,2},{3,4},};\n"
                            "float ks = {0.05F};\n"
                            "float4 c = float4(1, 2.5, 3e1, 4.0h);\n"
                            "float u[] = {1, 2, 3,};\n"
                            "int h = 0x1F + 017 + 5u;\n"
                            "float e = { };\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "var float2x2 m = {{1, 2}, {3, 4}}\n"
                       "var float ks = {0.05}\n"
                       "var float4 c = float4(1, 2.5, 30.0, 4.0)\n"
                       "var float[] u = {1, 2, 3}\n"
                       "var int h = ((31 + 15) + 5)\n"
                       "var float e = {}\n");
    hfx_decl *u = tp_find(r, "u");
    CHECK(u && u->type->kind == TY_ARRAY && u->type->array_len == 0 && !u->type->array_len_expr);
    hfx_decl *ks = tp_find(r, "ks");
    CHECK(ks && ks->init->kind == EX_INIT_LIST && ks->init->arg_count == 1);
    if (ks && ks->init->arg_count == 1) CHECK_NEAR(ks->init->args[0]->fval, 0.05, 1e-12);
    tp_free(r);
}

static void arrays(void) {
    tp_result *r = tp_parse("#define N 4\n"
                            "float a[N * 2 + 1];\n"
                            "float b[2][3];\n"
                            "static const int K = 3;\n"
                            "float c[K];\n"
                            "float3 L[(1 << 3) - 1], single;\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "var float[9] a\n"
                       "var float[2][3] b\n"
                       "var static const int K = 3\n"
                       "var float[K] c\n"
                       "var float3[7] L\n"
                       "var float3 single\n");
    hfx_decl *b = tp_find(r, "b");
    CHECK(b && b->type->kind == TY_ARRAY && b->type->array_len == 2);
    CHECK(b && b->type->elem->kind == TY_ARRAY && b->type->elem->array_len == 3);
    CHECK(b && b->type->elem->elem->kind == TY_SCALAR);
    hfx_decl *c = tp_find(r, "c");
    CHECK(c && c->type->array_len == 0 && c->type->array_len_expr && c->type->array_len_expr->kind == EX_IDENT);
    tp_free(r);

    r = tp_parse("float z[0];\nfloat y[-2];\n");
    CHECK_STR(r->errors, "t.fx(1,9): error X3059: array dimension must be between 1 and 65536\n"
                         "t.fx(2,9): error X3059: array dimension must be between 1 and 65536\n");
    tp_free(r);
}

static void type_spellings(void) {
    tp_result *r = tp_parse("bool b; int i; uint u; half h; float f; double d; min16float m; dword w;\n"
                            "float1x3 a; vector<float,3> v3; matrix<half,2,3> m23; vector v; matrix m44;\n"
                            "half2 h2; uint3 u3; int2x2 i22; bool4 b4; double1 d1;\n"
                            "string s; void fn() {}\n");
    CHECK_STR(r->errors, "");
    struct { const char *name; hfx_type_kind kind; hfx_base base; int rows, cols; } want[] = {
        {"b", TY_SCALAR, B_BOOL, 1, 1},   {"i", TY_SCALAR, B_INT, 1, 1},    {"u", TY_SCALAR, B_UINT, 1, 1},
        {"h", TY_SCALAR, B_HALF, 1, 1},   {"f", TY_SCALAR, B_FLOAT, 1, 1},  {"d", TY_SCALAR, B_DOUBLE, 1, 1},
        {"m", TY_SCALAR, B_MIN16FLOAT, 1, 1}, {"w", TY_SCALAR, B_UINT, 1, 1},
        {"a", TY_MATRIX, B_FLOAT, 1, 3},  {"v3", TY_VECTOR, B_FLOAT, 1, 3}, {"m23", TY_MATRIX, B_HALF, 2, 3},
        {"v", TY_VECTOR, B_FLOAT, 1, 4},  {"m44", TY_MATRIX, B_FLOAT, 4, 4}, {"h2", TY_VECTOR, B_HALF, 1, 2},
        {"u3", TY_VECTOR, B_UINT, 1, 3},  {"i22", TY_MATRIX, B_INT, 2, 2},  {"b4", TY_VECTOR, B_BOOL, 1, 4},
        {"d1", TY_VECTOR, B_DOUBLE, 1, 1},
    };
    for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
        hfx_decl *d = tp_find(r, want[i].name);
        CHECK(d != NULL);
        if (!d) continue;
        if (d->type->kind != want[i].kind || d->type->base != want[i].base || d->type->rows != want[i].rows ||
            d->type->cols != want[i].cols)
            fprintf(stderr, "type of %s is wrong\n", want[i].name);
        CHECK_INT(d->type->kind, want[i].kind);
        CHECK_INT(d->type->base, want[i].base);
        CHECK_INT(d->type->rows, want[i].rows);
        CHECK_INT(d->type->cols, want[i].cols);
    }
    hfx_decl *s = tp_find(r, "s");
    CHECK(s && s->type->kind == TY_STRING);
    hfx_decl *fn = tp_find(r, "fn");
    CHECK(fn && fn->kind == DECL_FUNC && fn->func->ret->kind == TY_VOID);
    tp_free(r);
}

static void typedefs(void) {
    tp_result *r = tp_parse("typedef float4 color;\n"
                            "color c;\n"
                            "typedef struct { float a; } S;\n"
                            "S s;\n"
                            "typedef float3 arr3[2], vec3;\n"
                            "arr3 q; vec3 p;\n"
                            "float f(color x) { typedef int I; I k = (I)x.r; return k; }\n"
                            "int I;\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "typedef float4 color\n"
                       "var float4 c\n"
                       "struct <anonymous>\n"
                       "  field float a\n"
                       "typedef struct S\n"
                       "var struct s\n"
                       "typedef float3[2] arr3\n"
                       "typedef float3 vec3\n"
                       "var float3[2] q\n"
                       "var float3 p\n"
                       "function float f\n"
                       "  param float4 x\n"
                       "  block\n"
                       "    typedef int I\n"
                       "    var int k = (int)x.r\n"
                       "    return k\n"
                       "var int I\n");
    hfx_decl *s = tp_find(r, "s");
    hfx_decl *st = r->ast->decls[2];
    CHECK(s && s->type->kind == TY_STRUCT && st->kind == DECL_STRUCT && s->type->st == st->type->st);
    tp_free(r);
}

static void typedef_of_generic_types(void) {
    expect_dump("typedef vector<float, 3> v3;\n"
                "typedef matrix<half, 2, 2> m2, m2b[2];\n"
                "typedef const float CF;\n"
                "v3 a; m2 b; m2b c; CF d = 1;\n"
                "typedef row_major float4x4 RM;\n"
                "RM e; static RM f; matrix g; float h = (CF)d;\n",
                "typedef float3 v3\n"
                "typedef half2x2 m2\n"
                "typedef half2x2[2] m2b\n"
                "typedef const float CF\n"
                "var float3 a\n"
                "var half2x2 b\n"
                "var half2x2[2] c\n"
                "var const float d = 1\n"
                "typedef row_major float4x4 RM\n"
                "var row_major float4x4 e\n"
                "var static row_major float4x4 f\n"
                "var float4x4 g\n"
                "var float h = (float)d\n");
}

/* The preprocessor hands `#pragma pack_matrix` over as `__hfx_pack_matrix ( x )` (token.h);
 * it becomes the majorness of later matrix declarations that name none. */
static void pragma_pack_matrix(void) {
    expect_dump("float4x4 a;\n"
                "#pragma pack_matrix(row_major)\n"
                "float4x4 b; float4 v; column_major float3x3 c;\n"
                "struct S { float2x2 m; };\n"
                "void f(float4x4 p) { float4x4 l = p; }\n"
                "#pragma pack_matrix(column_major)\n"
                "float4x4 d[2];\n",
                "var float4x4 a\n"
                "var row_major float4x4 b\n"
                "var float4 v\n"
                "var column_major float3x3 c\n"
                "struct S\n"
                "  field row_major float2x2 m\n"
                "function void f\n"
                "  param row_major float4x4 p\n"
                "  block\n"
                "    var row_major float4x4 l = p\n"
                "var column_major float4x4[2] d\n");
}

static void structs(void) {
    tp_result *r = tp_parse("struct V {\n"
                            "  linear float4 p : POSITION;\n"
                            "  centroid float2 uv : TEXCOORD0;\n"
                            "  nointerpolation float f : TEXCOORD1;\n"
                            "  noperspective float3 n; sample float s; float2 arr[2];\n"
                            "};\n"
                            "struct S2 { float a; } inst, more[2];\n"
                            "float linear = 1; float sample = linear;\n"
                            "struct V v2;\n"
                            "struct Fwd;\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "struct V\n"
                       "  field linear float4 p : POSITION\n"
                       "  field centroid float2 uv : TEXCOORD0\n"
                       "  field nointerpolation float f : TEXCOORD1\n"
                       "  field noperspective float3 n\n"
                       "  field sample float s\n"
                       "  field float2[2] arr\n"
                       "struct S2\n"
                       "  field float a\n"
                       "var S2 inst\n"
                       "var S2[2] more\n"
                       "var float linear = 1\n"
                       "var float sample = linear\n"
                       "var V v2\n");
    hfx_decl *v = tp_find(r, "V");
    CHECK(v && v->kind == DECL_STRUCT && v->loc.line == 1 && v->loc.col == 8);
    if (v && v->kind == DECL_STRUCT) {
        CHECK_INT(v->type->st->field_count, 6);
        CHECK_INT(v->type->st->fields[0].mods, MOD_LINEAR);
        CHECK_INT(v->type->st->fields[0].loc.line, 2);
        CHECK_INT(v->type->st->fields[0].loc.col, 17);
    }
    hfx_decl *v2 = tp_find(r, "v2");
    CHECK(v && v2 && v2->type->st == v->type->st);
    tp_free(r);
}

/* Struct names are scoped by braces; `struct G x;` inside a function uses the global G. */
static void struct_scopes(void) {
    tp_result *r = tp_parse("struct G { float g; };\n"
                            "void f() { struct G a; struct L { int x; }; L b; G c; }\n"
                            "L d;\n");
    CHECK_STR(r->errors, "t.fx(3,1): error X3000: unrecognized identifier 'L'\n");
    hfx_decl *g = tp_find(r, "G"), *f = tp_find(r, "f");
    CHECK(g && f && f->func->body && f->func->body->body_count == 4);
    if (g && f && f->func->body && f->func->body->body_count == 4) {
        hfx_stmt **body = f->func->body->body;
        CHECK(body[0]->decls[0]->type->st == g->type->st);          /* struct G a */
        CHECK_INT(body[1]->decls[0]->kind, DECL_STRUCT);            /* struct L {...}; */
        CHECK(body[2]->decls[0]->type->st == body[1]->decls[0]->type->st);
        CHECK(body[3]->decls[0]->type->st == g->type->st);
    }
    tp_free(r);
}

static void objects(void) {
    tp_result *r = tp_parse("texture t0; texture2D t2; Texture2D T2; TEXTURECUBE tc; texture3D t3; texture1D t1;\n"
                            "sampler1D s1; sampler3D s3; samplerCUBE sc; SamplerState ss;\n"
                            "sampler2D s2 { Texture = <t2>; AddressU = Wrap; };\n"
                            "string name = \"x\";\n"
                            "VertexShader vs = compile vs_2_0 f();\n"
                            "PixelShader PSArray[2] = { compile ps_2_0 A(), compile ps_2_0 B(1) };\n"
                            "pixelshader nul = NULL;\n");
    CHECK_STR(r->errors, "");
    struct { const char *name; hfx_type_kind kind; hfx_dim dim; } want[] = {
        {"t0", TY_TEXTURE, DIM_GENERIC}, {"t2", TY_TEXTURE, DIM_2D}, {"T2", TY_TEXTURE, DIM_2D},
        {"tc", TY_TEXTURE, DIM_CUBE},    {"t3", TY_TEXTURE, DIM_3D}, {"t1", TY_TEXTURE, DIM_1D},
        {"s1", TY_SAMPLER, DIM_1D},      {"s3", TY_SAMPLER, DIM_3D}, {"sc", TY_SAMPLER, DIM_CUBE},
        {"ss", TY_SAMPLER, DIM_GENERIC}, {"s2", TY_SAMPLER, DIM_2D}, {"vs", TY_VERTEXSHADER, DIM_GENERIC},
        {"nul", TY_PIXELSHADER, DIM_GENERIC},
    };
    for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
        hfx_decl *d = tp_find(r, want[i].name);
        CHECK(d && d->type->kind == want[i].kind && d->type->dim == want[i].dim);
        if (!d || d->type->kind != want[i].kind || d->type->dim != want[i].dim)
            fprintf(stderr, "wrong type for %s\n", want[i].name);
    }
    CHECK_CONTAINS(r->dump, "var sampler2D s2 = sampler_state { Texture = <t2>; AddressU = Wrap; }\n"
                            "var string name = \"x\"\n"
                            "var vertexshader vs = compile vs_2_0 f()\n"
                            "var pixelshader[2] PSArray = {compile ps_2_0 A(), compile ps_2_0 B(1)}\n"
                            "var pixelshader nul = NULL\n");
    hfx_decl *ps = tp_find(r, "PSArray");
    CHECK(ps && ps->type->kind == TY_ARRAY && ps->type->array_len == 2 && ps->type->elem->kind == TY_PIXELSHADER);
    tp_free(r);
    /* SM4 spellings of textures with an element type */
    r = tp_parse("Texture2D<float4> tt; TextureCube<float4> tcu;\nfloat<int> bad;\n");
    CHECK_STR(r->errors, "t.fx(2,6): error X3000: syntax error: unexpected token '<'\n");
    hfx_decl *tt = tp_find(r, "tt"), *tcu = tp_find(r, "tcu");
    CHECK(tt && tt->type->kind == TY_TEXTURE && tt->type->dim == DIM_2D);
    CHECK(tcu && tcu->type->kind == TY_TEXTURE && tcu->type->dim == DIM_CUBE);
    tp_free(r);
}

static void functions(void) {
    tp_result *r = tp_parse("float4 f(in float3 a : POSITION, out float2 b : TEXCOORD0, inout float c,\n"
                            "         uniform bool d, float e = 2.0) : COLOR0;\n"
                            "float4 f(in float3 a : POSITION, out float2 b : TEXCOORD0, inout float c,\n"
                            "         uniform bool d, float e) : COLOR0 { b = 0; return a.xyzz; }\n"
                            "int g(int x) { return x; }\n"
                            "float g(float x) { return x; }\n"
                            "[maxvertexcount(3)] void h(void) { }\n"
                            "float proto(float, int);\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "function float4 f : COLOR0 (prototype)\n"
                       "  param in float3 a : POSITION\n"
                       "  param out float2 b : TEXCOORD0\n"
                       "  param in out float c\n"
                       "  param uniform bool d\n"
                       "  param float e = 2.0\n"
                       "function float4 f : COLOR0\n"
                       "  param in float3 a : POSITION\n"
                       "  param out float2 b : TEXCOORD0\n"
                       "  param in out float c\n"
                       "  param uniform bool d\n"
                       "  param float e\n"
                       "  block\n"
                       "    expr (b = 0)\n"
                       "    return a.xyzz\n"
                       "function int g\n"
                       "  param int x\n"
                       "  block\n"
                       "    return x\n"
                       "function float g\n"
                       "  param float x\n"
                       "  block\n"
                       "    return x\n"
                       "function [maxvertexcount(3)] void h\n"
                       "  block\n"
                       "function float proto (prototype)\n"
                       "  param float <unnamed>\n"
                       "  param int <unnamed>\n");
    hfx_decl *f = tp_find_nth(r, "f", 1);
    CHECK(f && f->func->param_count == 5 && f->func->params[4]->index == 4);
    CHECK(f && f->func->params[2]->mods == (MOD_IN | MOD_OUT));
    CHECK(f && f->loc.line == 3 && f->loc.col == 8);
    hfx_decl *h = tp_find(r, "h");
    CHECK(h && h->func->param_count == 0 && h->func->attr_count == 1);
    tp_free(r);
}

int main(void) {
    RUN(storage_classes_and_modifiers);
    RUN(semantics_and_registers);
    RUN(annotations);
    RUN(initializers);
    RUN(arrays);
    RUN(type_spellings);
    RUN(typedefs);
    RUN(typedef_of_generic_types);
    RUN(pragma_pack_matrix);
    RUN(structs);
    RUN(struct_scopes);
    RUN(objects);
    RUN(functions);
    return test_summary();
}
