/* The compiler library keeps no global state (hfxc compiles files on many threads): the seeds
 * compiled on eight threads at once, each starting on a different file, give byte for byte the
 * .hfxo and the diagnostics they give one at a time. test.sh also runs this under TSan. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "test.h"

static const char *const seeds[] = {"tutorial0.fx", "phong.fx", "pointlights.fx", "ambient.fx",
                                    "ambient_textured.fx", "directional.fx", "point.fx", "spot.fx",
                                    "directional_specular.fx", "point_specular.fx", "spot_specular.fx",
                                    "multilights_repaired.fx", "fxcomposer_empty.fx", "multilights.fx"};
enum { SEEDS = sizeof seeds / sizeof *seeds, THREADS = 8, ROUNDS = 2 };

typedef struct blob {
    void *data;
    size_t size;
    char *diagnostics;
} blob;

static blob compile_seed(const char *name) {
    blob b = {0};
    char *path = test_seed_path(name);
    hfxc_result *r = hfxc_compile_file(path, NULL);
    b.diagnostics = hfxc_diagnostics_text(r);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (fx && hfx_fx_write_hfxo(fx, &b.data, &b.size) != 0) b.data = NULL;
    hfxc_result_free(r);
    free(path);
    return b;
}

typedef struct worker_arg {
    int id;
    blob out[ROUNDS][SEEDS];
} worker_arg;

static void *worker(void *p) {
    worker_arg *a = p;
    for (int round = 0; round < ROUNDS; round++)
        for (int i = 0; i < SEEDS; i++) {
            int k = (i + a->id * 3) % SEEDS; /* threads start on different files */
            a->out[round][k] = compile_seed(seeds[k]);
        }
    return NULL;
}

static void same_bytes_on_many_threads(void) {
    blob ref[SEEDS];
    for (int i = 0; i < SEEDS; i++) ref[i] = compile_seed(seeds[i]);
    CHECK(ref[SEEDS - 1].data == NULL); /* multilights.fx does not compile */
    static worker_arg args[THREADS];
    pthread_t t[THREADS];
    for (int i = 0; i < THREADS; i++) {
        args[i].id = i;
        CHECK_INT(pthread_create(&t[i], NULL, worker, &args[i]), 0);
    }
    for (int i = 0; i < THREADS; i++) pthread_join(t[i], NULL);
    for (int i = 0; i < THREADS; i++)
        for (int round = 0; round < ROUNDS; round++)
            for (int k = 0; k < SEEDS; k++) {
                blob *b = &args[i].out[round][k];
                CHECK(b->size == ref[k].size);
                CHECK((b->data == NULL) == (ref[k].data == NULL));
                if (b->data && ref[k].data && b->size == ref[k].size) CHECK(memcmp(b->data, ref[k].data, b->size) == 0);
                CHECK_STR(b->diagnostics, ref[k].diagnostics);
                free(b->data);
                free(b->diagnostics);
            }
    for (int i = 0; i < SEEDS; i++) {
        free(ref[i].data);
        free(ref[i].diagnostics);
    }
}

int main(void) {
    test_require_seeds();
    RUN(same_bytes_on_many_threads);
    return test_summary();
}
