/* scene_gpu.h: the seed scene's private state and the part of it that draws. scene.c (cameras,
 * meshes as data, effects, probes) is the same for every API; scene_gl.c draws with OpenGL
 * (OSMesa) and tests/seeds/vk/scene_vk.c with Vulkan (lavapipe), so the seed tests and their
 * hand-computed colours run unchanged on both. */
#ifndef HFX_SEED_SCENE_GPU_H
#define HFX_SEED_SCENE_GPU_H

#include "scene.h"

#define SEED_MAX_FILES 32

typedef struct seed_file_report {
    char file[64];
    int probes;
    double max_diff;
} seed_file_report;

struct seed_scene {
    void *gpu;         /* the back end's state */
    hfx_device *dev;
    int width, height;
    float view[16], proj[16];
    double inv_vp[16]; /* inverse(view * proj), for unprojecting pixels */
    int inv_ok;
    int d3d9_centres;
    int via_hfxo;
    hfx_target target; /* what seed_load compiles for and loads */
    int errors;
    seed_file_report files[SEED_MAX_FILES];
    int file_count;
};

/* A harness problem: printed, and counted for CHECK_SCENE. */
void seed_note(seed_scene *s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void seed_check_set(seed_scene *s, int rc, const char *what);

/* The back end: a context and s->dev (0 when there is none), and what draws and reads. */
int seed_gpu_open(seed_scene *s, int major, int minor);
void seed_gpu_close(seed_scene *s);
void seed_gpu_mesh_upload(seed_scene *s, seed_mesh *m);
void seed_gpu_mesh_free(seed_scene *s, seed_mesh *m);
int seed_gpu_set_texture(seed_scene *s, hfx_param *p, const seed_texture *t);
void seed_gpu_read(seed_scene *s, int x, int y, unsigned char rgba[4]);
int seed_gpu_write_png(seed_scene *s, const char *path);

#endif
