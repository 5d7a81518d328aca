/* run_twice.h: the main of the seed tests that run every test twice, once with each effect
 * loaded from its .fx and once from the .hfxo bytes hfxc makes of it. */
#ifndef HFX_SEED_RUN_TWICE_H
#define HFX_SEED_RUN_TWICE_H

#include "scene.h"

/* Skips when the seed corpus is absent; makes the 128 x 128 scene in *scene, calls run_all
 * (which RUNs the tests) for .fx then for .hfxo, prints the probe report and destroys the
 * scene. Returns nonzero when there is no GL context; else the caller returns test_summary(). */
int seed_run_twice(seed_scene **scene, void (*run_all)(void));

/* The same, then a third time with each effect compiled through hfx's D3D9 bytecode back end
 * (HFXC_VIA_D3D9: source -> bytecode -> compiler/d3d9's reader -> GLSL), and a fourth with each
 * written as fx_2_0 and loaded back (fxc's container round trip): the same probes. */
int seed_run_thrice(seed_scene **scene, void (*run_all)(void));

#endif
