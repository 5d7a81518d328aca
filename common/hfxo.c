/* hfxo.c: the .hfxo file, a compiled effect on disk (docs/hfxo-format.md). Little-endian,
 * versioned, CRC-32 checked, made of sections whose tables say their own record size. The
 * reader trusts nothing: every offset, count, size and cross reference is checked before use,
 * so a truncated, corrupted or hostile file gives a message and NULL, never a bad read. */
#include "effect.h"

#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "bytes.h"
#include "eval_code.h"
#include "states.h"

#define HFXO_VERSION 3u /* 3: preshaders (PRES, PCOD); 2: registers of HFXC_PACK_UNIFORMS (EXPR was added as an optional section) */
#define HFXO_OLDEST 2u  /* version 2 files read as they are: they have no preshaders */
#define HFXO_HEADER 20u /* magic 8, version, checksum, total size; then the section count */
#define NO_STRING 0xffffffffu

static const uint8_t magic[8] = {0x89, 'H', 'F', 'X', 'O', '\r', '\n', 0x1a};

#define FOURCC(a, b, c, d) ((uint32_t)(a) | (uint32_t)(b) << 8 | (uint32_t)(c) << 16 | (uint32_t)(d) << 24)
enum {
    SEC_STRINGS = FOURCC('S', 'T', 'R', 'S'), SEC_EFFECT = FOURCC('E', 'F', 'C', 'T'),
    SEC_PARAMS = FOURCC('P', 'A', 'R', 'M'), SEC_VALUES = FOURCC('V', 'A', 'L', 'S'),
    SEC_ANNOTATIONS = FOURCC('A', 'N', 'N', 'O'), SEC_ANNOTATION_DATA = FOURCC('A', 'D', 'A', 'T'),
    SEC_STATES = FOURCC('S', 'T', 'A', 'T'), SEC_SAMPLERS = FOURCC('S', 'A', 'M', 'P'),
    SEC_PROGRAMS = FOURCC('P', 'R', 'O', 'G'), SEC_ATTRIBUTES = FOURCC('A', 'T', 'T', 'R'),
    SEC_SAMPLER_USES = FOURCC('S', 'U', 'S', 'E'), SEC_UNIFORM_USES = FOURCC('U', 'U', 'S', 'E'),
    SEC_PASSES = FOURCC('P', 'A', 'S', 'S'), SEC_TECHNIQUES = FOURCC('T', 'E', 'C', 'H'),
    SEC_CODE = FOURCC('C', 'O', 'D', 'E'), SEC_EXPRS = FOURCC('E', 'X', 'P', 'R'),
    SEC_VARIANTS = FOURCC('V', 'A', 'R', 'I'), SEC_PRESHADERS = FOURCC('P', 'R', 'E', 'S'),
    SEC_PRE_CODE = FOURCC('P', 'C', 'O', 'D')
};

/* Words per record in version 2 (readers accept longer records and ignore the tail). PARM
 * records grew by 3 (file, line, col) within version 2: readers take 18 or more. */
enum {
    R_EFFECT = 3, R_PARAM = 18, R_PARAM_WRITTEN = 21, R_ANNOTATION = 8, R_STATE = 12, R_SAMPLER = 5,
    P_CODE = 7, P_REG_COUNT = P_CODE + 2 * HFX_STAGE_COUNT * HFX_TARGET_SPIRV_VK, /* program record fields */
    R_PROGRAM = P_REG_COUNT + 1, R_ATTRIBUTE = 3, R_SAMPLER_USE = 3,
    /* Vulkan's SPIR-V came later within version 2: at the program record's tail, which older
     * readers skip; a record without it has no Vulkan code */
    P_VK_CODE = R_PROGRAM, R_PROGRAM_WRITTEN = P_VK_CODE + 2 * HFX_STAGE_COUNT,
    R_UNIFORM_USE = 2, R_UNIFORM_USE_WRITTEN = 3, R_PASS = 6, R_TECHNIQUE = 5, R_VARIANT = 4, R_PRESHADER = 6
};

/* CRC-32 (IEEE 802.3) by zlib, whose crc32 works on words: a byte-table loop was 7% of a
 * compile (it runs over every emitted shader). */
static uint32_t crc32_of(const uint8_t *p, size_t n) {
    uLong crc = crc32(0L, Z_NULL, 0);
    while (n > 0) { /* zlib takes a uInt length */
        uInt chunk = n > 0x40000000u ? 0x40000000u : (uInt)n;
        crc = crc32(crc, p, chunk);
        p += chunk;
        n -= chunk;
    }
    return (uint32_t)crc;
}

static uint32_t rd32(const uint8_t *p) { return hfx_le32(p); }

/* ============================== writer ============================== */

typedef struct wbuf {
    uint8_t *data;
    size_t size, cap;
    bool failed;
} wbuf;

static void put_bytes(wbuf *b, const void *p, size_t n) {
    if (b->failed) return;
    if (b->size + n > b->cap) {
        size_t cap = b->cap ? b->cap : 1024;
        while (cap < b->size + n) cap *= 2;
        uint8_t *d = realloc(b->data, cap);
        if (!d) {
            b->failed = true;
            return;
        }
        b->data = d;
        b->cap = cap;
    }
    if (n) memcpy(b->data + b->size, p, n);
    b->size += n;
}

static void put32(wbuf *b, uint32_t v) {
    uint8_t q[4] = {(uint8_t)v, (uint8_t)(v >> 8), (uint8_t)(v >> 16), (uint8_t)(v >> 24)};
    put_bytes(b, q, 4);
}

static void set32(wbuf *b, size_t at, uint32_t v) {
    if (b->failed) return;
    b->data[at] = (uint8_t)v;
    b->data[at + 1] = (uint8_t)(v >> 8);
    b->data[at + 2] = (uint8_t)(v >> 16);
    b->data[at + 3] = (uint8_t)(v >> 24);
}

static void align4(wbuf *b) {
    static const uint8_t zero[4] = {0};
    put_bytes(b, zero, (4 - b->size % 4) % 4);
}

/* The string pool: each distinct string once, found again through a hash table. */
typedef struct strpool {
    wbuf text;
    uint32_t *slots; /* offset + 1, 0 = empty */
    size_t slot_count, used;
} strpool;

static uint32_t hash_str(const char *s) {
    uint32_t h = 2166136261u;
    for (; *s; s++) h = (h ^ (uint8_t)*s) * 16777619u;
    return h;
}

static bool pool_rehash(strpool *sp) {
    size_t n = sp->slot_count ? sp->slot_count * 2 : 256;
    uint32_t *slots = calloc(n, sizeof *slots);
    if (!slots) return false;
    for (size_t i = 0; i < sp->slot_count; i++) {
        if (!sp->slots[i]) continue;
        size_t j = hash_str((const char *)sp->text.data + sp->slots[i] - 1) & (n - 1);
        while (slots[j]) j = (j + 1) & (n - 1);
        slots[j] = sp->slots[i];
    }
    free(sp->slots);
    sp->slots = slots;
    sp->slot_count = n;
    return true;
}

static uint32_t pool_add(strpool *sp, const char *s) {
    if (!s) return NO_STRING;
    if ((sp->used + 1) * 2 > sp->slot_count && !pool_rehash(sp)) {
        sp->text.failed = true;
        return NO_STRING;
    }
    size_t j = hash_str(s) & (sp->slot_count - 1);
    for (; sp->slots[j]; j = (j + 1) & (sp->slot_count - 1))
        if (!sp->text.failed && strcmp((const char *)sp->text.data + sp->slots[j] - 1, s) == 0) return sp->slots[j] - 1;
    uint32_t off = (uint32_t)sp->text.size;
    put_bytes(&sp->text, s, strlen(s) + 1);
    sp->slots[j] = off + 1;
    sp->used++;
    return off;
}

/* Writer state: the section being written and the table of sections. */
typedef struct writer {
    wbuf out;
    strpool strings;
    wbuf code;
    uint32_t ids[32], offsets[32], sizes[32], count; /* room for SECTION_COUNT (static assert below) */
    size_t open_at;
} writer;

static void section_begin(writer *w, uint32_t id) {
    align4(&w->out);
    w->ids[w->count] = id;
    w->open_at = w->out.size;
}

static void section_end(writer *w) {
    w->offsets[w->count] = (uint32_t)w->open_at;
    w->sizes[w->count] = (uint32_t)(w->out.size - w->open_at);
    w->count++;
}

static void table_begin(writer *w, uint32_t id, uint32_t count, uint32_t words) {
    section_begin(w, id);
    put32(&w->out, count);
    put32(&w->out, words * 4);
}

static uint32_t str(writer *w, const char *s) { return pool_add(&w->strings, s); }

static void write_params(writer *w, const hfx_fx_effect *fx) {
    table_begin(w, SEC_PARAMS, fx->param_count, R_PARAM_WRITTEN);
    for (uint32_t i = 0; i < fx->param_count; i++) {
        const hfx_fx_param *p = &fx->params[i];
        uint32_t r[R_PARAM_WRITTEN] = {str(w, p->name), str(w, p->semantic), str(w, p->glsl_name), str(w, p->string),
                                       (uint32_t)p->klass, (uint32_t)p->type, p->rows, p->cols, p->elements, p->parent,
                                       p->first_child, p->child_count, p->offset, p->words, p->first_annotation,
                                       p->annotation_count, p->sampler, p->flags, str(w, p->file), p->line, p->col};
        for (int k = 0; k < R_PARAM_WRITTEN; k++) put32(&w->out, r[k]);
    }
    section_end(w);
    section_begin(w, SEC_VALUES);
    put32(&w->out, fx->value_words);
    for (uint32_t i = 0; i < fx->value_words; i++) put32(&w->out, fx->values[i]);
    section_end(w);
}

static void write_annotations(writer *w, const hfx_fx_effect *fx) {
    uint32_t data = 0;
    table_begin(w, SEC_ANNOTATIONS, fx->annotation_count, R_ANNOTATION);
    for (uint32_t i = 0; i < fx->annotation_count; i++) {
        const hfx_fx_annotation *a = &fx->annotations[i];
        uint32_t r[R_ANNOTATION] = {str(w, a->name), (uint32_t)a->type, (uint32_t)a->klass, a->rows, a->cols,
                                    a->count, data, str(w, a->string)};
        for (int k = 0; k < R_ANNOTATION; k++) put32(&w->out, r[k]);
        data += a->count;
    }
    section_end(w);
    section_begin(w, SEC_ANNOTATION_DATA);
    put32(&w->out, data);
    for (uint32_t i = 0; i < fx->annotation_count; i++)
        for (uint32_t k = 0; k < fx->annotations[i].count; k++) put32(&w->out, fx->annotations[i].data[k]);
    section_end(w);
}

static void write_states(writer *w, const hfx_fx_effect *fx) {
    table_begin(w, SEC_STATES, fx->state_count, R_STATE);
    for (uint32_t i = 0; i < fx->state_count; i++) {
        const hfx_fx_state *s = &fx->states[i];
        uint32_t f[4];
        memcpy(f, s->f, sizeof f);
        uint32_t r[R_STATE] = {s->id, s->index, (uint32_t)s->kind, s->count, (uint32_t)s->i, f[0], f[1], f[2], f[3],
                               s->ref, s->line, s->col};
        for (int k = 0; k < R_STATE; k++) put32(&w->out, r[k]);
    }
    section_end(w);
    section_begin(w, SEC_EXPRS);
    put32(&w->out, fx->expr_words);
    for (uint32_t i = 0; i < fx->expr_words; i++) put32(&w->out, fx->exprs[i]);
    section_end(w);
    table_begin(w, SEC_SAMPLERS, fx->sampler_count, R_SAMPLER);
    for (uint32_t i = 0; i < fx->sampler_count; i++) {
        const hfx_fx_sampler *s = &fx->samplers[i];
        uint32_t r[R_SAMPLER] = {s->param, s->texture_param, (uint32_t)s->dim, s->first_state, s->state_count};
        for (int k = 0; k < R_SAMPLER; k++) put32(&w->out, r[k]);
    }
    section_end(w);
}

/* One stage's code for one target: its place in the CODE section and its size. */
static void put_code(writer *w, const hfx_fx_code *c) {
    bool has = c->data != NULL;
    put32(&w->out, has ? (uint32_t)w->code.size : NO_STRING);
    put32(&w->out, has ? (uint32_t)c->size : 0);
    if (has) put_bytes(&w->code, c->data, c->size);
}

static void write_programs(writer *w, const hfx_fx_effect *fx) {
    uint32_t attrs = 0, samplers = 0, uniforms = 0;
    table_begin(w, SEC_PROGRAMS, fx->program_count, R_PROGRAM_WRITTEN);
    for (uint32_t i = 0; i < fx->program_count; i++) {
        const hfx_fx_program *p = &fx->programs[i];
        uint32_t r[7] = {p->flags, attrs, p->attribute_count, samplers, p->sampler_count, uniforms, p->uniform_count};
        for (int k = 0; k < 7; k++) put32(&w->out, r[k]);
        for (int s = 0; s < HFX_STAGE_COUNT; s++)
            for (int t = 0; t < HFX_TARGET_SPIRV_VK; t++) put_code(w, &p->code[s][t]);
        put32(&w->out, p->reg_count);
        for (int s = 0; s < HFX_STAGE_COUNT; s++) put_code(w, &p->code[s][HFX_TARGET_SPIRV_VK]);
        attrs += p->attribute_count;
        samplers += p->sampler_count;
        uniforms += p->uniform_count;
    }
    section_end(w);
    table_begin(w, SEC_ATTRIBUTES, attrs, R_ATTRIBUTE);
    for (uint32_t i = 0; i < fx->program_count; i++)
        for (uint32_t a = 0; a < fx->programs[i].attribute_count; a++) {
            const hfx_fx_attribute *at = &fx->programs[i].attributes[a];
            put32(&w->out, str(w, at->semantic));
            put32(&w->out, str(w, at->glsl_name));
            put32(&w->out, (uint32_t)at->location);
        }
    section_end(w);
    table_begin(w, SEC_SAMPLER_USES, samplers, R_SAMPLER_USE);
    for (uint32_t i = 0; i < fx->program_count; i++)
        for (uint32_t a = 0; a < fx->programs[i].sampler_count; a++) {
            const hfx_fx_sampler_use *u = &fx->programs[i].samplers[a];
            put32(&w->out, str(w, u->glsl_name));
            put32(&w->out, u->sampler);
            put32(&w->out, (uint32_t)u->unit);
        }
    section_end(w);
    table_begin(w, SEC_UNIFORM_USES, uniforms, R_UNIFORM_USE_WRITTEN);
    for (uint32_t i = 0; i < fx->program_count; i++)
        for (uint32_t a = 0; a < fx->programs[i].uniform_count; a++) {
            put32(&w->out, fx->programs[i].uniforms[a].param);
            put32(&w->out, fx->programs[i].uniforms[a].reg);
            put32(&w->out, fx->programs[i].uniforms[a].flags);
        }
    section_end(w);
}

/* Preshaders of every program in program order, each record naming its program; their code
 * words one program after another. */
static void write_preshaders(writer *w, const hfx_fx_effect *fx) {
    uint32_t count = 0, base = 0;
    for (uint32_t i = 0; i < fx->program_count; i++) count += fx->programs[i].preshader_count;
    table_begin(w, SEC_PRESHADERS, count, R_PRESHADER);
    for (uint32_t i = 0; i < fx->program_count; i++) {
        const hfx_fx_program *p = &fx->programs[i];
        for (uint32_t k = 0; k < p->preshader_count; k++) {
            const hfx_fx_preshader *q = &p->preshaders[k];
            uint32_t r[R_PRESHADER] = {i, base + q->first, q->words, q->reg, q->rows, q->cols};
            for (int f = 0; f < R_PRESHADER; f++) put32(&w->out, r[f]);
        }
        base += p->pre_words;
    }
    section_end(w);
    section_begin(w, SEC_PRE_CODE);
    put32(&w->out, base);
    for (uint32_t i = 0; i < fx->program_count; i++)
        for (uint32_t k = 0; k < fx->programs[i].pre_words; k++) put32(&w->out, fx->programs[i].pre_code[k]);
    section_end(w);
}

static void write_techniques(writer *w, const hfx_fx_effect *fx) {
    table_begin(w, SEC_PASSES, fx->pass_count, R_PASS);
    for (uint32_t i = 0; i < fx->pass_count; i++) {
        const hfx_fx_pass *p = &fx->passes[i];
        uint32_t r[R_PASS] = {str(w, p->name), p->first_annotation, p->annotation_count, p->first_state,
                              p->state_count, p->program};
        for (int k = 0; k < R_PASS; k++) put32(&w->out, r[k]);
    }
    section_end(w);
    table_begin(w, SEC_VARIANTS, fx->variant_count, R_VARIANT);
    for (uint32_t i = 0; i < fx->variant_count; i++) {
        const hfx_fx_variant *v = &fx->variants[i];
        uint32_t r[R_VARIANT] = {v->pass, v->vs, v->ps, v->program};
        for (int k = 0; k < R_VARIANT; k++) put32(&w->out, r[k]);
    }
    section_end(w);
    table_begin(w, SEC_TECHNIQUES, fx->technique_count, R_TECHNIQUE);
    for (uint32_t i = 0; i < fx->technique_count; i++) {
        const hfx_fx_technique *t = &fx->techniques[i];
        uint32_t r[R_TECHNIQUE] = {str(w, t->name), t->first_annotation, t->annotation_count, t->first_pass,
                                   t->pass_count};
        for (int k = 0; k < R_TECHNIQUE; k++) put32(&w->out, r[k]);
    }
    section_end(w);
}

enum { SECTION_COUNT = 19 };
_Static_assert(SECTION_COUNT <= 32, "the writer's section table holds 32");

int hfx_fx_write_hfxo(const hfx_fx_effect *fx, void **out, size_t *out_size) {
    if (!fx || !out || !out_size) return -1;
    writer w;
    memset(&w, 0, sizeof w);
    put_bytes(&w.out, magic, sizeof magic);
    put32(&w.out, HFXO_VERSION);
    put32(&w.out, 0); /* checksum */
    put32(&w.out, 0); /* total size */
    put32(&w.out, SECTION_COUNT);
    size_t table_at = w.out.size;
    for (int i = 0; i < SECTION_COUNT * 3; i++) put32(&w.out, 0);
    table_begin(&w, SEC_EFFECT, 1, R_EFFECT);
    put32(&w.out, str(&w, fx->source_name ? fx->source_name : ""));
    put32(&w.out, fx->targets);
    put32(&w.out, fx->top_param_count);
    section_end(&w);
    write_params(&w, fx);
    write_annotations(&w, fx);
    write_states(&w, fx);
    write_programs(&w, fx);
    write_preshaders(&w, fx);
    write_techniques(&w, fx);
    section_begin(&w, SEC_CODE);
    put_bytes(&w.out, w.code.data, w.code.size);
    section_end(&w);
    section_begin(&w, SEC_STRINGS);
    put_bytes(&w.out, w.strings.text.data, w.strings.text.size);
    section_end(&w);
    align4(&w.out);
    bool failed = w.out.failed || w.code.failed || w.strings.text.failed || w.count != SECTION_COUNT ||
                  w.out.size > 0xffffffffu;
    if (!failed) {
        for (uint32_t i = 0; i < w.count; i++) {
            set32(&w.out, table_at + 12 * i, w.ids[i]);
            set32(&w.out, table_at + 12 * i + 4, w.offsets[i]);
            set32(&w.out, table_at + 12 * i + 8, w.sizes[i]);
        }
        set32(&w.out, 16, (uint32_t)w.out.size);
        set32(&w.out, 12, crc32_of(w.out.data + 16, w.out.size - 16));
    }
    free(w.code.data);
    free(w.strings.text.data);
    free(w.strings.slots);
    if (failed) {
        free(w.out.data);
        return -1;
    }
    *out = w.out.data;
    *out_size = w.out.size;
    return 0;
}

int hfx_fx_is_hfxo(const void *data, size_t size) {
    return data && size >= sizeof magic && memcmp(data, magic, sizeof magic) == 0;
}

/* ============================== reader ============================== */

typedef struct table {
    const uint8_t *p;
    uint32_t count, stride; /* stride in bytes */
} table;

typedef struct reader {
    const uint8_t *d;
    size_t size;
    char *err;
    size_t err_size;
    bool failed;
    const char *strings;
    uint32_t strings_size;
    const uint8_t *code;
    uint32_t code_size;
    table t_effect, t_params, t_annotations, t_states, t_samplers, t_programs, t_attributes, t_sampler_uses,
        t_uniform_uses, t_passes, t_techniques, t_variants, t_preshaders;
    const uint8_t *values, *adata, *exprs, *pre_code;
    uint32_t value_words, adata_words, expr_words, pre_words;
    uint32_t version;
} reader;

__attribute__((format(printf, 2, 3))) static bool fail(reader *r, const char *fmt, ...) {
    if (r->failed) return false;
    r->failed = true;
    if (r->err && r->err_size) {
        int n = snprintf(r->err, r->err_size, "hfxo: ");
        va_list ap;
        va_start(ap, fmt);
        if (n >= 0 && (size_t)n < r->err_size) vsnprintf(r->err + n, r->err_size - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return false;
}

static uint32_t field(const table *t, uint32_t i, uint32_t k) { return rd32(t->p + (size_t)i * t->stride + 4u * k); }

/* A range [first, first + count) inside [0, limit); an empty range may say HFX_NONE. */
static bool range_ok(uint32_t first, uint32_t count, uint32_t limit) {
    if (count == 0) return first == HFX_NONE || first <= limit;
    return first <= limit && count <= limit - first;
}

static bool ref_ok(uint32_t ref, uint32_t limit) { return ref == HFX_NONE || ref < limit; }

static bool open_table(reader *r, const uint8_t *p, uint32_t size, uint32_t words, table *t, const char *what) {
    if (size < 8) return fail(r, "section %s is too short", what);
    t->count = rd32(p);
    t->stride = rd32(p + 4);
    t->p = p + 8;
    if (t->stride < words * 4 || t->stride % 4) return fail(r, "section %s has records of %u bytes", what, t->stride);
    if ((uint64_t)t->count * t->stride > size - 8) return fail(r, "section %s holds %u records, more than fit", what, t->count);
    return true;
}

static bool open_words(reader *r, const uint8_t *p, uint32_t size, const uint8_t **words, uint32_t *count,
                       const char *what) {
    if (size < 4) return fail(r, "section %s is too short", what);
    *count = rd32(p);
    *words = p + 4;
    if ((uint64_t)*count * 4 > size - 4) return fail(r, "section %s holds %u words, more than fit", what, *count);
    return true;
}

static bool open_section(reader *r, uint32_t id, const uint8_t *p, uint32_t size) {
    switch (id) {
    case SEC_STRINGS:
        if (size && p[size - 1] != 0) return fail(r, "the string table does not end with a NUL");
        r->strings = (const char *)p;
        r->strings_size = size;
        return true;
    case SEC_CODE: r->code = p; r->code_size = size; return true;
    case SEC_EFFECT: return open_table(r, p, size, R_EFFECT, &r->t_effect, "EFCT");
    case SEC_PARAMS: return open_table(r, p, size, R_PARAM, &r->t_params, "PARM");
    case SEC_VALUES: return open_words(r, p, size, &r->values, &r->value_words, "VALS");
    case SEC_ANNOTATIONS: return open_table(r, p, size, R_ANNOTATION, &r->t_annotations, "ANNO");
    case SEC_ANNOTATION_DATA: return open_words(r, p, size, &r->adata, &r->adata_words, "ADAT");
    case SEC_STATES: return open_table(r, p, size, R_STATE, &r->t_states, "STAT");
    case SEC_VARIANTS: /* optional, as EXPR */
        if (r->t_variants.p) return fail(r, "section VARI repeats");
        return open_table(r, p, size, R_VARIANT, &r->t_variants, "VARI");
    case SEC_EXPRS: /* optional (older files have none), but only once */
        if (r->exprs) return fail(r, "section EXPR repeats");
        return open_words(r, p, size, &r->exprs, &r->expr_words, "EXPR");
    case SEC_PRESHADERS: /* optional (version 2 has none) */
        if (r->version < 3) return fail(r, "a version %u file with preshaders (they came in version 3)", r->version);
        if (r->t_preshaders.p) return fail(r, "section PRES repeats");
        return open_table(r, p, size, R_PRESHADER, &r->t_preshaders, "PRES");
    case SEC_PRE_CODE:
        if (r->pre_code) return fail(r, "section PCOD repeats");
        return open_words(r, p, size, &r->pre_code, &r->pre_words, "PCOD");
    case SEC_SAMPLERS: return open_table(r, p, size, R_SAMPLER, &r->t_samplers, "SAMP");
    case SEC_PROGRAMS: return open_table(r, p, size, R_PROGRAM, &r->t_programs, "PROG");
    case SEC_ATTRIBUTES: return open_table(r, p, size, R_ATTRIBUTE, &r->t_attributes, "ATTR");
    case SEC_SAMPLER_USES: return open_table(r, p, size, R_SAMPLER_USE, &r->t_sampler_uses, "SUSE");
    case SEC_UNIFORM_USES: return open_table(r, p, size, R_UNIFORM_USE, &r->t_uniform_uses, "UUSE");
    case SEC_PASSES: return open_table(r, p, size, R_PASS, &r->t_passes, "PASS");
    case SEC_TECHNIQUES: return open_table(r, p, size, R_TECHNIQUE, &r->t_techniques, "TECH");
    default: return true; /* a later version's section: skipped */
    }
}

static bool read_header(reader *r) {
    const uint8_t *d = r->d;
    size_t m = r->size < sizeof magic ? r->size : sizeof magic;
    if (memcmp(d, magic, m) != 0) return fail(r, "not an .hfxo file (bad magic number)");
    if (r->size < HFXO_HEADER + 4) return fail(r, "file is %zu bytes, too short for the header (truncated?)", r->size);
    uint32_t version = r->version = rd32(d + 8);
    if (version < HFXO_OLDEST) /* nothing was released before version 2: no conversion */
        return fail(r, "format version %u is older than this reader's %u: compile the .fx again", version, HFXO_OLDEST);
    if (version > HFXO_VERSION) return fail(r, "format version %u is not supported (this reader knows %u)", version, HFXO_VERSION);
    if (rd32(d + 16) != r->size) return fail(r, "file is %zu bytes but its header says %u (truncated?)", r->size, rd32(d + 16));
    if (crc32_of(d + 16, r->size - 16) != rd32(d + 12)) return fail(r, "checksum mismatch (the file is corrupted)");
    uint32_t sections = rd32(d + 20);
    size_t table_end = HFXO_HEADER + 4 + (size_t)sections * 12;
    if (sections > 1024 || table_end > r->size) return fail(r, "section table of %u entries does not fit", sections);
    uint32_t seen = 0;
    static const uint32_t required[] = {SEC_STRINGS, SEC_EFFECT, SEC_PARAMS, SEC_VALUES, SEC_ANNOTATIONS,
                                        SEC_ANNOTATION_DATA, SEC_STATES, SEC_SAMPLERS, SEC_PROGRAMS, SEC_ATTRIBUTES,
                                        SEC_SAMPLER_USES, SEC_UNIFORM_USES, SEC_PASSES, SEC_TECHNIQUES, SEC_CODE};
    for (uint32_t i = 0; i < sections; i++) {
        const uint8_t *e = d + HFXO_HEADER + 4 + 12 * i;
        uint32_t id = rd32(e), off = rd32(e + 4), size = rd32(e + 8);
        if (off < table_end || off > r->size || size > r->size - off || off % 4)
            return fail(r, "section %u lies outside the file", i);
        for (uint32_t k = 0; k < sizeof required / sizeof *required; k++)
            if (required[k] == id) {
                if (seen & (1u << k)) return fail(r, "section %u repeats an earlier one", i);
                seen |= 1u << k;
            }
        if (!open_section(r, id, d + off, size)) return false;
    }
    if (seen != (1u << (sizeof required / sizeof *required)) - 1) return fail(r, "a required section is missing");
    if (r->t_effect.count != 1) return fail(r, "the effect record is missing");
    return true;
}

/* A string reference: NULL for NO_STRING when allowed, else a malloc'ed copy. */
static bool get_string(reader *r, uint32_t ref, bool required, char **out) {
    *out = NULL;
    if (ref == NO_STRING) return required ? fail(r, "a required name is missing") : true;
    if (ref >= r->strings_size) return fail(r, "string offset %u is outside the string table", ref);
    *out = strdup(r->strings + ref);
    return *out ? true : fail(r, "out of memory");
}

static void *alloc_array(reader *r, uint32_t count, size_t elem) {
    void *p = calloc(count ? count : 1, elem);
    if (!p) fail(r, "out of memory");
    return p;
}

static bool read_params(reader *r, hfx_fx_effect *fx) {
    const table *t = &r->t_params;
    fx->param_count = t->count;
    if (!(fx->params = alloc_array(r, t->count, sizeof *fx->params))) return false;
    for (uint32_t i = 0; i < t->count; i++) {
        hfx_fx_param *p = &fx->params[i];
        if (!get_string(r, field(t, i, 0), true, &p->name) || !get_string(r, field(t, i, 1), false, &p->semantic) ||
            !get_string(r, field(t, i, 2), false, &p->glsl_name) || !get_string(r, field(t, i, 3), false, &p->string))
            return false;
        p->klass = (hfx_param_class)field(t, i, 4);
        p->type = (hfx_param_type)field(t, i, 5);
        p->rows = field(t, i, 6);
        p->cols = field(t, i, 7);
        p->elements = field(t, i, 8);
        p->parent = field(t, i, 9);
        p->first_child = field(t, i, 10);
        p->child_count = field(t, i, 11);
        p->offset = field(t, i, 12);
        p->words = field(t, i, 13);
        p->first_annotation = field(t, i, 14);
        p->annotation_count = field(t, i, 15);
        p->sampler = field(t, i, 16);
        p->flags = field(t, i, 17);
        if (t->stride >= 4 * R_PARAM_WRITTEN) {
            if (!get_string(r, field(t, i, 18), false, &p->file)) return false;
            p->line = field(t, i, 19);
            p->col = field(t, i, 20);
        }
    }
    fx->value_words = r->value_words;
    if (!(fx->values = alloc_array(r, r->value_words, sizeof *fx->values))) return false;
    for (uint32_t i = 0; i < r->value_words; i++) fx->values[i] = rd32(r->values + 4 * i);
    return true;
}

static bool read_annotations(reader *r, hfx_fx_effect *fx) {
    const table *t = &r->t_annotations;
    fx->annotation_count = t->count;
    if (!(fx->annotations = alloc_array(r, t->count, sizeof *fx->annotations))) return false;
    for (uint32_t i = 0; i < t->count; i++) {
        hfx_fx_annotation *a = &fx->annotations[i];
        if (!get_string(r, field(t, i, 0), true, &a->name) || !get_string(r, field(t, i, 7), false, &a->string))
            return false;
        a->type = (hfx_param_type)field(t, i, 1);
        a->klass = (hfx_param_class)field(t, i, 2);
        a->rows = field(t, i, 3);
        a->cols = field(t, i, 4);
        a->count = field(t, i, 5);
        uint32_t first = field(t, i, 6);
        if (a->count > 16 || !range_ok(first, a->count, r->adata_words))
            return fail(r, "annotation %u has data outside its section", i);
        if (a->count) {
            if (!(a->data = alloc_array(r, a->count, sizeof *a->data))) return false;
            for (uint32_t k = 0; k < a->count; k++) a->data[k] = rd32(r->adata + 4 * ((size_t)first + k));
        }
    }
    return true;
}

static bool read_states(reader *r, hfx_fx_effect *fx) {
    const table *t = &r->t_states;
    fx->expr_words = r->expr_words;
    if (!(fx->exprs = alloc_array(r, r->expr_words, sizeof *fx->exprs))) return false;
    for (uint32_t i = 0; i < r->expr_words; i++) fx->exprs[i] = rd32(r->exprs + 4 * i);
    fx->state_count = t->count;
    if (!(fx->states = alloc_array(r, t->count, sizeof *fx->states))) return false;
    for (uint32_t i = 0; i < t->count; i++) {
        hfx_fx_state *s = &fx->states[i];
        s->id = field(t, i, 0);
        s->index = field(t, i, 1);
        s->kind = (hfx_fx_value_kind)field(t, i, 2);
        s->count = field(t, i, 3);
        s->i = (int32_t)field(t, i, 4);
        for (int k = 0; k < 4; k++) {
            uint32_t bits = field(t, i, 5 + (uint32_t)k);
            memcpy(&s->f[k], &bits, sizeof bits);
        }
        s->ref = field(t, i, 9);
        s->line = field(t, i, 10);
        s->col = field(t, i, 11);
    }
    t = &r->t_samplers;
    fx->sampler_count = t->count;
    if (!(fx->samplers = alloc_array(r, t->count, sizeof *fx->samplers))) return false;
    for (uint32_t i = 0; i < t->count; i++) {
        hfx_fx_sampler *s = &fx->samplers[i];
        s->param = field(t, i, 0);
        s->texture_param = field(t, i, 1);
        s->dim = (hfx_fx_dim)field(t, i, 2);
        s->first_state = field(t, i, 3);
        s->state_count = field(t, i, 4);
    }
    return true;
}

static bool read_code(reader *r, uint32_t off, uint32_t size, hfx_fx_code *c) {
    if (off == NO_STRING) return size == 0 ? true : fail(r, "code without data");
    if (off > r->code_size || size > r->code_size - off) return fail(r, "shader code lies outside its section");
    if (!(c->data = malloc((size_t)size + 1))) return fail(r, "out of memory");
    memcpy(c->data, r->code + off, size);
    c->data[size] = 0;
    c->size = size;
    return true;
}

static bool read_program(reader *r, hfx_fx_program *p, uint32_t i) {
    const table *t = &r->t_programs;
    p->flags = field(t, i, 0);
    uint32_t af = field(t, i, 1), an = field(t, i, 2), sf = field(t, i, 3), sn = field(t, i, 4);
    uint32_t uf = field(t, i, 5), un = field(t, i, 6);
    if (!range_ok(af, an, r->t_attributes.count) || !range_ok(sf, sn, r->t_sampler_uses.count) ||
        !range_ok(uf, un, r->t_uniform_uses.count))
        return fail(r, "program %u refers to records that do not exist", i);
    for (uint32_t s = 0, k = P_CODE; s < HFX_STAGE_COUNT; s++)
        for (uint32_t g = 0; g < HFX_TARGET_SPIRV_VK; g++, k += 2)
            if (!read_code(r, field(t, i, k), field(t, i, k + 1), &p->code[s][g])) return false;
    for (uint32_t s = 0, k = P_VK_CODE; s < HFX_STAGE_COUNT && t->stride >= 4u * R_PROGRAM_WRITTEN; s++, k += 2)
        if (!read_code(r, field(t, i, k), field(t, i, k + 1), &p->code[s][HFX_TARGET_SPIRV_VK])) return false;
    if (!(p->attributes = alloc_array(r, an, sizeof *p->attributes))) return false;
    p->attribute_count = an;
    for (uint32_t a = 0; a < an; a++) {
        hfx_fx_attribute *at = &p->attributes[a];
        if (!get_string(r, field(&r->t_attributes, af + a, 0), true, &at->semantic) ||
            !get_string(r, field(&r->t_attributes, af + a, 1), true, &at->glsl_name))
            return false;
        at->location = (int32_t)field(&r->t_attributes, af + a, 2);
    }
    if (!(p->samplers = alloc_array(r, sn, sizeof *p->samplers))) return false;
    p->sampler_count = sn;
    for (uint32_t a = 0; a < sn; a++) {
        hfx_fx_sampler_use *u = &p->samplers[a];
        if (!get_string(r, field(&r->t_sampler_uses, sf + a, 0), true, &u->glsl_name)) return false;
        u->sampler = field(&r->t_sampler_uses, sf + a, 1);
        u->unit = (int32_t)field(&r->t_sampler_uses, sf + a, 2);
    }
    if (!(p->uniforms = alloc_array(r, un, sizeof *p->uniforms))) return false;
    p->uniform_count = un;
    for (uint32_t a = 0; a < un; a++) {
        p->uniforms[a].param = field(&r->t_uniform_uses, uf + a, 0);
        p->uniforms[a].reg = field(&r->t_uniform_uses, uf + a, 1);
        /* switches came later within version 3, at the record's tail: none in older files */
        if (r->t_uniform_uses.stride >= 4u * R_UNIFORM_USE_WRITTEN) p->uniforms[a].flags = field(&r->t_uniform_uses, uf + a, 2);
    }
    p->reg_count = field(t, i, P_REG_COUNT);
    return true;
}

static bool read_programs(reader *r, hfx_fx_effect *fx) {
    fx->program_count = r->t_programs.count;
    if (!(fx->programs = alloc_array(r, fx->program_count, sizeof *fx->programs))) return false;
    for (uint32_t i = 0; i < fx->program_count; i++)
        if (!read_program(r, &fx->programs[i], i)) return false;
    return true;
}

/* Program p's preshaders: the records [first, first + count) of PRES, their code copied out. */
static bool take_preshaders(reader *r, hfx_fx_program *p, uint32_t first, uint32_t count) {
    const table *t = &r->t_preshaders;
    uint32_t lo = field(t, first, 1), hi = lo;
    for (uint32_t k = first; k < first + count; k++) {
        uint32_t f = field(t, k, 1), n = field(t, k, 2);
        if (!range_ok(f, n, r->pre_words) || !n) return fail(r, "preshader %u has its code outside PCOD", k);
        if (f < lo) lo = f;
        if (f + n > hi) hi = f + n;
    }
    if (!(p->preshaders = alloc_array(r, count, sizeof *p->preshaders)) || !(p->pre_code = alloc_array(r, hi - lo, 4)))
        return false;
    p->preshader_count = count;
    p->pre_words = hi - lo;
    for (uint32_t k = 0; k < hi - lo; k++) p->pre_code[k] = rd32(r->pre_code + 4 * ((size_t)lo + k));
    for (uint32_t k = 0; k < count; k++)
        p->preshaders[k] = (hfx_fx_preshader){field(t, first + k, 1) - lo, field(t, first + k, 2), field(t, first + k, 3),
                                              field(t, first + k, 4), field(t, first + k, 5)};
    return true;
}

static bool read_preshaders(reader *r, hfx_fx_effect *fx) {
    const table *t = &r->t_preshaders;
    for (uint32_t k = 0; k < t->count;) {
        uint32_t prog = field(t, k, 0), n = 1;
        while (k + n < t->count && field(t, k + n, 0) == prog) n++;
        if (prog >= fx->program_count || fx->programs[prog].preshader_count)
            return fail(r, "preshader %u names a missing program, or its program's come apart", k);
        if (!take_preshaders(r, &fx->programs[prog], k, n)) return false;
        k += n;
    }
    return true;
}

static bool read_techniques(reader *r, hfx_fx_effect *fx) {
    const table *t = &r->t_passes;
    fx->pass_count = t->count;
    if (!(fx->passes = alloc_array(r, t->count, sizeof *fx->passes))) return false;
    for (uint32_t i = 0; i < t->count; i++) {
        hfx_fx_pass *p = &fx->passes[i];
        if (!get_string(r, field(t, i, 0), true, &p->name)) return false;
        p->first_annotation = field(t, i, 1);
        p->annotation_count = field(t, i, 2);
        p->first_state = field(t, i, 3);
        p->state_count = field(t, i, 4);
        p->program = field(t, i, 5);
    }
    t = &r->t_variants;
    fx->variant_count = t->count;
    if (!(fx->variants = alloc_array(r, t->count, sizeof *fx->variants))) return false;
    for (uint32_t i = 0; i < t->count; i++)
        fx->variants[i] = (hfx_fx_variant){field(t, i, 0), field(t, i, 1), field(t, i, 2), field(t, i, 3)};
    t = &r->t_techniques;
    fx->technique_count = t->count;
    if (!(fx->techniques = alloc_array(r, t->count, sizeof *fx->techniques))) return false;
    for (uint32_t i = 0; i < t->count; i++) {
        hfx_fx_technique *q = &fx->techniques[i];
        if (!get_string(r, field(t, i, 0), true, &q->name)) return false;
        q->first_annotation = field(t, i, 1);
        q->annotation_count = field(t, i, 2);
        q->first_pass = field(t, i, 3);
        q->pass_count = field(t, i, 4);
    }
    return true;
}

/* --- cross-reference checks: what the runtime relies on without looking ------------------ */

static bool numeric_class(hfx_param_class k) { return k == HFX_CLASS_SCALAR || k == HFX_CLASS_VECTOR || k == HFX_CLASS_MATRIX; }

static bool check_param(reader *r, const hfx_fx_effect *fx, uint32_t i) {
    const hfx_fx_param *p = &fx->params[i];
    if ((unsigned)p->klass > HFX_CLASS_STRUCT || (unsigned)p->type > HFX_TYPE_VERTEXSHADER)
        return fail(r, "parameter %u has an unknown class or type", i);
    if (p->rows > 4 || p->cols > 4) return fail(r, "parameter %u is larger than 4x4", i);
    if ((i < fx->top_param_count) != (p->parent == HFX_NONE)) return fail(r, "parameter %u has a wrong parent", i);
    if (!range_ok(p->offset, p->words, fx->value_words)) return fail(r, "parameter %u has values outside the buffer", i);
    if (numeric_class(p->klass) &&
        (uint64_t)p->words != (uint64_t)p->rows * p->cols * (p->elements ? p->elements : 1))
        return fail(r, "parameter %u has %u words for its size", i, p->words);
    if (p->klass == HFX_CLASS_OBJECT && p->words) return fail(r, "object parameter %u owns values", i);
    if (p->elements && p->child_count != p->elements) return fail(r, "array parameter %u lacks its elements", i);
    if (!range_ok(p->first_annotation, p->annotation_count, fx->annotation_count))
        return fail(r, "parameter %u has annotations that do not exist", i);
    if (p->sampler != HFX_NONE && (p->sampler >= fx->sampler_count || fx->samplers[p->sampler].param != i))
        return fail(r, "parameter %u names a wrong sampler", i);
    if (p->child_count == 0) return true;
    /* Children come after their parent, inside its values: the tree has no cycles. */
    if (!range_ok(p->first_child, p->child_count, fx->param_count) || p->first_child <= i)
        return fail(r, "parameter %u has children that do not exist", i);
    for (uint32_t c = p->first_child; c < p->first_child + p->child_count; c++) {
        const hfx_fx_param *k = &fx->params[c];
        if (k->parent != i || k->offset < p->offset || k->offset - p->offset > p->words ||
            k->words > p->words - (k->offset - p->offset))
            return fail(r, "parameter %u is not inside its parent %u", c, i);
    }
    return true;
}

static bool check_annotation(reader *r, const hfx_fx_annotation *a, uint32_t i) {
    if (a->type == HFX_TYPE_STRING) {
        if (!a->string || a->count) return fail(r, "string annotation %u has no string", i);
        return true;
    }
    if (a->type != HFX_TYPE_BOOL && a->type != HFX_TYPE_INT && a->type != HFX_TYPE_FLOAT)
        return fail(r, "annotation %u has an unknown type", i);
    if (!numeric_class(a->klass) || a->rows > 4 || a->cols > 4 || a->count != a->rows * a->cols || !a->count)
        return fail(r, "annotation %u has a wrong shape", i);
    return true;
}

static bool reads_parameters(const uint32_t *code, uint32_t words) {
    for (uint32_t at = 0; at < words; at = hfx_evc_next(code, at, words))
        if ((code[at] & 0xffu) == HFX_EVC_PARAM || (code[at] & 0xffu) == HFX_EVC_ELEMENT) return true;
    return false;
}

/* A shader-array selector (`PixelShader = (PSArray[i]);`) must leave one index. A program's
 * shape does not depend on the values, so one run tells; a program of constants that gives no
 * exact index (1e30, NaN, -1, 2.5) always would, and is refused too. Apply clamps the others. */
static bool check_selector(reader *r, const hfx_fx_effect *fx, const hfx_fx_state *s, uint32_t i) {
    hfx_ev_value v;
    if (!hfx_evc_run(fx->exprs + s->ref, s->count, fx->values, &v)) return true; /* kept at Apply */
    if (v.n != 1) return fail(r, "state %u: a shader array selector gives %u values, not one index", i, (unsigned)v.n);
    if (!reads_parameters(fx->exprs + s->ref, s->count) && hfx_evc_index(&v, HFX_NONE - 1) != v.c[0])
        return fail(r, "state %u: a shader array selector always gives %g, no array index", i, v.c[0]);
    return true;
}

/* An expression program: inside EXPR, and valid (eval_code.h), so Apply can run it blindly. */
static bool check_expr(reader *r, const hfx_fx_effect *fx, const hfx_fx_state *s, uint32_t i) {
    char why[96];
    if (!s->count || !range_ok(s->ref, s->count, fx->expr_words)) return fail(r, "state %u has its program outside EXPR", i);
    if (hfx_evc_validate(fx->exprs + s->ref, s->count, fx->value_words, why, sizeof why) != 0)
        return fail(r, "state %u: %s", i, why);
    return s->id == HFX_ST_VERTEXSHADER || s->id == HFX_ST_PIXELSHADER ? check_selector(r, fx, s, i) : true;
}

static bool check_state(reader *r, const hfx_fx_effect *fx, const hfx_fx_state *s, uint32_t i) {
    switch (s->kind) {
    case HFX_FX_VALUE_INT: case HFX_FX_VALUE_UNSUPPORTED: return true;
    case HFX_FX_VALUE_FLOAT: return s->count >= 1 && s->count <= 4 ? true : fail(r, "state %u has %u floats", i, s->count);
    case HFX_FX_VALUE_PARAM:
        if (!ref_ok(s->ref, fx->param_count)) return fail(r, "state %u names a missing parameter", i);
        /* A numeric state reads the parameter's words: it must have some. */
        if (s->ref != HFX_NONE && fx->params[s->ref].klass != HFX_CLASS_OBJECT && fx->params[s->ref].words == 0)
            return fail(r, "state %u reads a parameter without values", i);
        return true;
    case HFX_FX_VALUE_PROGRAM: return ref_ok(s->ref, fx->program_count) ? true : fail(r, "state %u names a missing program", i);
    case HFX_FX_VALUE_EXPR: return check_expr(r, fx, s, i);
    default: return fail(r, "state %u has an unknown kind of value", i);
    }
}

/* HFXC_PACK_UNIFORMS: a runtime writes a packed parameter's rows into hfx_c without looking. */
static bool check_registers(reader *r, const hfx_fx_effect *fx, const hfx_fx_program *p, uint32_t i) {
    if (p->reg_count > HFX_FX_MAX_REGS) return fail(r, "program %u has %u registers (at most %u)", i, p->reg_count, HFX_FX_MAX_REGS);
    for (uint32_t k = 0; k < p->uniform_count; k++) {
        const hfx_fx_uniform_use *u = &p->uniforms[k];
        if (u->reg == HFX_NONE) continue;
        uint32_t n = hfx_fx_param_packable(fx, u->param);
        if (!n) return fail(r, "program %u packs parameter %u, which cannot be packed", i, u->param);
        if (u->reg >= p->reg_count || n > p->reg_count - u->reg)
            return fail(r, "program %u puts parameter %u outside its %u registers", i, u->param, p->reg_count);
    }
    return true;
}

/* Switches: scalar bools read as their own uniforms, at most HFX_FX_MAX_SWITCHES (a runtime may
 * link 2^n variants). */
static bool check_switches(reader *r, const hfx_fx_effect *fx, const hfx_fx_program *p, uint32_t i) {
    uint32_t n = 0;
    for (uint32_t k = 0; k < p->uniform_count; k++) {
        const hfx_fx_uniform_use *u = &p->uniforms[k];
        if (!(u->flags & HFX_FX_USE_SWITCH)) continue;
        if (++n > HFX_FX_MAX_SWITCHES || hfx_fx_use_packed(p, u) || !hfx_fx_param_switchable(fx, u->param))
            return fail(r, "program %u has a switch that is not a bool parameter of its own (or more than %u)", i,
                        HFX_FX_MAX_SWITCHES);
    }
    return true;
}

/* A preshader's program is valid over the values and its rows land inside the registers. */
static bool check_preshaders(reader *r, const hfx_fx_effect *fx, const hfx_fx_program *p, uint32_t i) {
    char why[96];
    for (uint32_t k = 0; k < p->preshader_count; k++) {
        const hfx_fx_preshader *q = &p->preshaders[k];
        if (q->rows < 1 || q->rows > 4 || q->cols < 1 || q->cols > 4 || q->reg >= p->reg_count ||
            q->rows > p->reg_count - q->reg)
            return fail(r, "program %u has preshader %u outside its %u registers", i, k, p->reg_count);
        if (hfx_evc_validate(p->pre_code + q->first, q->words, fx->value_words, why, sizeof why) != 0)
            return fail(r, "program %u, preshader %u: %s", i, k, why);
    }
    return true;
}

static bool check_effect(reader *r, const hfx_fx_effect *fx) {
    if (fx->top_param_count > fx->param_count) return fail(r, "more top-level parameters than parameters");
    for (uint32_t i = 0; i < fx->param_count; i++)
        if (!check_param(r, fx, i)) return false;
    for (uint32_t i = 0; i < fx->annotation_count; i++)
        if (!check_annotation(r, &fx->annotations[i], i)) return false;
    for (uint32_t i = 0; i < fx->state_count; i++)
        if (!check_state(r, fx, &fx->states[i], i)) return false;
    for (uint32_t i = 0; i < fx->sampler_count; i++) {
        const hfx_fx_sampler *s = &fx->samplers[i];
        if (s->param >= fx->param_count || fx->params[s->param].sampler != i || !ref_ok(s->texture_param, fx->param_count) ||
            (unsigned)s->dim > HFX_FX_DIM_CUBE || !range_ok(s->first_state, s->state_count, fx->state_count))
            return fail(r, "sampler %u is inconsistent", i);
    }
    for (uint32_t i = 0; i < fx->program_count; i++) {
        const hfx_fx_program *p = &fx->programs[i];
        for (uint32_t k = 0; k < p->sampler_count; k++)
            if (p->samplers[k].sampler >= fx->sampler_count) return fail(r, "program %u uses a missing sampler", i);
        for (uint32_t k = 0; k < p->uniform_count; k++)
            if (p->uniforms[k].param >= fx->top_param_count) return fail(r, "program %u uses a missing parameter", i);
        if (!check_registers(r, fx, p, i) || !check_preshaders(r, fx, p, i) || !check_switches(r, fx, p, i)) return false;
    }
    for (uint32_t i = 0; i < fx->pass_count; i++) {
        const hfx_fx_pass *p = &fx->passes[i];
        if (!range_ok(p->first_annotation, p->annotation_count, fx->annotation_count) ||
            !range_ok(p->first_state, p->state_count, fx->state_count) || !ref_ok(p->program, fx->program_count))
            return fail(r, "pass %u is inconsistent", i);
    }
    for (uint32_t i = 0; i < fx->variant_count; i++) {
        const hfx_fx_variant *v = &fx->variants[i];
        if (v->pass >= fx->pass_count || v->program >= fx->program_count || (i && v->pass < fx->variants[i - 1].pass))
            return fail(r, "variant %u is inconsistent", i);
    }
    for (uint32_t i = 0; i < fx->technique_count; i++) {
        const hfx_fx_technique *t = &fx->techniques[i];
        if (!range_ok(t->first_annotation, t->annotation_count, fx->annotation_count) ||
            !range_ok(t->first_pass, t->pass_count, fx->pass_count))
            return fail(r, "technique %u is inconsistent", i);
    }
    return true;
}

hfx_fx_effect *hfx_fx_read_hfxo(const void *data, size_t size, char *err, size_t err_size) {
    reader r;
    memset(&r, 0, sizeof r);
    r.d = data;
    r.size = size;
    r.err = err;
    r.err_size = err_size;
    if (err && err_size) err[0] = 0;
    if (!data) {
        fail(&r, "no data");
        return NULL;
    }
    if (size > 0xffffffffu) {
        fail(&r, "file too large");
        return NULL;
    }
    if (!read_header(&r)) return NULL;
    hfx_fx_effect *fx = calloc(1, sizeof *fx);
    if (!fx) {
        fail(&r, "out of memory");
        return NULL;
    }
    bool ok = get_string(&r, field(&r.t_effect, 0, 0), true, &fx->source_name);
    fx->targets = field(&r.t_effect, 0, 1);
    fx->top_param_count = field(&r.t_effect, 0, 2);
    ok = ok && read_params(&r, fx) && read_annotations(&r, fx) && read_states(&r, fx) && read_programs(&r, fx) &&
         read_preshaders(&r, fx) && read_techniques(&r, fx) && check_effect(&r, fx);
    if (!ok) {
        hfx_fx_effect_free(fx);
        return NULL;
    }
    return fx;
}
