/* run_twice.c: see run_twice.h. */
#include "run_twice.h"

#include <stdbool.h>

#include "files.h"

static int run(seed_scene **scene, void (*run_all)(void), bool bytecode) {
    test_require_seeds();
    *scene = seed_scene_create(128, 128);
    if (!*scene) {
        fprintf(stderr, "no OSMesa GL 3.3 context\n");
        return 1;
    }
    run_all();
    printf("== the same, loading the effects from .hfxo bytes (hfxc, then hfx_effect_load_memory)\n");
    seed_use_hfxo(*scene, 1);
    run_all();
    if (bytecode) {
        printf("== the same, each effect compiled through the D3D9 bytecode back end and read back\n");
        seed_use_hfxo(*scene, 2);
        run_all();
        printf("== the same, each effect written as fx_2_0 (hfxc /T fx_2_0 /Fo) and loaded back by its reader\n");
        seed_use_hfxo(*scene, 3);
        run_all();
    }
    seed_report(*scene);
    seed_scene_destroy(*scene);
    *scene = NULL;
    return 0;
}

int seed_run_twice(seed_scene **scene, void (*run_all)(void)) { return run(scene, run_all, false); }
int seed_run_thrice(seed_scene **scene, void (*run_all)(void)) { return run(scene, run_all, true); }
