/* zlib.h for the WebAssembly build: emscripten's sysroot has no zlib, and hfx takes only its
 * CRC-32 from it (the .hfxo checksum, the program cache), so this declares that one function
 * with zlib's signature; crc32.c implements it. The native build uses the real zlib. */
#ifndef HFX_WEB_ZLIB_H
#define HFX_WEB_ZLIB_H

typedef unsigned long uLong;
typedef unsigned int uInt;
typedef unsigned char Bytef;
#define Z_NULL 0

uLong crc32(uLong crc, const Bytef *buf, uInt len);

#endif
