/* The compiler from memory: any bytes are an effect file. Every target (GLSL 330, ES 300, 110,
 * SPIR-V) with glslang's self-check on; inputs of odd length pack the uniforms, even ones keep
 * them separate, so both code generators see every input shape. A result must be consistent:
 * ok with an effect, or not ok with at least one located error. */
#include <stdint.h>
#include <stdlib.h>

#include <hfx/hfx.h>
#include <hfx/hfxc.h>

#include "fuzz_check.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    hfxc_options opt = {0};
    opt.targets = (1u << HFX_TARGET_COUNT) - 1;
    opt.flags = size % 2 ? HFXC_PACK_UNIFORMS : 0;
    hfxc_result *r = hfxc_compile_memory((const char *)data, size, "fuzz.fx", &opt);
    fuzz_check_result(r);
    hfxc_result_free(r);
    return 0;
}
