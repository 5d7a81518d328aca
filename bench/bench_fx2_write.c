/* bench_fx2_write: in one run, on thread CPU time, every .fx of a folder compiled twice: the GLSL
 * path (the baseline) and as `hfxc /T fx_2_0 /Fo` compiles it (GLSL plus each pass's D3D9
 * bytecode, HFXC_D3D9_BYTECODE); that effect then written as fx_2_0 (hfx_fx2_write) and as .hfxo
 * (hfx_fx_write_hfxo). Every fxc binary (.fxb / .efb) is read and written both ways.
 *     bench_fx2_write FOLDER [REPEATS]      (e.g. /tmp/corpus, or a folder of FNA's .fxb) */
#include <dirent.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench.h"
#include "effect.h"
#include "bytes.h"
#include "effect/fx2_int.h"
#include "effect/fx2_write.h"
#include "files.h"
#include "hfx/hfxc.h"

typedef struct totals {
    double glsl, compile, fx2, hfxo;
    int effects, failed, refused;
} totals;

/* Thread CPU seconds of `repeats` writes, each as fx_2_0 (fx2 true) or .hfxo; -1 if one failed. */
static double writes(const hfx_fx_effect *fx, const char *path, int repeats, bool fx2) {
    double a = thread_now();
    for (int i = 0; i < repeats; i++) {
        void *out = NULL;
        size_t n;
        char err[512];
        int rc = fx2 ? hfx_fx2_write(fx, path, NULL, &out, &n, err, sizeof err) : hfx_fx_write_hfxo(fx, &out, &n);
        free(out);
        if (rc != 0) return -1;
    }
    return (thread_now() - a) / repeats;
}

static void one(const char *path, int repeats, totals *t) {
    size_t size;
    char *data = test_read_file(path, &size);
    if (!data) return;
    bool binary = size >= 4 && hfx_le32(data) == FX2_MAGIC; /* an fxc binary: read, not compiled */
    hfxc_options opt = {.flags = HFXC_PACK_UNIFORMS | HFXC_NO_SELF_CHECK};
    double t0 = thread_now();
    hfxc_result *base = binary ? NULL : hfxc_compile_memory(data, size, path, &opt);
    double t1 = thread_now();
    bool glsl_ok = binary || hfxc_result_effect(base);
    hfxc_result_free(base);
    opt.flags |= HFXC_D3D9_BYTECODE;
    double t2 = thread_now();
    hfxc_result *r = hfxc_compile_memory(data, size, path, &opt);
    double t3 = thread_now();
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    double fx2 = fx ? writes(fx, path, repeats, true) : -1, hfxo = fx ? writes(fx, path, repeats, false) : -1;
    if (fx && fx2 >= 0 && hfxo >= 0 && glsl_ok) {
        t->glsl += binary ? t3 - t2 : t1 - t0, t->compile += t3 - t2, t->fx2 += fx2, t->hfxo += hfxo, t->effects++;
    } else if (glsl_ok && !binary) {
        t->refused++; /* compiles for GLSL; the bytecode back end or the container refuses it */
    } else {
        t->failed++;
    }
    hfxc_result_free(r);
    free(data);
}

static void walk(const char *dir, int repeats, totals *t) {
    DIR *d = opendir(dir);
    if (!d) return;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        struct stat st;
        if (stat(path, &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            walk(path, repeats, t);
            continue;
        }
        const char *dot = strrchr(e->d_name, '.');
        if (dot && (!strcmp(dot, ".fx") || !strcmp(dot, ".fxb") || !strcmp(dot, ".efb"))) one(path, repeats, t);
    }
    closedir(d);
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: bench_fx2_write FOLDER [REPEATS]\n");
        return 2;
    }
    int repeats = argc > 2 ? atoi(argv[2]) : 20;
    totals t = {0};
    walk(argv[1], repeats < 1 ? 1 : repeats, &t);
    if (!t.effects) return 1;
    double n = t.effects;
    printf("%d effects written (%d compile for GLSL but not as fx_2_0, %d fail both), per effect:\n"
           "  GLSL compile %.3f ms (baseline), fx_2_0 compile %.3f ms (%.2fx), fx_2_0 write %.4f ms, "
           ".hfxo write %.4f ms\n  compile + write as fx_2_0: %.3f ms an effect\n",
           t.effects, t.refused, t.failed, 1e3 * t.glsl / n, 1e3 * t.compile / n, t.compile / t.glsl, 1e3 * t.fx2 / n,
           1e3 * t.hfxo / n, 1e3 * (t.compile + t.fx2) / n);
    return 0;
}
