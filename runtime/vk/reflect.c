/* reflect.c: the uniform block of a Vulkan SPIR-V module, read from the module itself: every
 * leaf (a scalar, vector or matrix, or an array of them) with its GLSL path ("Lights[1].Color",
 * as GL's uniform names go), byte offset, array and matrix strides and base type. The compiler
 * lays the block out by std140 through glslang; reading the decorations back means the runtime
 * never recomputes that layout, so the two cannot disagree. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spirv_loc.h"
#include "vk/vk.h"

enum {
    OP_NAME = 5, OP_MEMBER_NAME = 6, OP_TYPE_BOOL = 20, OP_TYPE_IMAGE = 25, OP_TYPE_INT = 21, OP_TYPE_FLOAT = 22, OP_TYPE_VECTOR = 23,
    OP_TYPE_MATRIX = 24, OP_TYPE_SAMPLED_IMAGE = 27, OP_TYPE_ARRAY = 28, OP_TYPE_STRUCT = 30, OP_TYPE_POINTER = 32, OP_CONSTANT = 43,
    OP_VARIABLE = 59, OP_DECORATE = 71, OP_MEMBER_DECORATE = 72,
    DEC_ARRAY_STRIDE = 6, DEC_MATRIX_STRIDE = 7, DEC_BINDING = 33, DEC_SET = 34, DEC_OFFSET = 35,
    STORAGE_UNIFORM_CONSTANT = 0, STORAGE_UNIFORM = 2, MAX_DEPTH = 8
};

typedef struct module {
    const uint32_t *w;
    size_t count;
    uint32_t bound;
    uint32_t *def;          /* per id: the word index of the instruction defining it, 0 if none */
    uint32_t *stride;       /* per id: ArrayStride */
    int32_t *binding, *set; /* per id: -1 if none */
    vk_block *out;
    uint32_t cap;
} module;

/* Calls fn for every instruction: op, its words, their count. Stops (returning -1) on a malformed one. */
static int each(const module *m, void (*fn)(const module *, uint32_t op, const uint32_t *w, uint32_t n, size_t at)) {
    for (size_t i = 5; i < m->count;) {
        uint32_t n = m->w[i] >> 16, op = m->w[i] & 0xffffu;
        if (n == 0 || i + n > m->count) return -1;
        fn(m, op, m->w + i, n, i);
        i += n;
    }
    return 0;
}

static int has_result_type(uint32_t op) { return op == OP_CONSTANT || op == OP_VARIABLE; }

static void index_ids(const module *m, uint32_t op, const uint32_t *w, uint32_t n, size_t at) {
    uint32_t id = has_result_type(op) ? (n > 2 ? w[2] : 0) : (n > 1 ? w[1] : 0);
    int defines = (op >= OP_TYPE_BOOL && op <= OP_TYPE_POINTER) || has_result_type(op); /* OpTypeImage too */
    if (defines && id < m->bound) m->def[id] = (uint32_t)at;
    if (op == OP_DECORATE && n >= 4 && w[1] < m->bound) {
        if (w[2] == DEC_ARRAY_STRIDE) m->stride[w[1]] = w[3];
        if (w[2] == DEC_BINDING) m->binding[w[1]] = (int32_t)w[3];
        if (w[2] == DEC_SET) m->set[w[1]] = (int32_t)w[3];
    }
}

static const uint32_t *def_of(const module *m, uint32_t id) { return id < m->bound && m->def[id] ? m->w + m->def[id] : NULL; }

/* A member's decoration value (Offset, MatrixStride), or 0. */
static uint32_t member_decoration(const module *m, uint32_t st, uint32_t member, uint32_t dec) {
    for (size_t i = 5; i < m->count;) {
        uint32_t n = m->w[i] >> 16, op = m->w[i] & 0xffffu;
        if (op == OP_MEMBER_DECORATE && n >= 5 && m->w[i + 1] == st && m->w[i + 2] == member && m->w[i + 3] == dec)
            return m->w[i + 4];
        i += n ? n : 1;
    }
    return 0;
}

static const char *member_name(const module *m, uint32_t st, uint32_t member) {
    for (size_t i = 5; i < m->count;) {
        uint32_t n = m->w[i] >> 16, op = m->w[i] & 0xffffu;
        if (op == OP_MEMBER_NAME && n >= 4 && m->w[i + 1] == st && m->w[i + 2] == member) {
            const char *s = (const char *)(const void *)(m->w + i + 3);
            return memchr(s, 0, (size_t)(n - 3) * 4) ? s : NULL;
        }
        i += n ? n : 1;
    }
    return NULL;
}

/* The scalar base of a scalar or vector type, and its component count. */
static int scalar_of(const module *m, uint32_t type, uint16_t *base, uint16_t *comps) {
    const uint32_t *d = def_of(m, type);
    if (!d) return 0;
    uint32_t op = d[0] & 0xffffu;
    *comps = 1;
    if (op == OP_TYPE_VECTOR) {
        *comps = (uint16_t)d[3];
        d = def_of(m, d[2]);
        if (!d) return 0;
        op = d[0] & 0xffffu;
    }
    if (op == OP_TYPE_FLOAT) *base = VK_BASE_FLOAT;
    else if (op == OP_TYPE_INT) *base = d[3] ? VK_BASE_INT : VK_BASE_UINT;
    else if (op == OP_TYPE_BOOL) *base = VK_BASE_BOOL;
    else return 0;
    return 1;
}

static int add_leaf(module *m, const vk_leaf *leaf) {
    vk_block *b = m->out;
    if (b->count == m->cap) {
        uint32_t cap = m->cap ? 2 * m->cap : 16;
        vk_leaf *grown = realloc(b->leaves, cap * sizeof *grown);
        if (!grown) return -1;
        b->leaves = grown, m->cap = cap;
    }
    b->leaves[b->count++] = *leaf;
    uint32_t one = leaf->cols > 1 ? (uint32_t)(leaf->cols - 1) * leaf->col_stride + 4u * leaf->comps : 4u * leaf->comps;
    uint32_t end = leaf->offset + (leaf->count ? (leaf->count - 1) * leaf->stride : 0) + one;
    if (end > b->size) b->size = end;
    return 0;
}

static int walk_struct(module *m, uint32_t st, uint32_t offset, const char *prefix, int depth);

/* An array of structs: each element's members, as "path[e].member". */
static int walk_struct_array(module *m, uint32_t st, uint32_t offset, const vk_leaf *arr, int depth) {
    for (uint32_t e = 0; e < arr->count; e++) {
        char sub[160];
        if (snprintf(sub, sizeof sub, "%s[%u]", arr->path, (unsigned)e) >= (int)sizeof sub) return -1;
        if (walk_struct(m, st, offset + e * arr->stride, sub, depth + 1)) return -1;
    }
    return 0;
}

/* A value of `type` at offset named path: a leaf, or the members of a struct (array). */
static int walk_type(module *m, uint32_t type, uint32_t offset, uint32_t matrix_stride, const char *path, int depth) {
    const uint32_t *d = def_of(m, type);
    if (!d || depth > MAX_DEPTH) return -1;
    uint32_t op = d[0] & 0xffffu;
    vk_leaf leaf;
    memset(&leaf, 0, sizeof leaf);
    snprintf(leaf.path, sizeof leaf.path, "%s", path);
    leaf.offset = offset;
    leaf.cols = 1;
    if (op == OP_TYPE_STRUCT) return walk_struct(m, type, offset, path, depth + 1);
    uint32_t t = type;
    if (op == OP_TYPE_ARRAY) {
        const uint32_t *len = def_of(m, d[3]);
        t = d[2];
        if (!len || (len[0] & 0xffffu) != OP_CONSTANT || (len[0] >> 16) < 4 || !(d = def_of(m, t))) return -1;
        leaf.count = len[3];
        leaf.stride = m->stride[type];
        op = d[0] & 0xffffu;
        if (op == OP_TYPE_STRUCT) return walk_struct_array(m, t, offset, &leaf, depth);
    }
    if (op == OP_TYPE_MATRIX) {
        leaf.cols = (uint16_t)d[3];
        leaf.col_stride = (uint16_t)matrix_stride;
        t = d[2];
    }
    if (!scalar_of(m, t, &leaf.base, &leaf.comps)) return -1;
    return add_leaf(m, &leaf);
}

static int walk_struct(module *m, uint32_t st, uint32_t offset, const char *prefix, int depth) {
    const uint32_t *d = def_of(m, st);
    if (!d || depth > MAX_DEPTH) return -1;
    uint32_t members = (d[0] >> 16) - 2;
    for (uint32_t i = 0; i < members; i++) {
        const char *name = member_name(m, st, i);
        if (!name) continue;
        char path[160];
        if (snprintf(path, sizeof path, "%s%s%s", prefix, *prefix ? "." : "", name) >= (int)sizeof path) return -1;
        uint32_t off = offset + member_decoration(m, st, i, DEC_OFFSET);
        if (walk_type(m, d[2 + i], off, member_decoration(m, st, i, DEC_MATRIX_STRIDE), path, depth)) return -1;
    }
    return 0;
}

/* The struct type of the Uniform variable at set 0, binding HFX_VK_BINDING_BLOCK; 0 if none. */
static uint32_t block_type(const module *m) {
    for (uint32_t id = 1; id < m->bound; id++) {
        const uint32_t *v = def_of(m, id);
        if (!v || (v[0] & 0xffffu) != OP_VARIABLE || (v[0] >> 16) < 4 || v[3] != STORAGE_UNIFORM) continue;
        if (m->binding[id] != HFX_VK_BINDING_BLOCK || m->set[id] != 0) continue;
        const uint32_t *ptr = def_of(m, v[1]);
        if (ptr && (ptr[0] & 0xffffu) == OP_TYPE_POINTER && (ptr[0] >> 16) >= 4) return ptr[3];
    }
    return 0;
}

/* Indexes a module's ids and decorations: 0; -1 when it is not SPIR-V, malformed or memory ran out. */
static int module_open(module *m, const uint32_t *words, size_t count, vk_block *out) {
    memset(m, 0, sizeof *m);
    if (!words || count < 5 || words[0] != 0x07230203u || words[3] > (1u << 22)) return -1;
    *m = (module){words, count, words[3], NULL, NULL, NULL, NULL, out, 0};
    m->def = calloc(m->bound, sizeof *m->def);
    m->stride = calloc(m->bound, sizeof *m->stride);
    m->binding = malloc(m->bound * sizeof *m->binding);
    m->set = malloc(m->bound * sizeof *m->set);
    if (!m->def || !m->stride || !m->binding || !m->set) return -1;
    memset(m->binding, 0xff, m->bound * sizeof *m->binding);
    memset(m->set, 0xff, m->bound * sizeof *m->set);
    return each(m, index_ids);
}

static void module_close(module *m) { free(m->def), free(m->stride), free(m->binding), free(m->set); }

int hfx_vk_reflect_block(const uint32_t *words, size_t count, vk_block *out) {
    memset(out, 0, sizeof *out);
    module m;
    int rc = module_open(&m, words, count, out);
    uint32_t st = rc ? 0 : block_type(&m);
    if (st) rc = walk_struct(&m, st, 0, "", 0);
    module_close(&m);
    if (rc) hfx_vk_block_free(out);
    return rc;
}

/* Whether one variable's descriptor decorations name a slot of the layout: set 0, the uniform
 * block at HFX_VK_BINDING_BLOCK, samplers at HFX_VK_BINDING_SAMPLER0 + k, k < sampler_count. */
static const char *variable_slot_error(const module *m, uint32_t id, uint32_t storage, uint32_t sampler_count,
                                       bool *block) {
    bool decorated = m->set[id] >= 0 || m->binding[id] >= 0;
    if (storage != STORAGE_UNIFORM && storage != STORAGE_UNIFORM_CONSTANT) return decorated ? "a descriptor outside a uniform" : NULL;
    if (m->set[id] != 0) return "a descriptor set other than 0";
    const uint32_t *ptr = def_of(m, m->w[m->def[id] + 1]), *pointee = ptr && (ptr[0] >> 16) >= 4 ? def_of(m, ptr[3]) : NULL;
    uint32_t want = storage == STORAGE_UNIFORM ? OP_TYPE_STRUCT : OP_TYPE_SAMPLED_IMAGE;
    if (!pointee || (pointee[0] & 0xffffu) != want) return "a descriptor of another type than the layout's";
    if (storage == STORAGE_UNIFORM) {
        *block = true;
        return m->binding[id] == HFX_VK_BINDING_BLOCK ? NULL : "a uniform block at another binding than the effect's";
    }
    int32_t k = m->binding[id] - HFX_VK_BINDING_SAMPLER0;
    return k >= 0 && (uint32_t)k < sampler_count ? NULL : "a sampler binding the program does not have";
}

const char *hfx_vk_check_slots(const uint32_t *words, size_t count, uint32_t sampler_count, bool *block) {
    module m;
    const char *why = module_open(&m, words, count, NULL) ? "an unreadable module" : NULL;
    for (uint32_t id = 1; !why && id < m.bound; id++) {
        const uint32_t *v = def_of(&m, id);
        if (v && (v[0] & 0xffffu) == OP_VARIABLE && (v[0] >> 16) >= 4)
            why = variable_slot_error(&m, id, v[3], sampler_count, block);
    }
    module_close(&m);
    return why;
}

/* SPIR-V's Dim of an OpTypeImage (1D 0, 2D 1, 3D 2, Cube 3) as hfx_fx_dim. */
static uint8_t fx_dim(uint32_t spirv_dim) {
    static const uint8_t dims[4] = {HFX_FX_DIM_1D, HFX_FX_DIM_2D, HFX_FX_DIM_3D, HFX_FX_DIM_CUBE};
    return spirv_dim < 4 ? dims[spirv_dim] : HFX_FX_DIM_2D;
}

/* A program's uniform may sample one effect sampler as another dimension than the effect's
 * record says (DigitalRise's VolumetricLight: tex2Dlod in one function, texCUBElod in
 * another): the module's own image type is what its binding needs. */
int hfx_vk_sampler_dims(const uint32_t *words, size_t count, uint8_t *dims, uint32_t dim_count) {
    module m;
    int rc = module_open(&m, words, count, NULL);
    for (uint32_t id = 1; !rc && id < m.bound; id++) {
        const uint32_t *v = def_of(&m, id);
        if (!v || (v[0] & 0xffffu) != OP_VARIABLE || (v[0] >> 16) < 4 || v[3] != STORAGE_UNIFORM_CONSTANT) continue;
        int32_t k = m.binding[id] - HFX_VK_BINDING_SAMPLER0;
        const uint32_t *ptr = def_of(&m, v[1]), *si = ptr && (ptr[0] >> 16) >= 4 ? def_of(&m, ptr[3]) : NULL;
        const uint32_t *im = si && (si[0] & 0xffffu) == OP_TYPE_SAMPLED_IMAGE && (si[0] >> 16) >= 3 ? def_of(&m, si[2]) : NULL;
        if (k >= 0 && (uint32_t)k < dim_count && im && (im[0] & 0xffffu) == OP_TYPE_IMAGE && (im[0] >> 16) >= 4)
            dims[k] = fx_dim(im[3]);
    }
    module_close(&m);
    return rc;
}

void hfx_vk_block_free(vk_block *b) {
    free(b->leaves);
    memset(b, 0, sizeof *b);
}
