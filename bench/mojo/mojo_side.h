/* mojo_side.h: drawing an fx_2_0 effect the way FNA does, through MojoShader's effect framework
 * and its GLSL (built outside the repository; bench/mojo/README.md). The device state is hfx's:
 * each pass is applied by hfx first (render states, which the fx_2_0 round trip compares
 * elsewhere), then MojoShader's program, uniforms, samplers and vertex attributes replace the
 * shader side. Parameter values are copied from the hfx effect drawn from source, so both sides
 * see the same inputs. */
#ifndef HFX_BENCH_MOJO_SIDE_H
#define HFX_BENCH_MOJO_SIDE_H

#include <stddef.h>

#include "hfx/hfx.h"
#include "render.h"

typedef struct mj_side mj_side;

/* A MojoShader GL context for `profile` ("glsl120") in the current GL context, drawing into its
 * width x height default framebuffer; NULL with err. */
mj_side *mj_create(const char *profile, hv_gl_loader load, int width, int height, char *err, size_t errlen);
void mj_destroy(mj_side *m);

/* Parses and compiles an fx_2_0 file (every shader to GLSL and through the driver's compiler);
 * 0, or -1 with MojoShader's first error in err. */
int mj_load(mj_side *m, const char *path, char *err, size_t errlen);
size_t mj_technique_count(const mj_side *m);
size_t mj_pass_count(const mj_side *m, size_t technique);

/* FNA's EffectParameter.SetValue for every numeric parameter: fx's current values (by name)
 * into the effect's. 0, or -1 with err (a parameter MojoShader lays out in fewer registers). */
int mj_copy_params(mj_side *m, hfx_effect *fx, char *err, size_t errlen);

/* Draws technique `technique` (all passes) over g with the values mj_copy_params gave. hfx_states:
 * fx's technique t is applied first for each pass (hfx_effect_begin / end around), so both sides
 * draw with the render states hfx read from the source; 0: XNA's device defaults and no hfx
 * call (what a benchmark of the shaders alone wants). 0, -1 with err (a program MojoShader
 * could not link), or -2 with err when a pass has no vertex shader (FNA draws those with the
 * vertex shader bound before, SpriteBatch's: not compared). */
int mj_draw(mj_side *m, const hv_gl *gl, hfx_effect *fx, hfx_technique *t, size_t technique, const hv_gpu_mesh *g,
            int hfx_states, char *err, size_t errlen);

/* Unbinds MojoShader's program and sampler objects, and forgets which program is bound: before
 * MojoShader draws after hfx did, or hfx after MojoShader (then hfx_device_sync). */
void mj_reset(mj_side *m);

#endif
