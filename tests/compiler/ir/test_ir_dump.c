/* test_ir_dump.c: golden IR dumps of small entry points after lowering: specialisation,
 * folding, dead-code removal and copy-on-write of globals, checked line by line. */
#include <stdlib.h>
#include <string.h>

#include "parse/ast.h"
#include "check/check.h"
#include "ir/ir.h"
#include "test.h"
#include "pp/token.h"

typedef struct fixture {
    hfx_arena arena;
    hfx_diags diags;
    hfx_types *types;
    hfx_ast *ast;
} fixture;

static int parse(fixture *fx, const char *src) {
    hfx_arena_init(&fx->arena);
    hfx_diags_init(&fx->diags, &fx->arena, 0);
    fx->types = hfx_types_new(&fx->arena);
    hfx_pp_options pp;
    memset(&pp, 0, sizeof pp);
    hfx_token *toks = hfx_preprocess(&fx->arena, &fx->diags, "t.fx", src, (uint32_t)strlen(src), &pp);
    fx->ast = hfx_parse(&fx->arena, &fx->diags, fx->types, toks);
    return fx->diags.errors == 0 && hfx_check(&fx->arena, &fx->diags, fx->types, fx->ast);
}

/* The lowered IR of `compile <profile> entry(args)`; args are boolean literals. */
static char *lowered(const char *src, const char *entry, int nargs, const bool *args, int pixel) {
    fixture f;
    char *out = NULL;
    if (parse(&f, src)) {
        hfx_expr *compile = HFX_NEW(&f.arena, hfx_expr);
        compile->kind = EX_COMPILE;
        compile->name = entry;
        compile->profile = pixel ? "ps_3_0" : "vs_3_0";
        compile->intrinsic = -1;
        compile->arg_count = (uint32_t)nargs;
        compile->args = HFX_NEW_ARRAY(&f.arena, hfx_expr *, nargs + 1);
        for (int i = 0; i < nargs; i++) {
            hfx_expr *b = HFX_NEW(&f.arena, hfx_expr);
            b->kind = EX_BOOL;
            b->ival = args[i];
            b->type = hfx_type_scalar(f.types, B_BOOL);
            b->intrinsic = -1;
            compile->args[i] = b;
        }
        ir_ctx c = { &f.arena, &f.diags, f.types, f.ast, NULL };
        ir_shader *sh = hfx_ir_build(&c, compile, pixel ? IR_PIXEL : IR_VERTEX);
        if (sh && hfx_ir_lower(&c, sh, 0) == 0) out = hfx_ir_dump_shader(sh);
    }
    if (!out) {
        char *d = hfx_diags_format(&f.diags, 0);
        fprintf(stderr, "%s", d);
        free(d);
    }
    hfx_arena_free(&f.arena);
    return out;
}

static void specialised_branch_folds_away(void) {
    const char *src =
        "float4 tint;\n"
        "sampler s;\n"
        "float4 ps(float2 uv : TEXCOORD0, uniform bool textured) : COLOR\n"
        "{\n"
        "    float4 c = tint * (2 + 3);\n"
        "    if (textured) c *= tex2D(s, uv);\n"
        "    else c.a = 1;\n"
        "    return c;\n"
        "}\n";
    bool on = true, off = false;
    char *t = lowered(src, "ps", 1, &on, 1), *u = lowered(src, "ps", 1, &off, 1);
    /* 2 + 3 folds to 5 (an int, converted to float4 by the checker: folded too);
     * the true branch keeps the sample, the false one the alpha write */
    CHECK_STR(t,
        "shader pixel ps\n"
        "global uniform float4 tint\n"
        "global sampler sampler s\n"
        "function ps : float4\n"
        "  param float2 uv\n"
        "  block\n"
        "    decl float4 c (* (uniform tint) (const float4 5 5 5 5))\n"
        "    expr (assign * (local c) (tex2D (sampler s) (param uv)))\n"
        "    return (local c)\n");
    CHECK_STR(u,
        "shader pixel ps\n"
        "global uniform float4 tint\n"
        "function ps : float4\n"
        "  param float2 uv\n"
        "  block\n"
        "    decl float4 c (* (uniform tint) (const float4 5 5 5 5))\n"
        "    expr (assign (swizzle 3 (local c)) (const float 1))\n"
        "    return (local c)\n");
    free(t);
    free(u);
}

static void written_global_gets_private_copy(void) {
    const char *src =
        "float3 dir;\n"
        "static const float k = 0.5 * 4;\n"
        "float3 helper(float3 v) { return v * k; }\n"
        "float4 vs(float4 p : POSITION) : POSITION\n"
        "{\n"
        "    dir = normalize(dir);\n"
        "    return p + float4(helper(dir), 0);\n"
        "    p.x = 1;\n"
        "}\n";
    char *t = lowered(src, "vs", 0, NULL, 0);
    /* dir is written: every use reads its private copy (which needs the uniform); the static
     * const folds to 2 and replaces its uses (the global goes); the statement after return is
     * gone; helper precedes vs */
    CHECK_STR(t,
        "shader vertex vs\n"
        "global uniform float3 dir\n"
        "global private float3 hfx_priv_dir\n"
        "function helper : float3\n"
        "  param float3 v\n"
        "  block\n"
        "    return (* (param v) (const float3 2 2 2))\n"
        "function vs : float4\n"
        "  param float4 p\n"
        "  block\n"
        "    expr (assign (private dir) (normalize (private dir)))\n"
        "    return (+ (param p) (construct float4 (call helper (private dir)) (const float 0)))\n");
    free(t);
}

/* Folding follows HLSL: ints divide toward zero, % keeps the dividend's sign (fmod for
 * floats), float results are single precision, conversions to int truncate. */
static void folds_with_hlsl_arithmetic(void) {
    const char *src =
        "float4 ps() : COLOR\n"
        "{\n"
        "    int a = -7 / 2;\n"
        "    int b = -7 % 2;\n"
        "    float c = 7.5 % -2;\n"
        "    int d = (int)-1.7;\n"
        "    bool e = 3 > 2 && !false;\n"
        "    float3 f = float3(1, 2, 3).zyx * 2;\n"
        "    float g = 0.1 + 0.2;\n"
        "    return float4(a, b, c, d) + e + f.xyzz + g;\n"
        "}\n";
    char *t = lowered(src, "ps", 0, NULL, 1);
    /* 7.5 fmod -2 = 7.5 - (-2) * trunc(-3.75) = 7.5 - 6 = 1.5; 0.1 + 0.2 rounded to float
     * is 0.300000012 (%g prints 0.3) */
    CHECK_STR(t,
        "shader pixel ps\n"
        "function ps : float4\n"
        "  block\n"
        "    decl int a (const int -3)\n"
        "    decl int b (const int -1)\n"
        "    decl float c (const float 1.5)\n"
        "    decl int d (const int -1)\n"
        "    decl bool e (const bool 1)\n"
        "    decl float3 f (const float3 6 4 2)\n"
        "    decl float g (const float 0.3)\n"
        "    return (+ (+ (+ (construct float4 (convert float (local a)) (convert float (local b)) (local c) "
        "(convert float (local d))) (convert float4 (local e))) (swizzle 0,1,2,2 (local f))) (convert float4 (local g)))\n");
    free(t);
}

/* common/eval's rules in the IR: float -> uint of a negative value is 0 (Direct3D 10's ftou,
 * where the old folder wrapped it to 4294967295); int -> uint keeps the bits; int arithmetic
 * wraps at 32 bits and shifts use the low 5 bits of the count; 1.0 / 0 is left to the GPU (GLSL
 * has no literal for infinity). */
static void folds_with_the_evaluator(void) {
    const char *src =
        "float4 ps() : COLOR\n"
        "{\n"
        "    uint a = (uint)-1.5;\n"
        "    uint b = (uint)-1;\n"
        "    int c = 2147483647 + 1;\n"
        "    int d = 1 << 33;\n"
        "    float e = 1.0 / 0;\n"
        "    return float4(a, b, c, d) + e;\n"
        "}\n";
    char *t = lowered(src, "ps", 0, NULL, 1);
    CHECK(t && strstr(t, "decl uint a (const uint 0)\n"));
    /* the dump prints %g: 4294967295 and -2147483648 */
    CHECK(t && strstr(t, "decl uint b (const uint 4.29497e+09)\n"));
    CHECK(t && strstr(t, "decl int c (const int -2.14748e+09)\n"));
    CHECK(t && strstr(t, "decl int d (const int 2)\n"));
    CHECK(t && strstr(t, "decl float e (/ (const float 1) (const float 0))\n"));
    free(t);
}

/* `static const` globals and `const` locals with constant values flow into their uses, so
 * the branch they switch off and its sampler disappear. */
static void constants_propagate(void) {
    const char *src =
        "sampler s;\n"
        "static const bool useTexture = false;\n"
        "static const float scale = 0.5 * 3;\n"
        "float4 ps(float2 uv : TEXCOORD0) : COLOR\n"
        "{\n"
        "    const int steps = 2 + 2;\n"
        "    if (useTexture) return tex2D(s, uv);\n"
        "    return float4(uv * scale, steps, 1);\n"
        "}\n";
    char *t = lowered(src, "ps", 0, NULL, 1);
    CHECK_STR(t,
        "shader pixel ps\n"
        "function ps : float4\n"
        "  param float2 uv\n"
        "  block\n"
        "    decl int steps (const int 4)\n"
        "    return (construct float4 (* (param uv) (const float2 1.5 1.5)) (const float 4) (const float 1))\n");
    free(t);
}

int main(void) {
    RUN(specialised_branch_folds_away);
    RUN(written_global_gets_private_copy);
    RUN(folds_with_hlsl_arithmetic);
    RUN(folds_with_the_evaluator);
    RUN(constants_propagate);
    return test_summary();
}
