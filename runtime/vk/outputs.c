/* outputs.c: pixel shader outputs past the target's colour attachments. D3D9 drops what a
 * pixel shader writes to COLOR1..3 when no render target is set there, and so does GL (no draw
 * buffer); Vulkan drops it too, but the validation layer reports every fragment output without
 * an attachment (OutputNotConsumed). So a program whose pixel shader writes more colours than
 * a target has gets, for that target, a copy of its module in which those outputs are Private
 * variables: written, never read, no longer outputs, the same pixels without the report.
 *
 * The rewrite, on the module's words: each Output variable with Location >= n (and every
 * access chain into it) takes a Private pointer type (an existing one, or one added after the
 * Output pointer to the same type), loses its Location and, before SPIR-V 1.4 (where the entry
 * point lists only inputs and outputs), its place in the entry point's interface. */
#include <stdlib.h>
#include <string.h>

#include "vk/vk.h"

enum {
    OP_ENTRY_POINT = 15, OP_TYPE_POINTER = 32, OP_VARIABLE = 59, OP_ACCESS_CHAIN = 65, OP_IN_BOUNDS_ACCESS_CHAIN = 66,
    OP_DECORATE = 71, DEC_LOCATION = 30, SC_OUTPUT = 3, SC_PRIVATE = 6, SPIRV_1_4 = 0x00010400
};

typedef struct demote {
    const uint32_t *w;
    size_t count;
    uint32_t ids, bound;    /* the module's id bound (the arrays' size), and with the ids added */
    uint8_t *gone;          /* per id: demoted (a variable or a chain into one) */
    uint32_t *private_of;   /* per Output pointer type id: its Private twin (0: none needed yet) */
    uint32_t *pointee;      /* per pointer type id: what it points to */
    uint8_t *storage;       /* per pointer type id: its storage class + 1 (0: not a pointer) */
    uint32_t *location;     /* per id: Location + 1 (0: none) */
} demote;

static uint32_t op_of(uint32_t word) { return word & 0xffffu; }
static uint32_t len_of(uint32_t word) { return word >> 16; }

/* Walks the instructions after the header; 0 when one runs past the end. */
#define EACH_INSTRUCTION(d, i, n) \
    for (size_t i = 5, n = 0; i < (d)->count && (n = len_of((d)->w[i])) > 0 && i + n <= (d)->count; i += n)

/* Pointer types, Locations, and which variables and chains go. */
static void analyse(demote *d, uint32_t colors) {
    EACH_INSTRUCTION(d, i, n) {
        const uint32_t *in = d->w + i;
        uint32_t op = op_of(in[0]);
        if (op == OP_TYPE_POINTER && n == 4 && in[1] < d->ids)
            d->storage[in[1]] = (uint8_t)(in[2] + 1), d->pointee[in[1]] = in[3];
        else if (op == OP_DECORATE && n == 4 && in[2] == DEC_LOCATION && in[1] < d->ids)
            d->location[in[1]] = in[3] + 1;
        else if (op == OP_VARIABLE && n >= 4 && in[3] == SC_OUTPUT && in[2] < d->ids && d->location[in[2]] > colors)
            d->gone[in[2]] = 1;
        else if ((op == OP_ACCESS_CHAIN || op == OP_IN_BOUNDS_ACCESS_CHAIN) && n >= 4 && in[2] < d->ids &&
                 in[3] < d->ids && d->gone[in[3]])
            d->gone[in[2]] = 1;
        if ((op == OP_VARIABLE || op == OP_ACCESS_CHAIN || op == OP_IN_BOUNDS_ACCESS_CHAIN) && n >= 4 &&
            in[2] < d->ids && d->gone[in[2]] && in[1] < d->ids)
            d->private_of[in[1]] = UINT32_MAX; /* its type needs a Private twin */
    }
    /* an existing Private pointer to the same type serves; else a new id */
    for (uint32_t t = 0; t < d->ids; t++) {
        if (d->private_of[t] != UINT32_MAX) continue;
        for (uint32_t u = 0; u < d->ids && d->private_of[t] == UINT32_MAX; u++)
            if (d->storage[u] == SC_PRIVATE + 1 && d->pointee[u] == d->pointee[t]) d->private_of[t] = u;
        if (d->private_of[t] == UINT32_MAX) d->private_of[t] = d->bound++ | 0x80000000u; /* high bit: to declare */
    }
}

/* The instruction at in, rewritten into out; the words written. */
static size_t rewrite(const demote *d, const uint32_t *in, size_t n, uint32_t *out, uint32_t version) {
    uint32_t op = op_of(in[0]);
    memcpy(out, in, n * sizeof *in);
    if (op == OP_DECORATE && n >= 3 && in[1] < d->ids && d->gone[in[1]] && in[2] == DEC_LOCATION) return 0;
    if (op == OP_ENTRY_POINT && version < SPIRV_1_4) {
        size_t k = 3;
        while (k < n && (in[k] & 0xff000000u) && (in[k] & 0xff) && (in[k] & 0xff00) && (in[k] & 0xff0000)) k++;
        k++; /* past the word holding the name's terminating zero */
        size_t m = k;
        for (size_t j = k; j < n; j++)
            if (!(in[j] < d->ids && d->gone[in[j]])) out[m++] = in[j];
        out[0] = (uint32_t)(m << 16) | op;
        return m;
    }
    if ((op == OP_VARIABLE || op == OP_ACCESS_CHAIN || op == OP_IN_BOUNDS_ACCESS_CHAIN) && n >= 4 && in[2] < d->ids &&
        d->gone[in[2]]) {
        out[1] = d->private_of[in[1]] & 0x7fffffffu;
        if (op == OP_VARIABLE) out[3] = SC_PRIVATE;
    }
    if (op == OP_TYPE_POINTER && n == 4 && in[1] < d->ids && (d->private_of[in[1]] & 0x80000000u)) {
        uint32_t twin[4] = {(4u << 16) | OP_TYPE_POINTER, d->private_of[in[1]] & 0x7fffffffu, SC_PRIVATE, in[3]};
        memcpy(out + n, twin, sizeof twin);
        return n + 4;
    }
    return n;
}

static int demote_alloc(demote *d, uint32_t bound) {
    d->gone = calloc(bound, 1);
    d->storage = calloc(bound, 1);
    d->private_of = calloc(bound, sizeof *d->private_of);
    d->pointee = calloc(bound, sizeof *d->pointee);
    d->location = calloc(bound, sizeof *d->location);
    return d->gone && d->storage && d->private_of && d->pointee && d->location;
}

static void demote_free(demote *d) {
    free(d->gone), free(d->storage), free(d->private_of), free(d->pointee), free(d->location);
}

/* The module's words with the outputs at Location >= colors made Private: malloc'ed, *out_count
 * words; NULL without memory or for words that are not a module. */
static uint32_t *demoted_words(const uint32_t *w, size_t count, uint32_t colors, size_t *out_count) {
    if (count < 5 || w[3] == 0 || w[3] > (1u << 22)) return NULL;
    demote d = {w, count, w[3], w[3], NULL, NULL, NULL, NULL, NULL};
    uint32_t *out = NULL;
    if (demote_alloc(&d, w[3])) {
        analyse(&d, colors);
        /* each pointer type gains at most one 4-word twin */
        out = malloc((count + 4 * (size_t)w[3]) * sizeof *out);
    }
    if (out) {
        memcpy(out, w, 5 * sizeof *w);
        out[3] = d.bound;
        size_t m = 5;
        EACH_INSTRUCTION(&d, i, n) m += rewrite(&d, w + i, n, out + m, w[1]);
        *out_count = m;
    }
    demote_free(&d);
    return out;
}

/* The highest colour output Location + 1 the pixel module writes (0: none). */
static uint32_t colors_written(const uint32_t *w, size_t count) {
    uint32_t bound = count >= 5 ? w[3] : 0, most = 0;
    if (!bound || bound > (1u << 22)) return 0;
    uint32_t *loc = calloc(bound, sizeof *loc);
    if (!loc) return 0;
    demote d = {w, count, bound, bound, NULL, NULL, NULL, NULL, NULL};
    EACH_INSTRUCTION(&d, i, n) {
        const uint32_t *in = w + i;
        if (op_of(in[0]) == OP_DECORATE && n == 4 && in[2] == DEC_LOCATION && in[1] < bound) loc[in[1]] = in[3] + 1;
        else if (op_of(in[0]) == OP_VARIABLE && n >= 4 && in[3] == SC_OUTPUT && in[2] < bound && loc[in[2]] > most)
            most = loc[in[2]];
    }
    free(loc);
    return most;
}

int hfx_vk_outputs_make(hfx_device *dev, const hfx_fx_code *code, vk_program *p) {
    const uint32_t *w = (const uint32_t *)(const void *)code->data;
    size_t count = code->size / 4;
    p->colors_written = colors_written(w, count);
    for (uint32_t n = 0; n < p->colors_written && n < 4; n++) {
        size_t m = 0;
        uint32_t *words = demoted_words(w, count, n, &m);
        if (!words) return hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
        char reason[256]; /* the rewrite of a valid module is checked too: no driver sees invalid SPIR-V */
        if (!hfx_vk_spirv_valid(dev->vk, words, m, reason)) {
            free(words);
            return hfx_rt_fail(dev, HFX_ERR_LOAD, "internal: the pixel shader rewritten for %u colour targets is not "
                               "valid SPIR-V: %s", n, reason);
        }
        VkShaderModuleCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, .codeSize = m * 4, .pCode = words};
        VkResult r = dev->vk->fn.CreateShaderModule(dev->vk->device, &ci, NULL, &p->fs_fewer[n]);
        free(words);
        if (r != VK_SUCCESS) return hfx_vk_fail(dev, r, "vkCreateShaderModule (pixel shader for fewer targets)");
    }
    return HFX_OK;
}

VkShaderModule hfx_vk_fragment_module(const vk_program *p, uint32_t color_count) {
    return color_count < p->colors_written && color_count < 4 && p->fs_fewer[color_count] ? p->fs_fewer[color_count] : p->fs;
}
