/* example_window.c: the interactive one. A GLFW window shows a sphere with
 * fx/shading_models.fx; keys 1-4 (or T) switch between the Gouraud, GouraudBlinn, Phong and
 * BlinnPhong techniques, Escape quits. Without a display it draws headless on OSMesa.
 * usage: example_window [OUT.png] [--frames N] [--technique NAME] [--headless]
 *   --frames N   stop after N frames (then OUT.png holds the last one); default: until closed
 *                in a window, 1 frame headless. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "example.h"

static const char *const techniques[] = {"Gouraud", "GouraudBlinn", "Phong", "BlinnPhong"};

static void set_scene(ex_app *app, hfx_effect *fx) {
    float world[16], view[16], projection[16], wv[16], wvit[16];
    hv_mat4_identity(world);
    ex_camera(app, hv_vec3_make(0, 0, 3), hv_vec3_make(0, 0, 0), view, projection);
    hv_mat4_mul(wv, world, view);
    hv_mat4_invert(wvit, wv);
    hv_mat4_transpose(wvit, wvit); /* the normal matrix */
    ex_set_matrix(fx, "World", world);
    ex_set_matrix(fx, "View", view);
    ex_set_matrix(fx, "Projection", projection);
    ex_set_matrix(fx, "WorldViewIT", wvit);
}

/* The technique the keys ask for, or -1. */
static int technique_key(hv_context *ctx, int current) {
    for (int k = 0; k < 4; k++)
        if (hv_context_key_pressed(ctx, '1' + k)) return k;
    if (hv_context_key_pressed(ctx, 'T')) return (current + 1) % 4;
    return -1;
}

int main(int argc, char **argv) {
    const char *out = NULL;
    int frames = -1, headless = 0, current = 2;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--frames") && i + 1 < argc) frames = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--headless")) headless = 1;
        else if (!strcmp(argv[i], "--technique") && i + 1 < argc) {
            const char *name = argv[++i];
            for (current = 0; current < 4 && strcmp(techniques[current], name); current++) {}
            if (current == 4) {
                fprintf(stderr, "no technique %s\n", name);
                return 2;
            }
        } else if (argv[i][0] != '-' && !out) out = argv[i];
        else {
            fprintf(stderr, "usage: %s [OUT.png] [--frames N] [--technique NAME] [--headless]\n", argv[0]);
            return 2;
        }
    }
    ex_app app;
    if (ex_app_init(&app, 400, 400, !headless) != 0) return 1;
    int windowed = hv_context_is_window(app.ctx);
    if (frames < 0) frames = windowed ? 0 : 1; /* 0: until the window closes */
    printf("%s, technique %s; keys 1-4 or T switch techniques\n", windowed ? "window" : "headless",
           techniques[current]);
    int rc = 1;
    hv_gpu_mesh sphere = {0};
    hfx_effect *effect = ex_load_effect(&app, "fx/shading_models.fx");
    if (effect && ex_load_mesh(&app, "sphere", &sphere) == 0) {
        set_scene(&app, effect);
        rc = 0;
        for (int frame = 0; rc == 0 && (frames == 0 || frame < frames); frame++) {
            int k = technique_key(app.ctx, current);
            if (k >= 0 && k != current) {
                current = k;
                printf("technique %s\n", techniques[current]);
            }
            hfx_effect_set_current_technique(effect, hfx_effect_technique(effect, techniques[current]));
            ex_clear(&app, 0.1f, 0.1f, 0.12f);
            rc = ex_draw_current_technique(&app, effect, &sphere) == 0 ? 0 : 1;
            int last = frames > 0 && frame == frames - 1;
            if (rc == 0 && last && out) rc = ex_save_png(&app, out) == 0 ? 0 : 1; /* before the swap */
            if (windowed) {
                hv_context_present(app.ctx);
                if (frames == 0 && hv_context_should_close(app.ctx)) break;
            }
        }
    }
    hv_gpu_mesh_release(app.gl, &sphere);
    hfx_effect_destroy(effect);
    ex_app_shutdown(&app);
    return rc;
}
