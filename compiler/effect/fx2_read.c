/* fx2_read.c: the fx_2_0 container (docs/fx2.md): header, parameters with their types,
 * annotations and default values, samplers' sampler_state blocks, techniques, passes and
 * their state records, the string table; then fx2_states.c's resources and programs. Every
 * read is bounds-checked; a bad offset is a located error, never a read outside the data. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect/fx2_int.h"

enum { XNA_MAGIC = 0xBCF00BCFu, MAX_TYPE_DEPTH = 16, MAX_ELEMENTS = 1u << 16 };

int hfx_fx2_is_binary(const void *data, size_t size) {
    const uint8_t *p = data;
    if (!p || size < 4) return 0;
    uint32_t m = hfx_le32(p);
    return m == FX2_MAGIC || m == XNA_MAGIC || (p[0] == 'X' && p[1] == 'N' && p[2] == 'B');
}

int hfx_fx2_file_is_binary(const char *path) {
    FILE *f = path ? fopen(path, "rb") : NULL;
    if (!f) return 0;
    uint8_t head[4];
    size_t n = fread(head, 1, sizeof head, f);
    fclose(f);
    return hfx_fx2_is_binary(head, n);
}

/* --- errors, reads, memory ----------------------------------------------------------------- */

uint32_t hfx_fx2_file_at(const fx2_reader *r, uint32_t off) { return r->skip + off; }

static void report(fx2_reader *r, uint32_t file_at, const char *fmt, va_list ap) {
    char msg[512];
    vsnprintf(msg, sizeof msg, fmt, ap);
    hfx_error(r->diags, (hfx_loc){r->file, 0, file_at}, X_FX2_BINARY, "%s", msg);
}

void hfx_fx2_error(fx2_reader *r, uint32_t at, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    report(r, hfx_fx2_file_at(r, at), fmt, ap);
    va_end(ap);
}

void hfx_fx2_fatal(fx2_reader *r, uint32_t at, const char *fmt, ...) {
    if (r->failed) return; /* one fatal error: what follows it is noise */
    va_list ap;
    va_start(ap, fmt);
    report(r, hfx_fx2_file_at(r, at), fmt, ap);
    va_end(ap);
    r->failed = true;
}

bool hfx_fx2_u32(fx2_reader *r, uint32_t off, uint32_t *v, const char *what) {
    if (r->failed) return false;
    if (off > r->size || r->size - off < 4) {
        hfx_fx2_fatal(r, off, "%s: the data ends at %u (truncated)", what, r->size + r->skip);
        *v = 0;
        return false;
    }
    *v = hfx_le32(r->data + off);
    return true;
}

/* An allocation of the effect failed: one error, and the read stops. */
static bool out_of_memory(fx2_reader *r) {
    if (!r->oom) hfx_error(r->diags, (hfx_loc){r->file, 0, 0}, X_MEMORY_LIMIT, "out of memory reading the effect");
    r->oom = r->failed = true;
    return false;
}

bool hfx_fx2_grow(fx2_reader *r, void **arr, size_t elem, uint32_t count, uint32_t *cap) {
    return hfx_grow(arr, elem, count, cap, 8, NULL, NULL) || out_of_memory(r);
}

char *hfx_fx2_strdup(fx2_reader *r, const char *s) {
    if (!s) return NULL;
    char *d = strdup(s);
    if (!d && !r->oom) {
        hfx_error(r->diags, (hfx_loc){r->file, 0, 0}, X_MEMORY_LIMIT, "out of memory reading the effect");
        r->oom = r->failed = true;
    }
    return d;
}

/* Whether the record of `need` bytes at off (read from the word at ptr_at) is inside the data. */
static bool inside(fx2_reader *r, uint32_t off, uint32_t need, uint32_t ptr_at, const char *what) {
    if (r->failed) return false;
    if (off <= r->size && r->size - off >= need) return true;
    hfx_fx2_fatal(r, ptr_at, "%s: offset %u is past the end of the data (%u bytes)", what, off, r->size);
    return false;
}

/* A name record: length (with its NUL), then the bytes. Empty ("") when the length is 0. */
static const char *read_name(fx2_reader *r, uint32_t off, uint32_t ptr_at, const char *what) {
    uint32_t len;
    if (!inside(r, off, 4, ptr_at, what) || !hfx_fx2_u32(r, off, &len, what)) return "";
    if (len > r->size - off - 4) {
        hfx_fx2_fatal(r, off, "%s: a string of %u bytes runs past the end of the data", what, len);
        return "";
    }
    return hfx_arena_strndup(r->arena, (const char *)r->data + off + 4, len);
}

const char *hfx_fx2_type_name(uint32_t pt) {
    static const char *const names[PT_COUNT] = {
        "void", "bool", "int", "float", "string", "texture", "texture1D", "texture2D", "texture3D",
        "textureCUBE", "sampler", "sampler1D", "sampler2D", "sampler3D", "samplerCUBE", "pixelshader",
        "vertexshader"};
    return pt < PT_COUNT ? names[pt] : "?";
}

/* --- types ----------------------------------------------------------------------------------- */

static bool numeric_type(uint32_t t) { return t == PT_BOOL || t == PT_INT || t == PT_FLOAT; }

/* The typedef at off into *t; returns the offset after it (members follow their struct). */
static uint32_t read_type(fx2_reader *r, uint32_t off, uint32_t ptr_at, fx2_type *t, int depth) {
    uint32_t w[5], name_off, sem_off;
    memset(t, 0, sizeof *t);
    t->at = off;
    t->name = t->semantic = "";
    if (!inside(r, off, 20, ptr_at, "type")) return off;
    for (int i = 0; i < 5; i++)
        if (!hfx_fx2_u32(r, off + 4u * (uint32_t)i, &w[i], "type")) return off;
    t->type = w[0], t->klass = w[1], name_off = w[2], sem_off = w[3], t->elements = w[4];
    t->name = read_name(r, name_off, off + 8, "type name");
    t->semantic = read_name(r, sem_off, off + 12, "semantic");
    off += 20;
    if (t->klass >= PC_COUNT || t->type >= PT_COUNT) {
        hfx_fx2_fatal(r, t->at, "unknown parameter class %u or type %u", t->klass, t->type);
        return off;
    }
    if (t->elements > MAX_ELEMENTS) {
        hfx_fx2_fatal(r, t->at + 16, "'%s': %u array elements (hfx reads at most %u)", t->name, t->elements, MAX_ELEMENTS);
        return off;
    }
    if (t->klass == PC_OBJECT) {
        if (t->type < PT_STRING) hfx_fx2_fatal(r, t->at, "'%s': an object of type %u", t->name, t->type);
        return off;
    }
    uint32_t a, b;
    if (!hfx_fx2_u32(r, off, &a, "type")) return off;
    if (t->klass == PC_STRUCT) {
        t->member_count = a; /* the members' typedefs follow the count */
        off += 4;
        if (depth >= MAX_TYPE_DEPTH || a > (r->size - off) / 20) {
            hfx_fx2_fatal(r, t->at, "'%s': %u struct members (nested %d deep) do not fit the data", t->name, a, depth);
            return off;
        }
        t->members = HFX_NEW_ARRAY(r->arena, fx2_type, a ? a : 1);
        for (uint32_t i = 0; i < a && !r->failed; i++) {
            off = read_type(r, off, off, &t->members[i], depth + 1);
            uint32_t n = t->members[i].elements ? t->members[i].elements : 1;
            if (t->members[i].klass == PC_OBJECT || (t->members[i].klass == PC_STRUCT && !t->members[i].words))
                hfx_fx2_fatal(r, t->members[i].at, "'%s.%s': structs with object members are not supported", t->name,
                              t->members[i].name);
            t->words += t->members[i].words * n;
        }
        return off;
    }
    if (!hfx_fx2_u32(r, off + 4, &b, "type")) return off;
    t->rows = t->klass == PC_VECTOR ? b : a;
    t->cols = t->klass == PC_VECTOR ? a : b;
    if (!numeric_type(t->type) || t->rows < 1 || t->rows > 4 || t->cols < 1 || t->cols > 4)
        hfx_fx2_fatal(r, t->at, "'%s': a %s of %u x %u", t->name, hfx_fx2_type_name(t->type), t->rows, t->cols);
    t->words = t->rows * t->cols;
    return off + 8;
}

static hfx_param_class model_class(uint32_t pc) {
    static const hfx_param_class map[PC_COUNT] = {HFX_CLASS_SCALAR, HFX_CLASS_VECTOR, HFX_CLASS_MATRIX,
                                                  HFX_CLASS_MATRIX, HFX_CLASS_OBJECT, HFX_CLASS_STRUCT};
    return map[pc];
}

static uint32_t all_words(const fx2_type *t) { return t->words * (t->elements ? t->elements : 1); }

/* --- annotations ----------------------------------------------------------------------------- */

/* count annotation records at *off (typedef, value); on fx->annotations. Strings are filled
 * when the string table is read (object ids in r->param_object's sibling, anno_object). */
typedef struct anno_fixup {
    uint32_t annotation, object;
} anno_fixup;

typedef struct reader_ext {
    anno_fixup *fix;
    uint32_t fix_count, fix_cap;
} reader_ext;

static uint32_t read_annotations(fx2_reader *r, reader_ext *x, uint32_t *off, uint32_t count, uint32_t *first) {
    hfx_fx_effect *fx = r->fx;
    *first = 0;
    uint32_t added = 0;
    if (count > (r->size - *off) / 8) {
        hfx_fx2_fatal(r, *off, "%u annotations do not fit the data", count);
        return 0;
    }
    for (uint32_t i = 0; i < count && !r->failed; i++, *off += 8) {
        uint32_t type_off, value_off;
        if (!hfx_fx2_u32(r, *off, &type_off, "annotation") || !hfx_fx2_u32(r, *off + 4, &value_off, "annotation"))
            break;
        fx2_type t;
        read_type(r, type_off, *off, &t, 0);
        if (r->failed) break;
        bool string = t.klass == PC_OBJECT && t.type == PT_STRING && !t.elements;
        bool numeric = t.klass <= PC_MATRIX_COLUMNS;
        /* textures, structs or arrays as annotations (hfx's annotation is one scalar, vector or
         * matrix, or a string): nothing the API shows */
        if ((!string && !numeric) || (numeric && t.elements)) continue;
        if (!FX2_GROW(r, fx->annotations, fx->annotation_count, r->anno_cap)) break;
        hfx_fx_annotation *a = &fx->annotations[fx->annotation_count];
        memset(a, 0, sizeof *a);
        if (!added++) *first = fx->annotation_count;
        fx->annotation_count++;
        a->name = hfx_fx2_strdup(r, t.name);
        a->type = (hfx_param_type)t.type;
        a->klass = string ? HFX_CLASS_OBJECT : model_class(t.klass);
        a->rows = string ? 0 : t.rows;
        a->cols = string ? 0 : t.cols;
        uint32_t v;
        if (string) {
            if (hfx_fx2_u32(r, value_off, &v, "annotation value") && HFX_ARENA_GROW(r->arena, x->fix, x->fix_count, x->fix_cap, 8))
                x->fix[x->fix_count++] = (anno_fixup){fx->annotation_count - 1, v};
            continue;
        }
        a->count = all_words(&t);
        if (a->count > (r->size - (value_off < r->size ? value_off : r->size)) / 4) {
            hfx_fx2_fatal(r, *off + 4, "annotation '%s': its %u values at %u run past the end of the data", t.name,
                          a->count, value_off + r->skip);
            break;
        }
        if (!(a->data = malloc(a->count * sizeof *a->data))) {
            out_of_memory(r);
            break;
        }
        for (uint32_t k = 0; k < a->count; k++) a->data[k] = hfx_le32(r->data + value_off + 4 * k);
    }
    return added;
}

/* --- parameters ------------------------------------------------------------------------------ */

/* Grows the per-parameter side arrays with fx->params. */
typedef struct param_side {
    const fx2_type **type;
    uint32_t cap;
} param_side;

static uint32_t new_param(fx2_reader *r, param_side *ps, const fx2_type *t, uint32_t parent, const char *name) {
    hfx_fx_effect *fx = r->fx;
    uint32_t i = fx->param_count, cap = r->param_cap;
    if (!FX2_GROW(r, fx->params, i, r->param_cap)) return HFX_NONE;
    if (cap != r->param_cap || !ps->type) { /* the side arrays follow fx->params's capacity */
        const fx2_type **nt = HFX_NEW_ARRAY(r->arena, const fx2_type *, r->param_cap);
        uint32_t *arrays[4];
        uint32_t **sides[4] = {&r->param_value_at, &r->param_object, &r->param_raw_first, &r->param_raw_count};
        for (int s = 0; s < 4; s++) {
            arrays[s] = HFX_NEW_ARRAY(r->arena, uint32_t, r->param_cap);
            if (*sides[s]) memcpy(arrays[s], *sides[s], i * sizeof(uint32_t));
            *sides[s] = arrays[s];
        }
        if (ps->type) memcpy(nt, ps->type, i * sizeof *nt);
        ps->type = nt;
    }
    fx->param_count++;
    hfx_fx_param *p = &fx->params[i];
    memset(p, 0, sizeof *p);
    p->name = hfx_fx2_strdup(r, name);
    p->semantic = t->semantic[0] ? hfx_fx2_strdup(r, t->semantic) : NULL;
    p->klass = model_class(t->klass);
    p->type = t->klass == PC_STRUCT ? HFX_TYPE_VOID : (hfx_param_type)t->type;
    p->rows = t->klass <= PC_MATRIX_COLUMNS ? t->rows : 0;
    p->cols = t->klass <= PC_MATRIX_COLUMNS ? t->cols : 0;
    p->elements = t->elements;
    p->parent = parent;
    p->words = all_words(t);
    p->sampler = HFX_NONE;
    if (t->klass == PC_MATRIX_ROWS) p->flags |= HFX_FX_PARAM_ROW_MAJOR;
    ps->type[i] = t;
    r->param_object[i] = HFX_NONE;
    r->param_raw_first[i] = r->param_raw_count[i] = 0;
    return i;
}

static bool is_sampler(uint32_t t) { return t >= PT_SAMPLER && t <= PT_SAMPLERCUBE; }

/* The sampler block at off (state count, then state records): its raws and hfx sampler. */

/* A state assignment at off, not yet read: no usage, no state, nothing but where it stands. */
static fx2_raw *new_raw(fx2_reader *r, uint32_t off) {
    if (!HFX_ARENA_GROW(r->arena, r->raws, r->raw_count, r->raw_cap, 16)) return NULL;
    fx2_raw *raw = &r->raws[r->raw_count++];
    memset(raw, 0, sizeof *raw);
    raw->at = off;
    raw->usage = USE_NONE;
    raw->state = HFX_NONE;
    return raw;
}

static uint32_t read_sampler(fx2_reader *r, uint32_t param, uint32_t off) {
    hfx_fx_effect *fx = r->fx;
    uint32_t count;
    if (!hfx_fx2_u32(r, off, &count, "sampler_state")) return off;
    if (count > (r->size - off - 4) / 16) {
        hfx_fx2_fatal(r, off, "sampler '%s': %u states do not fit the data", fx->params[param].name, count);
        return off;
    }
    if (!FX2_GROW(r, fx->samplers, fx->sampler_count, r->sampler_cap)) return off;
    uint32_t s = fx->sampler_count++;
    static const hfx_fx_dim dims[] = {HFX_FX_DIM_2D, HFX_FX_DIM_1D, HFX_FX_DIM_2D, HFX_FX_DIM_3D, HFX_FX_DIM_CUBE};
    fx->samplers[s] = (hfx_fx_sampler){param, HFX_NONE, dims[fx->params[param].type - HFX_TYPE_SAMPLER],
                                       fx->state_count, 0, 0};
    fx->params[param].sampler = s;
    r->param_raw_first[param] = r->raw_count;
    off += 4;
    for (uint32_t i = 0; i < count && !r->failed; i++, off += 16) {
        fx2_raw *raw = new_raw(r, off);
        uint32_t type_off;
        if (!raw) break;
        if (!hfx_fx2_u32(r, off, &raw->op, "sampler state") || !hfx_fx2_u32(r, off + 8, &type_off, "sampler state") ||
            !hfx_fx2_u32(r, off + 12, &raw->value_at, "sampler state"))
            break;
        read_type(r, type_off, off + 8, &raw->type, 0);
        if (raw->op < OP_TEXTURE || raw->op >= OP_SAMPLER) {
            hfx_fx2_fatal(r, off, "sampler '%s': operation %u is not a sampler state", fx->params[param].name, raw->op);
            break;
        }
        if (raw->op == OP_TEXTURE) { /* the sampler's texture: the sampler's own field, not a state */
            fx->samplers[s].texture_slot = fx->samplers[s].state_count;
            hfx_fx_state dummy;
            hfx_fx2_state_value(r, raw, &dummy);
            continue;
        }
        if (!FX2_GROW(r, fx->states, fx->state_count, r->state_cap)) break;
        raw->state = fx->state_count++;
        hfx_fx2_state_value(r, raw, &fx->states[raw->state]);
        fx->samplers[s].state_count++;
    }
    r->param_raw_count[param] = r->raw_count - r->param_raw_first[param];
    if (!fx->samplers[s].state_count) fx->samplers[s].first_state = 0;
    return off;
}

/* The value of a leaf parameter i (no elements, no members) at off: object ids, samplers.
 * Returns the offset after it, for arrays of objects read one element after another. */
static uint32_t read_object_value(fx2_reader *r, uint32_t i, uint32_t off) {
    hfx_fx_param *p = &r->fx->params[i];
    if (p->klass != HFX_CLASS_OBJECT) return off;
    if (is_sampler(p->type)) return read_sampler(r, i, off);
    uint32_t id;
    if (!hfx_fx2_u32(r, off, &id, "object id")) return off;
    if (id >= r->object_count) {
        hfx_fx2_fatal(r, off, "'%s': object %u is outside the object table (%u objects)", p->name, id, r->object_count);
        return off;
    }
    r->param_object[i] = id;
    r->objects[id].type = p->type;
    return off + 4;
}

/* Param i's children (elements or members), appended as one block; values located. */
static void add_children(fx2_reader *r, param_side *ps, uint32_t i) {
    const fx2_type *t = ps->type[i];
    uint32_t first = r->fx->param_count, count = 0, at = r->param_value_at[i];
    if (t->elements) {
        fx2_type *elem = HFX_NEW(r->arena, fx2_type);
        *elem = *t;
        elem->elements = 0;
        for (uint32_t e = 0; e < t->elements && !r->failed; e++, count++) {
            uint32_t c = new_param(r, ps, elem, i, t->name);
            if (c == HFX_NONE) return;
            r->param_value_at[c] = at;
            at = t->klass == PC_OBJECT ? read_object_value(r, c, at) : at + 4 * t->words;
        }
    } else if (t->klass == PC_STRUCT) {
        for (uint32_t m = 0; m < t->member_count && !r->failed; m++, count++) {
            uint32_t c = new_param(r, ps, &t->members[m], i, t->members[m].name);
            if (c == HFX_NONE) return;
            r->param_value_at[c] = at;
            at += 4 * all_words(&t->members[m]);
        }
    } else if (r->fx->params[i].parent == HFX_NONE || !r->fx->params[r->fx->params[i].parent].elements) {
        read_object_value(r, i, at); /* (an element's was read with its array's) */
    }
    r->fx->params[i].first_child = count ? first : 0;
    r->fx->params[i].child_count = count;
}

/* Offsets of every parameter's words: a parent's words are its children's, in order. */
static uint32_t place(hfx_fx_effect *fx, uint32_t i, uint32_t offset) {
    hfx_fx_param *p = &fx->params[i];
    p->offset = offset;
    for (uint32_t c = 0; c < p->child_count; c++) offset = place(fx, p->first_child + c, offset);
    return p->child_count ? offset : offset + p->words;
}

static bool read_params(fx2_reader *r, reader_ext *x, uint32_t *off, uint32_t count) {
    hfx_fx_effect *fx = r->fx;
    param_side ps = {0};
    if (count > (r->size - *off) / 16) {
        hfx_fx2_fatal(r, *off, "%u parameters do not fit the data", count);
        return false;
    }
    r->param_types = HFX_NEW_ARRAY(r->arena, fx2_type, count ? count : 1);
    for (uint32_t i = 0; i < count && !r->failed; i++) {
        uint32_t rec = *off, type_off, value_off, flags, annos;
        if (!hfx_fx2_u32(r, rec, &type_off, "parameter") || !hfx_fx2_u32(r, rec + 4, &value_off, "parameter") ||
            !hfx_fx2_u32(r, rec + 8, &flags, "parameter") || !hfx_fx2_u32(r, rec + 12, &annos, "parameter"))
            return false;
        *off += 16;
        read_type(r, type_off, rec, &r->param_types[i], 0);
        if (r->failed) return false;
        uint32_t p = new_param(r, &ps, &r->param_types[i], HFX_NONE, r->param_types[i].name);
        if (p == HFX_NONE) return false;
        if (flags & 1) fx->params[p].flags |= HFX_FX_PARAM_SHARED;
        r->param_value_at[p] = value_off;
        uint32_t words = fx->params[p].words;
        if (words && (value_off > r->size || words > (r->size - value_off) / 4))
            hfx_fx2_fatal(r, rec + 4, "parameter '%s': its %u values at %u run past the end of the data",
                          fx->params[p].name, words, value_off + r->skip);
        fx->params[p].annotation_count = read_annotations(r, x, off, annos, &fx->params[p].first_annotation);
    }
    fx->top_param_count = fx->param_count;
    for (uint32_t i = 0; i < fx->param_count && !r->failed; i++) add_children(r, &ps, i); /* breadth first */
    if (r->failed) return false;
    uint32_t words = 0;
    for (uint32_t i = 0; i < fx->top_param_count; i++) words = place(fx, i, words);
    fx->value_words = words;
    if (!(fx->values = calloc(words ? words : 1, sizeof *fx->values))) return out_of_memory(r);
    for (uint32_t i = 0; i < fx->top_param_count; i++) {
        const hfx_fx_param *p = &fx->params[i];
        if (p->klass == HFX_CLASS_OBJECT) continue;
        for (uint32_t k = 0; k < p->words; k++) fx->values[p->offset + k] = hfx_le32(r->data + r->param_value_at[i] + 4 * k);
    }
    return true;
}

/* --- techniques and passes ------------------------------------------------------------------- */

static void read_state(fx2_reader *r, uint32_t off) {
    hfx_fx_effect *fx = r->fx;
    fx2_raw *raw = new_raw(r, off);
    uint32_t type_off;
    if (!raw) return;
    if (!hfx_fx2_u32(r, off, &raw->op, "state") || !hfx_fx2_u32(r, off + 4, &raw->index, "state") ||
        !hfx_fx2_u32(r, off + 8, &type_off, "state") || !hfx_fx2_u32(r, off + 12, &raw->value_at, "state"))
        return;
    read_type(r, type_off, off + 8, &raw->type, 0);
    if (r->failed || !FX2_GROW(r, fx->states, fx->state_count, r->state_cap)) return;
    raw->state = fx->state_count++;
    hfx_fx2_state_value(r, raw, &fx->states[raw->state]);
}

static bool read_techniques(fx2_reader *r, reader_ext *x, uint32_t *off, uint32_t count) {
    hfx_fx_effect *fx = r->fx;
    uint32_t pass_side_cap = 0;
    if (count > (r->size - *off) / 12) {
        hfx_fx2_fatal(r, *off, "%u techniques do not fit the data", count);
        return false;
    }
    for (uint32_t t = 0; t < count && !r->failed; t++) {
        uint32_t name, annos, passes;
        if (!hfx_fx2_u32(r, *off, &name, "technique") || !hfx_fx2_u32(r, *off + 4, &annos, "technique") ||
            !hfx_fx2_u32(r, *off + 8, &passes, "technique") || !FX2_GROW(r, fx->techniques, fx->technique_count, r->tech_cap))
            return false;
        hfx_fx_technique *tq = &fx->techniques[fx->technique_count++];
        memset(tq, 0, sizeof *tq);
        tq->name = hfx_fx2_strdup(r, read_name(r, name, *off, "technique name"));
        *off += 12;
        tq->annotation_count = read_annotations(r, x, off, annos, &tq->first_annotation);
        if (passes > (r->size - *off) / 12) {
            hfx_fx2_fatal(r, *off - 4, "technique '%s': %u passes do not fit the data", tq->name, passes);
            return false;
        }
        tq->first_pass = passes ? fx->pass_count : 0;
        tq->pass_count = passes;
        for (uint32_t p = 0; p < passes && !r->failed; p++) {
            uint32_t states;
            if (!hfx_fx2_u32(r, *off, &name, "pass") || !hfx_fx2_u32(r, *off + 4, &annos, "pass") ||
                !hfx_fx2_u32(r, *off + 8, &states, "pass"))
                return false;
            uint32_t cap = r->pass_cap;
            if (!FX2_GROW(r, fx->passes, fx->pass_count, r->pass_cap)) return false;
            if (cap != r->pass_cap || !r->pass_raw_first) {
                uint32_t *a = HFX_NEW_ARRAY(r->arena, uint32_t, r->pass_cap), *b = HFX_NEW_ARRAY(r->arena, uint32_t, r->pass_cap);
                if (r->pass_raw_first) memcpy(a, r->pass_raw_first, fx->pass_count * sizeof *a);
                if (r->pass_tech) memcpy(b, r->pass_tech, fx->pass_count * sizeof *b);
                r->pass_raw_first = a, r->pass_tech = b;
                pass_side_cap = r->pass_cap;
            }
            hfx_fx_pass *pa = &fx->passes[fx->pass_count];
            memset(pa, 0, sizeof *pa);
            r->pass_tech[fx->pass_count] = t;
            fx->pass_count++;
            pa->name = hfx_fx2_strdup(r, read_name(r, name, *off, "pass name"));
            pa->program = HFX_NONE;
            *off += 12;
            pa->annotation_count = read_annotations(r, x, off, annos, &pa->first_annotation);
            if (states > (r->size - *off) / 16) {
                hfx_fx2_fatal(r, *off - 4, "pass '%s': %u states do not fit the data", pa->name, states);
                return false;
            }
            r->pass_raw_first[fx->pass_count - 1] = r->raw_count;
            pa->first_state = states ? fx->state_count : 0;
            for (uint32_t s = 0; s < states && !r->failed; s++, *off += 16) read_state(r, *off);
            pa->state_count = states;
        }
    }
    (void)pass_side_cap;
    return !r->failed;
}

/* --- the string table ------------------------------------------------------------------------ */

static bool read_strings(fx2_reader *r, uint32_t *off, uint32_t count) {
    if (count > (r->size - *off) / 8) {
        hfx_fx2_fatal(r, *off, "%u strings do not fit the data", count);
        return false;
    }
    for (uint32_t i = 0; i < count && !r->failed; i++) {
        uint32_t id, size;
        if (!hfx_fx2_u32(r, *off, &id, "string") || !hfx_fx2_u32(r, *off + 4, &size, "string")) return false;
        if (id >= r->object_count) {
            hfx_fx2_fatal(r, *off, "string %u: object %u is outside the object table (%u objects)", i, id, r->object_count);
            return false;
        }
        if (size > r->size - *off - 8) {
            hfx_fx2_fatal(r, *off + 4, "object %u: %u bytes run past the end of the data", id, size);
            return false;
        }
        r->objects[id].has_data = true;
        r->objects[id].blob = (fx2_blob){r->data + *off + 8, size, hfx_fx2_file_at(r, *off + 8)};
        *off += 8 + ((size + 3) & ~3u);
        if (*off > r->size) *off = r->size;
    }
    return true;
}

/* A string object's text (NULL when it has none). */
static char *object_string(fx2_reader *r, uint32_t id) {
    if (id >= r->object_count || !r->objects[id].has_data) return NULL;
    const fx2_blob *b = &r->objects[id].blob;
    return hfx_arena_strndup(r->arena, (const char *)b->data, b->size);
}

static void fill_strings(fx2_reader *r, const reader_ext *x) {
    hfx_fx_effect *fx = r->fx;
    for (uint32_t i = 0; i < x->fix_count; i++) {
        char *s = object_string(r, x->fix[i].object);
        fx->annotations[x->fix[i].annotation].string = hfx_fx2_strdup(r, s ? s : "");
    }
    for (uint32_t i = 0; i < fx->param_count; i++)
        if (fx->params[i].type == HFX_TYPE_STRING && !fx->params[i].child_count && r->param_object[i] != HFX_NONE) {
            char *s = object_string(r, r->param_object[i]);
            fx->params[i].string = hfx_fx2_strdup(r, s ? s : "");
        }
}

/* --- the whole ------------------------------------------------------------------------------- */

bool hfx_fx2_decode(fx2_reader *r, const char *name) {
    uint32_t magic, start, off, params, techniques, objects;
    if (!hfx_fx2_u32(r, 0, &magic, "header")) return false;
    (void)name;
    if (magic != FX2_MAGIC) {
        hfx_fx2_fatal(r, 0, "not an fx_2_0 effect (the first word is 0x%08x, fxc's effects start with 0xfeff0901)", magic);
        return false;
    }
    if (!hfx_fx2_u32(r, 4, &start, "header")) return false;
    /* from here offsets count from the container's data, 8 bytes in */
    r->data += 8, r->size -= 8, r->skip += 8;
    off = start;
    if (!hfx_fx2_u32(r, off, &params, "header") || !hfx_fx2_u32(r, off + 4, &techniques, "header") ||
        !hfx_fx2_u32(r, off + 8, &r->shader_count, "header") || !hfx_fx2_u32(r, off + 12, &objects, "header"))
        return false;
    if (objects > r->size / 4 + 1) {
        hfx_fx2_fatal(r, off + 12, "%u objects do not fit the data", objects);
        return false;
    }
    r->object_count = objects;
    r->objects = HFX_NEW_ARRAY(r->arena, fx2_object, objects ? objects : 1);
    off += 16;
    reader_ext x = {0};
    bool ok = read_params(r, &x, &off, params) && read_techniques(r, &x, &off, techniques);
    uint32_t strings = 0, resources = 0;
    ok = ok && hfx_fx2_u32(r, off, &strings, "object counts") && hfx_fx2_u32(r, off + 4, &resources, "object counts");
    off += 8;
    ok = ok && read_strings(r, &off, strings);
    if (ok) fill_strings(r, &x);
    return ok && !r->failed && hfx_fx2_resources(r, off, resources);
}

/* The parameter a state names (`<name>`, also "a[2]" and "s.m"). */
uint32_t hfx_fx2_param_by_name(const fx2_reader *r, const char *name) {
    const hfx_fx_effect *fx = r->fx;
    size_t n = strcspn(name, "[.");
    uint32_t p = HFX_NONE;
    for (uint32_t i = 0; i < fx->top_param_count && p == HFX_NONE; i++)
        if (strlen(fx->params[i].name) == n && !strncmp(fx->params[i].name, name, n)) p = i;
    for (const char *s = name + n; p != HFX_NONE && *s;) {
        const hfx_fx_param *q = &fx->params[p];
        if (*s == '[') {
            char *end;
            unsigned long e = strtoul(s + 1, &end, 10);
            if (*end != ']' || !q->elements || e >= q->child_count) return HFX_NONE;
            p = q->first_child + (uint32_t)e;
            s = end + 1;
        } else if (*s == '.') {
            size_t m = strcspn(s + 1, "[.");
            uint32_t found = HFX_NONE;
            for (uint32_t c = 0; !q->elements && c < q->child_count && found == HFX_NONE; c++)
                if (strlen(fx->params[q->first_child + c].name) == m && !strncmp(fx->params[q->first_child + c].name, s + 1, m))
                    found = q->first_child + c;
            p = found;
            s += 1 + m;
        } else {
            return HFX_NONE;
        }
    }
    return p;
}

/* A 7-bit encoded int of the .xnb format at *off. */
static bool xnb_7bit(fx2_reader *r, uint32_t *off, uint32_t *v) {
    *v = 0;
    for (int shift = 0; shift < 35; shift += 7) {
        if (*off >= r->size) {
            hfx_fx2_fatal(r, *off, "xnb: the data ends inside a number");
            return false;
        }
        uint8_t b = r->data[(*off)++];
        *v |= (uint32_t)(b & 0x7f) << shift;
        if (!(b & 0x80)) return true;
    }
    hfx_fx2_fatal(r, *off, "xnb: a number of more than 5 bytes");
    return false;
}

/* An XNA 4 .xnb whose content is an Effect: "XNB", platform, version, flags, size, the type
 * readers (name, version), shared resources, then the object: reader index, code size, code. */
bool hfx_fx2_xnb(fx2_reader *r, uint32_t *start) {
    if (r->size < 10) {
        hfx_fx2_fatal(r, 0, "xnb: the header is truncated");
        return false;
    }
    if (r->data[5] & 0xc0) {
        hfx_fx2_fatal(r, 5, "xnb: the content is compressed (%s); hfx reads uncompressed .xnb files (build the content "
                      "without compression)", r->data[5] & 0x80 ? "LZX" : "LZ4");
        return false;
    }
    uint32_t off = 10, readers, effect_reader = HFX_NONE, shared, type;
    if (!xnb_7bit(r, &off, &readers)) return false;
    for (uint32_t i = 0; i < readers && !r->failed; i++) {
        uint32_t len, at = off;
        if (!xnb_7bit(r, &off, &len)) return false;
        if (len > r->size - off || r->size - off - len < 4) {
            hfx_fx2_fatal(r, at, "xnb: type reader %u runs past the end of the data", i);
            return false;
        }
        const char *name = (const char *)r->data + off;
        static const char want[] = "Microsoft.Xna.Framework.Content.EffectReader";
        if (len >= sizeof want - 1 && !strncmp(name, want, sizeof want - 1) && effect_reader == HFX_NONE) effect_reader = i;
        off += len + 4;
    }
    if (!xnb_7bit(r, &off, &shared) || !xnb_7bit(r, &off, &type)) return false;
    if (!type || type - 1 != effect_reader) {
        hfx_fx2_fatal(r, off - 1, "xnb: the content is not an Effect (its type reader is %u; the Effect reader is %s)",
                      type, effect_reader == HFX_NONE ? "absent" : "another");
        return false;
    }
    uint32_t size;
    if (!hfx_fx2_u32(r, off, &size, "xnb effect size")) return false;
    if (size > r->size - off - 4) {
        hfx_fx2_fatal(r, off, "xnb: the effect's %u bytes run past the end of the data", size);
        return false;
    }
    *start = off + 4;
    return true;
}

/* Where the fx_2_0 container starts: after an XNA 4 header (0xBCF00BCF, its size) or inside an
 * uncompressed .xnb whose content is an Effect. 0 when the data is the container itself. */
static bool find_container(fx2_reader *r, uint32_t *start) {
    const uint8_t *p = r->data;
    *start = 0;
    if (r->size >= 8 && hfx_le32(p) == XNA_MAGIC) {
        uint32_t skip = hfx_le32(p + 4);
        if (skip < 8 || skip > r->size) {
            hfx_fx2_fatal(r, 4, "XNA effect header: %u bytes of header do not fit the data", skip);
            return false;
        }
        *start = skip;
        return true;
    }
    if (r->size >= 3 && p[0] == 'X' && p[1] == 'N' && p[2] == 'B') return hfx_fx2_xnb(r, start);
    return true;
}

bool hfx_fx2_open(fx2_reader *r, hfx_arena *arena, hfx_diags *diags, const char *name, const char *path,
                  const void *data, size_t size, unsigned targets, unsigned flags) {
    memset(r, 0, sizeof *r);
    r->arena = arena;
    r->diags = diags;
    r->file = hfx_diags_add_file(diags, name, path, NULL, 0);
    r->targets = targets;
    r->flags = flags;
    if (size > HFXC_MAX_SOURCE_BYTES) {
        hfx_error(diags, (hfx_loc){r->file, 0, 0}, X_SOURCE_TOO_LARGE, "the effect has %zu bytes (hfx reads at most %u)",
                  size, HFXC_MAX_SOURCE_BYTES);
        return false;
    }
    r->data = data;
    r->size = (uint32_t)size;
    if (!(r->fx = calloc(1, sizeof *r->fx))) {
        hfx_error(diags, (hfx_loc){r->file, 0, 0}, X_MEMORY_LIMIT, "out of memory reading the effect");
        return false;
    }
    hfx_arena_cleanup *cleanup = hfx_arena_on_escape(arena, (void (*)(void *))hfx_fx_effect_free, r->fx);
    uint32_t start = 0;
    if (find_container(r, &start)) {
        r->data += start, r->size -= start, r->skip = start;
        if (hfx_fx2_decode(r, name)) hfx_fx2_finish(r);
    }
    hfx_arena_forget(arena, cleanup);
    if (r->failed || diags->errors) {
        hfx_fx_effect_free(r->fx);
        r->fx = NULL;
        return false;
    }
    r->fx->source_name = hfx_fx2_strdup(r, name);
    if (flags & HFX_FX2_DECODE_ONLY) r->fx->targets = targets;
    return true;
}

hfx_fx_effect *hfx_fx2_read(hfx_arena *arena, hfx_diags *diags, const char *name, const char *path,
                            const void *data, size_t size, unsigned targets, unsigned flags) {
    fx2_reader r;
    return hfx_fx2_open(&r, arena, diags, name, path, data, size, targets, flags) ? r.fx : NULL;
}
