/* run_twice.c: see run_twice.h. */
#include "run_twice.h"

#include "files.h"

int seed_run_twice(seed_scene **scene, void (*run_all)(void)) {
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
    seed_report(*scene);
    seed_scene_destroy(*scene);
    *scene = NULL;
    return 0;
}
