/* d3d9_ctab.c: the constant table fxc writes in a CTAB comment (D3DXSHADER_CONSTANTTABLE):
 * a 28-byte header (size, creator, version, count, constant infos, flags, target), 20-byte
 * constant infos (name, register set, index, count, type info, default value) and 16-byte type
 * infos. Offsets count from the byte after the fourcc; every one is checked against the block. */
#include "d3d9/d3d9_int.h"

typedef struct ctab { d3d9_reader *r; const unsigned char *p; uint32_t size, at; } ctab;

static uint32_t u32(const ctab *t, uint32_t off) {
    const unsigned char *p = t->p + off;
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static uint16_t u16(const ctab *t, uint32_t off) { return (uint16_t)(t->p[off] | t->p[off + 1] << 8); }

static bool fits(const ctab *t, uint32_t off, uint32_t n) { return off <= t->size && n <= t->size - off; }

/* A NUL-terminated string at off, or NULL (with an error) if it runs out of the block. */
static const char *str(ctab *t, uint32_t off, const char *what) {
    if (!off) return NULL;
    for (uint32_t k = off; k < t->size; k++)
        if (!t->p[k]) return hfx_arena_strndup(t->r->arena, (const char *)t->p + off, k - off);
    hfx_d3d9_fail(t->r, t->at, X_D3D9_CTAB, "constant table: %s string at %u runs out of the table", what, off);
    return NULL;
}

static bool read_constant(ctab *t, uint32_t off, d3d9_constant *k) {
    if (!fits(t, off, 20)) return false;
    k->name = str(t, u32(t, off), "name");
    k->regset = (uint8_t)u16(t, off + 4);
    k->reg = u16(t, off + 6);
    k->count = u16(t, off + 8);
    uint32_t ti = u32(t, off + 12), dv = u32(t, off + 16);
    if (!k->name || k->regset > D3D9_RS_SAMPLER || !fits(t, ti, 16)) return false;
    k->cls = u16(t, ti);
    k->type = u16(t, ti + 2);
    k->rows = u16(t, ti + 4);
    k->cols = u16(t, ti + 6);
    k->elements = u16(t, ti + 8);
    k->members = u16(t, ti + 10);
    if (dv && k->regset != D3D9_RS_SAMPLER) {
        uint32_t words = (uint32_t)k->count * 4;
        if (!fits(t, dv, words * 4)) return false;
        uint32_t *w = HFX_NEW_ARRAY(t->r->arena, uint32_t, words ? words : 1);
        for (uint32_t j = 0; j < words; j++) w[j] = u32(t, dv + j * 4);
        k->default_value = w;
        k->default_words = words;
    }
    return true;
}

void hfx_d3d9_read_ctab(d3d9_reader *r, const d3d9_comment *c, uint32_t at) {
    ctab t = {r, r->bytes + (size_t)at * 4 + 8, (c->word_count - 1) * 4, at};
    d3d9_shader *s = r->sh;
    if (!fits(&t, 0, 28) || u32(&t, 0) < 28) {
        hfx_d3d9_fail(r, at, X_D3D9_CTAB, "constant table shorter than its header");
        return;
    }
    s->creator = str(&t, u32(&t, 4), "creator");
    uint32_t count = u32(&t, 12), infos = u32(&t, 16);
    s->target = str(&t, u32(&t, 24), "target");
    if (count > t.size / 20 || !fits(&t, infos, count * 20)) {
        hfx_d3d9_fail(r, at, X_D3D9_CTAB, "constant table: %u constants do not fit in the table", count);
        return;
    }
    d3d9_constant *k = HFX_NEW_ARRAY(r->arena, d3d9_constant, count ? count : 1);
    for (uint32_t i = 0; i < count; i++) {
        if (!read_constant(&t, infos + i * 20, &k[i])) {
            hfx_d3d9_fail(r, at, X_D3D9_CTAB, "constant table: constant %u points outside the table", i);
            return;
        }
    }
    s->constants = k;
    s->constant_count = count;
}
