/* .hfxo: a hand-built effect survives a write and a read field by field; every truncation and
 * every flipped byte of the file is refused with a message; files with a valid checksum but
 * hostile contents are refused too. The CRC here is an independent bit-by-bit implementation. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "eval_code.h"
#include "states.h"
#include "test.h"

static char *dup(const char *s) { return s ? strdup(s) : NULL; }

static uint32_t f2u(float f) {
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* An effect with one of everything: matrix with semantic, float4 with annotations, an array of
 * a struct, a texture, a sampler with states, a string param; one program, two passes. */
static hfx_fx_effect *sample_effect(void) {
    hfx_fx_effect *fx = calloc(1, sizeof *fx);
    fx->source_name = dup("sample.fx");
    fx->targets = 3;
    fx->param_count = 9;
    fx->top_param_count = 5;
    fx->params = calloc(fx->param_count, sizeof *fx->params);
    hfx_fx_param *p = fx->params;
    /* 0: float4x4 world : World */
    p[0] = (hfx_fx_param){dup("world"), dup("World"), dup("world"), HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 4, 4, 0,
                          HFX_NONE, HFX_NONE, 0, 0, 16, HFX_NONE, 0, HFX_NONE, 0, NULL, dup("sample.fx"), 3, 7, {0}};
    /* 1: float4 color <UIName, UIMin> = {0.05, 0.05, 0.05, 1} */
    p[1] = (hfx_fx_param){dup("color"), NULL, dup("color"), HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0,
                          HFX_NONE, HFX_NONE, 0, 16, 4, 0, 2, HFX_NONE, 0, NULL, NULL, 0, 0, {0}};
    /* 2: struct { float3 d; int on; } lights[2] */
    p[2] = (hfx_fx_param){dup("lights"), NULL, dup("lights"), HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 2,
                          HFX_NONE, 5, 2, 20, 8, HFX_NONE, 0, HFX_NONE, HFX_FX_PARAM_SHARED, NULL, NULL, 0, 0, {0}};
    /* 3: texture2D tex; 4: sampler s; */
    p[3] = (hfx_fx_param){dup("tex"), NULL, NULL, HFX_CLASS_OBJECT, HFX_TYPE_TEXTURE2D, 0, 0, 0,
                          HFX_NONE, HFX_NONE, 0, 28, 0, HFX_NONE, 0, HFX_NONE, 0, NULL, NULL, 0, 0, {0}};
    p[4] = (hfx_fx_param){dup("s"), NULL, dup("s"), HFX_CLASS_OBJECT, HFX_TYPE_SAMPLER, 0, 0, 0,
                          HFX_NONE, HFX_NONE, 0, 28, 0, HFX_NONE, 0, 0, 0, NULL, NULL, 0, 0, {0}};
    /* 5, 6: the elements; 7, 8: the members of element 0 */
    p[5] = (hfx_fx_param){dup("lights"), NULL, NULL, HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 0,
                          2, 7, 2, 20, 4, HFX_NONE, 0, HFX_NONE, 0, NULL, NULL, 0, 0, {0}};
    p[6] = (hfx_fx_param){dup("lights"), NULL, NULL, HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 0,
                          2, HFX_NONE, 0, 24, 4, HFX_NONE, 0, HFX_NONE, 0, dup("not really a string param"), NULL, 0, 0, {0}};
    p[7] = (hfx_fx_param){dup("d"), dup("DIR"), dup("d"), HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 3, 0,
                          5, HFX_NONE, 0, 20, 3, HFX_NONE, 0, HFX_NONE, 0, NULL, NULL, 0, 0, {0}};
    p[8] = (hfx_fx_param){dup("on"), NULL, dup("on"), HFX_CLASS_SCALAR, HFX_TYPE_INT, 1, 1, 0,
                          5, HFX_NONE, 0, 23, 1, HFX_NONE, 0, HFX_NONE, 0, NULL, NULL, 0, 0, {0}};
    fx->value_words = 28;
    fx->values = calloc(28, sizeof *fx->values);
    for (int i = 0; i < 16; i++) fx->values[i] = f2u(i % 5 == 0 ? 1.0f : 0.0f);
    fx->values[16] = fx->values[17] = fx->values[18] = f2u(0.05f);
    fx->values[19] = f2u(1.0f);
    fx->values[23] = (uint32_t)-7;

    fx->annotation_count = 3;
    fx->annotations = calloc(3, sizeof *fx->annotations);
    fx->annotations[0] = (hfx_fx_annotation){dup("UIName"), HFX_TYPE_STRING, HFX_CLASS_OBJECT, 0, 0, 0, NULL,
                                             dup("Color Ambiental")};
    uint32_t *d = calloc(1, sizeof *d);
    d[0] = f2u(0.5f);
    fx->annotations[1] = (hfx_fx_annotation){dup("UIMin"), HFX_TYPE_FLOAT, HFX_CLASS_SCALAR, 1, 1, 1, d, NULL};
    d = calloc(2, sizeof *d);
    d[0] = 3;
    d[1] = (uint32_t)-4;
    fx->annotations[2] = (hfx_fx_annotation){dup("Pair"), HFX_TYPE_INT, HFX_CLASS_VECTOR, 1, 2, 2, d, NULL};

    fx->state_count = 4;
    fx->states = calloc(4, sizeof *fx->states);
    fx->states[0] = (hfx_fx_state){5, 0, HFX_FX_VALUE_INT, 0, 3, {0}, 0, 12, 5, 0};
    fx->states[1] = (hfx_fx_state){7, 1, HFX_FX_VALUE_FLOAT, 4, 0, {0.25f, -1.5f, 2.0f, 1.0f}, 0, 13, 9, 0};
    fx->states[2] = (hfx_fx_state){9, 0, HFX_FX_VALUE_PARAM, 0, 0, {0}, 3, 14, 1, 0};
    fx->states[3] = (hfx_fx_state){11, 0, HFX_FX_VALUE_PROGRAM, 0, 0, {0}, 0, 15, 1, 0};

    fx->sampler_count = 1;
    fx->samplers = calloc(1, sizeof *fx->samplers);
    fx->samplers[0] = (hfx_fx_sampler){4, 3, HFX_FX_DIM_CUBE, 0, 1, 0};

    fx->program_count = 1;
    fx->programs = calloc(1, sizeof *fx->programs);
    hfx_fx_program *pr = &fx->programs[0];
    pr->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data = dup("#version 330\nvoid main() {}\n");
    pr->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].size = strlen(pr->code[0][0].data);
    pr->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSLES300].data = dup("#version 300 es\n");
    pr->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSLES300].size = 16;
    char *spirv = malloc(9);
    memcpy(spirv, "\x03\x02\x23\x07\0\0\1\0", 8);
    spirv[8] = 0;
    pr->code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV].data = spirv;
    pr->code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV].size = 8;
    char *vk = malloc(13); /* Vulkan's SPIR-V rides in the program record's tail */
    memcpy(vk, "\x03\x02\x23\x07\0\0\1\0\x11\x22\x33\x44", 12);
    vk[12] = 0;
    pr->code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV_VK].data = vk;
    pr->code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV_VK].size = 12;
    pr->attribute_count = 2;
    pr->attributes = calloc(2, sizeof *pr->attributes);
    pr->attributes[0] = (hfx_fx_attribute){dup("POSITION0"), dup("in_POSITION0"), 0};
    pr->attributes[1] = (hfx_fx_attribute){dup("TEXCOORD0"), dup("in_TEXCOORD0"), 8};
    pr->sampler_count = 1;
    pr->samplers = calloc(1, sizeof *pr->samplers);
    pr->samplers[0] = (hfx_fx_sampler_use){dup("s"), 0, 2};
    pr->uniform_count = 2;
    pr->uniforms = calloc(2, sizeof *pr->uniforms);
    pr->uniforms[0] = (hfx_fx_uniform_use){.param = 0, .reg = 0};        /* world: packed, registers 0..3 */
    pr->uniforms[1] = (hfx_fx_uniform_use){.param = 2, .reg = HFX_NONE}; /* lights: its own uniform */
    pr->reg_count = 5;
    pr->flags = HFX_FX_PROGRAM_ALPHA_TEST;
    /* a preshader: world's diagonal (components 0, 5, 10, 15) into register 4 */
    pr->pre_words = 4;
    pr->pre_code = malloc(4 * sizeof *pr->pre_code);
    uint32_t pre[4] = {hfx_evc_word(HFX_EVC_PARAM, HFX_EV_FLOAT, 16), 0, hfx_evc_word(HFX_EVC_SWIZZLE, 4, 0), 0xfa50u};
    memcpy(pr->pre_code, pre, sizeof pre);
    pr->preshader_count = 1;
    pr->preshaders = calloc(1, sizeof *pr->preshaders);
    pr->preshaders[0] = (hfx_fx_preshader){0, 4, 4, 1, 4};

    fx->pass_count = 2;
    fx->passes = calloc(2, sizeof *fx->passes);
    fx->passes[0] = (hfx_fx_pass){dup("p0"), 2, 1, 1, 3, 0};
    fx->passes[1] = (hfx_fx_pass){dup(""), HFX_NONE, 0, HFX_NONE, 0, HFX_NONE};
    fx->technique_count = 1;
    fx->techniques = calloc(1, sizeof *fx->techniques);
    fx->techniques[0] = (hfx_fx_technique){dup("Main"), HFX_NONE, 0, 0, 2};
    return fx;
}

static void same_string(const char *a, const char *b) {
    if (!a || !b) CHECK(a == b);
    else CHECK_STR(a, b);
}

static void compare_effects(const hfx_fx_effect *a, const hfx_fx_effect *b) {
    CHECK_STR(a->source_name, b->source_name);
    CHECK_INT(a->targets, b->targets);
    CHECK_INT(a->param_count, b->param_count);
    CHECK_INT(a->top_param_count, b->top_param_count);
    for (uint32_t i = 0; i < a->param_count && i < b->param_count; i++) {
        const hfx_fx_param *x = &a->params[i], *y = &b->params[i];
        same_string(x->name, y->name);
        same_string(x->semantic, y->semantic);
        same_string(x->glsl_name, y->glsl_name);
        same_string(x->string, y->string);
        same_string(x->file, y->file);
        CHECK_INT(x->line, y->line);
        CHECK_INT(x->col, y->col);
        CHECK_INT(x->klass, y->klass);
        CHECK_INT(x->type, y->type);
        CHECK_INT(x->rows, y->rows);
        CHECK_INT(x->cols, y->cols);
        CHECK_INT(x->elements, y->elements);
        CHECK_INT(x->parent, y->parent);
        CHECK_INT(x->first_child, y->first_child);
        CHECK_INT(x->child_count, y->child_count);
        CHECK_INT(x->offset, y->offset);
        CHECK_INT(x->words, y->words);
        CHECK_INT(x->first_annotation, y->first_annotation);
        CHECK_INT(x->annotation_count, y->annotation_count);
        CHECK_INT(x->sampler, y->sampler);
        CHECK_INT(x->flags, y->flags);
    }
    CHECK_INT(a->value_words, b->value_words);
    CHECK(a->value_words == 0 || memcmp(a->values, b->values, 4 * a->value_words) == 0);
    CHECK_INT(a->annotation_count, b->annotation_count);
    for (uint32_t i = 0; i < a->annotation_count && i < b->annotation_count; i++) {
        const hfx_fx_annotation *x = &a->annotations[i], *y = &b->annotations[i];
        CHECK_STR(x->name, y->name);
        CHECK_INT(x->type, y->type);
        CHECK_INT(x->klass, y->klass);
        CHECK_INT(x->rows, y->rows);
        CHECK_INT(x->cols, y->cols);
        CHECK_INT(x->count, y->count);
        CHECK(x->count == 0 || memcmp(x->data, y->data, 4 * x->count) == 0);
        same_string(x->string, y->string);
    }
    CHECK_INT(a->state_count, b->state_count);
    for (uint32_t i = 0; i < a->state_count && i < b->state_count; i++) {
        const hfx_fx_state *x = &a->states[i], *y = &b->states[i];
        CHECK_INT(x->id, y->id);
        CHECK_INT(x->index, y->index);
        CHECK_INT(x->kind, y->kind);
        CHECK_INT(x->count, y->count);
        CHECK_INT(x->i, y->i);
        CHECK(memcmp(x->f, y->f, sizeof x->f) == 0);
        CHECK_INT(x->ref, y->ref);
        CHECK_INT(x->line, y->line);
        CHECK_INT(x->col, y->col);
    }
    CHECK_INT(a->sampler_count, b->sampler_count);
    for (uint32_t i = 0; i < a->sampler_count && i < b->sampler_count; i++)
        CHECK(memcmp(&a->samplers[i], &b->samplers[i], sizeof a->samplers[i]) == 0);
    CHECK_INT(a->program_count, b->program_count);
    for (uint32_t i = 0; i < a->program_count && i < b->program_count; i++) {
        const hfx_fx_program *x = &a->programs[i], *y = &b->programs[i];
        CHECK_INT(x->flags, y->flags);
        CHECK_INT(x->reg_count, y->reg_count);
        for (int s = 0; s < HFX_STAGE_COUNT; s++)
            for (int t = 0; t < HFX_TARGET_COUNT; t++) {
                CHECK_INT(x->code[s][t].size, y->code[s][t].size);
                CHECK((x->code[s][t].data == NULL) == (y->code[s][t].data == NULL));
                if (x->code[s][t].data && y->code[s][t].data)
                    CHECK(memcmp(x->code[s][t].data, y->code[s][t].data, x->code[s][t].size) == 0);
            }
        CHECK_INT(x->attribute_count, y->attribute_count);
        for (uint32_t k = 0; k < x->attribute_count && k < y->attribute_count; k++) {
            CHECK_STR(x->attributes[k].semantic, y->attributes[k].semantic);
            CHECK_STR(x->attributes[k].glsl_name, y->attributes[k].glsl_name);
            CHECK_INT(x->attributes[k].location, y->attributes[k].location);
        }
        CHECK_INT(x->sampler_count, y->sampler_count);
        for (uint32_t k = 0; k < x->sampler_count && k < y->sampler_count; k++) {
            CHECK_STR(x->samplers[k].glsl_name, y->samplers[k].glsl_name);
            CHECK_INT(x->samplers[k].sampler, y->samplers[k].sampler);
            CHECK_INT(x->samplers[k].unit, y->samplers[k].unit);
        }
        CHECK_INT(x->uniform_count, y->uniform_count);
        for (uint32_t k = 0; k < x->uniform_count && k < y->uniform_count; k++) {
            CHECK_INT(x->uniforms[k].param, y->uniforms[k].param);
            CHECK_INT(x->uniforms[k].reg, y->uniforms[k].reg);
            CHECK_INT(x->uniforms[k].flags, y->uniforms[k].flags);
        }
        CHECK_INT(x->preshader_count, y->preshader_count);
        CHECK_INT(x->pre_words, y->pre_words);
        for (uint32_t k = 0; k < x->preshader_count && k < y->preshader_count; k++)
            CHECK(memcmp(&x->preshaders[k], &y->preshaders[k], sizeof x->preshaders[k]) == 0);
        if (x->pre_words == y->pre_words && x->pre_words)
            CHECK(memcmp(x->pre_code, y->pre_code, x->pre_words * sizeof *x->pre_code) == 0);
    }
    CHECK_INT(a->pass_count, b->pass_count);
    for (uint32_t i = 0; i < a->pass_count && i < b->pass_count; i++) {
        CHECK_STR(a->passes[i].name, b->passes[i].name);
        CHECK_INT(a->passes[i].first_annotation, b->passes[i].first_annotation);
        CHECK_INT(a->passes[i].annotation_count, b->passes[i].annotation_count);
        CHECK_INT(a->passes[i].first_state, b->passes[i].first_state);
        CHECK_INT(a->passes[i].state_count, b->passes[i].state_count);
        CHECK_INT(a->passes[i].program, b->passes[i].program);
    }
    CHECK_INT(a->technique_count, b->technique_count);
    for (uint32_t i = 0; i < a->technique_count && i < b->technique_count; i++) {
        CHECK_STR(a->techniques[i].name, b->techniques[i].name);
        CHECK_INT(a->techniques[i].first_pass, b->techniques[i].first_pass);
        CHECK_INT(a->techniques[i].pass_count, b->techniques[i].pass_count);
        CHECK_INT(a->techniques[i].first_annotation, b->techniques[i].first_annotation);
        CHECK_INT(a->techniques[i].annotation_count, b->techniques[i].annotation_count);
    }
}

/* CRC-32 bit by bit, straight from the polynomial: independent of hfxo.c's table. */
static uint32_t crc32_bitwise(const uint8_t *p, size_t n) {
    uint32_t crc = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        crc ^= p[i];
        for (int k = 0; k < 8; k++) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1)));
    }
    return ~crc;
}

static uint32_t get32(const uint8_t *p) { return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24; }
static void put32(uint8_t *p, uint32_t v) { p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24); }

static void round_trip(void) {
    hfx_fx_effect *fx = sample_effect();
    void *data = NULL;
    size_t size = 0;
    CHECK_INT(hfx_fx_write_hfxo(fx, &data, &size), 0);
    CHECK(hfx_fx_is_hfxo(data, size));
    CHECK(size % 4 == 0);
    const uint8_t *b = data;
    CHECK_INT(b[0], 0x89);
    CHECK(memcmp(b + 1, "HFXO", 4) == 0);
    CHECK_INT(get32(b + 8), 3);                         /* version */
    CHECK_INT(get32(b + 16), size);                     /* total size */
    CHECK_INT(get32(b + 12), crc32_bitwise(b + 16, size - 16));
    char err[256] = "untouched";
    hfx_fx_effect *back = hfx_fx_read_hfxo(data, size, err, sizeof err);
    CHECK(back != NULL);
    CHECK_STR(err, "");
    if (back) {
        compare_effects(fx, back);
        /* The code is handed back NUL-terminated even for binary SPIR-V. */
        CHECK_INT(back->programs[0].code[0][HFX_TARGET_SPIRV].data[8], 0);
        /* Writing what was read gives the same bytes: the format has one spelling per effect. */
        void *again = NULL;
        size_t again_size = 0;
        CHECK_INT(hfx_fx_write_hfxo(back, &again, &again_size), 0);
        CHECK(again_size == size && memcmp(again, data, size) == 0);
        free(again);
    }
    hfx_fx_effect *copy = hfx_fx_effect_copy(fx);
    CHECK(copy != NULL);
    if (copy) compare_effects(fx, copy);
    hfx_fx_effect_free(copy);
    hfx_fx_effect_free(back);
    hfx_fx_effect_free(fx);
    free(data);
}

static void empty_effect_round_trips(void) {
    hfx_fx_effect *fx = calloc(1, sizeof *fx);
    fx->source_name = strdup("");
    void *data = NULL;
    size_t size = 0;
    CHECK_INT(hfx_fx_write_hfxo(fx, &data, &size), 0);
    char err[256];
    hfx_fx_effect *back = hfx_fx_read_hfxo(data, size, err, sizeof err);
    CHECK(back != NULL);
    if (back) compare_effects(fx, back);
    hfx_fx_effect_free(back);
    hfx_fx_effect_free(fx);
    free(data);
}

static void every_truncation_is_refused(void) {
    hfx_fx_effect *fx = sample_effect();
    void *data = NULL;
    size_t size = 0;
    CHECK_INT(hfx_fx_write_hfxo(fx, &data, &size), 0);
    int refused = 0;
    for (size_t n = 0; n < size; n++) {
        /* A copy of exactly n bytes, so ASan sees any read past the end. */
        uint8_t *cut = malloc(n ? n : 1);
        memcpy(cut, data, n);
        char err[256] = "";
        hfx_fx_effect *r = hfx_fx_read_hfxo(cut, n, err, sizeof err);
        if (!r && strncmp(err, "hfxo: ", 6) == 0 && strlen(err) > 6) refused++;
        else fprintf(stderr, "truncation to %zu bytes: %s\n", n, r ? "accepted" : "no message");
        hfx_fx_effect_free(r);
        free(cut);
    }
    CHECK_INT(refused, size);
    char err[256];
    hfx_fx_effect *r = hfx_fx_read_hfxo(data, 10, err, sizeof err);
    CHECK(r == NULL);
    CHECK_STR(err, "hfxo: file is 10 bytes, too short for the header (truncated?)");
    r = hfx_fx_read_hfxo(data, size - 4, err, sizeof err);
    CHECK(r == NULL);
    char want[128];
    snprintf(want, sizeof want, "hfxo: file is %zu bytes but its header says %zu (truncated?)", size - 4, size);
    CHECK_STR(err, want);
    hfx_fx_effect_free(fx);
    free(data);
}

static void every_flipped_byte_is_refused(void) {
    hfx_fx_effect *fx = sample_effect();
    void *data = NULL;
    size_t size = 0;
    CHECK_INT(hfx_fx_write_hfxo(fx, &data, &size), 0);
    int refused = 0;
    uint8_t *copy = malloc(size);
    for (size_t i = 0; i < size; i++) {
        memcpy(copy, data, size);
        copy[i] ^= (uint8_t)(1u << (i % 8)); /* one bit, a different one each time */
        char err[256] = "";
        hfx_fx_effect *r = hfx_fx_read_hfxo(copy, size, err, sizeof err);
        if (!r && strlen(err) > 6) refused++;
        else fprintf(stderr, "flip at %zu: %s\n", i, r ? "accepted" : "no message");
        hfx_fx_effect_free(r);
        memcpy(copy, data, size);
        copy[i] ^= 0xff;
        r = hfx_fx_read_hfxo(copy, size, NULL, 0); /* no message buffer: still safe */
        CHECK(r == NULL);
        hfx_fx_effect_free(r);
    }
    CHECK_INT(refused, size);
    memcpy(copy, data, size);
    copy[1] = 'X';
    char err[256];
    CHECK(hfx_fx_read_hfxo(copy, size, err, sizeof err) == NULL);
    CHECK_STR(err, "hfxo: not an .hfxo file (bad magic number)");
    CHECK(!hfx_fx_is_hfxo(copy, size));
    memcpy(copy, data, size);
    put32(copy + 8, 4);
    CHECK(hfx_fx_read_hfxo(copy, size, err, sizeof err) == NULL);
    CHECK_STR(err, "hfxo: format version 4 is not supported (this reader knows 3)");
    memcpy(copy, data, size);
    put32(copy + 8, 2); /* version 2 is read, but it had no preshaders */
    CHECK(hfx_fx_read_hfxo(copy, size, err, sizeof err) == NULL);
    CHECK_STR(err, "hfxo: a version 2 file with preshaders (they came in version 3)");
    memcpy(copy, data, size);
    put32(copy + 8, 1);
    CHECK(hfx_fx_read_hfxo(copy, size, err, sizeof err) == NULL);
    CHECK_STR(err, "hfxo: format version 1 is older than this reader's 2: compile the .fx again");
    memcpy(copy, data, size);
    copy[size - 1] ^= 1;
    CHECK(hfx_fx_read_hfxo(copy, size, err, sizeof err) == NULL);
    CHECK_STR(err, "hfxo: checksum mismatch (the file is corrupted)");
    free(copy);
    hfx_fx_effect_free(fx);
    free(data);
}

/* Finds the section `id` in a written file; returns its offset (0 if absent). */
static uint32_t section_at(const uint8_t *b, const char *id) {
    uint32_t n = get32(b + 20);
    for (uint32_t i = 0; i < n; i++)
        if (memcmp(b + 24 + 12 * i, id, 4) == 0) return get32(b + 24 + 12 * i + 4);
    return 0;
}

/* Changes one word, then fixes the checksum, as a hostile writer would. */
static const char *read_patched(const void *data, size_t size, size_t at, uint32_t value, char *err, size_t err_size) {
    uint8_t *copy = malloc(size);
    memcpy(copy, data, size);
    put32(copy + at, value);
    put32(copy + 12, crc32_bitwise(copy + 16, size - 16));
    hfx_fx_effect *r = hfx_fx_read_hfxo(copy, size, err, err_size);
    if (r) snprintf(err, err_size, "accepted");
    hfx_fx_effect_free(r);
    free(copy);
    return err;
}

static void hostile_contents_are_refused(void) {
    hfx_fx_effect *fx = sample_effect();
    void *data = NULL;
    size_t size = 0;
    CHECK_INT(hfx_fx_write_hfxo(fx, &data, &size), 0);
    const uint8_t *b = data;
    uint32_t parm = section_at(b, "PARM"), prog = section_at(b, "PROG"), pass = section_at(b, "PASS");
    uint32_t strs = section_at(b, "STRS"), stat = section_at(b, "STAT");
    CHECK(parm && prog && pass && strs && stat);
    char err[256];
    /* A record count that would need more bytes than the section has. */
    CHECK_STR(read_patched(data, size, parm, 0x40000000u, err, sizeof err),
              "hfxo: section PARM holds 1073741824 records, more than fit");
    CHECK_INT(get32(b + parm + 4), 84); /* 21 words a record: positions added to version 2 */
    /* Param 5 (an element) claims its parent is itself: a cycle. */
    CHECK_STR(read_patched(data, size, parm + 8 + 5 * 84 + 9 * 4, 5, err, sizeof err),
              "hfxo: parameter 5 is not inside its parent 2");
    /* Param 0's name points past the string table. */
    CHECK_STR(read_patched(data, size, parm + 8, 0x7fffffff, err, sizeof err),
              "hfxo: string offset 2147483647 is outside the string table");
    /* Param 1's values run past the end of the buffer. */
    CHECK_STR(read_patched(data, size, parm + 8 + 84 + 12 * 4, 27, err, sizeof err),
              "hfxo: parameter 1 has values outside the buffer");
    /* Param 2's children start before it. */
    CHECK_STR(read_patched(data, size, parm + 8 + 2 * 84 + 10 * 4, 1, err, sizeof err),
              "hfxo: parameter 2 has children that do not exist");
    /* The first pass runs a program that does not exist. */
    CHECK_STR(read_patched(data, size, pass + 8 + 5 * 4, 1, err, sizeof err), "hfxo: pass 0 is inconsistent");
    /* A state names a parameter past the end. */
    CHECK_STR(read_patched(data, size, stat + 8 + 2 * 48 + 9 * 4, 9, err, sizeof err),
              "hfxo: state 2 names a missing parameter");
    /* Shader code whose size runs past its section. */
    CHECK_STR(read_patched(data, size, prog + 8 + 7 * 4 + 4, 0xfffffff0u, err, sizeof err),
              "hfxo: shader code lies outside its section");
    /* Registers (HFXC_PACK_UNIFORMS): too many, a packed parameter reaching past them, a
     * register on a parameter that cannot be packed (the struct array). */
    uint32_t uuse = section_at(b, "UUSE");
    CHECK(uuse != 0);
    CHECK_INT(get32(b + prog + 8 + 23 * 4), 5); /* reg_count, after the code fields */
    CHECK_INT(get32(b + uuse + 4), 12);         /* param, reg, flags */
    CHECK_STR(read_patched(data, size, prog + 8 + 23 * 4, 4097, err, sizeof err),
              "hfxo: program 0 has 4097 registers (at most 4096)");
    CHECK_STR(read_patched(data, size, prog + 8 + 23 * 4, 3, err, sizeof err),
              "hfxo: program 0 puts parameter 0 outside its 3 registers");
    CHECK_STR(read_patched(data, size, uuse + 8 + 4, 2, err, sizeof err),
              "hfxo: program 0 puts parameter 0 outside its 5 registers");
    CHECK_STR(read_patched(data, size, uuse + 8 + 4, 0xfffffffeu, err, sizeof err),
              "hfxo: program 0 puts parameter 0 outside its 5 registers");
    /* A switch (HFX_FX_USE_SWITCH) on a packed float matrix, and on the struct array. */
    CHECK_STR(read_patched(data, size, uuse + 8 + 8, 1, err, sizeof err),
              "hfxo: program 0 has a switch that is not a bool parameter of its own (or more than 4)");
    CHECK_STR(read_patched(data, size, uuse + 8 + 12 + 8, 1, err, sizeof err),
              "hfxo: program 0 has a switch that is not a bool parameter of its own (or more than 4)");
    /* A preshader (program, first, words, reg, rows, cols) writing past the registers, its
     * code reading past the values, its code outside PCOD, its program missing. */
    uint32_t pres = section_at(b, "PRES"), pcod = section_at(b, "PCOD");
    CHECK(pres != 0 && pcod != 0);
    CHECK_STR(read_patched(data, size, pres + 8 + 3 * 4, 5, err, sizeof err),
              "hfxo: program 0 has preshader 0 outside its 5 registers");
    CHECK_STR(read_patched(data, size, pres + 8 + 4 * 4, 2, err, sizeof err),
              "hfxo: program 0 has preshader 0 outside its 5 registers");
    CHECK_STR(read_patched(data, size, pcod + 4 + 4, 20, err, sizeof err),
              "hfxo: program 0, preshader 0: expression word 0: a parameter outside the values");
    CHECK_STR(read_patched(data, size, pres + 8 + 2 * 4, 5, err, sizeof err),
              "hfxo: preshader 0 has its code outside PCOD");
    CHECK_STR(read_patched(data, size, pres + 8, 1, err, sizeof err),
              "hfxo: preshader 0 names a missing program, or its program's come apart");
    CHECK_STR(read_patched(data, size, uuse + 8 + 12 + 4, 0, err, sizeof err),
              "hfxo: program 0 packs parameter 2, which cannot be packed");
    CHECK_STR(read_patched(data, size, prog + 8 + 23 * 4, 4096, err, sizeof err), "accepted");
    /* Records too short for version 2. */
    CHECK_STR(read_patched(data, size, parm + 4, 8, err, sizeof err), "hfxo: section PARM has records of 8 bytes");
    /* A section claimed to lie beyond the end of the file. */
    CHECK_STR(read_patched(data, size, 24 + 4, (uint32_t)size + 4, err, sizeof err),
              "hfxo: section 0 lies outside the file");
    /* The string table must end with its NUL. */
    uint32_t strs_size = 0;
    for (uint32_t i = 0; i < get32(b + 20); i++)
        if (memcmp(b + 24 + 12 * i, "STRS", 4) == 0) strs_size = get32(b + 24 + 12 * i + 8);
    CHECK(strs_size >= 4);
    uint8_t *copy = malloc(size);
    memcpy(copy, data, size);
    copy[strs + strs_size - 1] = 'x';
    put32(copy + 12, crc32_bitwise(copy + 16, size - 16));
    CHECK(hfx_fx_read_hfxo(copy, size, err, sizeof err) == NULL);
    CHECK_STR(err, "hfxo: the string table does not end with a NUL");
    free(copy);
    hfx_fx_effect_free(fx);
    free(data);
}

/* The sample effect plus an EXPR state: AlphaRef = (color.x * 255) as a program. */
static hfx_fx_effect *effect_with_expression(uint32_t *state) {
    hfx_fx_effect *fx = sample_effect();
    *state = fx->state_count;
    fx->states = realloc(fx->states, (fx->state_count + 1) * sizeof *fx->states);
    fx->states[fx->state_count++] = (hfx_fx_state){HFX_ST_ALPHAREF, 0, HFX_FX_VALUE_EXPR, 5, 0, {0}, 0, 3, 7, 0};
    const uint32_t code[5] = {hfx_evc_word(HFX_EVC_PARAM, HFX_EV_FLOAT, 1), 16, hfx_evc_word(HFX_EVC_CONST, HFX_EV_FLOAT, 1),
                              f2u(255.0f), hfx_evc_word(HFX_EVC_BINARY, HFX_EV_MUL, 0)};
    fx->expr_words = 5;
    fx->exprs = malloc(sizeof code);
    memcpy(fx->exprs, code, sizeof code);
    return fx;
}

/* EXPR programs are validated as they are read: a bad instruction, a parameter read outside
 * the values, a program outside its section; and no changed byte makes the reader crash. */
static void hostile_expressions_are_refused(void) {
    uint32_t k;
    hfx_fx_effect *fx = effect_with_expression(&k);
    void *data = NULL;
    size_t size = 0;
    CHECK_INT(hfx_fx_write_hfxo(fx, &data, &size), 0);
    char err[256];
    hfx_fx_effect *back = hfx_fx_read_hfxo(data, size, err, sizeof err);
    CHECK(back && back->expr_words == 5 && back->states[k].kind == HFX_FX_VALUE_EXPR &&
          memcmp(back->exprs, fx->exprs, 5 * sizeof *fx->exprs) == 0);
    hfx_fx_effect_free(back);
    const uint8_t *b = data;
    uint32_t expr = section_at(b, "EXPR"), stat = section_at(b, "STAT");
    CHECK(expr && stat);
    char want[128];
    snprintf(want, sizeof want, "hfxo: state %u: expression word 0: an unknown instruction", k);
    CHECK_STR(read_patched(data, size, expr + 4, 99, err, sizeof err), want);
    snprintf(want, sizeof want, "hfxo: state %u: expression word 0: a parameter outside the values", k);
    CHECK_STR(read_patched(data, size, expr + 8, 28, err, sizeof err), want); /* 28 + 1 > 28 words */
    CHECK_STR(read_patched(data, size, expr + 8, 27, err, sizeof err), "accepted");
    snprintf(want, sizeof want, "hfxo: state %u has its program outside EXPR", k);
    CHECK_STR(read_patched(data, size, stat + 8 + k * 48 + 3 * 4, 6, err, sizeof err), want);
    snprintf(want, sizeof want, "hfxo: state %u: expression word 4: takes more values than the stack holds", k);
    CHECK_STR(read_patched(data, size, expr + 4 + 2 * 4, hfx_evc_word(HFX_EVC_SWIZZLE, 1, 0), err, sizeof err), want);
    /* every bit of every byte flipped, the checksum fixed: refused or valid, never a bad read */
    uint8_t *copy = malloc(size);
    for (size_t at = 16; at < size; at++)
        for (int bit = 0; bit < 8; bit++) {
            memcpy(copy, data, size);
            copy[at] ^= (uint8_t)(1u << bit);
            put32(copy + 12, crc32_bitwise(copy + 16, size - 16));
            hfx_fx_effect_free(hfx_fx_read_hfxo(copy, size, NULL, 0));
        }
    free(copy);
    hfx_fx_effect_free(fx);
    free(data);
}

int main(void) {
    RUN(round_trip);
    RUN(empty_effect_round_trips);
    RUN(every_truncation_is_refused);
    RUN(every_flipped_byte_is_refused);
    RUN(hostile_contents_are_refused);
    RUN(hostile_expressions_are_refused);
    return test_summary();
}
