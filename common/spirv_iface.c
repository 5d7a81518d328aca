/* spirv_iface.c: a module's user-defined inputs or outputs by location; see spirv_iface.h. */
#include "spirv_iface.h"

#include <stdlib.h>
#include <string.h>

enum {
    OP_TYPE_INT = 21, OP_TYPE_FLOAT = 22, OP_TYPE_VECTOR = 23, OP_TYPE_MATRIX = 24, OP_TYPE_ARRAY = 28,
    OP_TYPE_STRUCT = 30, OP_TYPE_POINTER = 32, OP_CONSTANT = 43, OP_VARIABLE = 59, OP_DECORATE = 71,
    OP_MEMBER_DECORATE = 72, DEC_BUILTIN = 11, DEC_LOCATION = 30, DEC_COMPONENT = 31, SC_INPUT = 1, SC_OUTPUT = 3,
    MAX_BOUND = 1u << 22, MAX_DEPTH = 4
};

typedef struct index {
    const uint32_t *w;
    size_t count;
    uint32_t bound;
    uint32_t *def;      /* per id: word index of its defining instruction, 0 if none */
    uint32_t *location; /* per id: Location + 1, 0 if none */
    uint8_t *flags;     /* per id: F_BUILTIN, F_COMPONENT */
} index;

enum { F_BUILTIN = 1, F_COMPONENT = 2 };

static uint32_t op_of(uint32_t word) { return word & 0xffffu; }
static uint32_t len_of(uint32_t word) { return word >> 16; }

/* The id an instruction defines, 0 if it defines none this file looks at. */
static uint32_t defined_id(uint32_t op, const uint32_t *in, uint32_t n) {
    if (op >= OP_TYPE_INT && op <= OP_TYPE_POINTER) return n > 1 ? in[1] : 0;
    if (op == OP_CONSTANT || op == OP_VARIABLE) return n > 2 ? in[2] : 0;
    return 0;
}

static void note_decoration(index *x, uint32_t op, const uint32_t *in, uint32_t n) {
    if (op == OP_DECORATE && n >= 3 && in[1] < x->bound) {
        if (in[2] == DEC_BUILTIN) x->flags[in[1]] |= F_BUILTIN;
        if (in[2] == DEC_COMPONENT) x->flags[in[1]] |= F_COMPONENT;
        if (in[2] == DEC_LOCATION && n >= 4) x->location[in[1]] = in[3] < UINT32_MAX ? in[3] + 1 : UINT32_MAX;
    } else if (op == OP_MEMBER_DECORATE && n >= 4 && in[1] < x->bound && in[3] == DEC_BUILTIN) {
        x->flags[in[1]] |= F_BUILTIN; /* a block of built-ins (gl_PerVertex) */
    }
}

/* 0 when the module's instructions were indexed; -1 when malformed or memory ran out. */
static int index_open(index *x, const uint32_t *words, size_t count) {
    memset(x, 0, sizeof *x);
    if (!words || count < 5 || words[0] != 0x07230203u || words[3] > MAX_BOUND) return -1;
    x->w = words, x->count = count, x->bound = words[3];
    x->def = calloc(x->bound, sizeof *x->def);
    x->location = calloc(x->bound, sizeof *x->location);
    x->flags = calloc(x->bound, 1);
    if (!x->def || !x->location || !x->flags) return -1;
    for (size_t i = 5; i < count;) {
        uint32_t n = len_of(words[i]), op = op_of(words[i]);
        if (n == 0 || i + n > count) return -1;
        uint32_t id = defined_id(op, words + i, n);
        if (id && id < x->bound) x->def[id] = (uint32_t)i;
        note_decoration(x, op, words + i, n);
        i += n;
    }
    return 0;
}

static void index_close(index *x) { free(x->def), free(x->location), free(x->flags); }

static const uint32_t *def_of(const index *x, uint32_t id) { return id < x->bound && x->def[id] ? x->w + x->def[id] : NULL; }

/* The kind of a 32-bit scalar or vector type (HFX_SPIRV_FLOAT * 8 + components), 0 for any other. */
static uint8_t vector_kind(const index *x, uint32_t type) {
    const uint32_t *d = def_of(x, type);
    uint32_t comps = 1;
    if (d && op_of(d[0]) == OP_TYPE_VECTOR && len_of(d[0]) >= 4) comps = d[3], d = def_of(x, d[2]);
    if (!d || comps < 1 || comps > 4 || len_of(d[0]) < 3 || d[2] != 32) return 0;
    if (op_of(d[0]) == OP_TYPE_FLOAT) return (uint8_t)(HFX_SPIRV_FLOAT * 8 + comps);
    if (op_of(d[0]) == OP_TYPE_INT && len_of(d[0]) >= 4) return (uint8_t)((d[3] ? HFX_SPIRV_INT : HFX_SPIRV_UINT) * 8 + comps);
    return 0;
}

/* Places a value of `type` at location *at onwards: one location per vector, matrix column or
 * array element. NULL when placed, else why not. */
static const char *place(const index *x, uint32_t type, uint32_t *at, hfx_spirv_iface *out, int depth) {
    const uint32_t *d = def_of(x, type);
    if (!d || depth > MAX_DEPTH) return "an interface variable of a type no varying has";
    uint32_t op = op_of(d[0]), repeat = 1, inner = type;
    if (op == OP_TYPE_ARRAY && len_of(d[0]) >= 4) {
        const uint32_t *len = def_of(x, d[3]);
        if (!len || op_of(len[0]) != OP_CONSTANT || len_of(len[0]) != 4 || len[3] > HFX_SPIRV_MAX_LOCATIONS)
            return "an interface array without a small constant length";
        for (uint32_t e = 0; e < len[3]; e++) {
            const char *why = place(x, d[2], at, out, depth + 1);
            if (why) return why;
        }
        return NULL;
    }
    if (op == OP_TYPE_MATRIX && len_of(d[0]) >= 4) repeat = d[3], inner = d[2];
    uint8_t kind = vector_kind(x, inner);
    if (!kind || repeat > 4) return "an interface variable of a type no varying has";
    for (uint32_t c = 0; c < repeat; c++, (*at)++) {
        if (*at >= HFX_SPIRV_MAX_LOCATIONS) return "an interface location past the last one a device has";
        if (out->kind[*at]) return "two interface variables on one location";
        out->kind[*at] = kind;
        if (*at + 1 > out->end) out->end = *at + 1;
    }
    return NULL;
}

/* One Input or Output variable: its locations into *out, unless it is a built-in. */
static const char *add_variable(const index *x, uint32_t id, const uint32_t *v, hfx_spirv_iface *out) {
    const uint32_t *ptr = def_of(x, v[1]);
    if (!ptr || op_of(ptr[0]) != OP_TYPE_POINTER || len_of(ptr[0]) < 4) return "an interface variable without a pointer type";
    uint32_t pointee = ptr[3];
    const uint32_t *t = def_of(x, pointee);
    if (t && op_of(t[0]) == OP_TYPE_ARRAY && len_of(t[0]) >= 3 && (x->flags[t[2] < x->bound ? t[2] : 0] & F_BUILTIN))
        return NULL; /* an array of built-in blocks */
    if ((x->flags[id] & F_BUILTIN) || (pointee < x->bound && (x->flags[pointee] & F_BUILTIN))) return NULL;
    if (x->flags[id] & F_COMPONENT) return "an interface variable with a Component decoration";
    if (!x->location[id]) return "an interface variable without a Location";
    if (x->location[id] > HFX_SPIRV_MAX_LOCATIONS) return "an interface location past the last one a device has";
    uint32_t at = x->location[id] - 1;
    return place(x, pointee, &at, out, 0);
}

const char *hfx_spirv_interface(const uint32_t *words, size_t count, int output, hfx_spirv_iface *out) {
    memset(out, 0, sizeof *out);
    index x;
    const char *why = index_open(&x, words, count) ? "an unreadable module" : NULL;
    uint32_t storage = output ? SC_OUTPUT : SC_INPUT;
    for (uint32_t id = 1; !why && id < x.bound; id++) {
        const uint32_t *v = def_of(&x, id);
        if (v && op_of(v[0]) == OP_VARIABLE && len_of(v[0]) >= 4 && v[3] == storage) why = add_variable(&x, id, v, out);
    }
    index_close(&x);
    return why;
}

const char *hfx_spirv_interface_fed(const hfx_spirv_iface *from, const hfx_spirv_iface *to) {
    for (uint32_t l = 0; l < to->end; l++) {
        if (!to->kind[l]) continue;
        if (!from->kind[l]) return "a pixel shader input no vertex shader output writes";
        /* an input may read fewer components than were written, never more, nor another scalar type */
        if (from->kind[l] / 8 != to->kind[l] / 8 || from->kind[l] % 8 < to->kind[l] % 8)
            return "a pixel shader input of another type than the vertex shader's output";
    }
    return NULL;
}
