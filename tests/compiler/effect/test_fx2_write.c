/* The fx_2_0 writer (compiler/effect/fx2_write.c, fxlvm_write.c): a tiny effect's bytes checked
 * word by word against the layout worked out by hand from docs/fx2.md; state expressions
 * written as FXLVM, read back by fxlvm.c and run, against the values Direct3D gives (worked out
 * below); NULL shaders and passes with states alone; shaders taken from the bytecode hook
 * (hand-assembled tokens) and read back into programs; hand-laid fxc containers (every
 * parameter type, a sampler, a shader array selector) read -> written -> read with the same
 * listing and values. With HFX_FX2_SAMPLES=<folder> it does the same for every .fxb / .efb
 * there (scripts/fx2_roundtrip.sh fetches FNA's and DigitalRune's, which CI does not have). */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "effect/fx2_write.h"
#include "bytes.h"
#include "eval_code.h"
#include "files.h"
#include "fx2_builder.h"
#include "hfx/hfxc.h"
#include "states.h"
#include "test.h"

/* As hfxc reads binaries: packed registers (fxc's preshaders need them). */
static const hfxc_options packed = {.flags = HFXC_PACK_UNIFORMS};

static uint32_t state_id(const char *name) { return hfx_state_lookup(name)->id; }

static hfxc_result *compile(const char *src) {
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "t.fx", NULL);
    if (!hfxc_result_effect(r)) {
        char *t = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s", t);
        free(t);
    }
    return r;
}

/* fx written, then read back by hfx's fx_2_0 reader (hfxc_compile_memory sees the magic). */
static hfxc_result *round_trip(const hfx_fx_effect *fx, const hfx_fx2_write_options *opt, void **bytes, size_t *size) {
    char err[512];
    void *data;
    size_t n;
    if (hfx_fx2_write(fx, "t.fx", opt, &data, &n, err, sizeof err) != 0) {
        fprintf(stderr, "write: %s\n", err);
        return NULL;
    }
    hfxc_result *r = hfxc_compile_memory(data, n, "t.fxo", &packed);
    if (!hfxc_result_effect(r)) {
        char *t = hfxc_diagnostics_text(r);
        fprintf(stderr, "read back: %s", t);
        free(t);
    }
    if (bytes) *bytes = data, *size = n;
    else free(data);
    return r;
}

/* text compiled, written as fx_2_0 and read back: the read-back effect (NULL when either step
 * failed, which is checked); the caller frees *r and *back. */
static const hfx_fx_effect *compile_round_trip(const char *text, hfxc_result **r, hfxc_result **back) {
    *r = compile(text);
    *back = NULL;
    const hfx_fx_effect *src = hfxc_result_effect(*r);
    CHECK(src != NULL);
    if (!src) return NULL;
    *back = round_trip(src, NULL, NULL, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(*back);
    CHECK(fx != NULL);
    return fx;
}

/* The written bytes against the words worked out by hand, each difference printed. */
static void check_words(const void *data, size_t size, const uint32_t *expect, size_t n) {
    CHECK_INT(size, 4 * n);
    for (size_t i = 0; i < size / 4 && i < n; i++) {
        uint32_t w;
        memcpy(&w, (const uint8_t *)data + 4 * i, 4);
        if (w != expect[i]) fprintf(stderr, "word %zu: 0x%x, expected 0x%x\n", i, w, expect[i]);
        CHECK_INT(w, expect[i]);
    }
}

/* float Ref = 0.5; one technique, one pass, CullMode = None: every word, by hand. The data
 * (offsets from byte 8) is: 0x00 the empty name; 0x04 "Ref" (length 4, 2 words); 0x0c Ref's
 * typedef (float 3, scalar 0, name 0x04, no semantic, no elements, 1 row, 1 column); 0x28 its
 * value 0.5; 0x2c "T"; 0x34 "P"; 0x3c CullMode's typedef (int 2 as a 1x1 of class 2, fxc's
 * spelling of a DWORD state); 0x58 its value D3DCULL_NONE = 1. Then the structure at 0x5c:
 * 1 parameter, 1 technique, 0 shaders, 1 object id (0, unused); Ref's record (typedef, value,
 * flags, annotations); T (name, annotations, passes); P (name, annotations, states); the state
 * (operation 8 = CullMode in D3DX's table, index 0, typedef, value); no strings, no resources. */
static void tiny_effect_bytes(void) {
    hfxc_result *r = compile("float Ref = 0.5;\ntechnique T { pass P { CullMode = None; } }\n");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    void *data;
    size_t size;
    char err[256];
    CHECK_INT(hfx_fx2_write(fx, "t.fx", NULL, &data, &size, err, sizeof err), 0);
    const uint32_t expect[] = {
        0xfeff0901u, 0x5c,                                   /* magic, the structure's offset */
        0,                                                   /* 0x00: "" */
        4, 0x00666552u,                                      /* 0x04: "Ref" */
        3, 0, 0x04, 0, 0, 1, 1,                              /* 0x0c: float Ref */
        0x3f000000u,                                         /* 0x28: 0.5 */
        2, 0x54,                                             /* 0x2c: "T" */
        2, 0x50,                                             /* 0x34: "P" */
        2, 2, 0, 0, 0, 1, 1,                                 /* 0x3c: int 1x1 */
        1,                                                   /* 0x58: D3DCULL_NONE */
        1, 1, 0, 1,                                          /* 0x5c: counts */
        0x0c, 0x28, 0, 0,                                    /* Ref */
        0x2c, 0, 1,                                          /* technique T */
        0x34, 0, 1,                                          /* pass P */
        8, 0, 0x3c, 0x58,                                    /* CullMode = None */
        0, 0};                                               /* strings, resources */
    check_words(data, size, expect, sizeof expect / 4);
    free(data);
done:
    hfxc_result_free(r);
}

/* A pass naming a sampler and a texture: `Sampler[0] = (S); Texture[1] = <Tex>;`. D3DX reads a
 * sampler-typed value as a block (state count, then records; Wine's d3dx_parse_value and
 * MojoShader's readvalue alike), a texture-typed one as an object id: so Sampler[0]'s value is an
 * empty block (count 0), its resource (usage 1) naming S, and Texture[1]'s is a fresh object id
 * (3) with its resource naming Tex. The data: 0x00 ""; 0x04 "Tex"; 0x0c Tex's typedef (texture 5,
 * object 4, name 0x04); 0x20 its object id 1; 0x24 "S"; 0x2c S's typedef (sampler 10, object 4,
 * name 0x24); 0x40 the typedef of S's Texture record (texture, anonymous); 0x54 its object id 2;
 * 0x58 S's block (1 record: Texture = 164, index 0, 0x40, 0x54); 0x6c "T"; 0x74 "P"; 0x7c the
 * Sampler state's typedef (sampler, anonymous); 0x90 its empty block; 0x94 the Texture state's
 * typedef; 0xa8 its object id 3. The structure at 0xac: 2 parameters, 1 technique, no shaders,
 * 4 object ids (0..3); Tex, S; T; P with 2 states (178 = Sampler index 0; 164 = Texture index 1);
 * no strings; 3 resources: S's Texture record (parameter 1, element 0, state 0) "Tex", the pass's
 * state 0 "S", state 1 "Tex" (technique, pass, element -1, state, usage 1, size, the name). */
static void sampler_and_texture_states_bytes(void) {
    hfxc_result *r = compile("texture Tex;\nsampler S = sampler_state { Texture = <Tex>; };\n"
                             "technique T { pass P { Sampler[0] = (S); Texture[1] = <Tex>; } }\n");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    void *data;
    size_t size;
    char err[256];
    CHECK_INT(hfx_fx2_write(fx, "t.fx", NULL, &data, &size, err, sizeof err), 0);
    const uint32_t none = 0xffffffffu, tex = 0x00786554u, s = 0x53u;
    const uint32_t expect[] = {
        0xfeff0901u, 0xac,         /* magic, the structure's offset */
        0,                         /* 0x00: "" */
        4, tex,                    /* 0x04: "Tex" */
        5, 4, 0x04, 0, 0,          /* 0x0c: texture Tex */
        1,                         /* 0x20: object 1 */
        2, s,                      /* 0x24: "S" */
        10, 4, 0x24, 0, 0,         /* 0x2c: sampler S */
        5, 4, 0, 0, 0,             /* 0x40: its Texture record's typedef */
        2,                         /* 0x54: object 2 */
        1, 164, 0, 0x40, 0x54,     /* 0x58: S's block */
        2, 0x54,                   /* 0x6c: "T" */
        2, 0x50,                   /* 0x74: "P" */
        10, 4, 0, 0, 0,            /* 0x7c: Sampler[0]'s typedef */
        0,                         /* 0x90: an empty sampler block */
        5, 4, 0, 0, 0,             /* 0x94: Texture[1]'s typedef */
        3,                         /* 0xa8: object 3 */
        2, 1, 0, 4,                /* 0xac: counts */
        0x0c, 0x20, 0, 0,          /* Tex */
        0x2c, 0x58, 0, 0,          /* S */
        0x6c, 0, 1,                /* technique T */
        0x74, 0, 2,                /* pass P */
        178, 0, 0x7c, 0x90,        /* Sampler[0] = (S) */
        164, 1, 0x94, 0xa8,        /* Texture[1] = <Tex> */
        0, 3,                      /* strings, resources */
        none, 1, 0, 0, 1, 4, tex,  /* S's Texture = <Tex> */
        0, 0, none, 0, 1, 2, s,    /* Sampler[0] = (S) */
        0, 0, none, 1, 1, 4, tex}; /* Texture[1] = <Tex> */
    check_words(data, size, expect, sizeof expect / 4);
    free(data);
done:
    hfxc_result_free(r);
}

/* The state of sampler leaf `leaf` named `name` (its int value), or -1. */
static int sampler_state_of(const hfx_fx_effect *fx, uint32_t leaf, const char *name) {
    uint32_t si = fx->params[leaf].sampler;
    if (si >= fx->sampler_count) return -1;
    const hfx_fx_sampler *s = &fx->samplers[si];
    for (uint32_t i = 0; i < s->state_count; i++)
        if (fx->states[s->first_state + i].id == state_id(name)) return fx->states[s->first_state + i].i;
    return -1;
}

/* The same pass read back by hfx's reader: Sampler[0] names S (whose block keeps its Texture, so
 * the pass binds S's states and Tex on unit 0, as runtime/gl/passes.c applies it) and Texture[1]
 * names Tex; `<S>` reads as `(S)`. */
static void sampler_states_round_trip(void) {
    hfxc_result *r, *back;
    const hfx_fx_effect *fx = compile_round_trip(
        "texture Tex;\nsampler S = sampler_state { Texture = <Tex>; MinFilter = Point; };\n"
        "sampler S2 = sampler_state { Texture = <Tex>; };\n"
        "technique T { pass P { Sampler[0] = (S); Sampler[2] = <S2>; Texture[1] = <Tex>; } }\n", &r, &back);
    if (fx) {
        uint32_t tex = hfx_fx_param_find(fx, "Tex"), s = hfx_fx_param_find(fx, "S"), s2 = hfx_fx_param_find(fx, "S2");
        CHECK_INT(fx->passes[0].state_count, 3);
        const hfx_fx_state *st = &fx->states[fx->passes[0].first_state];
        CHECK_INT(st[0].id, state_id("Sampler"));
        CHECK_INT(st[0].index, 0);
        CHECK_INT(st[0].kind, HFX_FX_VALUE_PARAM);
        CHECK_INT(st[0].ref, s);
        CHECK_INT(st[1].id, state_id("Sampler"));
        CHECK_INT(st[1].index, 2);
        CHECK_INT(st[1].kind, HFX_FX_VALUE_PARAM);
        CHECK_INT(st[1].ref, s2);
        CHECK_INT(st[2].id, state_id("Texture"));
        CHECK_INT(st[2].index, 1);
        CHECK_INT(st[2].kind, HFX_FX_VALUE_PARAM);
        CHECK_INT(st[2].ref, tex);
        CHECK(fx->params[s].sampler < fx->sampler_count && fx->samplers[fx->params[s].sampler].texture_param == tex);
        CHECK_INT(sampler_state_of(fx, s, "MinFilter"), 1); /* D3DTEXF_POINT */
    }
    hfxc_result_free(back);
    hfxc_result_free(r);
}

/* A state's EXPR program read back, over the effect's values with one word changed. */
static double run_state(const hfx_fx_effect *fx, uint32_t state, uint32_t word, uint32_t value) {
    const hfx_fx_state *st = &fx->states[state];
    uint32_t *values = malloc(fx->value_words * sizeof *values);
    memcpy(values, fx->values, fx->value_words * sizeof *values);
    if (word != HFX_NONE) values[word] = value;
    hfx_ev_value v = {0};
    CHECK_INT(st->kind, HFX_FX_VALUE_EXPR);
    CHECK(hfx_evc_run(fx->exprs + st->ref, st->count, values, &v));
    free(values);
    return v.c[0];
}

static uint32_t fbits(float f) {
    uint32_t w;
    memcpy(&w, &f, 4);
    return w;
}

/* The state of pass 0 with this id. */
static uint32_t find_state(const hfx_fx_effect *fx, const char *name) {
    for (uint32_t i = 0; i < fx->passes[0].state_count; i++)
        if (fx->states[fx->passes[0].first_state + i].id == state_id(name)) return fx->passes[0].first_state + i;
    return HFX_NONE;
}

/* Expressions through FXLVM and back. D3DX computes in float and truncates for a DWORD state:
 * AlphaRef = Ref * 255 is 127 for 0.5 (127.5) and 51 for 0.2 (0.2f * 255 = 51.0000007);
 * StencilRef = Index * 3 - 1 is 5 for 2 and -7 for -2; CullMode = Flip ? 2 : 3 is 2 for true,
 * 3 for false; FillMode = Modes[Sel] with {1, 2, 3} is 2 for 1, and 3 for 5 (the index clamps
 * to the last element as D3D9's relative addressing of an effect's expression does);
 * PointSize = max(Size, 2) is 2 for 1.5 and 3.25 for 3.25. */
static void expressions_round_trip(void) {
    hfxc_result *r, *back;
    const hfx_fx_effect *fx =
        compile_round_trip("float Ref = 0.5; int Index = 2; bool Flip = true; int Modes[3] = {1, 2, 3}; int Sel = 1;\n"
                           "float Size = 1.5;\n"
                           "technique T { pass P { AlphaRef = (Ref * 255); StencilRef = (Index * 3 - 1);\n"
                           "  CullMode = (Flip ? 2 : 3); FillMode = (Modes[Sel]); PointSize = (max(Size, 2.0)); } }\n",
                           &r, &back);
    if (fx) {
        uint32_t ref = fx->params[hfx_fx_param_find(fx, "Ref")].offset, index = fx->params[hfx_fx_param_find(fx, "Index")].offset;
        uint32_t flip = fx->params[hfx_fx_param_find(fx, "Flip")].offset, sel = fx->params[hfx_fx_param_find(fx, "Sel")].offset;
        uint32_t size = fx->params[hfx_fx_param_find(fx, "Size")].offset;
        uint32_t alpha = find_state(fx, "AlphaRef"), stencil = find_state(fx, "StencilRef"), cull = find_state(fx, "CullMode");
        uint32_t fill = find_state(fx, "FillMode"), point = find_state(fx, "PointSize");
        CHECK(alpha != HFX_NONE && stencil != HFX_NONE && cull != HFX_NONE && fill != HFX_NONE && point != HFX_NONE);
        if (alpha != HFX_NONE && stencil != HFX_NONE && cull != HFX_NONE && fill != HFX_NONE && point != HFX_NONE) {
            CHECK_NEAR(run_state(fx, alpha, HFX_NONE, 0), 127, 0);
            CHECK_NEAR(run_state(fx, alpha, ref, fbits(0.2f)), 51, 0);
            CHECK_NEAR(run_state(fx, stencil, HFX_NONE, 0), 5, 0);
            CHECK_NEAR(run_state(fx, stencil, index, (uint32_t)-2), -7, 0);
            CHECK_NEAR(run_state(fx, cull, HFX_NONE, 0), 2, 0);
            CHECK_NEAR(run_state(fx, cull, flip, 0), 3, 0);
            CHECK_NEAR(run_state(fx, fill, HFX_NONE, 0), 2, 0);
            CHECK_NEAR(run_state(fx, fill, sel, 5), 3, 0);
            CHECK_NEAR(run_state(fx, point, HFX_NONE, 0), 2, 0);
            CHECK_NEAR(run_state(fx, point, size, fbits(3.25f)), 3.25, 0);
        }
    }
    hfxc_result_free(back);
    hfxc_result_free(r);
}

/* A sampler array: each element's block follows the one before in the file (readers step from
 * one to the next), so element 1 keeps its own states: MinFilter = Point (D3DTEXF_POINT, 1) on
 * SA[0], AddressU = Wrap (D3DTADDRESS_WRAP, 1) and MagFilter = Linear (2) on SA[1], both on T2. */
static void sampler_array_round_trip(void) {
    hfxc_result *r, *back;
    const hfx_fx_effect *fx = compile_round_trip(
        "texture T2;\nsampler2D SA[2] = { sampler_state { Texture = <T2>; MinFilter = Point; },\n"
        "  sampler_state { Texture = <T2>; AddressU = Wrap; MagFilter = Linear; } };\n"
        "technique T { pass P { CullMode = None; } }\n", &r, &back);
    uint32_t sa = fx ? hfx_fx_param_find(fx, "SA") : HFX_NONE;
    CHECK(sa != HFX_NONE);
    if (sa != HFX_NONE) {
        uint32_t e0 = fx->params[sa].first_child, e1 = e0 + 1, t2 = hfx_fx_param_find(fx, "T2");
        CHECK_INT(fx->params[sa].child_count, 2);
        CHECK_INT(sampler_state_of(fx, e0, "MinFilter"), 1);
        CHECK_INT(sampler_state_of(fx, e0, "AddressU"), -1);
        CHECK_INT(sampler_state_of(fx, e1, "AddressU"), 1);
        CHECK_INT(sampler_state_of(fx, e1, "MagFilter"), 2);
        CHECK_INT(sampler_state_of(fx, e1, "MinFilter"), -1);
        CHECK(fx->params[e0].sampler < fx->sampler_count && fx->samplers[fx->params[e0].sampler].texture_param == t2);
        CHECK(fx->params[e1].sampler < fx->sampler_count && fx->samplers[fx->params[e1].sampler].texture_param == t2);
    }
    hfxc_result_free(back);
    hfxc_result_free(r);
}

/* An expression FXLVM cannot say (a shift): a located error, nothing written. */
static void inexpressible_expression(void) {
    hfxc_result *r = compile("int Index = 2;\ntechnique T { pass P {\n  StencilRef = (Index << 2); } }\n");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        char err[512];
        void *data = NULL;
        size_t size = 0;
        CHECK_INT(hfx_fx2_write(fx, "t.fx", NULL, &data, &size, err, sizeof err), -1);
        CHECK(data == NULL);
        CHECK_STR(err, "t.fx(3,3): error X9011: state StencilRef: bit operations have no form in fxc's expressions");
    }
    hfxc_result_free(r);
}

/* Passes that set states alone, or NULL shaders: read back with no program, every state kept. */
static void null_shaders_and_state_only_passes(void) {
    hfxc_result *r, *back;
    const hfx_fx_effect *fx =
        compile_round_trip("technique T { pass A { ZEnable = false; AlphaBlendEnable = true; SrcBlend = SrcAlpha; }\n"
                           "  pass B { VertexShader = NULL; PixelShader = NULL; CullMode = CW; } }\n", &r, &back);
    if (fx) {
        CHECK_INT(fx->pass_count, 2);
        CHECK_INT(fx->passes[0].program, HFX_NONE);
        CHECK_INT(fx->passes[1].program, HFX_NONE);
        CHECK_INT(fx->passes[0].state_count, 3);
        const hfx_fx_state *a = &fx->states[fx->passes[0].first_state];
        CHECK_INT(a[0].id, state_id("ZEnable"));
        CHECK_INT(a[0].i, 0);
        CHECK_INT(a[1].id, state_id("AlphaBlendEnable"));
        CHECK_INT(a[1].i, 1);
        CHECK_INT(a[2].id, state_id("SrcBlend"));
        CHECK_INT(a[2].i, 5); /* D3DBLEND_SRCALPHA */
        CHECK_INT(fx->passes[1].state_count, 3);
        const hfx_fx_state *b = &fx->states[fx->passes[1].first_state];
        CHECK_INT(b[0].id, state_id("VertexShader"));
        CHECK_INT(b[0].kind, HFX_FX_VALUE_PROGRAM);
        CHECK_INT(b[0].ref, HFX_NONE);
        CHECK_INT(b[1].id, state_id("PixelShader"));
        CHECK_INT(b[2].i, 2); /* D3DCULL_CW */
        CHECK_INT(fx->program_count, 0);
    }
    hfxc_result_free(back);
    hfxc_result_free(r);
}

/* The bytecode hook: fxb_builder's hand-assembled vs_2_0 pass-through and ps_2_0 colour. */
typedef struct tokens {
    fxb vs, ps;
    int calls;
} tokens;

static int hook(void *ctx, const hfx_fx_effect *fx, uint32_t program, int stage, const void **data, size_t *size, char *err,
                size_t err_size) {
    tokens *t = ctx;
    (void)fx, (void)program, (void)err, (void)err_size;
    t->calls++;
    *data = stage ? t->ps.d : t->vs.d;
    *size = stage ? t->ps.n : t->vs.n;
    return 0;
}

static int refusing_hook(void *ctx, const hfx_fx_effect *fx, uint32_t program, int stage, const void **data, size_t *size,
                         char *err, size_t err_size) {
    (void)ctx, (void)fx, (void)program, (void)stage, (void)data, (void)size;
    snprintf(err, err_size, "no back end");
    return -1;
}

/* A compiled source's shaders come from the hook until the D3D9 back end fills the programs:
 * the written effect reads back with the hook's bytecode in its program, and the program's
 * pixel shader writes the colour the ps_2_0's def gives (0.25, 0.75, 0, 1 in its GLSL). */
static void shaders_from_the_hook(void) {
    hfxc_result *r = compile("float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                             "float4 PS() : COLOR { return float4(0.25, 0.75, 0, 1); }\n"
                             "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n");
    const hfx_fx_effect *src = hfxc_result_effect(r);
    CHECK(src != NULL);
    if (!src) goto done;
    tokens t = {0};
    fxb_vs_passthrough(&t.vs);
    fxb_ps_colour(&t.ps, 0.25f, 0.75f);
    hfx_fx2_write_options opt = {hook, &t, 0};
    hfxc_result *back = round_trip(src, &opt, NULL, NULL);
    CHECK_INT(t.calls, 2);
    const hfx_fx_effect *fx = hfxc_result_effect(back);
    CHECK(fx != NULL);
    if (fx) {
        CHECK_INT(fx->program_count, 1);
        CHECK(fx->passes[0].program == 0);
        const hfx_fx_program *p = &fx->programs[0];
        CHECK_INT(p->d3d9[0].size, t.vs.n);
        CHECK_INT(p->d3d9[1].size, t.ps.n);
        CHECK(p->d3d9[0].data && memcmp(p->d3d9[0].data, t.vs.d, t.vs.n) == 0);
        CHECK(p->d3d9[1].data && memcmp(p->d3d9[1].data, t.ps.d, t.ps.n) == 0);
        CHECK(p->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data != NULL);
        CHECK_CONTAINS(p->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data, "0.75");
    }
    hfxc_result_free(back);
    /* a hook that has no bytecode: the write fails at the shader's state */
    hfx_fx2_write_options refuse = {refusing_hook, NULL, 0};
    char err[512];
    void *data = NULL;
    size_t size;
    CHECK_INT(hfx_fx2_write(src, "t.fx", &refuse, &data, &size, err, sizeof err), -1);
    CHECK_STR(err, "t.fx(3,24): error X9011: vertex shader: no back end");
    free(t.vs.d);
    free(t.ps.d);
done:
    hfxc_result_free(r);
}

/* A pass that names no shader keeps the previous pass's, as a D3D9 device keeps its shaders
 * (DigitalRise's terrain effects: pass Restore { FillMode = SOLID; CullMode = CCW; } after
 * a wireframe pass): the reader gives pass B pass A's program, C (= NULL) none, D (after C)
 * none, and the next technique's first pass starts with nothing held, as the builder does for
 * the source. */
static void state_only_passes_keep_the_shaders(void) {
    static const char text[] =
        "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
        "float4 PS() : COLOR { return float4(0.25, 0.75, 0, 1); }\n"
        "technique T { pass A { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); }\n"
        "  pass B { CullMode = CW; } pass C { VertexShader = NULL; PixelShader = NULL; } pass D { ZEnable = false; } }\n"
        "technique U { pass E { CullMode = None; } }\n";
    hfxc_result *r = compile(text);
    const hfx_fx_effect *src = hfxc_result_effect(r);
    CHECK(src != NULL);
    if (!src) goto done;
    CHECK(src->passes[1].program == src->passes[0].program); /* the builder's rule, the reference */
    tokens t = {0};
    fxb_vs_passthrough(&t.vs);
    fxb_ps_colour(&t.ps, 0.25f, 0.75f);
    hfx_fx2_write_options opt = {hook, &t, 0};
    hfxc_result *back = round_trip(src, &opt, NULL, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(back);
    CHECK(fx != NULL);
    if (fx) {
        CHECK_INT(fx->pass_count, 5);
        CHECK_INT(fx->program_count, 1);
        CHECK_INT(fx->passes[0].program, 0);
        CHECK_INT(fx->passes[1].program, 0);
        CHECK_INT(fx->passes[1].state_count, 1); /* CullMode alone: the kept program is no state */
        CHECK_INT(fx->passes[2].program, HFX_NONE);
        CHECK_INT(fx->passes[3].program, HFX_NONE);
        CHECK_INT(fx->passes[4].program, HFX_NONE);
    }
    hfxc_result_free(back);
    free(t.vs.d);
    free(t.ps.d);
done:
    hfxc_result_free(r);
}

/* hfxc_result_fx2 (the library's /T fx_2_0 /Fo): without HFXC_D3D9_BYTECODE the programs have no
 * shader to write, and the refusal says so at the pass's compile; with it, the container's
 * version is fx_2_0's (0xFEFF0901) and its pixel shader is ps_2_0 bytecode (0xFFFF0200). */
static void compiled_sources_need_the_back_end(void) {
    static const char src[] = "float4 PS() : COLOR { return 1; }\ntechnique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    hfxc_result *r = compile(src);
    size_t size = 1;
    char *why = NULL;
    void *data = hfxc_result_fx2(r, 0, &size, &why);
    CHECK(data == NULL && size == 0);
    CHECK_STR(why ? why : "", "t.fx(2,24): error X9011: pixel shader: no Direct3D 9 bytecode for this shader: compile "
                              "with HFXC_D3D9_BYTECODE");
    free(why);
    hfxc_result_free(r);
    hfxc_options o = {.flags = HFXC_D3D9_BYTECODE};
    r = hfxc_compile_memory(src, sizeof src - 1, "t.fx", &o);
    data = hfxc_result_fx2(r, 0, &size, &why);
    CHECK(data != NULL && size > 8 && why == NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx && fx->program_count == 1 && fx->programs[0].d3d9[HFX_STAGE_FRAGMENT].size >= 4);
    if (data) CHECK_INT(hfx_le32(data), 0xFEFF0901u);
    if (fx && fx->program_count == 1 && fx->programs[0].d3d9[HFX_STAGE_FRAGMENT].size >= 4)
        CHECK_INT(hfx_le32((const uint8_t *)fx->programs[0].d3d9[HFX_STAGE_FRAGMENT].data), 0xFFFF0200u);
    free(data);
    free(why);
    hfxc_result_free(r);
    CHECK(hfxc_result_fx2(NULL, 0, &size, &why) == NULL && why == NULL); /* no result, nothing to say */
}

/* data (an fxc container) read, written, read: the same listing, values and variants. */
static void same_after_rewrite(const void *data, size_t size, const char *name) {
    char *diags = NULL, *before = hfxc_disassemble(data, size, name, &diags);
    free(diags);
    hfxc_result *r = hfxc_compile_memory(data, size, name, &packed);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(before != NULL);
    CHECK(fx != NULL);
    if (!fx || !before) {
        fprintf(stderr, "  %s does not load\n", name);
        goto done;
    }
    void *again;
    size_t again_size;
    hfxc_result *back = round_trip(fx, NULL, &again, &again_size);
    const hfx_fx_effect *gx = hfxc_result_effect(back);
    CHECK(gx != NULL);
    if (gx) {
        char *after = hfxc_disassemble(again, again_size, name, &diags);
        free(diags);
        CHECK(after != NULL);
        if (after && strcmp(before, after) != 0) {
            size_t k = 0, line = 1;
            for (; before[k] && before[k] == after[k]; k++) line += before[k] == '\n';
            fprintf(stderr, "  %s: the listing differs after writing, line %zu:\n  %.80s\n  %.80s\n", name, line,
                    before + k - (k > 20 ? 20 : k), after + k - (k > 20 ? 20 : k));
        }
        CHECK(after && strcmp(before, after) == 0);
        free(after);
        CHECK_INT(gx->param_count, fx->param_count);
        CHECK_INT(gx->value_words, fx->value_words);
        CHECK(memcmp(gx->values, fx->values, fx->value_words * 4) == 0);
        CHECK_INT(gx->state_count, fx->state_count);
        CHECK_INT(gx->program_count, fx->program_count);
        CHECK_INT(gx->variant_count, fx->variant_count);
        for (uint32_t i = 0; i < fx->variant_count && i < gx->variant_count; i++) {
            CHECK_INT(gx->variants[i].vs, fx->variants[i].vs);
            CHECK_INT(gx->variants[i].ps, fx->variants[i].ps);
        }
        for (uint32_t i = 0; i < fx->program_count && i < gx->program_count; i++)
            for (int s = 0; s < HFX_STAGE_COUNT; s++) {
                CHECK_INT(gx->programs[i].d3d9[s].size, fx->programs[i].d3d9[s].size);
                CHECK(!fx->programs[i].d3d9[s].size || gx->programs[i].d3d9[s].size != fx->programs[i].d3d9[s].size ||
                      memcmp(gx->programs[i].d3d9[s].data, fx->programs[i].d3d9[s].data, fx->programs[i].d3d9[s].size) == 0);
            }
    }
    free(again);
    hfxc_result_free(back);
done:
    hfxc_result_free(r);
    free(before);
}

static void hand_laid_containers_round_trip(void) {
    size_t size;
    uint8_t *f = fxb_sample_file(&size, NULL, 0); /* (its selector's array has no bytecode: no programs) */
    same_after_rewrite(f, size, "sample.fxb");
    free(f);
    f = fxb_shader_file(&size);
    same_after_rewrite(f, size, "shaders.fxb");
    free(f);
}

/* HFX_FX2_SAMPLES: every .fxb / .efb / .fxo of a folder (fxc's own binaries). */
static void sample_folder_round_trip(void) {
    const char *dir = getenv("HFX_FX2_SAMPLES");
    DIR *d = dir ? opendir(dir) : NULL;
    if (!d) {
        fprintf(stderr, "  (fxc's binaries: set HFX_FX2_SAMPLES to a folder of them; scripts/fx2_roundtrip.sh does)\n");
        return;
    }
    int count = 0;
    for (struct dirent *e; (e = readdir(d));) {
        const char *dot = strrchr(e->d_name, '.');
        if (!dot || (strcmp(dot, ".fxb") && strcmp(dot, ".efb") && strcmp(dot, ".fxo"))) continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        size_t size;
        char *data = test_read_file(path, &size);
        if (!data) continue;
        /* binaries hfx's reader does not load (int preshader outputs) are the reader's business */
        hfxc_result *probe = hfxc_compile_memory(data, size, e->d_name, &packed);
        if (hfxc_result_effect(probe)) same_after_rewrite(data, size, e->d_name), count++;
        hfxc_result_free(probe);
        free(data);
    }
    closedir(d);
    fprintf(stderr, "  %d of fxc's binaries rewritten\n", count);
}

int main(void) {
    RUN(tiny_effect_bytes);
    RUN(sampler_and_texture_states_bytes);
    RUN(sampler_states_round_trip);
    RUN(expressions_round_trip);
    RUN(inexpressible_expression);
    RUN(sampler_array_round_trip);
    RUN(null_shaders_and_state_only_passes);
    RUN(shaders_from_the_hook);
    RUN(state_only_passes_keep_the_shaders);
    RUN(compiled_sources_need_the_back_end);
    RUN(hand_laid_containers_round_trip);
    RUN(sample_folder_round_trip);
    return test_summary();
}
