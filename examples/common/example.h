/* example.h: the little "Game class" the examples share, so each example shows only what an
 * XNA Draw method would: setting parameters, choosing a technique, applying passes, drawing.
 * It wraps hfxview's kit: a GL context (headless OSMesa, or a GLFW window), meshes, PNG. */
#ifndef HFX_EXAMPLE_H
#define HFX_EXAMPLE_H

#include "context.h"
#include "hfx/hfx.h"
#include "image.h"
#include "mesh.h"
#include "render.h"
#include "vmath.h"

typedef struct ex_app {
    hv_context *ctx;
    const hv_gl *gl;     /* GL entry points, for the few calls an application makes itself */
    hfx_device *device;  /* GraphicsDevice */
    int width, height;
} ex_app;

/* Opens a width x height context (a window when asked and possible) and the hfx device.
 * 0, or -1 after printing why. */
int ex_app_init(ex_app *app, int width, int height, int window);
void ex_app_shutdown(ex_app *app);

/* Content.Load<Effect>: path relative to the source tree ("fx/phong.fx") or absolute.
 * Prints the compiler's diagnostics and returns NULL when the effect does not load. */
hfx_effect *ex_load_effect(ex_app *app, const char *path);

/* A built-in mesh ("sphere", "plane", "quad", "cube", "torus", "teapot") in GPU buffers. */
int ex_load_mesh(ex_app *app, const char *name, hv_gpu_mesh *out);

/* A mipmapped texture: an image file, or a checkerboard when path is NULL. 0 on failure. */
unsigned int ex_load_texture(ex_app *app, const char *path);

void ex_clear(ex_app *app, float r, float g, float b);            /* GraphicsDevice.Clear */
void ex_draw(ex_app *app, hfx_pass *pass, const hv_gpu_mesh *m);  /* DrawIndexedPrimitives */
int ex_save_png(ex_app *app, const char *path);                   /* 0, or -1 after printing why */

/* foreach (EffectPass pass in effect.CurrentTechnique.Passes) { pass.Apply(); Draw...; },
 * between hfx_effect_begin and hfx_effect_end, which let the runtime see the state the
 * application set and restore it afterwards. 0, or -1 after printing why a pass failed. */
int ex_draw_current_technique(ex_app *app, hfx_effect *fx, const hv_gpu_mesh *m);

/* GraphicsDevice.BlendState = BlendState.Additive (on) or BlendState.Opaque (off); additive
 * drawing also stops writing depth, as the second pass of a multi-light effect needs. */
void ex_additive_blending(ex_app *app, int on);

/* XNA's Matrix.CreateLookAt / CreatePerspectiveFieldOfView with a 45 degree lens. */
void ex_camera(const ex_app *app, hv_vec3 eye, hv_vec3 at, float view[16], float projection[16]);

/* Sets a parameter by name, failing loudly: examples must not silently miss a name. */
int ex_set_matrix(hfx_effect *fx, const char *name, const float m[16]);
int ex_set_floats(hfx_effect *fx, const char *name, const float *v, size_t n);

#endif
