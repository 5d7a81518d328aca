/* One writer of evaluator programs, one folder of constants (issue 31): a state value and a
 * preshader of the same expression are the same common/eval_code program, and a constant
 * expression folds to Direct3D's value both as a parameter's default and in shader code.
 * Expected words are worked out by hand from eval_code.h's layout (op | a << 8 | b << 16):
 * CONST 0, PARAM 1, BINARY 5, TABLE 7; bases BOOL 0, INT 1, UINT 2, FLOAT 3; MUL 6. */
#include <stdlib.h>
#include <string.h>

#include "check/check.h"
#include "effect/build.h"
#include "hfx/hfxc.h"
#include "ir/ir.h"
#include "parse/ast.h"
#include "pp/token.h"
#include "states.h"
#include "test.h"

static const hfx_fx_effect *compile(hfxc_result **r, const char *src, unsigned flags) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    o.flags = flags | HFXC_NO_WARNINGS;
    *r = hfxc_compile_memory(src, strlen(src), "t.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(*r);
    if (!fx) {
        char *text = hfxc_diagnostics_text(*r);
        fprintf(stderr, "did not build:\n%s", text);
        free(text);
    }
    return fx;
}

/* The EXPR program of the first state `name` of the effect's first pass. */
static const uint32_t *state_code(const hfx_fx_effect *fx, const char *name, uint32_t *words) {
    const hfx_state_info *info = hfx_state_lookup(name);
    const hfx_fx_pass *p = &fx->passes[0];
    for (uint32_t i = 0; info && i < p->state_count; i++) {
        const hfx_fx_state *s = &fx->states[p->first_state + i];
        if (s->id == info->id && s->kind == HFX_FX_VALUE_EXPR) {
            *words = s->count;
            return fx->exprs + s->ref;
        }
    }
    *words = 0;
    return NULL;
}

static void check_words(const uint32_t *got, uint32_t n, const uint32_t *want, uint32_t m) {
    if (n != m)
        for (uint32_t i = 0; got && i < n; i++) fprintf(stderr, "  word %u: %08x\n", (unsigned)i, got[i]);
    CHECK_INT(n, m);
    for (uint32_t i = 0; got && i < n && i < m; i++) {
        if (got[i] != want[i]) fprintf(stderr, "  word %u: %08x, want %08x\n", (unsigned)i, got[i], want[i]);
        CHECK_INT(got[i], want[i]);
    }
}

/* `AlphaRef = (Ref * 255);` and a vertex shader's `p.w * (Ref * 255)` (a preshader with packed
 * parameters): Ref (offset 0) as float, 255 as the float 0x437f0000, a multiplication. */
static void state_and_preshader_agree(void) {
    static const uint32_t want[] = {0x00010301, 0, 0x00010300, 0x437f0000, 0x0605};
    hfxc_result *r;
    const hfx_fx_effect *fx = compile(&r,
        "float Ref;\n"
        "float4 VS(float4 p : POSITION) : POSITION { return float4(p.xyz, p.w * (Ref * 255)); }\n"
        "float4 PS() : COLOR { return 1; }\n"
        "technique T { pass P { AlphaRef = (Ref * 255);\n"
        "  VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n",
        HFXC_PACK_UNIFORMS);
    CHECK(fx != NULL);
    if (fx) {
        uint32_t n;
        const uint32_t *state = state_code(fx, "AlphaRef", &n);
        check_words(state, n, want, 5);
        const hfx_fx_program *p = &fx->programs[0];
        CHECK_INT(p->preshader_count, 1);
        if (p->preshader_count == 1)
            check_words(p->pre_code + p->preshaders[0].first, p->preshaders[0].words, want, 5);
    }
    hfxc_result_free(r);
}

/* `AlphaFunc = (Funcs[Which]);` over `static const int Funcs[2] = {1, 8}`: Which (offset 0) as
 * int, then TABLE int x1 of 2 entries, 1 and 8. */
static void a_table_is_written_by_it_too(void) {
    static const uint32_t want[] = {0x00010101, 0, 0x00010107, 2, 1, 8};
    hfxc_result *r;
    const hfx_fx_effect *fx = compile(&r,
        "int Which;\n"
        "static const int Funcs[2] = {1, 8};\n"
        "technique T { pass P { AlphaFunc = (Funcs[Which]); } }\n", 0);
    CHECK(fx != NULL);
    if (fx) {
        uint32_t n;
        const uint32_t *code = state_code(fx, "AlphaFunc", &n);
        check_words(code, n, want, 6);
    }
    hfxc_result_free(r);
}

/* Direct3D's rules (eval.h): integer division and % truncate toward zero (7 / -2 is -3, -7 % 3
 * is -1), float to int truncates (-2.7 is -2), >> on an int is arithmetic (-8 >> 1 is -4),
 * floats are single precision (1 / 3.0 is 0x3eaaaaab), pow is |x|^y (pow(-2, 2) is 4). */
static const char folded_src[] =
    "int q = 7 / -2;\n"
    "int rm = -7 % 3;\n"
    "int t = (int)-2.7;\n"
    "int sh = -8 >> 1;\n"
    "float third = 1 / 3.0;\n"
    "float pw = pow(-2, 2);\n"
    "float4 PS() : COLOR { return float4(7 / -2, -7 % 3, (int)-2.7, 1 / 3.0); }\n"
    "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";

static uint32_t word(const hfx_fx_effect *fx, const char *name) {
    uint32_t i = hfx_fx_param_find(fx, name);
    CHECK(i != HFX_NONE);
    return i == HFX_NONE ? 0xdeadbeef : fx->values[fx->params[i].offset];
}

static void defaults_fold_as_direct3d(void) {
    hfxc_result *r;
    const hfx_fx_effect *fx = compile(&r, folded_src, 0);
    CHECK(fx != NULL);
    if (fx) {
        CHECK_INT((int32_t)word(fx, "q"), -3);
        CHECK_INT((int32_t)word(fx, "rm"), -1);
        CHECK_INT((int32_t)word(fx, "t"), -2);
        CHECK_INT((int32_t)word(fx, "sh"), -4);
        CHECK_INT(word(fx, "third"), 0x3eaaaaab);
        CHECK_INT(word(fx, "pw"), 0x40800000); /* 4.0f */
    }
    hfxc_result_free(r);
}

/* The float4 constant the shader's return folded to (lower/fold.c, the same walk). */
static void find_const4(ir_ctx *c, ir_expr **slot, void *data) {
    const ir_expr **found = data;
    if ((*slot)->kind == IE_CONST && hfx_type_components((*slot)->type) == 4) *found = *slot;
}

static void shader_constants_fold_as_direct3d(void) {
    hfx_arena arena;
    hfx_diags diags;
    hfx_arena_init(&arena);
    hfx_diags_init(&diags, &arena, 0);
    hfx_types *types = hfx_types_new(&arena);
    hfx_pp_options pp;
    memset(&pp, 0, sizeof pp);
    hfx_token *toks = hfx_preprocess(&arena, &diags, "t.fx", folded_src, (uint32_t)strlen(folded_src), &pp);
    hfx_ast *ast = hfx_parse(&arena, &diags, types, toks);
    hfx_fx_effect *fx = diags.errors == 0 && hfx_check(&arena, &diags, types, ast)
                            ? hfx_build_effect(&arena, &diags, types, ast, "t.fx", 1u << HFX_TARGET_GLSL330) : NULL;
    CHECK(fx != NULL);
    const hfx_state_assign *a = fx ? &ast->decls[ast->decl_count - 1]->technique->passes[0].states[0] : NULL;
    ir_ctx c = {&arena, &diags, types, ast, fx};
    ir_shader *sh = a ? hfx_ir_build(&c, a->value, IR_PIXEL) : NULL;
    CHECK(sh != NULL && hfx_ir_lower(&c, sh, 0) == 0);
    const ir_expr *k = NULL;
    if (sh) hfx_ir_walk_stmt_exprs(&c, sh->entry->body, find_const4, &k);
    CHECK(k != NULL);
    if (k) {
        CHECK_NEAR(k->cval[0], -3, 0);
        CHECK_NEAR(k->cval[1], -1, 0);
        CHECK_NEAR(k->cval[2], -2, 0);
        CHECK_NEAR(k->cval[3], (double)(1.0f / 3.0f), 0); /* rounded to single precision */
    }
    hfx_fx_effect_free(fx);
    hfx_arena_free(&arena);
}

int main(void) {
    RUN(state_and_preshader_agree);
    RUN(a_table_is_written_by_it_too);
    RUN(defaults_fold_as_direct3d);
    RUN(shader_constants_fold_as_direct3d);
    return test_summary();
}
