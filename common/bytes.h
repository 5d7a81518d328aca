/* bytes.h: reading little-endian words from byte buffers, the one way every binary reader here
 * (.hfxo, fxc's fx_2_0 containers, D3D9 bytecode) does it, whatever the host's byte order. */
#ifndef HFX_COMMON_BYTES_H
#define HFX_COMMON_BYTES_H

#include <stdint.h>

/* The little-endian 32-bit word at p (4 readable bytes). */
static inline uint32_t hfx_le32(const void *p) {
    const uint8_t *b = (const uint8_t *)p;
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

#endif
