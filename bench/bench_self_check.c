/* bench_self_check.c: what the self-check costs. The seed corpus and fx/ compiled in one
 * process for the default targets (GLSL 330 + ES 300), with glslang checking every emitted
 * shader (the default) and without (HFXC_NO_SELF_CHECK), best of `rounds`, in the same run.
 * Prints ms per effect and the ratio. Run by hand: bench_self_check [rounds]. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "files.h"
#include "hfx/hfxc.h"

static const char *const files[] = {
    HFX_SEED_DIR "/ambient.fx", HFX_SEED_DIR "/ambient_textured.fx", HFX_SEED_DIR "/directional.fx",
    HFX_SEED_DIR "/directional_specular.fx", HFX_SEED_DIR "/fxcomposer_empty.fx", HFX_SEED_DIR "/multilights_repaired.fx",
    HFX_SEED_DIR "/phong.fx", HFX_SEED_DIR "/point.fx", HFX_SEED_DIR "/point_specular.fx", HFX_SEED_DIR "/pointlights.fx",
    HFX_SEED_DIR "/spot.fx", HFX_SEED_DIR "/spot_specular.fx", HFX_SEED_DIR "/tutorial0.fx",
    HFX_SOURCE_DIR "/fx/ambient.fx", HFX_SOURCE_DIR "/fx/directional.fx", HFX_SOURCE_DIR "/fx/multipass.fx",
    HFX_SOURCE_DIR "/fx/point.fx", HFX_SOURCE_DIR "/fx/point_lights.fx", HFX_SOURCE_DIR "/fx/sas_blinn.fx",
    HFX_SOURCE_DIR "/fx/shading_models.fx", HFX_SOURCE_DIR "/fx/spot.fx", HFX_SOURCE_DIR "/fx/textured.fx",
};
enum { FILES = sizeof files / sizeof *files };

/* Seconds for one compile of every file; -1 when one fails. */
static double round_of(char *const *src, const size_t *size, unsigned flags) {
    hfxc_options o;
    memset(&o, 0, sizeof o);
    o.flags = flags | HFXC_PACK_UNIFORMS;
    double t0 = now();
    for (int i = 0; i < FILES; i++) {
        hfxc_result *r = hfxc_compile_memory(src[i], size[i], files[i], &o);
        int ok = hfxc_result_ok(r);
        hfxc_result_free(r);
        if (!ok) return -1;
    }
    return now() - t0;
}

static double best_of(char *const *src, const size_t *size, unsigned flags, int rounds) {
    double best = 1e9;
    for (int k = 0; k < rounds; k++) {
        double t = round_of(src, size, flags);
        if (t < 0) return -1;
        if (t < best) best = t;
    }
    return best;
}

int main(int argc, char **argv) {
    int rounds = argc > 1 ? atoi(argv[1]) : 10;
    char *src[FILES];
    size_t size[FILES];
    for (int i = 0; i < FILES; i++)
        if (!(src[i] = test_read_file(files[i], &size[i]))) { fprintf(stderr, "cannot read %s\n", files[i]); return 1; }
    double off = best_of(src, size, HFXC_NO_SELF_CHECK, rounds < 1 ? 1 : rounds);
    double on = best_of(src, size, 0, rounds < 1 ? 1 : rounds);
    if (off < 0 || on < 0) { fprintf(stderr, "a file did not compile\n"); return 1; }
    printf("%d effects, GLSL 330 + ES 300, best of %d\n", FILES, rounds);
    printf("  without self-check: %8.3f ms/effect\n", off * 1e3 / FILES);
    printf("  with self-check:    %8.3f ms/effect\n", on * 1e3 / FILES);
    printf("  self-check costs %.2fx the compile without it\n", on / off);
    for (int i = 0; i < FILES; i++) free(src[i]);
    return 0;
}
