/* The fx_2_0 reader (compiler/effect/fx2_*.c, fxlvm.c) on containers laid out by hand
 * (support/fx2_builder.h): every parameter type with its annotations, semantic and default
 * words; the sampler and its texture; the technique, passes and states with D3D9's numbers;
 * the expressions (AlphaRef = Ref * 255, a shader picked by VSIndices[ShaderIndex]) run with
 * values worked out by hand; and the located errors of spoiled files, with their exact text. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "effect/fx2.h"
#include "effect/fx2_int.h"
#include "eval_code.h"
#include "fx2_builder.h"
#include "hfx/hfxc.h"
#include "states.h"
#include "test.h"

static float fword(uint32_t w) {
    float f;
    memcpy(&f, &w, sizeof f);
    return f;
}

static uint32_t state_id(const char *name) { return hfx_state_lookup(name)->id; }

/* A state's EXPR program over these values: the first component. */
static double run(const hfx_fx_effect *fx, const hfx_fx_state *st, const uint32_t *values) {
    hfx_ev_value v;
    CHECK_INT(st->kind, HFX_FX_VALUE_EXPR);
    CHECK_INT(hfx_evc_validate(fx->exprs + st->ref, st->count, fx->value_words, NULL, 0), 0);
    CHECK(hfx_evc_run(fx->exprs + st->ref, st->count, values, &v));
    return v.c[0];
}

static void parameters_reflect_the_file(void) {
    size_t size;
    uint8_t *file = fxb_sample_file(&size, NULL, 0);
    hfxc_result *r = hfxc_compile_memory((const char *)file, size, "t.fxb", NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) {
        char *t = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s", t);
        free(t);
        goto done;
    }
    /* 12 top-level, then the children breadth first: Weights[3] 12-14, St's a, b 15-16,
     * VSIndices[3] 17-19, VSArray[2] 20-21 */
    CHECK_INT(fx->top_param_count, 12);
    CHECK_INT(fx->param_count, 22);
    const hfx_fx_param *color = &fx->params[0], *world = &fx->params[1], *weights = &fx->params[3], *st = &fx->params[4];
    CHECK_STR(color->name, "Color");
    CHECK_STR(color->semantic, "DIFFUSE");
    CHECK_INT(color->klass, HFX_CLASS_VECTOR);
    CHECK_INT(color->type, HFX_TYPE_FLOAT);
    CHECK_INT(color->rows, 1);
    CHECK_INT(color->cols, 4);
    CHECK_INT(color->offset, 0);
    CHECK_NEAR(fword(fx->values[2]), 0.75, 0);
    CHECK_INT(color->annotation_count, 2);
    const hfx_fx_annotation *a = &fx->annotations[color->first_annotation];
    CHECK_STR(a[0].name, "UIName");
    CHECK_INT(a[0].type, HFX_TYPE_STRING);
    CHECK_STR(a[0].string, "Tint");
    CHECK_STR(a[1].name, "UIMin");
    CHECK_INT(a[1].count, 1);
    CHECK_NEAR(fword(a[1].data[0]), 0.5, 0);
    /* World: row_major float4x4 = 1..16 in row-major words after Color's 4 */
    CHECK_INT(world->klass, HFX_CLASS_MATRIX);
    CHECK_INT(world->rows * 10 + world->cols, 44);
    CHECK_INT(world->flags & HFX_FX_PARAM_ROW_MAJOR, HFX_FX_PARAM_ROW_MAJOR);
    CHECK_INT(world->offset, 4);
    CHECK_NEAR(fword(fx->values[4 + 12]), 13, 0); /* row 3, column 0 */
    CHECK_INT(fx->params[2].offset, 20);
    CHECK_INT((int32_t)fx->values[20], 2); /* Index */
    CHECK_INT(weights->elements, 3);
    CHECK_INT(weights->child_count, 3);
    CHECK_INT(weights->first_child, 12);
    CHECK_STR(fx->params[13].name, "Weights");
    CHECK_INT(fx->params[13].offset, 22);
    CHECK_NEAR(fword(fx->values[22]), 2, 0);
    CHECK_INT(st->klass, HFX_CLASS_STRUCT);
    CHECK_INT(st->words, 3);
    CHECK_INT(st->first_child, 15);
    CHECK_STR(fx->params[16].name, "b");
    CHECK_INT(fx->params[16].cols, 2);
    CHECK_INT(fx->params[16].offset, 25);
    CHECK_NEAR(fword(fx->values[26]), 9, 0);
    CHECK_STR(fx->params[5].string, "hello");
    CHECK_INT(fx->params[6].type, HFX_TYPE_TEXTURE2D);
    CHECK_INT(fx->params[11].type, HFX_TYPE_VERTEXSHADER);
    CHECK_INT(fx->value_words, 32);
    /* the sampler: Texture = <Tex> is its field; MinFilter = Linear (2), AddressU = Clamp (3) */
    CHECK_INT(fx->sampler_count, 1);
    const hfx_fx_sampler *s = &fx->samplers[0];
    CHECK_INT(s->param, 7);
    CHECK_INT(fx->params[7].sampler, 0);
    CHECK_INT(s->texture_param, 6);
    CHECK_INT(s->dim, HFX_FX_DIM_2D);
    CHECK_INT(s->state_count, 2);
    CHECK_INT(fx->states[s->first_state].id, state_id("MinFilter"));
    CHECK_INT(fx->states[s->first_state].i, 2);
    CHECK_INT(fx->states[s->first_state + 1].id, state_id("AddressU"));
    CHECK_INT(fx->states[s->first_state + 1].i, 3);
done:
    hfxc_result_free(r);
    free(file);
}

static void passes_and_states(void) {
    size_t size;
    uint8_t *file = fxb_sample_file(&size, NULL, 0);
    hfxc_result *r = hfxc_compile_memory((const char *)file, size, "t.fxb", NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    CHECK_INT(fx->technique_count, 1);
    CHECK_STR(fx->techniques[0].name, "T");
    CHECK_INT(fx->techniques[0].annotation_count, 1);
    CHECK_STR(fx->annotations[fx->techniques[0].first_annotation].name, "Order");
    CHECK_INT((int32_t)fx->annotations[fx->techniques[0].first_annotation].data[0], 3);
    const hfx_fx_pass *p = &fx->passes[0];
    CHECK_STR(p->name, "P0");
    CHECK_STR(fx->annotations[p->first_annotation].string, "x");
    CHECK_INT(p->program, HFX_NONE);
    CHECK_INT(p->state_count, 6);
    const hfx_fx_state *st = &fx->states[p->first_state];
    CHECK_INT(st[0].id, state_id("CullMode"));
    CHECK_INT(st[0].kind, HFX_FX_VALUE_INT);
    CHECK_INT(st[0].i, 1); /* D3DCULL_NONE */
    CHECK_INT(st[1].id, state_id("ZEnable"));
    CHECK_INT(st[1].i, 0);
    CHECK_INT(st[2].id, state_id("BlendFactor"));
    CHECK_INT(st[2].kind, HFX_FX_VALUE_FLOAT);
    CHECK_INT(st[2].count, 4);
    CHECK_NEAR(st[2].f[1], 0.25, 0);
    /* AlphaRef = Ref * 255: 0.5 * 255 = 127.5, an int state: 127 (truncated, as D3DX converts) */
    CHECK_INT(st[3].id, state_id("AlphaRef"));
    CHECK_NEAR(run(fx, &st[3], fx->values), 127, 0);
    uint32_t values[32];
    memcpy(values, fx->values, sizeof values);
    float ref = 0.2f; /* 0.2 * 255 = 51.0000007...: 51 */
    memcpy(&values[27], &ref, 4);
    CHECK_NEAR(run(fx, &st[3], values), 51, 0);
    CHECK_INT(st[4].id, state_id("Texture"));
    CHECK_INT(st[4].index, 0);
    CHECK_INT(st[4].kind, HFX_FX_VALUE_PARAM);
    CHECK_INT(st[4].ref, 6);
    CHECK_INT(st[5].id, state_id("StencilRef"));
    CHECK_INT(st[5].kind, HFX_FX_VALUE_PARAM);
    CHECK_INT(st[5].ref, 2);
    /* the model the reader made is a valid .hfxo */
    void *bytes;
    size_t n;
    CHECK_INT(hfx_fx_write_hfxo(fx, &bytes, &n), 0);
    char err[256] = "";
    hfx_fx_effect *back = hfx_fx_read_hfxo(bytes, n, err, sizeof err);
    CHECK_STR(err, "");
    CHECK(back != NULL);
    hfx_fx_effect_free(back);
    free(bytes);
done:
    hfxc_result_free(r);
    free(file);
}

/* Decoded without programs (as listings are): VertexShader = (VSArray[VSIndices[ShaderIndex]])
 * is an index: VSIndices = {1, 0, 1}; ShaderIndex 2 gives 1, 1 gives 0, 7 is clamped to 2: 1. */
static void shader_selector_is_an_index(void) {
    size_t size;
    uint8_t *file = fxb_sample_file(&size, NULL, 1);
    hfx_arena arena;
    hfx_arena_init(&arena);
    hfx_diags diags;
    hfx_diags_init(&diags, &arena, 0);
    hfx_fx_effect *fx = hfx_fx2_read(&arena, &diags, "t.fxb", NULL, file, size, 1, HFX_FX2_DECODE_ONLY);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_pass *p1 = &fx->passes[1];
        CHECK_STR(p1->name, "P1");
        const hfx_fx_state *vs = &fx->states[p1->first_state];
        CHECK_INT(vs->id, state_id("VertexShader"));
        uint32_t values[32];
        memcpy(values, fx->values, sizeof values);
        CHECK_NEAR(run(fx, vs, values), 1, 0);
        values[31] = 1;
        CHECK_NEAR(run(fx, vs, values), 0, 0);
        values[31] = 7;
        CHECK_NEAR(run(fx, vs, values), 1, 0);
    }
    hfx_fx_effect_free(fx);
    /* loaded for real, the array's entries have no bytecode: a located error, no effect */
    hfxc_result *r = hfxc_compile_memory((const char *)file, size, "t.fxb", NULL);
    char *text = hfxc_diagnostics_text(r);
    CHECK(!hfxc_result_ok(r));
    CHECK_CONTAINS(text, "error X9010: pass 'P1': the shader array entries it picks have no bytecode");
    free(text);
    hfxc_result_free(r);
    hfx_arena_free(&arena);
    free(file);
}

/* The text of reading these bytes. */
static char *errors_named(const uint8_t *file, size_t size, const char *name) {
    hfxc_result *r = hfxc_compile_memory((const char *)file, size, name, NULL);
    char *text = hfxc_diagnostics_text(r);
    CHECK(!hfxc_result_ok(r));
    CHECK(hfxc_result_effect(r) == NULL);
    hfxc_result_free(r);
    return text;
}

static char *errors_of(const uint8_t *file, size_t size) { return errors_named(file, size, "t.fxb"); }

static void put32(uint8_t *file, uint32_t at, uint32_t v) {
    for (int i = 0; i < 4; i++) file[at + i] = (uint8_t)(v >> (8 * i));
}

static void spoiled_files_give_located_errors(void) {
    size_t size;
    fxb_sample w;
    uint8_t *file = fxb_sample_file(&size, &w, 1);
    uint8_t *copy = malloc(size);
    char expect[256], *text;
    /* cut inside the header's counts: the shader count's word is at 8 + start + 8 */
    memcpy(copy, file, size);
    text = errors_of(copy, 8 + w.start + 10);
    snprintf(expect, sizeof expect, "t.fxb(0,%u): error X9010: header: the data ends at %u (truncated)\n", 8 + w.start + 8,
             8 + w.start + 10);
    CHECK_STR(text, expect);
    free(text);
    /* Color's name offset far outside */
    memcpy(copy, file, size);
    put32(copy, 8 + w.color_type + 8, 0x7fffffffu);
    text = errors_of(copy, size);
    snprintf(expect, sizeof expect, "t.fxb(0,%u): error X9010: type name: offset 2147483647 is past the end of the data "
             "(%u bytes)\n", 8 + w.color_type + 8, (unsigned)size - 8);
    CHECK_STR(text, expect);
    free(text);
    /* a sampler state that is no sampler state */
    memcpy(copy, file, size);
    put32(copy, 8 + w.samp_texture, 200);
    text = errors_of(copy, size);
    snprintf(expect, sizeof expect, "t.fxb(0,%u): error X9010: sampler 'Samp': operation 200 is not a sampler state\n",
             8 + w.samp_texture);
    CHECK_STR(text, expect);
    free(text);
    /* an unknown pass state */
    memcpy(copy, file, size);
    put32(copy, 8 + w.pass_states, 500);
    text = errors_of(copy, size);
    snprintf(expect, sizeof expect, "t.fxb(0,%u): error X9010: unknown state operation 500\n", 8 + w.pass_states);
    CHECK_STR(text, expect);
    free(text);
    /* a resource for a sampler state that is not there */
    memcpy(copy, file, size);
    put32(copy, 8 + w.resources + 12, 9);
    text = errors_of(copy, size);
    snprintf(expect, sizeof expect, "t.fxb(0,%u): error X9010: resource: state 9 of sampler 'Samp' (3 states)\n",
             8 + w.resources + 12);
    CHECK_STR(text, expect);
    free(text);
    /* an object id past the object table (Samp's Texture value: object 3 -> 99) */
    memcpy(copy, file, size);
    put32(copy, 8 + w.start + 12, 3); /* three objects: the string of id 10 is outside */
    text = errors_of(copy, size);
    CHECK_CONTAINS(text, "error X9010: ");
    CHECK_CONTAINS(text, "is outside the object table (3 objects)");
    free(text);
    /* not fx_2_0: the reader's first check */
    hfx_arena arena;
    hfx_arena_init(&arena);
    hfx_diags diags;
    hfx_diags_init(&diags, &arena, 0);
    memcpy(copy, file, size);
    put32(copy, 0, 0x12345678u);
    CHECK(hfx_fx2_read(&arena, &diags, "t.fxb", NULL, copy, size, 1, 0) == NULL);
    text = hfx_diags_format(&diags, 0);
    CHECK_STR(text, "t.fxb(0,0): error X9010: not an fx_2_0 effect (the first word is 0x12345678, fxc's effects start "
                    "with 0xfeff0901)\n");
    free(text);
    hfx_arena_free(&arena);
    free(copy);
    free(file);
}

/* Every prefix of the file is refused with an error, never read past (ASan watches). */
static void every_truncation_is_an_error(void) {
    size_t size;
    uint8_t *file = fxb_sample_file(&size, NULL, 0);
    for (size_t n = 4; n < size; n++) {
        uint8_t *copy = malloc(n); /* exactly n bytes: a read past them is ASan's */
        memcpy(copy, file, n);
        hfxc_result *r = hfxc_compile_memory((const char *)copy, n, "t.fxb", NULL);
        if (hfxc_result_ok(r)) fprintf(stderr, "a file cut at %zu bytes was read\n", n);
        CHECK(!hfxc_result_ok(r));
        hfxc_result_free(r);
        free(copy);
    }
    free(file);
}

/* XNA 4's .xnb around the same effect (uncompressed); a compressed one is refused. */
static void xnb_files(void) {
    size_t size;
    uint8_t *fx = fxb_sample_file(&size, NULL, 0);
    static const char reader[] = "Microsoft.Xna.Framework.Content.EffectReader, Microsoft.Xna.Framework.Graphics";
    size_t rn = sizeof reader - 1, n = 10 + 1 + 1 + rn + 4 + 1 + 1 + 4 + size;
    uint8_t *x = calloc(1, n), *p = x;
    memcpy(p, "XNBw\x05\x01", 6), p += 6;  /* platform w, version 5, HiDef */
    put32(p - 0, 0, (uint32_t)n), p += 4;
    *p++ = 1;                               /* one type reader */
    *p++ = (uint8_t)rn, memcpy(p, reader, rn), p += rn;
    put32(p, 0, 0), p += 4;                 /* its version */
    *p++ = 0;                               /* shared resources */
    *p++ = 1;                               /* the object: reader 1 */
    put32(p, 0, (uint32_t)size), p += 4;
    memcpy(p, fx, size);
    hfxc_result *r = hfxc_compile_memory((const char *)x, n, "t.xnb", NULL);
    CHECK(hfxc_result_ok(r));
    const hfx_fx_effect *e = hfxc_result_effect(r);
    CHECK(e && e->param_count == 22);
    hfxc_result_free(r);
    x[5] = 0x81; /* compressed with LZX */
    char *text = errors_named(x, n, "t.xnb");
    CHECK_STR(text, "t.xnb(0,5): error X9010: xnb: the content is compressed (LZX); hfx reads uncompressed .xnb files "
                    "(build the content without compression)\n");
    free(text);
    free(x);
    free(fx);
}

/* hfxc --disassemble's listing of the test effect, line by line as fx2_builder.h lays it out:
 * D3DTEXF_LINEAR 2 and D3DTADDRESS_CLAMP 3 by their names, D3DCULL_NONE 1, the expressions as
 * FXLVM instructions (mul by the literal 255; the selector's relative read c[0 + c3.x]). */
static void listing_of_the_test_effect(void) {
    size_t size;
    uint8_t *file = fxb_sample_file(&size, NULL, 1);
    char *diags = NULL, *text = hfxc_disassemble(file, size, "t.fxb", &diags);
    CHECK_STR(diags, "");
    CHECK_STR(text,
        "//\n"
        "// FX Version: fx_2_0\n"
        "// Child effect (requires effect pool): false\n"
        "//\n"
        "// 12 local parameter(s)\n"
        "//\n"
        "float4 Color : DIFFUSE\n"
        "<\n"
        "    string UIName = \"Tint\";\n"
        "    float UIMin = 0.5;\n"
        ">\n"
        " = { 0.25, 0.5, 0.75, 1 };\n"
        "\n"
        "row_major float4x4 World = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16 };\n"
        "\n"
        "int Index = 2;\n"
        "\n"
        "float Weights[3] = { 1, 2, 3 };\n"
        "\n"
        "struct { float a; float2 b; } St = { 7, 8, 9 };\n"
        "\n"
        "string Name = \"hello\";\n"
        "\n"
        "texture2D Tex;\n"
        "\n"
        "sampler2D Samp = sampler_state\n"
        "{\n"
        "    Texture = <Tex>;\n"
        "    MinFilter = Linear;\n"
        "    AddressU = Clamp;\n"
        "};\n"
        "\n"
        "float Ref = 0.5;\n"
        "\n"
        "int VSIndices[3] = { 1, 0, 1 };\n"
        "\n"
        "int ShaderIndex = 2;\n"
        "\n"
        "vertexshader VSArray[2] =\n"
        "    // VSArray[0]\n"
        "    NULL,\n"
        "    // VSArray[1]\n"
        "    NULL;\n"
        "\n"
        "//\n"
        "// 1 technique(s)\n"
        "//\n"
        "technique T\n"
        "<\n"
        "    int Order = 3;\n"
        ">\n"
        "{\n"
        "    pass P0\n"
        "    <\n"
        "        string Mode = \"x\";\n"
        "    >\n"
        "    {\n"
        "        CullMode = None;\n"
        "        ZEnable = False;\n"
        "        BlendFactor = float4(0.5, 0.25, 1, 0);\n"
        "        AlphaRef = \n"
        "            expression {\n"
        "                mul oc0.x, c0.x, (255)\n"
        "            };\n"
        "        Texture[0] = <Tex>;\n"
        "        StencilRef = <Index>;\n"
        "    }\n"
        "    pass P1\n"
        "    {\n"
        "        VertexShader = VSArray[\n"
        "            expression {\n"
        "                mov oc0.x, c[0 + c3.x].x\n"
        "            }];\n"
        "    }\n"
        "}\n"
        "\n");
    free(text);
    free(diags);
    /* a spoiled file: no listing, the reader's located error */
    file[7] = 0x7f; /* the structure far past the end */
    text = hfxc_disassemble(file, size, "t.fxb", &diags);
    CHECK(text == NULL);
    CHECK_CONTAINS(diags, "t.fxb(0,");
    CHECK_CONTAINS(diags, "error X9010:");
    free(text);
    free(diags);
    free(file);
}

/* A reader over an effect of two float parameters, A and B (values words 0 and 1), for fxlvm.c
 * alone. */
static void open_reader(fx2_reader *r, hfx_arena *arena, hfx_diags *diags) {
    hfx_arena_init(arena);
    hfx_diags_init(diags, arena, 0);
    *r = (fx2_reader){0};
    r->arena = arena;
    r->diags = diags;
    r->file = hfx_diags_add_file(diags, "t.fxb", NULL, NULL, 0);
    r->fx = calloc(1, sizeof *r->fx);
    r->fx->params = calloc(2, sizeof *r->fx->params);
    r->fx->param_count = r->fx->top_param_count = 2;
    const char *names[2] = {"A", "B"};
    for (uint32_t i = 0; i < 2; i++)
        r->fx->params[i] = (hfx_fx_param){.name = strdup(names[i]), .klass = HFX_CLASS_SCALAR, .type = HFX_TYPE_FLOAT,
                                           .rows = 1, .cols = 1, .parent = HFX_NONE, .offset = i, .words = 1,
                                           .sampler = HFX_NONE};
    r->fx->value_words = 2;
}

/* The first component of preshader output o run with A = a. */
static double run_output(const d3d9_preshader_out *o, float a) {
    uint32_t values[2] = {0, 0};
    memcpy(values, &a, 4);
    hfx_ev_value out;
    CHECK(hfx_evc_run(o->code, o->words, values, &out));
    CHECK_INT(out.n, 4);
    return out.c[0];
}

/* A preshader setting a bool and an int register besides a float one (fxc's ob# and oi#, which
 * DigitalRune's ColorEncoder uses for `if b#`), with A in c0:
 *     cmp ob0.x, c0.x, (0), (1);  add oi1.x, c0.x, (2);  mov oc2.x, c0.x
 * Outputs: c2 first, then b0, then i1, each 4 floats (unwritten components 0). A = -1.5: b0.x =
 * 1 (cmp picks its third input when the first is negative), i1.x = 0.5, c2.x = -1.5; A = 0.5:
 * b0.x = 0, i1.x = 2.5. */
static void fxlvm_bool_and_int_outputs(void) {
    hfx_arena arena;
    hfx_diags diags;
    fx2_reader r;
    open_reader(&r, &arena, &diags);
    fxb b = {0};
    const fxb_input in[] = {{"A", 0, 1, FXB_FLOAT, 1, 1}};
    const double lit[4] = {0, 1, 2, 0};
    const uint32_t code[] = {0x30000001u, 3, 0, 2, 0, 0, 1, 0, 0, 1, 1, 0, 5, 0,
                             0x20400001u, 2, 0, 2, 0, 0, 1, 2, 0, 6, 4,
                             0x10000001u, 1, 0, 2, 0, 0, 4, 8};
    fxb_fxlvm(&b, in, 1, lit, 4, 3, code, sizeof code / sizeof *code);
    fx2_blob blob = {b.d, b.n, 0};
    d3d9_preshader_out *outs = NULL;
    uint32_t n = 0;
    CHECK(hfx_fxlvm_preshader(&r, &blob, &outs, &n));
    CHECK_INT(n, 3);
    if (n == 3) {
        CHECK(outs[0].file == D3D9_PRE_C && outs[0].reg == 2 && outs[0].count == 1);
        CHECK(outs[1].file == D3D9_PRE_B && outs[1].reg == 0 && outs[1].count == 1);
        CHECK(outs[2].file == D3D9_PRE_I && outs[2].reg == 1 && outs[2].count == 1);
        CHECK_NEAR(run_output(&outs[0], -1.5f), -1.5, 0);
        CHECK_NEAR(run_output(&outs[1], -1.5f), 1, 0);
        CHECK_NEAR(run_output(&outs[2], -1.5f), 0.5, 0);
        CHECK_NEAR(run_output(&outs[1], 0.5f), 0, 0);
        CHECK_NEAR(run_output(&outs[2], 0.5f), 2.5, 0);
    }
    CHECK_INT(diags.errors, 0);
    free(b.d);
    hfx_fx_effect_free(r.fx);
    hfx_arena_free(&arena);
}

/* fxlvm.c alone on a program with temporaries, literals, cmp and rcp and two outputs:
 *     mul r0.x, c0.x, (2);  add r0.x, r0.x, c1.x;  cmp oc0.x, c1.x, r0.x, (0.5);  rcp oc0.y, r0.x
 * with A in c0 and B in c1. A = 1.5, B = 0.25: r0 = 3.25, (3.25, 1 / 3.25 = 0.30769231);
 * B = -1: r0 = 2, (0.5, 0.5). */
static void fxlvm_temporaries_and_outputs(void) {
    hfx_arena arena;
    hfx_diags diags;
    fx2_reader r;
    open_reader(&r, &arena, &diags);
    fxb b = {0};
    const fxb_input in[] = {{"A", 0, 1, FXB_FLOAT, 1, 1}, {"B", 1, 1, FXB_FLOAT, 1, 1}};
    const double lit[4] = {2, 0.5, 0, 0};
    const uint32_t code[] = {0x20500001u, 2, 0, 2, 0, 0, 1, 0, 0, 7, 0,
                             0x20400001u, 2, 0, 7, 0, 0, 2, 4, 0, 7, 0,
                             0x30000001u, 3, 0, 2, 4, 0, 7, 0, 0, 1, 1, 0, 4, 0,
                             0x10300001u, 1, 0, 7, 0, 0, 4, 1};
    fxb_fxlvm(&b, in, 2, lit, 4, 4, code, sizeof code / sizeof *code);
    fx2_blob blob = {b.d, b.n, 0};
    uint32_t first = 0, words = 0;
    CHECK(hfx_fxlvm_translate(&r, &blob, 2, HFX_EV_FLOAT, &first, &words));
    CHECK_INT(diags.errors, 0);
    float v[2] = {1.5f, 0.25f};
    uint32_t values[2];
    memcpy(values, v, sizeof values);
    hfx_ev_value out;
    CHECK(hfx_evc_run(r.fx->exprs + first, words, values, &out));
    CHECK_INT(out.n, 2);
    CHECK_NEAR(out.c[0], 3.25, 0);
    CHECK_NEAR(out.c[1], 0.30769231, 1e-7);
    v[1] = -1;
    memcpy(values, v, sizeof values);
    CHECK(hfx_evc_run(r.fx->exprs + first, words, values, &out));
    CHECK_NEAR(out.c[0], 0.5, 0);
    CHECK_NEAR(out.c[1], 0.5, 0);
    /* a read of a temporary nobody wrote: located at its operand (word 13 of the code: byte 52 on) */
    const uint32_t bad[] = {0x10000001u, 1, 0, 7, 8, 0, 4, 0};
    fxb c = {0};
    fxb_fxlvm(&c, in, 2, NULL, 0, 1, bad, 8);
    fx2_blob bad_blob = {c.d, c.n, 1000};
    CHECK(!hfx_fxlvm_translate(&r, &bad_blob, 1, HFX_EV_FLOAT, &first, &words));
    char *text = hfx_diags_format(&diags, 0);
    CHECK_CONTAINS(text, "t.fxb(0,");
    CHECK_CONTAINS(text, "error X9010: expression: a register read before it is written");
    free(text);
    free(b.d);
    free(c.d);
    hfx_fx_effect_free(r.fx);
    hfx_arena_free(&arena);
}

/* A table entry claiming a matrix of 0 columns (a spoiled file; fuzz_fx2 in CI divided by the
 * column count): it reads nothing, as a register outside every parameter does. The program is
 * mov oc0.x, c0.x with A's type record patched to class matrix-columns (3) and 0 columns: the
 * output is 0 whatever A is. The record is the CTAB's first type, 52 bytes in (header 28, one
 * entry 20, the name "A" 4), the CTAB 12 bytes after the program's start. */
static void fxlvm_matrix_of_no_columns(void) {
    hfx_arena arena;
    hfx_diags diags;
    fx2_reader r;
    open_reader(&r, &arena, &diags);
    fxb b = {0};
    const fxb_input in[] = {{"A", 0, 1, FXB_FLOAT, 1, 1}};
    const uint32_t code[] = {0x10000001u, 1, 0, 2, 0, 0, 4, 0};
    uint32_t at = fxb_fxlvm(&b, in, 1, NULL, 0, 1, code, sizeof code / sizeof *code);
    const uint16_t klass = 3, cols = 0;
    memcpy(b.d + at + 12 + 52, &klass, 2);
    memcpy(b.d + at + 12 + 52 + 6, &cols, 2);
    fx2_blob blob = {b.d, b.n, 0};
    uint32_t first = 0, words = 0;
    CHECK(hfx_fxlvm_translate(&r, &blob, 1, HFX_EV_FLOAT, &first, &words));
    float a = 2.5f;
    uint32_t values[2] = {0, 0};
    memcpy(values, &a, 4);
    hfx_ev_value out;
    CHECK(hfx_evc_run(r.fx->exprs + first, words, values, &out));
    CHECK_NEAR(out.c[0], 0, 0);
    free(b.d);
    hfx_fx_effect_free(r.fx);
    hfx_arena_free(&arena);
}

int main(void) {
    RUN(parameters_reflect_the_file);
    RUN(passes_and_states);
    RUN(shader_selector_is_an_index);
    RUN(spoiled_files_give_located_errors);
    RUN(every_truncation_is_an_error);
    RUN(xnb_files);
    RUN(listing_of_the_test_effect);
    RUN(fxlvm_temporaries_and_outputs);
    RUN(fxlvm_bool_and_int_outputs);
    RUN(fxlvm_matrix_of_no_columns);
    return test_summary();
}
