/* Shared by every fuzz harness (fuzz_check.h): the abort on a broken promise, the .hfxo repair. */
#include "fuzz_check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fuzz_require(int cond, const char *why) {
    if (cond) return;
    fprintf(stderr, "fuzz: broken promise: %s\n", why);
    abort();
}

/* CRC-32, IEEE polynomial, bit by bit: the harness's own, so a bug in the reader's table
 * cannot hide itself. */
static uint32_t crc32_bits(const uint8_t *p, size_t n) {
    uint32_t crc = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        crc ^= p[i];
        for (int k = 0; k < 8; k++) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

static void put32(uint8_t *p, uint32_t v) {
    for (int i = 0; i < 4; i++) p[i] = (uint8_t)(v >> (8 * i));
}

uint8_t *fuzz_repair_hfxo(const uint8_t *data, size_t size, uint8_t *out) {
    if (size) memcpy(out, data, size);
    if (size < 20) return out;
    put32(out + 16, (uint32_t)size);
    put32(out + 12, crc32_bits(out + 16, size - 16));
    return out;
}
