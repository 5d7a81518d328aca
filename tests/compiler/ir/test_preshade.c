/* test_preshade.c: after the preshade pass, no shader of the seeds (and of fx/) keeps work a
 * preshader could take. The test walks the IR of every pass's stages and looks for a
 * subexpression that is float all through, reads a parameter, computes (an operator or an
 * intrinsic) and is built only of what the test itself, not pre_code.c, knows a preshader
 * computes: a short list written here from D3D9's preshader instructions. There must be none,
 * and without the preshade rows there must be some (so the oracle can fail). Small effects
 * count their preshaders by hand. The GLSL names what each preshader register holds, in HLSL. */
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "check/check.h"
#include "effect/build.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "ir/ir.h"
#include "parse/ast.h"
#include "pp/token.h"
#include "test.h"

typedef struct scan {
    ir_ctx *c;
    unsigned left;      /* subexpressions a preshader could still take */
    const char *where;
} scan;

enum { CAN = 1, WORK = 2, READS = 4 };

static bool floating(const hfx_type *t) {
    return hfx_type_is_numeric(t) && (t->base == B_FLOAT || t->base == B_HALF) && hfx_type_components(t) <= 16;
}

/* Intrinsics D3D9's preshaders compute (fxc's preshader listings use them), by HLSL name. */
static bool cpu_intrinsic(int id) {
    static const char *const names[] = {"abs", "cos", "sin", "dot", "normalize", "length", "mul", "sqrt",
                                        "rsqrt", "max", "min", "saturate", "exp", "log", "frac", "cross"};
    const char *n = hfx_intrinsic_name(id);
    for (size_t i = 0; n && i < sizeof names / sizeof *names; i++)
        if (!strcmp(n, names[i])) return true;
    return false;
}

/* A node of float type that a preshader computes from its operands: a constant, a parameter
 * (a uniform the shader does not write: a written one reads its private copy), arithmetic,
 * one of the intrinsics above, or a move (swizzle, constructor, conversion between floats). */
static bool cpu_node(const ir_expr *e) {
    if (!floating(e->type)) return false;
    switch (e->kind) {
    case IE_CONST: return true;
    case IE_VAR: return e->var->kind == IRV_UNIFORM && e->var->param != HFX_NONE;
    case IE_UNARY: return e->op == OP_NEG;
    case IE_BINARY: return e->op == OP_ADD || e->op == OP_SUB || e->op == OP_MUL || e->op == OP_DIV;
    case IE_INTRIN: return cpu_intrinsic((int)e->intrin);
    case IE_SWIZZLE: case IE_CONSTRUCT: return true;
    case IE_CONVERT: return floating(e->a[0]->type);
    default: return false;
    }
}

static unsigned flags_of(const ir_expr *e) {
    bool work = e->kind == IE_UNARY || e->kind == IE_BINARY || e->kind == IE_INTRIN;
    unsigned all = CAN, more = (work ? WORK : 0) | (e->kind == IE_VAR ? READS : 0);
    for (uint32_t i = 0; i < e->n; i++) {
        unsigned f = flags_of(e->a[i]);
        all &= f;
        more |= f & (WORK | READS);
    }
    return all && cpu_node(e) ? CAN | more : 0;
}

static void look(ir_ctx *c, ir_expr **slot, void *data) {
    scan *s = data;
    const ir_expr *e = *slot;
    if (flags_of(e) == (CAN | WORK | READS)) {
        if (s->where) fprintf(stderr, "  %s: left in the shader: %s\n", s->where, hfx_ir_pre_text(c, e));
        s->left++;
    }
}

/* The IR of one compile expression, lowered (preshaded unless told not to: where NULL), scanned. */
static unsigned stage_left(ir_ctx *c, const hfx_expr *compile, ir_stage st, const char *where, uint32_t *pres) {
    ir_shader *sh = hfx_ir_build(c, compile, st);
    if (!sh || hfx_ir_lower(c, sh, IR_LOWER_PACKED | (where ? IR_LOWER_PRESHADE : 0)) != 0) return 1;
    *pres += sh->pre_count;
    scan s = {c, 0, where};
    for (uint32_t i = 0; i < sh->func_count; i++) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, look, &s);
    return s.left;
}

/* Every pass's shaders of the effect in path; *pres counts the preshaders made. preshade false:
 * without the preshade rows (nothing printed). */
static unsigned effect_left(const char *path, uint32_t *pres, bool preshade) {
    size_t size = 0;
    char *src = test_read_file(path, &size);
    if (!src) return 1;
    hfx_arena arena;
    hfx_diags diags;
    hfx_arena_init(&arena);
    hfx_diags_init(&diags, &arena, HFXC_PACK_UNIFORMS);
    hfx_types *types = hfx_types_new(&arena);
    hfx_pp_options pp;
    memset(&pp, 0, sizeof pp);
    hfx_token *toks = hfx_preprocess(&arena, &diags, path, src, (uint32_t)size, &pp);
    hfx_ast *ast = hfx_parse(&arena, &diags, types, toks);
    unsigned left = 0;
    hfx_fx_effect *fx = diags.errors == 0 && hfx_check(&arena, &diags, types, ast)
                            ? hfx_build_effect(&arena, &diags, types, ast, path, 1u << HFX_TARGET_GLSL330) : NULL;
    ir_ctx c = {&arena, &diags, types, ast, fx};
    for (uint32_t d = 0; fx && d < ast->decl_count; d++) {
        const hfx_technique_ast *t = ast->decls[d]->kind == DECL_TECHNIQUE ? ast->decls[d]->technique : NULL;
        for (uint32_t p = 0; t && p < t->pass_count; p++)
            for (uint32_t k = 0; k < t->passes[p].state_count; k++) {
                const hfx_state_assign *a = &t->passes[p].states[k];
                bool vs = strcasecmp(a->name, "VertexShader") == 0, ps = strcasecmp(a->name, "PixelShader") == 0;
                if ((vs || ps) && a->value && a->value->kind == EX_COMPILE)
                    left += stage_left(&c, a->value, vs ? IR_VERTEX : IR_PIXEL, preshade ? path : NULL, pres);
            }
    }
    if (!fx) left++, fprintf(stderr, "  %s did not compile\n", path);
    hfx_fx_effect_free(fx);
    hfx_arena_free(&arena);
    free(src);
    return left;
}

static const char *const seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
    "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
    "spot_specular.fx", "tutorial0.fx",
};

/* Every seed but the empty FX Composer one has a preshader: each transforms by World, View and
 * Projection, as one product or in turn (tutorial0.fx: the position through each, regrouped). */
static void seeds_keep_nothing(void) {
    for (size_t i = 0; i < sizeof seeds / sizeof *seeds; i++) {
        char *path = test_seed_path(seeds[i]);
        uint32_t pres = 0;
        CHECK_INT(effect_left(path, &pres, true), 0);
        bool none = strcmp(seeds[i], "fxcomposer_empty.fx") == 0;
        if (none != (pres == 0)) fprintf(stderr, "  %s: %u preshaders\n", seeds[i], (unsigned)pres);
        CHECK(none == (pres == 0));
        free(path);
    }
}

static void project_effects_keep_nothing(void) {
    static const char *const mine[] = {"ambient.fx", "basic_lighting.fx", "directional.fx", "multipass.fx", "point.fx",
                                       "point_lights.fx", "sas_blinn.fx", "shading_models.fx", "spot.fx", "textured.fx"};
    for (size_t i = 0; i < sizeof mine / sizeof *mine; i++) {
        char path[512];
        snprintf(path, sizeof path, "%s/fx/%s", HFX_SOURCE_DIR, mine[i]);
        uint32_t pres = 0;
        CHECK_INT(effect_left(path, &pres, true), 0);
    }
}

/* The oracle sees the work when the preshade rows do not run: spot_specular.fx's five
 * preshaders' worth (the_glsl_says_what_a_register_holds), and at least one per seed that has
 * a preshader. */
static void the_oracle_finds_work_left_unpreshaded(void) {
    char *path = test_seed_path("spot_specular.fx");
    uint32_t pres = 0;
    CHECK(effect_left(path, &pres, false) >= 5);
    CHECK_INT(pres, 0);
    free(path);
    path = test_seed_path("point.fx");
    CHECK(effect_left(path, &pres, false) >= 1);
    free(path);
}

/* The first program's GLSL 330 of an effect compiled with packed parameters (preshaders on):
 * *out keeps the result alive (hfxc_result_free). */
static const hfx_fx_program *first_program(hfxc_result **out, const char *path, const char *src, const char *name) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    o.flags = HFXC_PACK_UNIFORMS | HFXC_NO_WARNINGS;
    *out = path ? hfxc_compile_file(path, &o) : hfxc_compile_memory(src, strlen(src), name, &o);
    const hfx_fx_effect *fx = hfxc_result_effect(*out);
    CHECK(fx != NULL && fx->program_count > 0);
    return fx && fx->program_count ? &fx->programs[0] : NULL;
}

static const char *glsl_of(const hfx_fx_program *p, int stage) { return p->code[stage][HFX_TARGET_GLSL330].data; }

/* spot_specular.fx: the vertex shader's mul(world, mul(view, projection)) and the pixel
 * shader's normalize(posicionLuz - blancoLuz), ks * colorMaterialEspecular (the specular term's
 * parameter factors, put together by lower/factors.c), cos(anguloInterno) and
 * cos(anguloExterno). The pixel stage goes first: the ten scalars and vectors it reads as they
 * are take registers 0..9, its preshaders 10..13; then the vertex stage's world 14..17 and its
 * matrix 18..21. */
static void the_glsl_says_what_a_register_holds(void) {
    char *path = test_seed_path("spot_specular.fx");
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, path, NULL, NULL);
    if (p) {
        const char *vs = glsl_of(p, HFX_STAGE_VERTEX), *ps = glsl_of(p, HFX_STAGE_FRAGMENT);
        CHECK_CONTAINS(vs, "mat4 hfx_pre0; // hfx_c[18..21] = mul(world, mul(view, projection)), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(vs, "    hfx_pre0 = mat4(hfx_c[18], hfx_c[19], hfx_c[20], hfx_c[21]);\n");
        CHECK_CONTAINS(vs, "    salida.Posicion = hfx_pre0 * entrada.Posicion;\n"); /* mvp, read once, moved forward */
        CHECK_CONTAINS(ps, "vec3 hfx_pre0; // hfx_c[10] = normalize(posicionLuz - blancoLuz), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "vec4 hfx_pre1; // hfx_c[11] = ((float4)ks * colorMaterialEspecular), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "float hfx_pre2; // hfx_c[12] = cos(anguloInterno), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "float hfx_pre3; // hfx_c[13] = cos(anguloExterno), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(vs, "mat4 world; // hfx_c[14..17]\n");
        CHECK_INT(p->reg_count, 22);
        CHECK_INT(p->preshader_count, 5);
    }
    hfxc_result_free(r);
    free(path);
}

/* `L = normalize(L);` first thing in the entry: the private copy still holds the parameter, so
 * the right side is a preshader; after a statement that is not such an assignment it is not
 * (the copy may have changed; here the second assignment reads a varying anyway). */
static void a_parameter_normalised_in_place(void) {
    static const char src[] =
        "float3 L; float3 K;\n"
        "float4 PS(float3 n : TEXCOORD0) : COLOR0 {\n"
        "    L = normalize(L);\n"
        "    float d = dot(L, n);\n"
        "    K = normalize(K + n);\n"
        "    return float4(d, K);\n"
        "}\n"
        "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n";
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, NULL, src, "in_place.fx");
    if (p) {
        const char *ps = glsl_of(p, HFX_STAGE_FRAGMENT);
        /* L and K are copied (the shader writes them), so the preshader is the first register */
        CHECK_CONTAINS(ps, "vec3 hfx_pre0; // hfx_c[0] = normalize(L), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "    hfx_priv_L = hfx_pre0;\n");
        CHECK_CONTAINS(ps, "    hfx_priv_K = normalize(hfx_priv_K + n);\n");
        CHECK_INT(p->preshader_count, 1);
    }
    hfxc_result_free(r);
}

/* directional.fx's way: `L = normalize(L);` first (after a local declared with a constant, and
 * inside a leading block), and L read only negated, `dot(-L, n)`: the negation goes into the
 * preshader and the copy and its assignment go. Read both as -M and M, M keeps its copy and
 * one preshader (two registers would cost more than the negation); written twice, N keeps
 * its assignments. */
static void a_negated_copy_is_the_preshader(void) {
    static const char src[] =
        "float3 L; float3 M; float3 N;\n"
        "float4 PS(float3 n : TEXCOORD0) : COLOR0 {\n"
        "    float4 c = 0;\n"
        "    { L = normalize(L); M = normalize(M); N = normalize(N);\n"
        "      c.x = max(dot(-L, n), 0) + dot(-L, n.zyx);\n"
        "      c.y = dot(-M, n) + M.x;\n"
        "      N = N * n.x;\n"
        "      c.z = dot(-N, n); }\n"
        "    return c;\n"
        "}\n"
        "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n";
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, NULL, src, "negated.fx");
    if (p) {
        const char *ps = glsl_of(p, HFX_STAGE_FRAGMENT);
        /* the kept copies' preshaders are made first, in order; L's in the walk after them */
        CHECK_CONTAINS(ps, "vec3 hfx_pre2; // hfx_c[2] = -normalize(L), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "        c.x = max(dot(hfx_pre2, n), 0.0) + dot(hfx_pre2, n.zyx);\n");
        CHECK(strstr(ps, "hfx_priv_L") == NULL);
        CHECK_CONTAINS(ps, "vec3 hfx_pre0; // hfx_c[0] = normalize(M), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "        hfx_priv_M = hfx_pre0;\n");
        CHECK_CONTAINS(ps, "        c.y = dot(-hfx_priv_M, n) + hfx_priv_M.x;\n");
        CHECK_CONTAINS(ps, "        hfx_priv_N = hfx_pre1;\n");
        CHECK_CONTAINS(ps, "        hfx_priv_N = hfx_priv_N * n.x;\n");
        CHECK_INT(p->preshader_count, 3);
    }
    hfxc_result_free(r);
}

/* tutorial0.fx's way: the position through World, View and Projection in turn, through locals
 * read once by the next statement. They move forward and the products regroup, so the three
 * matrices make one preshader and a vertex does one vector product. A local read twice stays,
 * and so does one whose next statement is a loop (it would run there more than once). */
static void transforms_in_turn_regroup(void) {
    static const char src[] =
        "float4x4 World, View, Projection; float4x4 A, B; int N;\n"
        "float4 VS(float4 p : POSITION0) : POSITION0 {\n"
        "    float4 w = mul(p, World);\n"
        "    float4 v = mul(w, View);\n"
        "    float4 o = mul(v, Projection);\n"
        "    float4 twice = mul(p, A);\n"
        "    float4 t = mul(twice, B) + twice;\n"
        "    float4 l = mul(p, B);\n"
        "    for (int i = 0; i < N; i++) t += l;\n"
        "    return o + t;\n"
        "}\n"
        "technique T { pass P { VertexShader = compile vs_3_0 VS(); } }\n";
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, NULL, src, "turns.fx");
    if (p) {
        const char *vs = glsl_of(p, HFX_STAGE_VERTEX);
        CHECK_CONTAINS(vs, "= mul(mul(World, View), Projection), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(vs, "    vec4 o = hfx_pre0 * p;\n");
        CHECK_CONTAINS(vs, "    vec4 twice = A * p;\n");
        CHECK_CONTAINS(vs, "    vec4 t = B * twice + twice;\n");
        CHECK_CONTAINS(vs, "    vec4 l = B * p;\n");
        CHECK_INT(p->preshader_count, 1);
    }
    hfxc_result_free(r);
}

/* lower/factors.c: a vector product's scalar factors are multiplied first, its parameters'
 * factors together (one preshader: k * Tint), then the vectors; a product with one scalar, an
 * integer one, and a shader compiled without preshaders keep the order written. */
static void products_take_scalars_first(void) {
    static const char src[] =
        "float4 Tint; float k; sampler S;\n"
        "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
        "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { float4 t = tex2D(S, uv);\n"
        "  float4 a = k * t * t.x * Tint * t.y;\n"
        "  float4 b = t * t.z;\n"
        "  int4 c = (int4)(t * 8) * (int)(t.x * 8) * 2;\n"
        "  return a + b + c + 2 * t * t.w; }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, NULL, src, "factors.fx");
    if (p) {
        const char *ps = glsl_of(p, HFX_STAGE_FRAGMENT);
        CHECK_CONTAINS(ps, "vec4 hfx_pre0; // hfx_c[0] = ((float4)k * Tint), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "vec4 a = t.x * t.y * hfx_pre0 * t;\n");
        CHECK_CONTAINS(ps, "vec4 b = t * t.z;\n");
        CHECK_CONTAINS(ps, "ivec4(t * vec4(8.0)) * int(t.x * 8.0) * ivec4(2)"); /* integers: as written */
        CHECK_CONTAINS(ps, "2.0 * t.w * t");
    }
    hfxc_result_free(r);
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    o.flags = HFXC_PACK_UNIFORMS | HFXC_NO_WARNINGS | HFXC_NO_PRESHADERS;
    r = hfxc_compile_memory(src, strlen(src), "factors.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL && fx->program_count == 1);
    if (fx && fx->program_count == 1)
        CHECK_CONTAINS(glsl_of(&fx->programs[0], HFX_STAGE_FRAGMENT), "vec4 a = k * t * t.x * Tint * t.y;\n");
    hfxc_result_free(r);
}

/* lower/sums.c: a counted loop's sum gives its parameter-only terms (licm's local among them)
 * to one addition before the loop, times the trips, which a preshader computes; a loop that
 * breaks, an accumulator read in the loop, an addition under an if and a `<=` bound stay. */
static void sums_add_invariant_terms_once(void) {
    static const char src[] =
        "float4 Amb; float k; int n; sampler S;\n"
        "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
        "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { float4 a = 0, b = 0, c = 0, d = 0, e = 0;\n"
        "  for (int i = 2; i < n; i++) a += Amb * k + tex2D(S, uv * i);\n"
        "  for (int j = 0; j < n; j++) { b += Amb + uv.x; if (b.x > 1) break; }\n"
        "  for (int l = 0; l < n; l++) c += Amb + c.x;\n"
        "  for (int m = 0; m < n; m++) if (uv.y > 0.5) d += Amb;\n"
        "  for (int q = 0; q <= n; q++) e += Amb;\n"
        "  return a + b + c + d + e; }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, NULL, src, "sums.fx");
    if (p) {
        const char *ps = glsl_of(p, HFX_STAGE_FRAGMENT);
        CHECK_CONTAINS(ps, "vec4 hfx_pre0; // hfx_c[1] = ((Amb * (float4)k) * (float4)(float)((n > 2) ? (n - 2) : 0)), "
                           "computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "    a += hfx_pre0;\n    for (int i = 2; i < n; i++)\n    {\n        a += texture(S, uv * vec2(i));\n");
        CHECK(strstr(ps, "hfx_inv0") == NULL); /* licm's local for Amb * k: read by nothing now, gone */
        CHECK_CONTAINS(ps, "vec4 hfx_inv1 = Amb + uv.x;\n    for (int j = 0; j < n; j++)\n    {\n        b += hfx_inv1;\n");
        CHECK_CONTAINS(ps, "c += Amb + c.x;");
        CHECK_CONTAINS(ps, "d += Amb;");
        CHECK_CONTAINS(ps, "e += Amb;");
        CHECK_INT(p->preshader_count, 1);
    }
    hfxc_result_free(r);
}

/* forward.c: a position taken through World and then ViewProj from a local that other outputs
 * read too is computed from its source, float4(p, 1), with one preshader matrix (w = 1: the
 * driver skips those products); not when p changes after the local is set. */
static void positions_from_their_source(void) {
    static const char src[] =
        "float4x4 World, ViewProj; float3 Cam;\n"
        "struct O { float4 pos : POSITION0; float3 v : TEXCOORD0; };\n"
        "O VS(float3 p : POSITION0) { O o; float4 w = mul(float4(p, 1), World);\n"
        "  %s o.pos = mul(w, ViewProj); o.v = Cam - w.xyz; return o; }\n"
        "float4 PS(float3 v : TEXCOORD0) : COLOR0 { return float4(v, 1); }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    char text[1024];
    snprintf(text, sizeof text, src, "");
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, NULL, text, "source.fx");
    if (p) {
        const char *vs = glsl_of(p, HFX_STAGE_VERTEX);
        CHECK_CONTAINS(vs, "= mul(World, ViewProj), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(vs, "    o.pos = hfx_pre0 * vec4(p, 1.0);\n");
        CHECK_CONTAINS(vs, "    o.v = Cam - w.xyz;\n");
    }
    hfxc_result_free(r);
    snprintf(text, sizeof text, src, "p.x += 1;");
    p = first_program(&r, NULL, text, "source.fx");
    if (p) CHECK_CONTAINS(glsl_of(p, HFX_STAGE_VERTEX), "    o.pos = ViewProj * w;\n");
    hfxc_result_free(r);
}

/* Preshaders counted by hand, a line each: the maximal parameter-only subexpression that
 * computes becomes one, equal ones share it, a parameter read as it is (or only converted) is
 * none, and work that reads a varying stays.
 *   A * k                 1: (A * (float4)k), k splat by a conversion (one product: factors.c
 *                            reorders only when that saves multiplications)
 *   A                     0: a move
 *   tex2D(S, uv) * k      0: k alone computes nothing
 *   cos(k) * uv.x         1: cos(k)
 *   A + B + uv.x          1: (A + B), the left operand of the second +
 *   uv.x + A + B          0: (uv.x + A) + B reads the varying at every step (no reassociation)
 *   mul(M, A)             1: mul(M, A)
 *   cos(k) * 2            1: the whole product, with the splat to float4 that `r +=` adds (a
 *                            move: maximal takes it in); 2 folded to a float, printed %g
 *   cos(k) * uv.y         0 more: the cos(k) of line 4, shared
 * five in all. */
static void hand_counted_preshaders(void) {
    static const char src[] =
        "float4 A, B; float k; float4x4 M; sampler S;\n"
        "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { float4 r = 0;\n"
        "  r += A * k;\n"
        "  r += A;\n"
        "  r += tex2D(S, uv) * k;\n"
        "  r += cos(k) * uv.x;\n"
        "  r += A + B + uv.x;\n"
        "  r += uv.x + A + B;\n"
        "  r += mul(M, A);\n"
        "  r += cos(k) * 2;\n"
        "  r += cos(k) * uv.y;\n"
        "  return r; }\n"
        "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n";
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, NULL, src, "counted.fx");
    if (p) {
        const char *ps = glsl_of(p, HFX_STAGE_FRAGMENT);
        CHECK_INT(p->preshader_count, 5);
        CHECK_CONTAINS(ps, " = (A * (float4)k), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, " = cos(k), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, " = (A + B), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, " = mul(M, A), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, " = (float4)(cos(k) * 2), computed on the CPU (a preshader)\n");
    }
    hfxc_result_free(r);
}

/* The register file, pixel stage first: the parameters it reads as they are (in parameter
 * order), its preshaders, the parameters it copies, then the vertex stage's parameters and
 * preshaders. Gain, read by both stages, counts as the pixel stage's; World and ViewProj are read
 * by the preshader only and take no register. */
static void pixel_registers_come_first(void) {
    static const char src[] =
        "float4x4 World; float4x4 ViewProj; float4 Tint; float3 L; float Gain; float4 Bias;\n"
        "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, mul(World, ViewProj)) * Gain + Bias; }\n"
        "float4 PS(float3 n : TEXCOORD0) : COLOR0 { L = normalize(L); return Tint * dot(L, n) + Gain; }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    hfxc_result *r;
    const hfx_fx_program *p = first_program(&r, NULL, src, "order.fx");
    if (p) {
        const char *vs = glsl_of(p, HFX_STAGE_VERTEX), *ps = glsl_of(p, HFX_STAGE_FRAGMENT);
        CHECK_CONTAINS(ps, "vec4 Tint; // hfx_c[0]\n");
        CHECK_CONTAINS(ps, "float Gain; // hfx_c[1]\n");
        CHECK_CONTAINS(ps, "vec3 hfx_pre0; // hfx_c[2] = normalize(L), computed on the CPU (a preshader)\n");
        CHECK_CONTAINS(ps, "vec3 L; // hfx_c[3]\n");
        CHECK_CONTAINS(vs, "vec4 Bias; // hfx_c[4]\n");
        CHECK_CONTAINS(vs, "mat4 hfx_pre0; // hfx_c[5..8] = mul(World, ViewProj), computed on the CPU (a preshader)\n");
        CHECK_INT(p->reg_count, 9);
    }
    hfxc_result_free(r);
}

/* Every seed program whose pixel shader reads registers reads hfx_c[0] in main(): llvmpipe runs
 * a fragment shader that does not measurably slower (codegen.c, assign_register_file). */
static void seed_pixel_shaders_read_register_0(void) {
    for (size_t i = 0; i < sizeof seeds / sizeof *seeds; i++) {
        char *path = test_seed_path(seeds[i]);
        hfxc_result *r;
        first_program(&r, path, NULL, NULL);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        for (uint32_t k = 0; fx && k < fx->program_count; k++) {
            const char *ps = glsl_of(&fx->programs[k], HFX_STAGE_FRAGMENT);
            if (!ps || !strstr(ps, "uniform vec4 hfx_c[")) continue;
            const char *init = strstr(ps, "\nvoid main()\n{\n");
            bool reads = init && strstr(init, " = hfx_c[0]");
            if (!reads) fprintf(stderr, "  %s program %u\n", seeds[i], (unsigned)k);
            CHECK(reads);
        }
        hfxc_result_free(r);
        free(path);
    }
}

int main(void) {
    RUN(project_effects_keep_nothing);
    RUN(a_parameter_normalised_in_place);
    RUN(a_negated_copy_is_the_preshader);
    RUN(transforms_in_turn_regroup);
    RUN(positions_from_their_source);
    RUN(pixel_registers_come_first);
    RUN(products_take_scalars_first);
    RUN(sums_add_invariant_terms_once);
    RUN(hand_counted_preshaders);
    test_seeds_or_finish();
    RUN(the_oracle_finds_work_left_unpreshaded);
    RUN(seed_pixel_shaders_read_register_0);
    RUN(seeds_keep_nothing);
    RUN(the_glsl_says_what_a_register_holds);
    return test_summary();
}
