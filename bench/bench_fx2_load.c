/* bench_fx2_load: issue 29's speed check, in one run on thread CPU time (OSMesa, llvmpipe shading
 * and compiling on the calling thread, Mesa's disk cache off so that no load finds another's
 * shaders), in user-space instructions of the thread (thread CPU time where the kernel has no
 * counter: the machine's other work then adds noise). For every fxc binary (.fxb / .efb / .fxo) below FOLDER whose .fx source is there too
 * (the .fx whose path ends with the longest run of the binary's own path, as
 * scripts/fx2_oracle.sh pairs them: FNA/Deferred/Fog.efb -> Deferred/Fog.fx), the best of
 * REPEATS loads (each on a new device, destroyed after) of
 *   fx:       the source, compiled and loaded (hfx_effect_load of the .fx, glslang's check on);
 *   binary:   fxc's binary, read, translated and loaded (hfx_effect_load of the binary);
 *   bin.hfxo: the binary converted once to .hfxo (hfxc -o X.hfxo X.fxb), loaded;
 *   fx.hfxo:  the source compiled once to .hfxo, loaded (what "as fast as any .hfxo" means).
 * The goals: binary <= fx, and bin.hfxo about fx.hfxo.
 *     bench_fx2_load FOLDER [REPEATS]   (REPEATS 3; a folder extracted as docs/fx2.md says) */
#define _DEFAULT_SOURCE /* setenv */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench.h"
#include "effect.h"
#include "files.h"
#include "gl_context.h"
#include "hfx/hfx.h"
#include "hfx/hfxc.h"

enum { MAX_FILES = 1024, KINDS = 4 };
static const char *const kind_names[KINDS] = {"fx", "binary", "bin.hfxo", "fx.hfxo"};

typedef struct file_list {
    char *path[MAX_FILES];
    int count;
} file_list;

static int has_ext(const char *p, const char *ext) {
    size_t n = strlen(p), e = strlen(ext);
    return n > e && strcmp(p + n - e, ext) == 0;
}

static int is_binary(const char *p) { return has_ext(p, ".fxb") || has_ext(p, ".efb") || has_ext(p, ".fxo"); }

/* Every .fx and binary below dir, paths relative to the root (prefix). */
static void walk(const char *root, const char *rel, file_list *fx, file_list *bin) {
    char dir[4096];
    snprintf(dir, sizeof dir, "%s%s%s", root, *rel ? "/" : "", rel);
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        char sub[4096], full[8192];
        snprintf(sub, sizeof sub, "%s%s%s", rel, *rel ? "/" : "", e->d_name);
        snprintf(full, sizeof full, "%s/%s", root, sub);
        struct stat st;
        if (stat(full, &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) walk(root, sub, fx, bin);
        else if (has_ext(sub, ".fx") && fx->count < MAX_FILES) fx->path[fx->count++] = strdup(sub);
        else if (is_binary(sub) && bin->count < MAX_FILES) bin->path[bin->count++] = strdup(sub);
    }
    if (d) closedir(d);
}

/* How many of the last path components of a and b (stems) are equal. */
static int common_tail(const char *a, const char *b) {
    const char *ea = strrchr(a, '.'), *eb = strrchr(b, '.');
    size_t i = (size_t)(ea - a), j = (size_t)(eb - b);
    int parts = 0;
    while (i > 0 && j > 0 && a[i - 1] == b[j - 1]) {
        i--, j--;
        if (a[i] == '/') parts++;
    }
    if ((i == 0 || a[i - 1] == '/') && (j == 0 || b[j - 1] == '/')) parts++;
    return parts;
}

/* The source of a binary: the .fx sharing the most trailing components (at least the stem), and
 * only one such; NULL otherwise. */
static const char *source_of(const file_list *fx, const char *bin) {
    const char *best = NULL;
    int best_n = 0, ties = 0;
    for (int i = 0; i < fx->count; i++) {
        int n = common_tail(fx->path[i], bin);
        if (n > best_n) best = fx->path[i], best_n = n, ties = 0;
        else if (n == best_n && n > 0) ties++;
    }
    return ties ? NULL : best;
}

/* The counter of this thread's user-space instructions (-1: none; the figures are then CPU time). */
static int counter = -1;

/* One load of path (bytes NULL) or bytes, on a new device: millions of instructions, or thread CPU
 * milliseconds without a counter; -1 if it failed. */
static double load_once(const char *path, const void *bytes, size_t size) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    if (!dev) return -1;
    double t0 = thread_now();
    uint64_t n0 = instructions_read(counter);
    hfx_effect *e = bytes ? hfx_effect_load_memory(dev, bytes, size, path, NULL, NULL)
                          : hfx_effect_load(dev, path, NULL, NULL);
    double t = counter >= 0 ? (double)(instructions_read(counter) - n0) * 1e-6 : (thread_now() - t0) * 1e3;
    hfx_effect_destroy(e);
    hfx_device_destroy(dev);
    return e ? t : -1;
}

/* path compiled (or converted, for a binary) to .hfxo bytes; NULL if it fails. */
static void *to_hfxo(const char *path, size_t *size) {
    hfxc_options o = {0};
    o.flags = HFXC_PACK_UNIFORMS;
    hfxc_result *r = hfxc_compile_file(path, &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    void *bytes = NULL;
    if (!fx || hfx_fx_write_hfxo(fx, &bytes, size) != 0) bytes = NULL;
    hfxc_result_free(r);
    return bytes;
}

/* The best of repeats rounds, the four kinds taking turns within a round; 0 if all loaded. */
static int measure(const char *src, const char *bin, int repeats, double best[KINDS]) {
    size_t bin_size = 0, src_size = 0;
    void *bin_hfxo = to_hfxo(bin, &bin_size), *src_hfxo = to_hfxo(src, &src_size);
    int rc = bin_hfxo && src_hfxo ? 0 : -1;
    for (int k = 0; k < KINDS; k++) best[k] = 1e30;
    for (int round = 0; rc == 0 && round < repeats; round++) {
        double t[KINDS] = {load_once(src, NULL, 0), load_once(bin, NULL, 0), load_once(bin, bin_hfxo, bin_size),
                           load_once(src, src_hfxo, src_size)};
        for (int k = 0; k < KINDS; k++) {
            if (t[k] < 0) rc = -1;
            if (t[k] < best[k]) best[k] = t[k];
        }
    }
    free(bin_hfxo);
    free(src_hfxo);
    return rc;
}

static void run(const char *root, const file_list *fx, const file_list *bin, int repeats) {
    double sum[KINDS] = {0};
    int pairs = 0, failed = 0;
    printf("%s of one load, the best of %d rounds\n", counter >= 0 ? "millions of instructions" : "thread CPU ms", repeats);
    printf("%-44s %8s %8s %8s %8s | %10s %14s\n", "binary", kind_names[0], kind_names[1],
           kind_names[2], kind_names[3], "binary/fx", "bin.hfxo/fx.h");
    for (int i = 0; i < bin->count; i++) {
        const char *s = source_of(fx, bin->path[i]);
        if (!s) continue;
        char bp[8192], sp[8192];
        snprintf(bp, sizeof bp, "%s/%s", root, bin->path[i]);
        snprintf(sp, sizeof sp, "%s/%s", root, s);
        double t[KINDS];
        if (measure(sp, bp, repeats, t) != 0) {
            printf("%-44s (a load failed)\n", bin->path[i]);
            failed++;
            continue;
        }
        printf("%-44s %8.2f %8.2f %8.2f %8.2f | %9.3fx %13.3fx\n", bin->path[i], t[0], t[1], t[2], t[3], t[1] / t[0],
               t[2] / t[3]);
        for (int k = 0; k < KINDS; k++) sum[k] += t[k];
        pairs++;
    }
    printf("\n%d pairs (%d failed to load): fx %.1f, binary %.1f, bin.hfxo %.1f, fx.hfxo %.1f\n", pairs, failed, sum[0],
           sum[1], sum[2], sum[3]);
    if (pairs)
        printf("binary / fx: %.3fx   bin.hfxo / fx.hfxo: %.3fx   bin.hfxo / binary: %.3fx\n", sum[1] / sum[0],
               sum[2] / sum[3], sum[2] / sum[1]);
}

int main(int argc, char **argv) {
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: bench_fx2_load FOLDER [REPEATS]\n");
        return 2;
    }
    int repeats = argc > 2 ? atoi(argv[2]) : 3;
    if (repeats < 1) repeats = 1;
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    counter = instructions_open();
    test_gl *gl = test_gl_create(64, 64);
    if (!gl) {
        fprintf(stderr, "no OSMesa context\n");
        return 1;
    }
    file_list fx = {{0}, 0}, bin = {{0}, 0};
    walk(argv[1], "", &fx, &bin);
    run(argv[1], &fx, &bin, repeats);
    for (int i = 0; i < fx.count; i++) free(fx.path[i]);
    for (int i = 0; i < bin.count; i++) free(bin.path[i]);
    test_gl_destroy(gl);
    if (counter >= 0) close(counter);
    return 0;
}
