/* fx2_write.c: hfx's effect model as fxc's fx_2_0 container (docs/fx2.md, "Writing"): the
 * inverse of fx2_read.c. Laid out as fxc lays it out, so that hfx's reader, MojoShader (FNA's
 * loader) and D3DX read it: offset 0 of the data holds an empty name (the name of anything
 * anonymous); each parameter's names, then its typedef immediately followed by its value
 * (MojoShader reads a struct's defaults from after its typedef); the techniques' names, states'
 * typedefs and values; then the structure (counts, parameter and technique records), the
 * string table (strings, shader parameters' bytecode) and the resources (a pass's shaders,
 * `<name>` references, expressions and shader array selectors).
 *
 * Object ids count from 1. A numeric state computed by an expression holds an object id as its
 * value (its resource is found by position; MojoShader treats the id as an object's). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect/fx2_int.h"
#include "effect/fx2_write.h"
#include "eval_code.h"
#include "grow.h"
#include "states.h"

typedef struct bytes {
    uint8_t *d;
    uint32_t n, cap;
} bytes;

/* A resource record: what a state's value object holds. */
typedef struct resource {
    uint32_t w[5];         /* technique (or -1), pass (or parameter), element, state, usage */
    uint8_t *data;         /* malloc'ed */
    uint32_t size;
} resource;

typedef struct string_obj {
    uint32_t id;
    const void *data;      /* the effect's (strings, bytecode) */
    uint32_t size;
} string_obj;

typedef struct writer {
    const hfx_fx_effect *fx;
    const char *name;
    const hfx_fx2_write_options *opt;
    bytes data, st;        /* the data (typedefs, values, names), the structure's records */
    uint32_t objects;      /* next object id */
    uint32_t shaders;      /* shader objects */
    string_obj *strings; uint32_t string_count, string_cap;
    resource *res; uint32_t res_count, res_cap;
    uint32_t *ops;         /* per hfx state id: its operation (malloc'ed on first use) */
    hfx_fx_code *leaf_code; /* per parameter: a shader leaf's bytecode (size 0: none; not owned) */
    char *err; size_t err_size;
    bool failed;
} writer;

static void fail(writer *w, uint32_t line, uint32_t col, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static void fail(writer *w, uint32_t line, uint32_t col, const char *fmt, ...) {
    if (w->failed) return;
    w->failed = true;
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (w->err) snprintf(w->err, w->err_size, "%s(%u,%u): error X%d: %s", w->name, line, col, X_FX2_WRITE, msg);
}

/* --- bytes ----------------------------------------------------------------------------------- */

static uint32_t put_bytes(writer *w, bytes *b, const void *p, uint32_t n) {
    uint32_t at = b->n, padded = (n + 3) & ~3u;
    if (w->failed) return at;
    while (b->n + padded > b->cap) {
        uint32_t cap = b->cap ? b->cap * 2 : 1024;
        uint8_t *d = realloc(b->d, cap);
        if (!d) {
            fail(w, 0, 0, "out of memory writing the effect");
            return at;
        }
        b->d = d, b->cap = cap;
    }
    memset(b->d + b->n, 0, padded);
    if (n) memcpy(b->d + b->n, p, n);
    b->n += padded;
    return at;
}

static uint32_t u32(writer *w, bytes *b, uint32_t v) {
    uint8_t q[4] = {(uint8_t)v, (uint8_t)(v >> 8), (uint8_t)(v >> 16), (uint8_t)(v >> 24)};
    return put_bytes(w, b, q, 4);
}

/* A name record: length with the NUL, the bytes; NULL or "" is the empty name at offset 0. */
static uint32_t name(writer *w, const char *s, bool keep_empty) {
    if (!s || (!*s && !keep_empty)) return 0;
    uint32_t at = u32(w, &w->data, (uint32_t)strlen(s) + 1);
    put_bytes(w, &w->data, s, (uint32_t)strlen(s) + 1);
    return at;
}

static uint32_t new_object(writer *w) { return w->objects++; }

static void add_string(writer *w, uint32_t id, const void *data, uint32_t size) {
    if (w->failed || !hfx_grow((void **)&w->strings, sizeof *w->strings, w->string_count, &w->string_cap, 8, NULL, NULL)) {
        fail(w, 0, 0, "out of memory writing the effect");
        return;
    }
    w->strings[w->string_count++] = (string_obj){id, data, size};
}

/* A resource; data is copied (size bytes). */
static void add_resource(writer *w, const uint32_t where[4], uint32_t usage, const void *data, uint32_t size) {
    uint8_t *copy = size ? malloc(size) : NULL;
    if (w->failed || (size && !copy) ||
        !hfx_grow((void **)&w->res, sizeof *w->res, w->res_count, &w->res_cap, 8, NULL, NULL)) {
        free(copy);
        fail(w, 0, 0, "out of memory writing the effect");
        return;
    }
    if (size) memcpy(copy, data, size);
    w->res[w->res_count++] = (resource){{where[0], where[1], where[2], where[3], usage}, copy, size};
}

/* --- types and values ------------------------------------------------------------------------ */

static uint32_t file_class(const writer *w, const hfx_fx_param *p) {
    bool rows = w->opt && w->opt->matrix_packing > 0 ? !(p->flags & HFX_FX_PARAM_COLUMN_MAJOR) : (p->flags & HFX_FX_PARAM_ROW_MAJOR) != 0;
    switch (p->klass) {
    case HFX_CLASS_SCALAR: return PC_SCALAR;
    case HFX_CLASS_VECTOR: return PC_VECTOR;
    case HFX_CLASS_MATRIX: return rows ? PC_MATRIX_ROWS : PC_MATRIX_COLUMNS;
    case HFX_CLASS_STRUCT: return PC_STRUCT;
    default: return PC_OBJECT;
    }
}

/* The parameter whose children are a struct's members (an array's first element holds them). */
static const hfx_fx_param *members_of(const hfx_fx_effect *fx, const hfx_fx_param *p) {
    return p->elements && p->child_count ? &fx->params[p->first_child] : p;
}

/* Name records of p and its members (before the typedef, which must be contiguous). */
static void type_names(writer *w, const hfx_fx_param *p, uint32_t *names, uint32_t *sems, uint32_t *k) {
    names[*k] = name(w, p->name, false);
    sems[*k] = name(w, p->semantic, false);
    (*k)++;
    if (p->klass != HFX_CLASS_STRUCT) return;
    const hfx_fx_param *m = members_of(w->fx, p);
    for (uint32_t c = 0; c < m->child_count && *k < 256; c++) type_names(w, &w->fx->params[m->first_child + c], names, sems, k);
}

static void typedef_words(writer *w, const hfx_fx_param *p, const uint32_t *names, const uint32_t *sems, uint32_t *k) {
    uint32_t i = (*k)++;
    u32(w, &w->data, p->klass == HFX_CLASS_STRUCT ? PT_VOID : (uint32_t)p->type);
    u32(w, &w->data, file_class(w, p));
    u32(w, &w->data, names[i]);
    u32(w, &w->data, sems[i]);
    u32(w, &w->data, p->elements);
    if (p->klass == HFX_CLASS_OBJECT) return;
    if (p->klass == HFX_CLASS_STRUCT) {
        const hfx_fx_param *m = members_of(w->fx, p);
        u32(w, &w->data, m->child_count);
        for (uint32_t c = 0; c < m->child_count && *k < 256; c++) typedef_words(w, &w->fx->params[m->first_child + c], names, sems, k);
        return;
    }
    bool vector = p->klass == HFX_CLASS_VECTOR;
    u32(w, &w->data, vector ? p->cols : p->rows);
    u32(w, &w->data, vector ? p->rows : p->cols);
}

static uint32_t param_typedef(writer *w, const hfx_fx_param *p) {
    uint32_t names[256], sems[256], k = 0;
    type_names(w, p, names, sems, &k);
    uint32_t at = w->data.n;
    k = 0;
    typedef_words(w, p, names, sems, &k);
    if (k >= 256) fail(w, p->line, p->col, "'%s': a structure of more than 255 members", p->name);
    return at;
}

/* An anonymous typedef (states, a sampler's Texture): type, class, then rows / columns. */
static uint32_t plain_typedef(writer *w, uint32_t type, uint32_t klass, uint32_t rows, uint32_t cols) {
    uint32_t at = u32(w, &w->data, type);
    u32(w, &w->data, klass), u32(w, &w->data, 0), u32(w, &w->data, 0), u32(w, &w->data, 0);
    if (klass == PC_OBJECT) return at;
    u32(w, &w->data, klass == PC_VECTOR ? cols : rows);
    u32(w, &w->data, klass == PC_VECTOR ? rows : cols);
    return at;
}

/* "Lights[2].Color": a parameter's name as a `<name>` reference spells it. */
static void param_path(const hfx_fx_effect *fx, uint32_t p, char *buf, size_t size) {
    const hfx_fx_param *q = &fx->params[p];
    if (q->parent == HFX_NONE) {
        snprintf(buf, size, "%s", q->name);
        return;
    }
    param_path(fx, q->parent, buf, size);
    size_t n = strlen(buf);
    const hfx_fx_param *parent = &fx->params[q->parent];
    if (parent->elements) snprintf(buf + n, size - n, "[%u]", p - parent->first_child);
    else snprintf(buf + n, size - n, ".%s", q->name);
}

/* --- states ---------------------------------------------------------------------------------- */

/* D3DX's operation number of an hfx state (the reader's table read backwards, once a write). */
static uint32_t op_of(writer *w, uint32_t id) {
    if (!w->ops) {
        uint32_t n = hfx_state_count() + 1;
        if (!(w->ops = malloc(n * sizeof *w->ops))) return HFX_NONE;
        memset(w->ops, 0xff, n * sizeof *w->ops);
        for (uint32_t op = OP_COUNT; op-- > 0;) {
            uint32_t s = hfx_fx2_state_id(op);
            if (s && s < n) w->ops[s] = op;
        }
    }
    return id <= hfx_state_count() ? w->ops[id] : HFX_NONE;
}

/* The resource record of a state: (technique, pass, -1, state) or (-1, parameter, element, state). */
typedef struct place {
    uint32_t a, b, element, state;
} place;

static void resource_at(writer *w, const place *at, uint32_t usage, const void *data, uint32_t size) {
    const uint32_t where[4] = {at->a, at->b, at->element, at->state};
    add_resource(w, where, usage, data, size);
}

/* The value type a computed state takes: float for float-valued states, int (bool) otherwise. */
static uint32_t expr_typedef(writer *w, const hfx_state_info *info) {
    if (info->kind == HFX_SV_FLOAT) return plain_typedef(w, PT_FLOAT, PC_SCALAR, 1, 1);
    if (info->kind == HFX_SV_VECTOR) return plain_typedef(w, PT_FLOAT, PC_VECTOR, 1, 4);
    return plain_typedef(w, PT_INT, PC_MATRIX_ROWS, 1, 1);
}

/* An expression's FXLVM program (a selector's with the array's name before it). */
static void expression(writer *w, const hfx_fx_state *s, const place *at, uint32_t array) {
    uint32_t words = 0;
    char why[256] = "";
    uint32_t *code = hfx_fxlvm_write(w->fx, w->fx->exprs + s->ref, s->count, &words, why, sizeof why);
    if (!code) {
        fail(w, s->line, s->col, "state %s: %s", hfx_state_by_id(s->id)->name, why);
        return;
    }
    if (array == HFX_NONE) {
        resource_at(w, at, USE_DATA, code, words * 4);
    } else {
        const char *n = w->fx->params[array].name;
        uint32_t len = (uint32_t)strlen(n) + 1, padded = (len + 3) & ~3u, size = 4 + padded + words * 4;
        uint8_t *blob = calloc(1, size);
        if (!blob) {
            free(code);
            fail(w, 0, 0, "out of memory writing the effect");
            return;
        }
        memcpy(blob, &len, 4); /* little-endian hosts only, as the rest of hfx's binary code */
        memcpy(blob + 4, n, len);
        memcpy(blob + 4 + padded, code, words * 4);
        resource_at(w, at, USE_SELECTOR, blob, size);
        free(blob);
    }
    free(code);
}

/* A stage's bytecode for a pass's program: the program's own, else the hook's. */
static bool stage_code(writer *w, uint32_t program, int stage, const void **data, size_t *size, const hfx_fx_state *s) {
    *data = NULL, *size = 0;
    if (program == HFX_NONE || program >= w->fx->program_count) return true;
    const hfx_fx_code *c = &w->fx->programs[program].d3d9[stage];
    if (c->size) {
        *data = c->data, *size = c->size;
        return true;
    }
    if (!w->opt || !w->opt->bytecode) return true;
    char why[256] = "no reason given";
    if (w->opt->bytecode(w->opt->ctx, w->fx, program, stage, data, size, why, sizeof why) == 0) return true;
    fail(w, s->line, s->col, "%s shader: %s", stage ? "pixel" : "vertex", why);
    return false;
}

/* The program a pass's shader state takes its bytecode from: the pass's, or in a pass drawn from
 * shader arrays (which has none), any variant's: a stage given inline is the same in each. */
static uint32_t program_of(const writer *w, const hfx_fx_state *s, const place *at) {
    const hfx_fx_effect *fx = w->fx;
    if (s->ref != HFX_NONE || at->a >= fx->technique_count) return s->ref;
    uint32_t pass = fx->techniques[at->a].first_pass + at->b;
    for (uint32_t i = 0; i < fx->variant_count; i++)
        if (fx->variants[i].pass == pass) return fx->variants[i].program;
    return HFX_NONE;
}

static void shader_state(writer *w, const hfx_fx_state *s, const place *at, uint32_t *type, uint32_t *value) {
    int stage = s->id == HFX_ST_PIXELSHADER;
    uint32_t id = new_object(w);
    w->shaders++;
    *type = plain_typedef(w, stage ? PT_PIXELSHADER : PT_VERTEXSHADER, PC_OBJECT, 0, 0);
    *value = u32(w, &w->data, id);
    uint32_t src = s->source ? s->source - 1 : HFX_NONE;
    if (s->kind == HFX_FX_VALUE_EXPR) {
        if (src >= w->fx->param_count) {
            fail(w, s->line, s->col, "%s: the shader array this index picks from is unknown", hfx_state_by_id(s->id)->name);
            return;
        }
        expression(w, s, at, src);
        return;
    }
    if (src < w->fx->param_count && w->leaf_code[src].size) { /* `VertexShader = <vs>` */
        char path[512];
        param_path(w->fx, src, path, sizeof path);
        resource_at(w, at, USE_PARAM, path, (uint32_t)strlen(path) + 1);
        return;
    }
    const void *data;
    size_t size;
    if (!stage_code(w, program_of(w, s, at), stage, &data, &size, s) || !size) return; /* NULL: no data */
    resource_at(w, at, USE_DATA, data, (uint32_t)size);
}

/* One state record's typedef and value offsets (its resource added); false: not written. */
static bool state(writer *w, const hfx_fx_state *s, const place *at, uint32_t *op, uint32_t *type, uint32_t *value) {
    const hfx_state_info *info = hfx_state_by_id(s->id);
    *op = op_of(w, s->id);
    if (!info || *op == HFX_NONE || s->kind == HFX_FX_VALUE_UNSUPPORTED) return false; /* nothing fx_2_0 can say */
    if (info->kind == HFX_SV_SHADER) {
        shader_state(w, s, at, type, value);
        return true;
    }
    switch (s->kind) {
    case HFX_FX_VALUE_INT:
        *type = plain_typedef(w, PT_INT, PC_MATRIX_ROWS, 1, 1); /* fxc's spelling of a DWORD state: an int 1x1 */
        *value = u32(w, &w->data, (uint32_t)s->i);
        return true;
    case HFX_FX_VALUE_FLOAT: {
        uint32_t n = s->count ? s->count : 1;
        *type = plain_typedef(w, PT_FLOAT, n > 1 ? PC_VECTOR : PC_SCALAR, 1, n);
        *value = put_bytes(w, &w->data, s->f, 4 * n);
        return true;
    }
    case HFX_FX_VALUE_PARAM: {
        const hfx_fx_param *p = s->ref < w->fx->param_count ? &w->fx->params[s->ref] : NULL;
        if (!p) return false;
        if (p->klass == HFX_CLASS_OBJECT) *type = plain_typedef(w, (uint32_t)p->type, PC_OBJECT, 0, 0);
        else *type = plain_typedef(w, p->type == HFX_TYPE_FLOAT ? PT_FLOAT : PT_INT, PC_SCALAR, 1, 1);
        /* A sampler's value is a block (state count, records), not an object id: `Sampler[0] =
         * (S)` is an empty block, the resource naming S, as D3DX and MojoShader read it. */
        bool sampler = p->klass == HFX_CLASS_OBJECT && p->type >= HFX_TYPE_SAMPLER && p->type <= HFX_TYPE_SAMPLERCUBE;
        *value = u32(w, &w->data, sampler ? 0 : new_object(w));
        char path[512];
        param_path(w->fx, s->ref, path, sizeof path);
        resource_at(w, at, USE_PARAM, path, (uint32_t)strlen(path) + 1);
        return true;
    }
    case HFX_FX_VALUE_EXPR:
        *type = expr_typedef(w, info);
        *value = u32(w, &w->data, new_object(w));
        expression(w, s, at, HFX_NONE);
        return true;
    default: return false;
    }
}

/* --- parameters ------------------------------------------------------------------------------ */

/* A sampler's Texture record (a `<name>` resource) at position `count` of its block. */
static void sampler_texture(writer *w, uint32_t top, uint32_t element, const hfx_fx_sampler *s, uint32_t count,
                            uint32_t rec[4]) {
    const hfx_fx_param *t = &w->fx->params[s->texture_param];
    place at = {HFX_NONE, top, element, count};
    rec[0] = OP_TEXTURE, rec[1] = 0;
    rec[2] = plain_typedef(w, t->klass == HFX_CLASS_OBJECT ? (uint32_t)t->type : PT_TEXTURE, PC_OBJECT, 0, 0);
    rec[3] = u32(w, &w->data, new_object(w));
    char path[512];
    param_path(w->fx, s->texture_param, path, sizeof path);
    resource_at(w, &at, USE_PARAM, path, (uint32_t)strlen(path) + 1);
}

/* A sampler's state records (their typedefs and values written to the data now), its Texture
 * where the block had it; returns how many (at most 64). */
typedef uint32_t sampler_recs[64][4];

static uint32_t sampler_records(writer *w, uint32_t top, uint32_t element, const hfx_fx_sampler *s, sampler_recs rec) {
    uint32_t count = 0;
    bool texture = s->texture_param != HFX_NONE && s->texture_param < w->fx->param_count;
    for (uint32_t i = 0; i <= s->state_count && count < 64; i++) {
        if (texture && i == (s->texture_slot < s->state_count ? s->texture_slot : s->state_count))
            sampler_texture(w, top, element, s, count, rec[count]), count++;
        if (i == s->state_count || count == 64) break;
        place at = {HFX_NONE, top, element, count};
        if (state(w, &w->fx->states[s->first_state + i], &at, &rec[count][0], &rec[count][2], &rec[count][3]))
            rec[count++][1] = 0;
    }
    return count;
}

/* A sampler parameter's value: for each element its state count, then its records. The blocks of
 * an array follow one another (readers step from one to the next), so every element's records
 * are made, with their data, before the first block is written. */
static uint32_t sampler_value(writer *w, uint32_t top) {
    const hfx_fx_effect *fx = w->fx;
    const hfx_fx_param *p = &fx->params[top];
    uint32_t n = p->elements ? p->child_count : 1;
    sampler_recs *recs = calloc(n ? n : 1, sizeof *recs);
    uint32_t *counts = calloc(n ? n : 1, sizeof *counts);
    if (!recs || !counts) {
        free(recs), free(counts);
        fail(w, p->line, p->col, "out of memory writing the effect");
        return 0;
    }
    for (uint32_t e = 0; e < n; e++) {
        const hfx_fx_param *leaf = p->elements ? &fx->params[p->first_child + e] : p;
        hfx_fx_sampler none = {top, HFX_NONE, HFX_FX_DIM_2D, 0, 0, 0};
        const hfx_fx_sampler *s = leaf->sampler < fx->sampler_count ? &fx->samplers[leaf->sampler] : &none;
        counts[e] = sampler_records(w, top, p->elements ? e : 0, s, recs[e]);
    }
    uint32_t value = w->data.n;
    for (uint32_t e = 0; e < n; e++) {
        u32(w, &w->data, counts[e]);
        for (uint32_t i = 0; i < counts[e]; i++)
            for (int k = 0; k < 4; k++) u32(w, &w->data, recs[e][i][k]);
    }
    free(recs), free(counts);
    return value;
}

/* The value of leaf (or array) parameter p: object ids, sampler blocks, or numeric words. */
static uint32_t param_value(writer *w, uint32_t top) {
    const hfx_fx_effect *fx = w->fx;
    const hfx_fx_param *p = &fx->params[top];
    if (p->klass != HFX_CLASS_OBJECT) {
        uint32_t at = w->data.n;
        for (uint32_t k = 0; k < p->words; k++) u32(w, &w->data, fx->values[p->offset + k]);
        return at;
    }
    uint32_t n = p->elements ? p->child_count : 1;
    if (p->type >= HFX_TYPE_SAMPLER && p->type <= HFX_TYPE_SAMPLERCUBE) return sampler_value(w, top);
    uint32_t ids[4096], count = n < 4096 ? n : 4096;
    for (uint32_t e = 0; e < count; e++) {
        uint32_t leaf = p->elements ? p->first_child + e : top;
        ids[e] = new_object(w);
        if (p->type == HFX_TYPE_STRING && fx->params[leaf].string)
            add_string(w, ids[e], fx->params[leaf].string, (uint32_t)strlen(fx->params[leaf].string) + 1);
        if (p->type == HFX_TYPE_VERTEXSHADER || p->type == HFX_TYPE_PIXELSHADER) {
            w->shaders++;
            if (w->leaf_code[leaf].size) add_string(w, ids[e], w->leaf_code[leaf].data, (uint32_t)w->leaf_code[leaf].size);
        }
    }
    uint32_t at = w->data.n;
    for (uint32_t e = 0; e < count; e++) u32(w, &w->data, ids[e]);
    return at;
}

/* Annotation records (typedef, value) for the structure, their data written now. */
static void annotations(writer *w, uint32_t first, uint32_t count, uint32_t *recs) {
    for (uint32_t i = 0; i < count; i++) {
        const hfx_fx_annotation *a = &w->fx->annotations[first + i];
        uint32_t n = name(w, a->name, false), type;
        if (a->type == HFX_TYPE_STRING) {
            type = u32(w, &w->data, PT_STRING);
            u32(w, &w->data, PC_OBJECT), u32(w, &w->data, n), u32(w, &w->data, 0), u32(w, &w->data, 0);
            uint32_t id = new_object(w);
            recs[2 * i + 1] = u32(w, &w->data, id);
            add_string(w, id, a->string ? a->string : "", (uint32_t)strlen(a->string ? a->string : "") + 1);
        } else {
            hfx_fx_param shape = {.klass = a->klass, .type = a->type, .rows = a->rows, .cols = a->cols};
            uint32_t klass = file_class(w, &shape);
            type = u32(w, &w->data, (uint32_t)a->type);
            u32(w, &w->data, klass), u32(w, &w->data, n), u32(w, &w->data, 0), u32(w, &w->data, 0);
            u32(w, &w->data, klass == PC_VECTOR ? a->cols : a->rows), u32(w, &w->data, klass == PC_VECTOR ? a->rows : a->cols);
            recs[2 * i + 1] = w->data.n;
            for (uint32_t k = 0; k < a->count; k++) u32(w, &w->data, a->data[k]);
        }
        recs[2 * i] = type;
    }
}

static void put_annotation_records(writer *w, const uint32_t *recs, uint32_t count) {
    for (uint32_t i = 0; i < 2 * count; i++) u32(w, &w->st, recs[i]);
}

static void parameters(writer *w) {
    const hfx_fx_effect *fx = w->fx;
    for (uint32_t i = 0; i < fx->top_param_count && !w->failed; i++) {
        const hfx_fx_param *p = &fx->params[i];
        uint32_t *recs = calloc(2 * (size_t)p->annotation_count + 1, sizeof *recs);
        if (!recs) return fail(w, 0, 0, "out of memory writing the effect");
        annotations(w, p->first_annotation, p->annotation_count, recs);
        uint32_t type = param_typedef(w, p), value = param_value(w, i);
        u32(w, &w->st, type), u32(w, &w->st, value), u32(w, &w->st, p->flags & HFX_FX_PARAM_SHARED ? 1 : 0);
        u32(w, &w->st, p->annotation_count);
        put_annotation_records(w, recs, p->annotation_count);
        free(recs);
    }
}

/* --- techniques ------------------------------------------------------------------------------ */

static void pass(writer *w, uint32_t tech, uint32_t index, const hfx_fx_pass *pa) {
    uint32_t *recs = calloc(2 * (size_t)pa->annotation_count + 4 * (size_t)pa->state_count + 1, sizeof *recs);
    if (!recs) return fail(w, 0, 0, "out of memory writing the effect");
    uint32_t *states = recs + 2 * pa->annotation_count, written = 0, n = name(w, pa->name, true);
    annotations(w, pa->first_annotation, pa->annotation_count, recs);
    for (uint32_t i = 0; i < pa->state_count && !w->failed; i++) {
        const hfx_fx_state *s = &w->fx->states[pa->first_state + i];
        place at = {tech, index, HFX_NONE, written};
        uint32_t *r = &states[4 * written];
        if (!state(w, s, &at, &r[0], &r[2], &r[3])) continue;
        r[1] = s->index;
        written++;
    }
    u32(w, &w->st, n), u32(w, &w->st, pa->annotation_count), u32(w, &w->st, written);
    put_annotation_records(w, recs, pa->annotation_count);
    for (uint32_t i = 0; i < 4 * written; i++) u32(w, &w->st, states[i]);
    free(recs);
}

static void techniques(writer *w) {
    const hfx_fx_effect *fx = w->fx;
    for (uint32_t t = 0; t < fx->technique_count && !w->failed; t++) {
        const hfx_fx_technique *tq = &fx->techniques[t];
        uint32_t *recs = calloc(2 * (size_t)tq->annotation_count + 1, sizeof *recs);
        if (!recs) return fail(w, 0, 0, "out of memory writing the effect");
        uint32_t n = name(w, tq->name, true);
        annotations(w, tq->first_annotation, tq->annotation_count, recs);
        u32(w, &w->st, n), u32(w, &w->st, tq->annotation_count), u32(w, &w->st, tq->pass_count);
        put_annotation_records(w, recs, tq->annotation_count);
        free(recs);
        for (uint32_t p = 0; p < tq->pass_count && !w->failed; p++) pass(w, t, p, &fx->passes[tq->first_pass + p]);
    }
}

/* --- shader parameters' bytecode -------------------------------------------------------------- */

/* A shader leaf's bytecode: its own (a binary's), else the program of a variant that picks it
 * from its array (a compiled source's shader arrays, `VSArray[VSIndices[ShaderIndex]]`). The
 * hook's bytecode stays valid until hfx_fx2_write returns. */
static bool leaf_codes(writer *w) {
    const hfx_fx_effect *fx = w->fx;
    if (!(w->leaf_code = calloc(fx->param_count ? fx->param_count : 1, sizeof *w->leaf_code))) return false;
    for (uint32_t i = 0; i < fx->param_count; i++) w->leaf_code[i] = fx->params[i].d3d9;
    for (uint32_t v = 0; v < fx->variant_count && !w->failed; v++) {
        const hfx_fx_variant *var = &fx->variants[v];
        const hfx_fx_pass *pa = &fx->passes[var->pass];
        for (uint32_t i = 0; i < pa->state_count; i++) {
            const hfx_fx_state *s = &fx->states[pa->first_state + i];
            int stage = s->id == HFX_ST_PIXELSHADER;
            uint32_t idx = stage ? var->ps : var->vs, array = s->source - 1;
            if (s->kind != HFX_FX_VALUE_EXPR || (s->id != HFX_ST_VERTEXSHADER && !stage) || !s->source ||
                array >= fx->param_count || idx >= fx->params[array].child_count)
                continue;
            hfx_fx_code *leaf = &w->leaf_code[fx->params[array].first_child + idx];
            const void *data;
            size_t size;
            if (!leaf->size && stage_code(w, var->program, stage, &data, &size, s))
                *leaf = (hfx_fx_code){(char *)data, size};
        }
    }
    return true;
}

/* --- the whole ------------------------------------------------------------------------------- */

static void tables(writer *w) {
    u32(w, &w->st, w->string_count), u32(w, &w->st, w->res_count);
    for (uint32_t i = 0; i < w->string_count; i++) {
        u32(w, &w->st, w->strings[i].id), u32(w, &w->st, w->strings[i].size);
        put_bytes(w, &w->st, w->strings[i].data, w->strings[i].size);
    }
    for (uint32_t i = 0; i < w->res_count; i++) {
        for (int k = 0; k < 5; k++) u32(w, &w->st, w->res[i].w[k]);
        u32(w, &w->st, w->res[i].size);
        put_bytes(w, &w->st, w->res[i].data, w->res[i].size);
    }
}

int hfx_fx2_write(const hfx_fx_effect *fx, const char *name_, const hfx_fx2_write_options *opt, void **out, size_t *size,
                  char *err, size_t err_size) {
    writer w = {.fx = fx, .name = name_ ? name_ : "effect", .opt = opt, .objects = 1, .err = err, .err_size = err_size};
    *out = NULL, *size = 0;
    if (err && err_size) err[0] = 0;
    if (!leaf_codes(&w)) fail(&w, 0, 0, "out of memory writing the effect");
    if (!fx->top_param_count && !fx->technique_count) { /* nothing else to say */ }
    u32(&w, &w.data, 0); /* offset 0: the empty name */
    parameters(&w);
    techniques(&w);
    tables(&w);
    bytes file = {0};
    if (!w.failed) {
        u32(&w, &file, FX2_MAGIC), u32(&w, &file, w.data.n);
        put_bytes(&w, &file, w.data.d, w.data.n);
        uint32_t head[4] = {fx->top_param_count, fx->technique_count, w.shaders, w.objects};
        for (int k = 0; k < 4; k++) u32(&w, &file, head[k]);
        put_bytes(&w, &file, w.st.d, w.st.n);
    }
    for (uint32_t i = 0; i < w.res_count; i++) free(w.res[i].data);
    free(w.res);
    free(w.strings);
    free(w.leaf_code);
    free(w.ops);
    free(w.data.d);
    free(w.st.d);
    if (w.failed) {
        free(file.d);
        return -1;
    }
    *out = file.d;
    *size = file.n;
    return 0;
}
