/* d3d9_asm.h: hand assembly of D3D9 shader tokens for the tests, written from the token layout
 * of Microsoft's "Shader Code Format" pages (instruction, destination and source parameter
 * tokens), independently of compiler/d3d9's decoder. */
#ifndef HFX_TEST_D3D9_ASM_H
#define HFX_TEST_D3D9_ASM_H

#include <stdint.h>
#include <string.h>

#define VS(maj, min) (0xfffe0000u | (maj) << 8 | (min))
#define PS(maj, min) (0xffff0000u | (maj) << 8 | (min))
#define END_TOKEN 0x0000ffffu
/* Instruction token: opcode, operand token count (SM2+ length field), controls in 16-23. */
#define OP(op, len) ((uint32_t)(op) | (uint32_t)(len) << 24)
#define OPC(op, len, ctl) (OP(op, len) | (uint32_t)(ctl) << 16)
#define PRED_BIT (1u << 28)
#define COISSUE_BIT (1u << 30)
/* Register type split over bits 28-30 and 11-12. */
#define REGT(t) ((((uint32_t)(t) & 7u) << 28) | (((uint32_t)(t) & 0x18u) << 8))
#define DST(t, n, mask) (0x80000000u | REGT(t) | (uint32_t)(n) | (uint32_t)(mask) << 16)
#define DSTM(t, n, mask, mods) (DST(t, n, mask) | (uint32_t)(mods) << 20)
#define SW(x, y, z, w) ((x) | (y) << 2 | (z) << 4 | (w) << 6)
#define XYZW SW(0, 1, 2, 3)
#define SRC(t, n, swz) (0x80000000u | REGT(t) | (uint32_t)(n) | (uint32_t)(swz) << 16)
#define SRCM(t, n, swz, mod) (SRC(t, n, swz) | (uint32_t)(mod) << 24)
#define REL (1u << 13)
#define COMMENT(words) (0xfffeu | (uint32_t)(words) << 16)

/* Register types. */
enum { R_TEMP, R_INPUT, R_CONST, R_ADDR, R_RASTOUT, R_ATTROUT, R_OUTPUT, R_CONSTINT, R_COLOROUT,
       R_DEPTHOUT, R_SAMPLER, R_CONSTBOOL = 14, R_LOOP = 15, R_MISC = 17, R_LABEL = 18, R_PRED = 19 };

static inline uint32_t fbits(float f) {
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

/* A CTAB comment laid out by hand: header, constant infos, type infos, then strings. */
typedef struct ctab_const { const char *name; uint16_t set, reg, count, cls, type, rows, cols, elems; } ctab_const;

static inline size_t put_ctab(uint32_t *w, const char *creator, const ctab_const *k, unsigned n) {
    unsigned char b[1024] = {0};
    size_t infos = 28, types = infos + 20 * n, strs = types + 16 * n, at = strs;
#define PUT32(off, v) do { uint32_t v_ = (v); memcpy(b + (off), &v_, 4); } while (0)
#define PUT16(off, v) do { uint16_t v_ = (uint16_t)(v); memcpy(b + (off), &v_, 2); } while (0)
    PUT32(0, 28);
    PUT32(4, at); memcpy(b + at, creator, strlen(creator) + 1); at += strlen(creator) + 1;
    PUT32(8, 0xfffe0300u);
    PUT32(12, n);
    PUT32(16, infos);
    PUT32(24, at); memcpy(b + at, "vs_3_0", 7); at += 7;
    for (unsigned i = 0; i < n; i++) {
        size_t c = infos + 20 * i, t = types + 16 * i;
        PUT32(c, at); memcpy(b + at, k[i].name, strlen(k[i].name) + 1); at += strlen(k[i].name) + 1;
        PUT16(c + 4, k[i].set); PUT16(c + 6, k[i].reg); PUT16(c + 8, k[i].count);
        PUT32(c + 12, t);
        PUT16(t, k[i].cls); PUT16(t + 2, k[i].type); PUT16(t + 4, k[i].rows); PUT16(t + 6, k[i].cols);
        PUT16(t + 8, k[i].elems);
    }
    size_t words = (at + 3) / 4;
    w[0] = COMMENT(words + 1);
    w[1] = 0x42415443u; /* CTAB */
    memcpy(w + 2, b, words * 4);
    return words + 2;
}

#endif
