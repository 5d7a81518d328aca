/* bench_fx2_write: writing fx_2_0 (hfx_fx2_write) against writing .hfxo (hfx_fx_write_hfxo), the
 * same models, in one run, on thread CPU time: every .fx of a folder compiled (GLSL path) and,
 * with its effect, written both ways; every fxc binary (.fxb / .efb) read and written both ways.
 * Until hfxc's D3D9 back end is built in, a compiled source's shaders are written as NULL shaders
 * (no hook): the figure is the container's and the expressions', not the back end's.
 *     bench_fx2_write FOLDER [REPEATS]      (e.g. /tmp/corpus, or a folder of FNA's .fxb) */
#include <dirent.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench.h"
#include "effect.h"
#include "effect/fx2_write.h"
#include "files.h"
#include "hfx/hfxc.h"

typedef struct totals {
    double compile, fx2, hfxo;
    int effects, failed;
} totals;

static void one(const char *path, int repeats, totals *t) {
    size_t size;
    char *data = test_read_file(path, &size);
    if (!data) return;
    hfxc_options opt = {.flags = HFXC_PACK_UNIFORMS | HFXC_NO_SELF_CHECK};
    double t0 = thread_now();
    hfxc_result *r = hfxc_compile_memory(data, size, path, &opt);
    double t1 = thread_now();
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (fx) {
        double a = thread_now();
        bool ok = true;
        for (int i = 0; i < repeats && ok; i++) {
            void *out;
            size_t n;
            char err[512];
            ok = hfx_fx2_write(fx, path, NULL, &out, &n, err, sizeof err) == 0;
            free(out);
        }
        double b = thread_now();
        for (int i = 0; i < repeats; i++) {
            void *out;
            size_t n;
            if (hfx_fx_write_hfxo(fx, &out, &n) == 0) free(out);
        }
        double c = thread_now();
        if (ok) {
            t->compile += t1 - t0, t->fx2 += (b - a) / repeats, t->hfxo += (c - b) / repeats, t->effects++;
        } else {
            t->failed++;
        }
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
    printf("%d effects (%d not writable as fx_2_0), per effect: compile or read %.3f ms, fx_2_0 write %.4f ms, "
           ".hfxo write %.4f ms (fx_2_0 / .hfxo = %.2f)\n", t.effects, t.failed, 1e3 * t.compile / t.effects,
           1e3 * t.fx2 / t.effects, 1e3 * t.hfxo / t.effects, t.fx2 / t.hfxo);
    return 0;
}
