/* The fx_2_0 reader (compiler/effect/fx2_*.c, fxlvm.c) through hfxc_compile_memory, as the
 * runtime reaches it. An input that does not start like an fxc binary gets fx_2_0's magic, so
 * mutations reach the container behind it. A refused file must say why; an accepted one must
 * be a valid effect (written as .hfxo, it reads back). Seeds: fuzz/fx2_seed.c. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "effect/fx2.h"
#include "fuzz_check.h"
#include "hfx/hfxc.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (size < 8) return 0;
    uint8_t *bytes = malloc(size);
    if (!bytes) return 0;
    memcpy(bytes, data, size);
    if (!hfx_fx2_is_binary(bytes, size)) bytes[0] = 0x01, bytes[1] = 0x09, bytes[2] = 0xff, bytes[3] = 0xfe;
    hfxc_options opt = {0};
    opt.flags = HFXC_NO_SELF_CHECK;
    hfxc_result *r = hfxc_compile_memory((const char *)bytes, size, "fuzz.fxb", &opt);
    fuzz_check_result(r);
    if (hfxc_result_ok(r)) {
        void *out = NULL;
        size_t n = 0;
        fuzz_require(hfx_fx_write_hfxo(hfxc_result_effect(r), &out, &n) == 0, "an accepted effect does not write");
        char err[256];
        hfx_fx_effect *back = hfx_fx_read_hfxo(out, n, err, sizeof err);
        if (!back) fprintf(stderr, "fuzz_fx2: the .hfxo reader says: %s\n", err);
        fuzz_require(back != NULL, "an accepted effect is no valid .hfxo");
        hfx_fx_effect_free(back);
        free(out);
    } else {
        fuzz_require(hfxc_diag_count(r) > 0, "a refused file without a reason");
    }
    hfxc_result_free(r);
    free(bytes);
    return 0;
}
