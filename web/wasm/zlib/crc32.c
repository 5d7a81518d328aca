/* crc32.c: zlib's crc32() (IEEE 802.3, reflected, init and final xor ~0) for the WebAssembly
 * build. A bitwise loop: it checks an .hfxo of a few kilobytes once per load. */
#include "zlib.h"

uLong crc32(uLong crc, const Bytef *buf, uInt len) {
    if (!buf) return 0;
    unsigned long c = crc ^ 0xffffffffUL;
    for (uInt i = 0; i < len; i++) {
        c ^= buf[i];
        for (int k = 0; k < 8; k++) c = (c >> 1) ^ (0xedb88320UL & (0UL - (c & 1)));
    }
    return c ^ 0xffffffffUL;
}
