/* bench_load.c: effect load time on OSMesa (llvmpipe), and what the program cache
 * (hfx_device_set_program_cache) saves. For every seed effect and a few fx/ effects, compiled
 * to .hfxo bytes once, in this order on new devices:
 *   cold:   the first load ever, with the cache on: the driver compiles and links every
 *           program, and hfx writes their binaries;
 *   cached: the same load again: hfx hands the driver its binaries, no GLSL is compiled;
 *   mesa:   the load again without hfx's cache: Mesa's own shader cache (a per-user disk cache
 *           many drivers lack) now knows the shaders; shown for comparison.
 * A cold load can only happen once per process, so each figure is one measurement; Mesa's disk
 * cache is pointed at an empty temporary folder at start, and the .hfxo and .fx loads run in
 * processes of their own. A cached .fx load compiles without glslang's self-check (the cached
 * binaries were checked when written) and builds every program from the cache. Run by hand:
 * bench_load (both kinds), bench_load hfxo, bench_load fx. */
#define _DEFAULT_SOURCE /* mkdtemp, setenv */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "effect.h"
#include "files.h"
#include "gl_context.h"
#include "hfx/hfx.h"
#include "hfx/hfxc.h"

static const char *const files[] = {
    HFX_SEED_DIR "/ambient.fx", HFX_SEED_DIR "/ambient_textured.fx", HFX_SEED_DIR "/directional.fx",
    HFX_SEED_DIR "/directional_specular.fx", HFX_SEED_DIR "/fxcomposer_empty.fx", HFX_SEED_DIR "/multilights_repaired.fx",
    HFX_SEED_DIR "/phong.fx", HFX_SEED_DIR "/point.fx", HFX_SEED_DIR "/point_specular.fx", HFX_SEED_DIR "/pointlights.fx",
    HFX_SEED_DIR "/spot.fx", HFX_SEED_DIR "/spot_specular.fx", HFX_SEED_DIR "/tutorial0.fx",
    HFX_SOURCE_DIR "/fx/basic_lighting.fx", HFX_SOURCE_DIR "/fx/shading_models.fx", HFX_SOURCE_DIR "/fx/sas_blinn.fx",
};
enum { FILES = sizeof files / sizeof *files };

static void empty_folder(const char *dir) {
    DIR *d = opendir(dir);
    struct dirent *e;
    char path[1024];
    while (d && (e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.') continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        remove(path);
    }
    if (d) closedir(d);
}

/* Seconds for one load (and destroy) of the bytes on a new device; cache NULL = off. */
static double load_once(const void *data, size_t size, const char *name, const char *cache) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    if (!dev) return -1;
    hfx_device_set_program_cache(dev, cache);
    double t0 = now();
    hfx_effect *fx = hfx_effect_load_memory(dev, data, size, name, NULL, NULL);
    double t = now() - t0;
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    return fx ? t : -1;
}

typedef struct timing { double cold, cached, mesa; } timing;

static timing measure(const void *data, size_t size, const char *name, const char *cache) {
    timing t;
    t.cold = load_once(data, size, name, cache);
    t.cached = load_once(data, size, name, cache);
    t.mesa = load_once(data, size, name, NULL);
    return t;
}

static const char *base_name(const char *p) {
    const char *s = strrchr(p, '/');
    return s ? s + 1 : p;
}

/* One kind of load (".fx" or ".hfxo") for every effect, in a process of its own: a cold load
 * happens once per Mesa cache, and the two kinds share their GLSL. */
static int run_kind(int fx_source) {
    char cache[] = "/tmp/hfx_bench_load_XXXXXX", mesa_cache[] = "/tmp/hfx_bench_mesa_XXXXXX";
    if (!mkdtemp(cache) || !mkdtemp(mesa_cache)) return 1;
    setenv("MESA_SHADER_CACHE_DIR", mesa_cache, 1); /* Mesa's program binaries need its cache on */
    test_gl *gl = test_gl_create(64, 64);
    if (!gl) { fprintf(stderr, "no OSMesa context\n"); return 1; }
    printf("%s loads on llvmpipe, ms (one measurement each: a cold load happens once)\n", fx_source ? ".fx" : ".hfxo");
    printf("%-26s %5s | %8s %8s %7s | %8s\n", "effect", "progs", "cold", "cached", "ratio", "mesa");
    double sum_first = 0, sum_second = 0;
    for (int i = 0; i < FILES; i++) {
        size_t src_size = 0;
        char *src = test_read_file(files[i], &src_size);
        hfxc_options o = {0};
        o.flags = HFXC_PACK_UNIFORMS;
        hfxc_result *r = src ? hfxc_compile_memory(src, src_size, files[i], &o) : NULL;
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        void *bytes = NULL;
        size_t size = 0;
        if (!fx || hfx_fx_write_hfxo(fx, &bytes, &size) != 0) {
            printf("%-26s (not compiled)\n", base_name(files[i]));
        } else {
            empty_folder(cache);
            timing t = fx_source ? measure(src, src_size, files[i], cache) : measure(bytes, size, files[i], cache);
            sum_first += t.cold;
            sum_second += t.cached;
            printf("%-26s %5u | %8.2f %8.2f %6.1fx | %8.2f\n", base_name(files[i]), fx->program_count, t.cold * 1e3,
                   t.cached * 1e3, t.cold / t.cached, t.mesa * 1e3);
        }
        free(bytes);
        hfxc_result_free(r);
        free(src);
    }
    printf("all %s loads: cold %.1f ms, cached %.1f ms: %.1fx\n\n", fx_source ? ".fx" : ".hfxo", sum_first * 1e3,
           sum_second * 1e3, sum_first / sum_second);
    test_remove_dir(cache);
    test_remove_dir(mesa_cache);
    test_gl_destroy(gl);
    return 0;
}

int main(int argc, char **argv) {
    if (argc > 1) return run_kind(strcmp(argv[1], "fx") == 0);
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' hfxo && '%s' fx", argv[0], argv[0]);
    fflush(stdout);
    return system(cmd) == 0 ? 0 : 1;
}
