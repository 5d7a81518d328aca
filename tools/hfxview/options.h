/* options.h: hfxview's command line. */
#ifndef HFXVIEW_OPTIONS_H
#define HFXVIEW_OPTIONS_H

#include <stddef.h>

#include "vmath.h"

enum { HV_PASS_ALL = -1, HV_PASS_EACH = -2 }; /* hv_options.pass besides a pass number */

typedef struct hv_kv { const char *name, *value; } hv_kv; /* NAME=VALUE, pointing into argv */

typedef struct hv_options {
    const char *input;       /* the .fx or .hfxo */
    const char *output;      /* the PNG; NULL: the input's base name + .png */
    const char *technique;   /* name or index; NULL: the first */
    int pass;                /* HV_PASS_ALL: every pass in order, HV_PASS_EACH: each alone
                                (with --technique all), else only pass N */
    const char *mesh;        /* built-in name or .obj path */
    int mesh_given;          /* --mesh: else an effect in pixels (SpriteEffect) gets "screen" */
    int width, height;
    hv_kv textures[32]; size_t texture_count;
    hv_kv sets[64]; size_t set_count;
    const char *defines[32]; size_t define_count;
    const char *include_dirs[16]; size_t include_dir_count;
    hv_vec3 eye, at, up;
    float fov_degrees;
    hv_vec3 light_position, light_direction;
    float light_color[3];
    int light_direction_given;
    int light_given;         /* any --light */
    float yaw_degrees;       /* turns the mesh about y */
    int blend_add;           /* --blend-passes add */
    float background[4];
    int window;              /* --window: show in a GLFW window */
    int watch;               /* --watch: reload the effect when its files change */
    int no_preshaders;       /* --no-preshaders: hfx_load_options.no_preshaders */
    int egl;                 /* --egl: headless on EGL (into a framebuffer object) instead of OSMesa */
    int vulkan;              /* --vulkan: headless on a Vulkan device (lavapipe) */
    int list;                /* --list: print techniques and parameters */
    int help;
} hv_options;

void hv_options_defaults(hv_options *o);
/* 0 on success; -1 with a message in err on a usage error (exit code 2). */
int hv_options_parse(hv_options *o, int argc, char **argv, char *err, size_t errlen);
/* Up to max comma-separated floats from s; the count, or -1 if s holds anything else. */
int hv_parse_floats(const char *s, float *out, int max);
const char *hv_usage(void);

#endif
