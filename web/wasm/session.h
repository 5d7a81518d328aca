/* session.h: the page's one session (one canvas, one WebGL 2 context, one effect at a time).
 * This is the only mutable global of the WebAssembly module, and it lives here in the glue,
 * never in hfx's libraries, which stay reentrant as in the native build. */
#ifndef HFX_WEB_SESSION_H
#define HFX_WEB_SESSION_H

#include <emscripten/html5.h>
#include <stddef.h>

#include "common/effect.h"
#include "hfx/hfx.h"
#include "render.h"

typedef struct hfxw_session {
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context;
    hfx_device *dev;
    hfx_effect *fx;          /* the last effect that compiled and loaded; kept while edits fail */
    hfx_fx_effect *code;     /* its compiled data: the GLSL tab reads the programs' text */
    void *hfxo;              /* its .hfxo bytes, for the download button */
    size_t hfxo_size;
    int technique, pass;     /* pass -1: every pass of the technique, in order */
    int blend_add;           /* the application adds passes 2.. to the first (hfxview --blend-passes add) */
    hv_gl gl;                /* hfxview's GL table over WebGL 2, for its drawing code (render.c) */
    hv_gpu_mesh mesh;
    int mesh_auto;           /* the mesh follows the effect as hfxview's: its screen rectangle or the sphere */
    int mesh_screen_w, mesh_screen_h; /* the screen rectangle's size when that is the mesh, else 0 */
    unsigned checker, cube, volume; /* the default 2D, cube and volume textures (hfxview's) */
    unsigned textures[64];   /* textures the page made for parameters, to free with the effect */
    size_t texture_count;
    float yaw, pitch, distance; /* orbit camera around the origin, degrees and units */
    float clear[4];
    int width, height;       /* the canvas at the last frame */
    const char **bound;      /* how bind.c bound each top-level parameter (NULL: not bound), for the panel */
    size_t bound_count;
    double start_ms;         /* when the effect loaded: time parameters count from it */
    double clock_s;          /* < 0: the page's clock runs; else the time parameters' fixed value (hfxw_set_clock) */
    char *answer;            /* the last JSON handed to JavaScript (freed on the next answer) */
    char message[256];       /* the last setter's error, "" when it worked */
} hfxw_session;

hfxw_session *hfxw_get(void);
const char *hfxw_answer(char *json); /* keeps json as the session's answer and returns it */

/* draw.c */
int hfxw_draw_init(hfxw_session *s);
void hfxw_draw_frame(hfxw_session *s, int width, int height);
int hfxw_mesh_set(hfxw_session *s, const char *spec, char *err, size_t errlen);
/* With mesh_auto, hfxview's choice for the loaded effect at width x height (hv_effect_wants_pixels:
 * the image's rectangle in pixels for post-processing and sprite effects, else the sphere). */
int hfxw_mesh_fit(hfxw_session *s, int width, int height);
unsigned hfxw_texture_rgba(hfxw_session *s, const unsigned char *rgba, int width, int height);
void hfxw_bind_default_textures(hfxw_session *s);
/* World (identity), View, Projection, the camera, and hfxview's default light into every
 * parameter they fit by name, semantic or annotation (bind.h); lights and materials only where
 * the effect left zero. Once, when an effect loads (each frame binds only the camera's and the
 * clock's); keeps how each parameter was bound in s->bound for the panel. */
void hfxw_bind_scene(hfxw_session *s, int width, int height);

#endif
