/* The Vulkan runtime on .hfxo bytes (lavapipe, the validation layer on when installed; the
 * device of tests/harness/vk_context.c): as fuzz_runtime.c does on GL, the repaired file is
 * loaded, its annotations read, its parameters set to hostile values and a hostile scene bound,
 * and every pass applied into a frame's command buffer, on the effect and on a clone. Refused
 * files must say why; nothing may crash or be undefined. Validation messages are counted and
 * printed by the harness (libFuzzer's output) but are not findings. */
#include <stdint.h>
#include <stdlib.h>

#include <hfx/hfx.h>
#include <hfx/hfx_vulkan.h>

#include "fuzz_check.h"
#include "fuzz_values.h"
#include "vk_context.h"

/* One Vulkan device, target and vertex layout for the whole run: the harness's state. */
static test_vk *vk;
static hfx_vertex_layout *layout;

int LLVMFuzzerInitialize(int *argc, char ***argv) {
    (void)argc, (void)argv;
    const char *why = NULL;
    vk = test_vk_create(16, 16, &why);
    fuzz_require(vk != NULL, why ? why : "no Vulkan device");
    const hfx_vertex_element e[4] = {{"POSITION", VK_FORMAT_R32G32B32_SFLOAT, 0, 0, 48},
                                     {"NORMAL", VK_FORMAT_R32G32B32_SFLOAT, 12, 0, 48},
                                     {"TEXCOORD0", VK_FORMAT_R32G32_SFLOAT, 24, 0, 48},
                                     {"COLOR0", VK_FORMAT_R32G32B32A32_SFLOAT, 32, 0, 48}};
    layout = hfx_vertex_layout_create(test_vk_device(vk), e, 4);
    fuzz_require(layout != NULL, "no vertex layout");
    test_vk_target(vk)->layout = layout;
    return 0;
}

/* One frame: every pass of every technique applied, inside begin/end. */
static void apply_all(hfx_effect *fx) {
    static const float clear[4] = {0, 0, 0, 1};
    VkCommandBuffer cmd = test_vk_begin(vk, clear);
    fuzz_require(cmd != VK_NULL_HANDLE, "no command buffer");
    fuzz_require(hfx_effect_begin(fx) == HFX_OK, "begin failed on a loaded effect");
    for (size_t t = 0; t < hfx_effect_technique_count(fx); t++) {
        hfx_technique *tech = hfx_effect_technique_at(fx, t);
        hfx_effect_set_current_technique(fx, tech);
        for (size_t p = 0; p < hfx_technique_pass_count(tech); p++)
            (void)hfx_pass_apply_vk(hfx_technique_pass(tech, p), cmd, test_vk_target(vk));
    }
    fuzz_require(hfx_effect_end(fx) == HFX_OK, "end failed on a loaded effect");
    fuzz_require(test_vk_end(vk) == 0, "the frame failed");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    uint8_t *bytes = malloc(size ? size : 1);
    if (!bytes) return 0;
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(test_vk_device(vk), fuzz_repair_hfxo(data, size, bytes), size, "fuzz.hfxo",
                                            NULL, &errors);
    fuzz_require(fx != NULL || (errors && *errors), "a refused effect without a reason");
    if (fx) {
        uint32_t seed = fuzz_seed(data, size);
        fuzz_read_annotations(fx, bytes, size);
        fuzz_hostile_values(fx, seed);
        apply_all(fx);
        hfx_effect *copy = hfx_effect_clone(fx);
        fuzz_require(copy != NULL, "clone failed");
        hfx_effect_destroy(fx);
        fuzz_hostile_values(copy, seed + 1);
        apply_all(copy);
        hfx_effect_destroy(copy);
    }
    hfx_free(errors);
    free(bytes);
    return 0;
}
