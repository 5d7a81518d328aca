/* rto_scenes.h: a few seed scenes drawn through nothing but the public runtime API (hfx.h) and
 * GL, so that the same code runs in a program linked with hfx (which compiles .fx) and in one
 * linked with hfx_runtime (which loads .hfxo only). Each scene fixes its camera, meshes,
 * textures and parameter values, so two renders of the same scene with the same GLSL on the
 * same GL give the same bytes.
 *
 * Contexts are OSMesa (llvmpipe) ones made here rather than by the harness, because the GLSL 110
 * target wants a compatibility profile. */
#ifndef HFX_RTO_SCENES_H
#define HFX_RTO_SCENES_H

#include <stddef.h>

#include "hfx/hfx.h"

#define RTO_SIZE 96 /* every scene renders RTO_SIZE x RTO_SIZE pixels */

typedef enum { RTO_CORE_33, RTO_COMPAT } rto_profile;

typedef struct rto_ctx rto_ctx;

/* A context of the profile, made current, with an hfx device on it; NULL if OSMesa refuses. */
rto_ctx *rto_ctx_create(rto_profile profile);
void rto_ctx_destroy(rto_ctx *c);
hfx_device *rto_device(rto_ctx *c);
const char *rto_gl_version(rto_ctx *c);        /* GL_VERSION */
int rto_has_extension(rto_ctx *c, const char *name);
/* The framebuffer as RGBA8, top row first, RTO_SIZE * RTO_SIZE * 4 bytes (after glFinish). */
void rto_read(rto_ctx *c, unsigned char *out);
int rto_write_png(rto_ctx *c, const char *path); /* 0 on success; for looking at failures */

/* The scenes. */
int rto_scene_count(void);
const char *rto_scene_name(int i);  /* "tutorial0", "phong"... (file names of reference dumps) */
const char *rto_scene_file(int i);  /* the seed file: "tutorial0.fx"... */
/* Clears, sets every parameter the scene uses, draws every pass of its technique(s). Returns the
 * number of passes drawn; 0 with a message in why on any failure (unknown parameter, failed
 * Apply, GL error). */
int rto_scene_render(rto_ctx *c, hfx_effect *fx, int i, char *why, size_t why_size);
int rto_scene_passes(int i);        /* how many passes rto_scene_render should draw */

#endif
