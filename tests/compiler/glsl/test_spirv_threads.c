/* test_spirv_threads.c: hfxc compiles files on several threads, and each effect brackets its
 * glslang work with glslang_initialize_process / glslang_finalize_process (reference counted
 * under glslang's own lock). Four threads compiling every good seed to SPIR-V at once must give
 * byte for byte what one thread gives. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "glsl/spirv.h"
#include "test.h"

static const char *const seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
    "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
    "spot_specular.fx", "tutorial0.fx",
};
enum { SEEDS = sizeof seeds / sizeof *seeds, THREADS = 4, ROUNDS = 2 };

static hfx_fx_effect *reference[SEEDS];

static hfx_fx_effect *compile(const char *name) {
    char *path = test_seed_path(name);
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_SPIRV;
    hfxc_result *r = hfxc_compile_file(path, &o);
    free(path);
    hfx_fx_effect *fx = hfxc_result_take_effect(r);
    hfxc_result_free(r);
    return fx;
}

/* 1 when both effects carry the same SPIR-V everywhere. */
static int same_spirv(const hfx_fx_effect *a, const hfx_fx_effect *b) {
    if (!a || !b || a->program_count != b->program_count) return 0;
    for (uint32_t p = 0; p < a->program_count; p++)
        for (int s = 0; s < HFX_STAGE_COUNT; s++) {
            const hfx_fx_code *x = &a->programs[p].code[s][HFX_TARGET_SPIRV], *y = &b->programs[p].code[s][HFX_TARGET_SPIRV];
            if (!x->data || !y->data || x->size != y->size || memcmp(x->data, y->data, x->size) != 0) return 0;
        }
    return 1;
}

static void *worker(void *arg) {
    size_t start = (size_t)(uintptr_t)arg, bad = 0;
    for (int round = 0; round < ROUNDS; round++)
        for (size_t k = 0; k < SEEDS; k++) {
            size_t i = (start + k) % SEEDS; /* threads start on different files */
            hfx_fx_effect *fx = compile(seeds[i]);
            if (!same_spirv(fx, reference[i])) bad++;
            hfx_fx_effect_free(fx);
        }
    return (void *)(uintptr_t)bad;
}

static void threads_agree_with_one_thread(void) {
    for (size_t i = 0; i < SEEDS; i++) {
        reference[i] = compile(seeds[i]);
        CHECK(reference[i] != NULL);
        CHECK(reference[i] && reference[i]->program_count > 0);
    }
    pthread_t t[THREADS];
    for (size_t i = 0; i < THREADS; i++) CHECK_INT(pthread_create(&t[i], NULL, worker, (void *)(uintptr_t)(i * 3)), 0);
    for (size_t i = 0; i < THREADS; i++) {
        void *bad = NULL;
        pthread_join(t[i], &bad);
        CHECK_INT((uintptr_t)bad, 0);
    }
    for (size_t i = 0; i < SEEDS; i++) hfx_fx_effect_free(reference[i]);
}

int main(void) {
    if (!hfx_spirv_available()) test_skip("built without glslang: no SPIR-V target");
    test_require_seeds();
    RUN(threads_agree_with_one_thread);
    return test_summary();
}
