/* The runtime on .hfxo bytes (linked with hfx_runtime: no compiler), on an OSMesa context:
 * the size field and CRC-32 are repaired first (fuzz_check.h), the effect is loaded for GLSL
 * 330, every annotation is read, every parameter set to hostile values (NaN, infinities,
 * FLT_MAX, denormals, INT_MIN, INT_MAX: fuzz_values.h) and a scene bound with hostile matrices,
 * then every pass of every technique is applied, inside begin/end, on the effect and on a clone
 * (given other hostile values). Refused files must say why; accepted ones must apply without a
 * crash or undefined behaviour (UBSan with float-cast-overflow). */
#include <stdint.h>
#include <stdlib.h>

#include <hfx/hfx.h>

#include "fuzz_check.h"
#include "fuzz_values.h"
#include "gl_context.h"

typedef unsigned (*gl_get_error_fn)(void);

/* One context and device for the whole run: the harness's state, not the library's. */
static test_gl *context;
static hfx_device *device;

int LLVMFuzzerInitialize(int *argc, char ***argv) {
    (void)argc, (void)argv;
    context = test_gl_create(64, 64);
    fuzz_require(context != NULL, "no OSMesa context");
    device = hfx_device_create_gl(test_gl_loader);
    fuzz_require(device != NULL, "no hfx device");
    return 0;
}

static void apply_all(hfx_effect *fx) {
    fuzz_require(hfx_effect_begin(fx) == HFX_OK, "begin failed on a loaded effect");
    for (size_t t = 0; t < hfx_effect_technique_count(fx); t++) {
        hfx_technique *tech = hfx_effect_technique_at(fx, t);
        hfx_effect_set_current_technique(fx, tech);
        for (size_t p = 0; p < hfx_technique_pass_count(tech); p++) (void)hfx_pass_apply(hfx_technique_pass(tech, p));
    }
    fuzz_require(hfx_effect_end(fx) == HFX_OK, "end failed on a loaded effect");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    hfx_device *dev = device;
    uint8_t *bytes = malloc(size ? size : 1);
    if (!bytes) return 0;
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, fuzz_repair_hfxo(data, size, bytes), size, "fuzz.hfxo", NULL, &errors);
    fuzz_require(fx != NULL || (errors && *errors), "a refused effect without a reason");
    if (fx) {
        uint32_t seed = fuzz_seed(data, size);
        fuzz_read_annotations(fx, bytes, size);
        apply_all(fx);
        fuzz_hostile_values(fx, seed);
        apply_all(fx);
        hfx_effect *copy = hfx_effect_clone(fx);
        fuzz_require(copy != NULL, "clone failed");
        hfx_effect_destroy(fx);
        apply_all(copy);
        fuzz_hostile_values(copy, seed + 1);
        apply_all(copy);
        hfx_effect_destroy(copy);
    }
    hfx_free(errors);
    free(bytes);
    return 0;
}
