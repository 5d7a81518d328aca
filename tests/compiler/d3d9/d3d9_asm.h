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

#endif
