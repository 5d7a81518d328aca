/* The .hfxo reader. Built twice: fuzz_hfxo takes the bytes as they come (the magic, version,
 * size and CRC checks), fuzz_hfxo_repair first makes the size field and the CRC-32 match, so
 * mutations reach the section and index checks behind them. Whatever the reader accepts must
 * write back out and read again to the same bytes. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "fuzz_check.h"

static void check_round_trip(const hfx_fx_effect *fx) {
    void *out = NULL, *again = NULL;
    size_t size = 0, size2 = 0;
    fuzz_require(hfx_fx_write_hfxo(fx, &out, &size) == 0, "an accepted effect does not write");
    char err[256];
    hfx_fx_effect *back = hfx_fx_read_hfxo(out, size, err, sizeof err);
    fuzz_require(back != NULL, "a written effect does not read back");
    fuzz_require(hfx_fx_write_hfxo(back, &again, &size2) == 0, "a re-read effect does not write");
    fuzz_require(size == size2 && memcmp(out, again, size) == 0, "write(read(write(x))) differs");
    hfx_fx_effect_free(back);
    free(out);
    free(again);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    uint8_t *bytes = malloc(size ? size : 1);
    if (!bytes) return 0;
#ifdef HFX_FUZZ_REPAIR
    fuzz_repair_hfxo(data, size, bytes);
#else
    if (size) memcpy(bytes, data, size);
#endif
    char err[256] = "";
    hfx_fx_effect *fx = hfx_fx_read_hfxo(bytes, size, err, sizeof err);
    fuzz_require(fx != NULL || err[0] != '\0', "a refused file without a reason");
    if (fx) check_round_trip(fx);
    hfx_fx_effect_free(fx);
    free(bytes);
    return 0;
}
