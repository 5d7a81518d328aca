/* Differential: whatever the compiler accepts, glslang accepts. The compiler runs with its own
 * self-check off (HFXC_NO_SELF_CHECK) for GLSL 330, ES 300 and 110; every program it emits is
 * then compiled and linked by glslang through the tests' independent judge (tests/harness/
 * glsl_check.c). A refusal aborts with glslang's log: the compiler produced invalid GLSL. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <hfx/hfx.h>
#include <hfx/hfxc.h>

#include "effect.h"
#include "fuzz_check.h"
#include "glsl_check.h"

static void judge(const hfx_fx_program *p, hfx_target t) {
    const char *vs = p->code[HFX_STAGE_VERTEX][t].data, *fs = p->code[HFX_STAGE_FRAGMENT][t].data;
    if (!vs || !fs) return;
    char *log = NULL;
    int ok = test_glsl_link(vs, fs, &log);
    if (!ok) fprintf(stderr, "glslang refuses target %d:\n%s\n--- vertex\n%s\n--- fragment\n%s\n", (int)t, log, vs, fs);
    free(log);
    fuzz_require(ok, "the compiler accepted an effect whose GLSL glslang refuses");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    hfxc_options opt = {0};
    opt.targets = 1u << HFX_TARGET_GLSL330 | 1u << HFX_TARGET_GLSLES300 | 1u << HFX_TARGET_GLSL110;
    opt.flags = HFXC_NO_SELF_CHECK | (size % 2 ? HFXC_PACK_UNIFORMS : 0);
    hfxc_result *r = hfxc_compile_memory((const char *)data, size, "fuzz.fx", &opt);
    fuzz_check_result(r);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    for (uint32_t i = 0; fx && i < fx->program_count; i++)
        for (int t = HFX_TARGET_GLSL330; t <= HFX_TARGET_GLSL110; t++) judge(&fx->programs[i], (hfx_target)t);
    hfxc_result_free(r);
    return 0;
}
