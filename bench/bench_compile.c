/* bench_compile.c: the full compile of the seed corpus by hfx (preprocess, parse, check,
 * build, GLSL 330 for every pass) against glslangValidator compiling the GLSL hfx emitted to
 * SPIR-V (-G: OpenGL SPIR-V), for the same passes, in the same run; and, as a lower bound
 * without process starts, glslang in process parsing and linking the same GLSL (no SPIR-V).
 * Prints the times and ratios; hfx's goal is >= 10x. Run by hand: bench_compile [rounds]. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "files.h"

#include "effect.h"
#include "glsl_check.h"
#include "hfx/hfxc.h"
#include "bench.h"

static const char *const seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
    "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
    "spot_specular.fx", "tutorial0.fx",
};
enum { SEEDS = sizeof seeds / sizeof *seeds };

enum { MAX_PROGRAMS = 256 };
static char *kept[MAX_PROGRAMS][2]; /* the GLSL of the first round, for the in-process baseline */
static int kept_count;

/* One round of hfx over the corpus (sources already in memory); returns the programs made. */
static int hfx_round(char *const *src, const size_t *size, const char *dir) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    int programs = 0;
    for (int i = 0; i < SEEDS; i++) {
        hfxc_result *r = hfxc_compile_memory(src[i], size[i], seeds[i], &o);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        for (uint32_t p = 0; fx && p < fx->program_count; p++, programs++) {
            if (!dir) continue;
            if (kept_count < MAX_PROGRAMS) {
                for (int s = 0; s < 2; s++) {
                    const char *t = fx->programs[p].code[s][HFX_TARGET_GLSL330].data;
                    kept[kept_count][s] = t ? strdup(t) : NULL;
                }
                kept_count++;
            }
            for (int s = 0; s < 2; s++) {
                char path[512];
                snprintf(path, sizeof path, "%s/p%02d_%u.%s", dir, i, p, s ? "frag" : "vert");
                FILE *f = fopen(path, "w");
                if (f) { fputs(fx->programs[p].code[s][HFX_TARGET_GLSL330].data, f); fclose(f); }
            }
        }
        hfxc_result_free(r);
    }
    return programs;
}

int main(int argc, char **argv) {
    int rounds = argc > 1 ? atoi(argv[1]) : 20;
    if (rounds < 1) rounds = 1;
    char *src[SEEDS];
    size_t size[SEEDS];
    for (int i = 0; i < SEEDS; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", HFX_SEED_DIR, seeds[i]);
        if (!(src[i] = test_read_file(path, &size[i]))) { fprintf(stderr, "no seed corpus at %s\n", HFX_SEED_DIR); return 1; }
    }
    char dir[] = "/tmp/hfx_bench_XXXXXX";
    if (!mkdtemp(dir)) { perror("mkdtemp"); return 1; }
    int programs = hfx_round(src, size, dir);

    double best_hfx = 1e9;
    for (int r = 0; r < rounds; r++) {
        double t0 = now();
        hfx_round(src, size, NULL);
        double t = now() - t0;
        if (t < best_hfx) best_hfx = t;
    }
    /* glslangValidator: one process per program (vertex + fragment, as glslang links a stage's
     * files together); the cost of starting the process is measured apart with --version */
    double best_glslang = 1e9, best_spawn = 1e9;
    int status = 0;
    int grounds = rounds < 3 ? rounds : 3;
    char cmd[1024];
    for (int r = 0; r < grounds; r++) {
        double t0 = now(), spawn = 0;
        for (int i = 0; i < SEEDS; i++)
            for (int p = 0; p < 8; p++) {
                snprintf(cmd, sizeof cmd, "cd %s && test -f p%02d_%d.vert && glslangValidator -G --aml --amb -o p.spv "
                         "p%02d_%d.vert p%02d_%d.frag >> glslang.log 2>&1", dir, i, p, i, p, i, p);
                char probe[600];
                snprintf(probe, sizeof probe, "%s/p%02d_%d.vert", dir, i, p);
                FILE *f = fopen(probe, "r");
                if (!f) break;
                fclose(f);
                status |= system(cmd);
            }
        double t = now() - t0;
        if (t < best_glslang) best_glslang = t;
        t0 = now();
        for (int k = 0; k < programs; k++) status |= system("glslangValidator --version > /dev/null");
        spawn = now() - t0;
        if (spawn < best_spawn) best_spawn = spawn;
    }
    double best_inproc = 1e9;
    int linked = 0;
    for (int r = 0; r < rounds; r++) {
        double t0 = now();
        linked = 0;
        for (int k = 0; k < kept_count; k++)
            if (kept[k][0] && kept[k][1]) linked += test_glsl_link(kept[k][0], kept[k][1], NULL);
        double t = now() - t0;
        if (t < best_inproc) best_inproc = t;
    }
    printf("corpus: %d files, %d programs (%d shaders)\n", SEEDS, programs, 2 * programs);
    printf("hfx full compile (.fx -> GLSL 330): %.3f ms (best of %d)\n", best_hfx * 1e3, rounds);
    printf("glslangValidator (GLSL -> SPIR-V):  %.3f ms (best of %d)%s\n", best_glslang * 1e3, grounds,
           status ? "  [glslangValidator reported errors: see glslang.log]" : "");
    printf("  of which starting %d processes:   %.3f ms\n", programs, best_spawn * 1e3);
    printf("ratio glslang / hfx: %.1fx (goal >= 10x)\n", best_glslang / best_hfx);
    printf("ratio without process start: %.1fx\n", (best_glslang - best_spawn) / best_hfx);
    printf("glslang in process (parse + link, no SPIR-V): %.3f ms (best of %d, %d/%d linked)\n", best_inproc * 1e3,
           rounds, linked, kept_count);
    printf("ratio glslang in process / hfx: %.1fx\n", best_inproc / best_hfx);
    for (int k = 0; k < kept_count; k++) { free(kept[k][0]); free(kept[k][1]); }
    if (status) { printf("(left %s for inspection)\n", dir); for (int i = 0; i < SEEDS; i++) free(src[i]); return 0; }
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
    for (int i = 0; i < SEEDS; i++) free(src[i]);
    return 0;
}
