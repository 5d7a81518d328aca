/* fx2_builder.h: fx_2_0 containers laid out by hand for the reader's tests (docs/fx2.md has
 * the layout). A buffer holds the container's data (offsets count from its start, 8 bytes into
 * the file); records go in with fxb_u32 and friends, each returning its offset; fxb_file puts
 * the header (magic 0xFEFF0901, the structure's offset) in front. Also the test effect both
 * tests/compiler/effect/test_fx2.c and tests/runtime/test_fx2_load.c read, with every value
 * written below by hand. */
#ifndef HFX_TEST_FX2_BUILDER_H
#define HFX_TEST_FX2_BUILDER_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct fxb {
    uint8_t *d;
    uint32_t n, cap;
} fxb;

enum { FXB_SCALAR, FXB_VECTOR, FXB_ROWS, FXB_COLUMNS, FXB_OBJECT, FXB_STRUCT };
enum { FXB_BOOL = 1, FXB_INT = 2, FXB_FLOAT = 3, FXB_STRING = 4, FXB_TEXTURE2D = 7, FXB_SAMPLER2D = 12,
       FXB_PIXELSHADER = 15, FXB_VERTEXSHADER = 16 };

static inline uint32_t fxb_bytes(fxb *b, const void *p, uint32_t n) {
    uint32_t at = b->n, padded = (n + 3) & ~3u;
    if (b->n + padded > b->cap) {
        b->cap = (b->n + padded) * 2 + 64;
        b->d = realloc(b->d, b->cap);
    }
    memset(b->d + b->n, 0, padded);
    if (n) memcpy(b->d + b->n, p, n);
    b->n += padded;
    return at;
}

static inline uint32_t fxb_u32(fxb *b, uint32_t v) {
    uint8_t w[4] = {(uint8_t)v, (uint8_t)(v >> 8), (uint8_t)(v >> 16), (uint8_t)(v >> 24)};
    return fxb_bytes(b, w, 4);
}

static inline uint32_t fxb_f32(fxb *b, float f) {
    uint32_t w;
    memcpy(&w, &f, 4);
    return fxb_u32(b, w);
}

static inline uint32_t fxb_words(fxb *b, const uint32_t *w, uint32_t n) {
    uint32_t at = b->n;
    for (uint32_t i = 0; i < n; i++) fxb_u32(b, w[i]);
    return at;
}

static inline uint32_t fxb_floats(fxb *b, const float *f, uint32_t n) {
    uint32_t at = b->n;
    for (uint32_t i = 0; i < n; i++) fxb_f32(b, f[i]);
    return at;
}

/* A name record: its length with the NUL, then the bytes (padded). NULL: length 0. */
static inline uint32_t fxb_name(fxb *b, const char *s) {
    uint32_t at = fxb_u32(b, s ? (uint32_t)strlen(s) + 1 : 0);
    if (s) fxb_bytes(b, s, (uint32_t)strlen(s) + 1);
    return at;
}

/* A typedef (names first, then the record): a vector stores columns then rows, the others rows
 * then columns; objects stop after the element count. */
static inline uint32_t fxb_type(fxb *b, uint32_t type, uint32_t klass, const char *name, const char *sem,
                                uint32_t elements, uint32_t rows, uint32_t cols) {
    uint32_t n = fxb_name(b, name), s = fxb_name(b, sem), at = b->n;
    fxb_u32(b, type), fxb_u32(b, klass), fxb_u32(b, n), fxb_u32(b, s), fxb_u32(b, elements);
    if (klass == FXB_VECTOR) fxb_u32(b, cols), fxb_u32(b, rows);
    else if (klass != FXB_OBJECT) fxb_u32(b, rows), fxb_u32(b, cols);
    return at;
}

/* The file: magic, the structure's offset, then the data (malloc'ed). */
static inline uint8_t *fxb_file(const fxb *b, uint32_t start, size_t *size) {
    uint8_t *f = malloc(b->n + 8);
    uint32_t head[2] = {0xFEFF0901u, start};
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < 4; i++) f[4 * k + i] = (uint8_t)(head[k] >> (8 * i));
    memcpy(f + 8, b->d, b->n);
    *size = b->n + 8;
    return f;
}

/* An FXLVM program: version 'FX' 2.0, a CTAB naming the inputs (name, first c register,
 * registers, type, columns, elements: all scalars or vectors), literals (CLIT, doubles), the
 * code (FXLC: instruction count, then the words), the end token. */
typedef struct fxb_input {
    const char *name;
    uint16_t reg, regs, type, cols, elements;
} fxb_input;

static inline uint32_t fxb_fxlvm(fxb *b, const fxb_input *in, uint32_t nin, const double *lit, uint32_t nlit,
                                 uint32_t instructions, const uint32_t *code, uint32_t ncode) {
    fxb c = {0}; /* the CTAB's bytes: header 28, entries 20 each, names, types 16 each */
    uint32_t names = 28 + 20 * nin, types, at;
    fxb_u32(&c, 28), fxb_u32(&c, 0), fxb_u32(&c, 0x46580200u), fxb_u32(&c, nin), fxb_u32(&c, 28), fxb_u32(&c, 0),
        fxb_u32(&c, 0);
    uint32_t name_at[8], len = 0;
    for (uint32_t i = 0; i < nin; i++) name_at[i] = names + len, len += ((uint32_t)strlen(in[i].name) + 4) & ~3u;
    types = names + len;
    for (uint32_t i = 0; i < nin; i++)
        fxb_u32(&c, name_at[i]), fxb_u32(&c, 2u | (uint32_t)in[i].reg << 16), fxb_u32(&c, in[i].regs),
            fxb_u32(&c, types + 16 * i), fxb_u32(&c, 0);
    for (uint32_t i = 0; i < nin; i++) fxb_bytes(&c, in[i].name, (uint32_t)strlen(in[i].name) + 1);
    for (uint32_t i = 0; i < nin; i++) {
        uint16_t t[8] = {in[i].cols > 1 ? 1 : 0, in[i].type, 1, in[i].cols, in[i].elements, 0, 0, 0};
        fxb_bytes(&c, t, 16);
    }
    at = fxb_u32(b, 0x46580200u);
    fxb_u32(b, 0xfffeu | (c.n / 4 + 1) << 16), fxb_u32(b, 0x42415443u), fxb_bytes(b, c.d, c.n);
    fxb_u32(b, 0xfffeu | (2 * nlit + 2) << 16), fxb_u32(b, 0x54494c43u), fxb_u32(b, nlit), fxb_bytes(b, lit, 8 * nlit);
    fxb_u32(b, 0xfffeu | (ncode + 2) << 16), fxb_u32(b, 0x434c5846u), fxb_u32(b, instructions), fxb_words(b, code, ncode);
    fxb_u32(b, 0x0000ffffu);
    free(c.d);
    return at;
}

/* Where the test effect keeps what the error tests spoil. */
typedef struct fxb_sample {
    uint32_t start;           /* the structure (parameter count...) */
    uint32_t color_type;      /* Color's typedef */
    uint32_t samp_texture;    /* Samp's Texture state record */
    uint32_t pass_states;     /* the first state record of pass P0 */
    uint32_t strings;         /* the string count */
    uint32_t resources;       /* the first resource record */
} fxb_sample;

/* The test effect, as this source would give it:
 *     float4 Color : DIFFUSE <string UIName = "Tint"; float UIMin = 0.5;> = {0.25, 0.5, 0.75, 1};
 *     row_major float4x4 World = {1, 2, ..., 16};
 *     int Index = 2;
 *     float Weights[3] = {1, 2, 3};
 *     struct S { float a; float2 b; } St = {7, 8, 9};
 *     string Name = "hello";
 *     texture2D Tex;
 *     sampler2D Samp = sampler_state { Texture = <Tex>; MinFilter = Linear; AddressU = Clamp; };
 *     float Ref = 0.5;
 *     int VSIndices[3] = {1, 0, 1};
 *     int ShaderIndex = 2;
 *     vertexshader VSArray[2];           (objects without bytecode)
 *     technique T <int Order = 3;> {
 *       pass P0 <string Mode = "x";> { CullMode = None; ZEnable = false; BlendFactor = float4(0.5, 0.25, 1, 0);
 *                                      AlphaRef = (Ref * 255); Texture[0] = <Tex>; StencilRef = <Index>; }
 *       pass P1 { VertexShader = (VSArray[VSIndices[ShaderIndex]]); } }   (P1 only with `selector`)
 * Objects: 1 Name's string, 2 Tex, 3 Samp's Texture, 4-5 VSArray, 6 pass Texture[0], 7 StencilRef,
 * 8 AlphaRef, 9 VertexShader. */
static inline uint8_t *fxb_sample_file(size_t *size, fxb_sample *where, int selector) {
    fxb b = {0};
    fxb_sample w;
    uint32_t t[13], v[13];
    t[0] = w.color_type = fxb_type(&b, FXB_FLOAT, FXB_VECTOR, "Color", "DIFFUSE", 0, 1, 4);
    v[0] = fxb_floats(&b, (const float[]){0.25f, 0.5f, 0.75f, 1.0f}, 4);
    t[1] = fxb_type(&b, FXB_FLOAT, FXB_ROWS, "World", NULL, 0, 4, 4);
    v[1] = b.n;
    for (int i = 1; i <= 16; i++) fxb_f32(&b, (float)i);
    t[2] = fxb_type(&b, FXB_INT, FXB_SCALAR, "Index", NULL, 0, 1, 1);
    v[2] = fxb_u32(&b, 2);
    t[3] = fxb_type(&b, FXB_FLOAT, FXB_SCALAR, "Weights", NULL, 3, 1, 1);
    v[3] = fxb_floats(&b, (const float[]){1, 2, 3}, 3);
    { /* struct: its record, then the members' typedefs inline */
        uint32_t n = fxb_name(&b, "St"), s = fxb_name(&b, NULL), na = fxb_name(&b, "a"), nb = fxb_name(&b, "b");
        t[4] = b.n;
        fxb_words(&b, (const uint32_t[]){0, FXB_STRUCT, n, s, 0, 2}, 6);
        fxb_words(&b, (const uint32_t[]){FXB_FLOAT, FXB_SCALAR, na, s, 0, 1, 1}, 7);
        fxb_words(&b, (const uint32_t[]){FXB_FLOAT, FXB_VECTOR, nb, s, 0, 2, 1}, 7);
        v[4] = fxb_floats(&b, (const float[]){7, 8, 9}, 3);
    }
    t[5] = fxb_type(&b, FXB_STRING, FXB_OBJECT, "Name", NULL, 0, 0, 0);
    v[5] = fxb_u32(&b, 1);
    t[6] = fxb_type(&b, FXB_TEXTURE2D, FXB_OBJECT, "Tex", NULL, 0, 0, 0);
    v[6] = fxb_u32(&b, 2);
    { /* the sampler: state count, then (operation, index, typedef, value) records */
        uint32_t tt = fxb_type(&b, FXB_TEXTURE2D, FXB_OBJECT, NULL, NULL, 0, 0, 0), ti = fxb_type(&b, FXB_INT, FXB_SCALAR, NULL, NULL, 0, 1, 1);
        uint32_t obj = fxb_u32(&b, 3), lin = fxb_u32(&b, 2), clamp = fxb_u32(&b, 3);
        t[7] = fxb_type(&b, FXB_SAMPLER2D, FXB_OBJECT, "Samp", NULL, 0, 0, 0);
        v[7] = fxb_u32(&b, 3);
        w.samp_texture = fxb_words(&b, (const uint32_t[]){164, 0, tt, obj}, 4);
        fxb_words(&b, (const uint32_t[]){170, 0, ti, lin, 165, 0, ti, clamp}, 8);
    }
    t[8] = fxb_type(&b, FXB_FLOAT, FXB_SCALAR, "Ref", NULL, 0, 1, 1);
    v[8] = fxb_f32(&b, 0.5f);
    t[9] = fxb_type(&b, FXB_INT, FXB_SCALAR, "VSIndices", NULL, 3, 1, 1);
    v[9] = fxb_words(&b, (const uint32_t[]){1, 0, 1}, 3);
    t[10] = fxb_type(&b, FXB_INT, FXB_SCALAR, "ShaderIndex", NULL, 0, 1, 1);
    v[10] = fxb_u32(&b, 2);
    t[11] = fxb_type(&b, FXB_VERTEXSHADER, FXB_OBJECT, "VSArray", NULL, 2, 0, 0);
    v[11] = fxb_words(&b, (const uint32_t[]){4, 5}, 2);
    /* annotation types and values */
    uint32_t a_uiname = fxb_type(&b, FXB_STRING, FXB_OBJECT, "UIName", NULL, 0, 0, 0), a_uiname_v = fxb_u32(&b, 10);
    uint32_t a_uimin = fxb_type(&b, FXB_FLOAT, FXB_SCALAR, "UIMin", NULL, 0, 1, 1), a_uimin_v = fxb_f32(&b, 0.5f);
    uint32_t a_order = fxb_type(&b, FXB_INT, FXB_SCALAR, "Order", NULL, 0, 1, 1), a_order_v = fxb_u32(&b, 3);
    uint32_t a_mode = fxb_type(&b, FXB_STRING, FXB_OBJECT, "Mode", NULL, 0, 0, 0), a_mode_v = fxb_u32(&b, 11);
    /* state types and values */
    uint32_t s_int = fxb_type(&b, FXB_INT, FXB_SCALAR, NULL, NULL, 0, 1, 1);
    uint32_t s_bool = fxb_type(&b, FXB_BOOL, FXB_SCALAR, NULL, NULL, 0, 1, 1);
    uint32_t s_f4 = fxb_type(&b, FXB_FLOAT, FXB_VECTOR, NULL, NULL, 0, 1, 4);
    uint32_t s_tex = fxb_type(&b, FXB_TEXTURE2D, FXB_OBJECT, NULL, NULL, 0, 0, 0);
    uint32_t s_vs = fxb_type(&b, FXB_VERTEXSHADER, FXB_OBJECT, NULL, NULL, 0, 0, 0);
    uint32_t none = fxb_u32(&b, 1), zero = fxb_u32(&b, 0), bf = fxb_floats(&b, (const float[]){0.5f, 0.25f, 1, 0}, 4);
    uint32_t o6 = fxb_u32(&b, 6), o7 = fxb_u32(&b, 7), o8 = fxb_u32(&b, 8), o9 = fxb_u32(&b, 9);
    uint32_t tn = fxb_name(&b, "T"), p0 = fxb_name(&b, "P0"), p1 = fxb_name(&b, "P1");
    /* the structure: records one after another from here */
    w.start = fxb_u32(&b, 12);          /* parameters */
    fxb_u32(&b, 1), fxb_u32(&b, 2), fxb_u32(&b, 12); /* techniques, shaders, objects */
    for (int i = 0; i < 12; i++) {
        fxb_u32(&b, t[i]), fxb_u32(&b, v[i]), fxb_u32(&b, 0), fxb_u32(&b, i == 0 ? 2 : 0);
        if (i == 0) fxb_words(&b, (const uint32_t[]){a_uiname, a_uiname_v, a_uimin, a_uimin_v}, 4);
    }
    fxb_words(&b, (const uint32_t[]){tn, 1, selector ? 2 : 1, a_order, a_order_v}, 5);
    fxb_words(&b, (const uint32_t[]){p0, 1, 6, a_mode, a_mode_v}, 5);
    w.pass_states = fxb_words(&b, (const uint32_t[]){8, 0, s_int, none,      /* CullMode = None (1) */
                                                      0, 0, s_bool, zero,     /* ZEnable = false */
                                                      96, 0, s_f4, bf,        /* BlendFactor */
                                                      10, 0, s_int, o8,       /* AlphaRef: resource */
                                                      164, 0, s_tex, o6,      /* Texture[0]: resource */
                                                      27, 0, s_int, o7}, 24); /* StencilRef: resource */
    if (selector) fxb_words(&b, (const uint32_t[]){p1, 0, 1, 146, 0, s_vs, o9}, 7);
    w.strings = fxb_u32(&b, 3);        /* strings */
    fxb_u32(&b, selector ? 5 : 4);     /* resources */
    fxb_u32(&b, 1), fxb_name(&b, "hello");
    fxb_u32(&b, 10), fxb_name(&b, "Tint");
    fxb_u32(&b, 11), fxb_name(&b, "x");
    /* resources: technique (-1: a parameter), pass or parameter, element, state, usage, data */
    w.resources = fxb_words(&b, (const uint32_t[]){0xffffffffu, 7, 0xffffffffu, 0, 1}, 5);
    fxb_name(&b, "Tex");                 /* Samp's Texture = <Tex> */
    fxb_words(&b, (const uint32_t[]){0, 0, 0xffffffffu, 4, 1}, 5);
    fxb_name(&b, "Tex");                 /* Texture[0] = <Tex> */
    fxb_words(&b, (const uint32_t[]){0, 0, 0xffffffffu, 5, 1}, 5);
    fxb_name(&b, "Index");               /* StencilRef = <Index> */
    { /* AlphaRef = (Ref * 255): mul oc0.x, c0.x, imm(255) */
        fxb_words(&b, (const uint32_t[]){0, 0, 0xffffffffu, 3, 0}, 5);
        uint32_t size_at = fxb_u32(&b, 0), begin = b.n;
        const fxb_input in[] = {{"Ref", 0, 1, FXB_FLOAT, 1, 1}};
        const double lit[4] = {255, 0, 0, 0};
        const uint32_t code[] = {0x20500001u, 2, 0, 2, 0, 0, 1, 0, 0, 4, 0};
        fxb_fxlvm(&b, in, 1, lit, 4, 1, code, 11);
        uint32_t n = b.n - begin;
        memcpy(b.d + size_at, &n, 4);
    }
    if (selector) { /* VertexShader = (VSArray[VSIndices[ShaderIndex]]): the array's name, then
       * mov oc0.x, c[0 + c3.x].x with VSIndices in c0..c2 and ShaderIndex in c3 */
        fxb_words(&b, (const uint32_t[]){0, 1, 0xffffffffu, 0, 2}, 5);
        uint32_t size_at = fxb_u32(&b, 0), begin = b.n;
        fxb_name(&b, "VSArray");
        const fxb_input in[] = {{"VSIndices", 0, 3, FXB_INT, 1, 3}, {"ShaderIndex", 3, 1, FXB_INT, 1, 1}};
        const uint32_t code[] = {0x10000001u, 1, 1, 2, 12, 2, 0, 0, 4, 0};
        fxb_fxlvm(&b, in, 2, NULL, 0, 1, code, 10);
        uint32_t n = b.n - begin;
        memcpy(b.d + size_at, &n, 4);
    }
    uint8_t *f = fxb_file(&b, w.start, size);
    free(b.d);
    if (where) *where = w;
    return f;
}

/* Hand-assembled shaders (D3D9 tokens):
 *   vs_2_0: dcl_position v0; mov oPos, v0
 *   ps_2_0: def c0, R, G, 0, 1; mov oC0, c0 */
static inline uint32_t fxb_vs_passthrough(fxb *b) {
    const uint32_t t[] = {0xfffe0200u, 0x0200001fu, 0x80000000u, 0x900f0000u,
                          0x02000001u, 0xc00f0000u, 0x90e40000u, 0x0000ffffu};
    return fxb_words(b, t, 8);
}

static inline uint32_t fxb_ps_colour(fxb *b, float red, float green) {
    uint32_t r, g, one = 0x3f800000u;
    memcpy(&r, &red, 4), memcpy(&g, &green, 4);
    const uint32_t t[] = {0xffff0200u, 0x05000051u, 0xa00f0000u, r, g, 0, one,
                          0x02000001u, 0x800f0800u, 0xa0e40000u, 0x0000ffffu};
    return fxb_words(b, t, 11);
}

/* An effect with real shaders:
 *     int ShaderIndex = 0;
 *     pixelshader PSArray[2] = { (red: 1, 0, 0, 1), (green: 0, 1, 0, 1) };
 *     technique T { pass P { CullMode = None; VertexShader = <passthrough>;
 *                            PixelShader = (PSArray[ShaderIndex]); } }
 * Objects: 1-2 PSArray, 3 the pass's VertexShader, 4 its PixelShader. */
static inline uint8_t *fxb_shader_file(size_t *size) {
    fxb b = {0};
    uint32_t t_index = fxb_type(&b, FXB_INT, FXB_SCALAR, "ShaderIndex", NULL, 0, 1, 1), v_index = fxb_u32(&b, 0);
    uint32_t t_ps = fxb_type(&b, FXB_PIXELSHADER, FXB_OBJECT, "PSArray", NULL, 2, 0, 0);
    uint32_t v_ps = fxb_words(&b, (const uint32_t[]){1, 2}, 2);
    uint32_t s_int = fxb_type(&b, FXB_INT, FXB_SCALAR, NULL, NULL, 0, 1, 1), none = fxb_u32(&b, 1);
    uint32_t s_vs = fxb_type(&b, FXB_VERTEXSHADER, FXB_OBJECT, NULL, NULL, 0, 0, 0), o3 = fxb_u32(&b, 3);
    uint32_t s_pst = fxb_type(&b, FXB_PIXELSHADER, FXB_OBJECT, NULL, NULL, 0, 0, 0), o4 = fxb_u32(&b, 4);
    uint32_t tn = fxb_name(&b, "T"), pn = fxb_name(&b, "P");
    uint32_t start = fxb_words(&b, (const uint32_t[]){2, 1, 3, 5}, 4);
    fxb_words(&b, (const uint32_t[]){t_index, v_index, 0, 0, t_ps, v_ps, 0, 0}, 8);
    fxb_words(&b, (const uint32_t[]){tn, 0, 1, pn, 0, 3}, 6);
    fxb_words(&b, (const uint32_t[]){8, 0, s_int, none, 146, 0, s_vs, o3, 147, 0, s_pst, o4}, 12);
    fxb_words(&b, (const uint32_t[]){2, 2}, 2); /* strings (the array's shaders), resources */
    for (int k = 0; k < 2; k++) {
        fxb_u32(&b, 1 + (uint32_t)k), fxb_u32(&b, 44);
        fxb_ps_colour(&b, k ? 0.0f : 1.0f, k ? 1.0f : 0.0f);
    }
    fxb_words(&b, (const uint32_t[]){0, 0, 0xffffffffu, 1, 0, 32}, 6); /* VertexShader: bytecode */
    fxb_vs_passthrough(&b);
    { /* PixelShader = (PSArray[ShaderIndex]): mov oc0.x, c0.x */
        fxb_words(&b, (const uint32_t[]){0, 0, 0xffffffffu, 2, 2}, 5);
        uint32_t size_at = fxb_u32(&b, 0), begin = b.n;
        fxb_name(&b, "PSArray");
        const fxb_input in[] = {{"ShaderIndex", 0, 1, FXB_INT, 1, 1}};
        const uint32_t code[] = {0x10000001u, 1, 0, 2, 0, 0, 4, 0};
        fxb_fxlvm(&b, in, 1, NULL, 0, 1, code, 8);
        uint32_t n = b.n - begin;
        memcpy(b.d + size_at, &n, 4);
    }
    uint8_t *f = fxb_file(&b, start, size);
    free(b.d);
    return f;
}

#endif
