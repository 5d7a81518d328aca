/* example_techniques.c: one effect, two techniques that differ only in a `uniform bool` the
 * pixel shader is compiled with (fx/ambient.fx: Textured compiles AmbientPS(true), Material
 * AmbientPS(false)). The left half of the image draws with Techniques["Textured"], the right
 * half with Techniques["Material"]: switching CurrentTechnique switches compiled shaders.
 * usage: example_techniques OUT.png */
#include <stdio.h>

#include "example.h"

static int draw_half(ex_app *app, hfx_effect *fx, const char *technique, int right, const hv_gpu_mesh *m) {
    float view[16], projection[16];
    ex_app half = *app;
    half.width = app->width / 2; /* the camera's aspect ratio is the half's */
    ex_camera(&half, hv_vec3_make(0, 0.8f, 2.8f), hv_vec3_make(0, 0, 0), view, projection);
    ex_set_matrix(fx, "View", view);
    ex_set_matrix(fx, "Projection", projection);
    hfx_device_set_viewport(app->device, right ? app->width / 2 : 0, 0, app->width / 2, app->height);
    hfx_technique *t = hfx_effect_technique(fx, technique);
    if (!t) {
        fprintf(stderr, "no technique %s\n", technique);
        return -1;
    }
    hfx_effect_set_current_technique(fx, t);
    return ex_draw_current_technique(app, fx, m);
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 2;
    }
    ex_app app;
    if (ex_app_init(&app, 512, 256, 0) != 0) return 1;
    int rc = 1;
    hv_gpu_mesh teapot = {0};
    unsigned int texture = 0;
    hfx_effect *effect = ex_load_effect(&app, "fx/ambient.fx");
    if (effect && ex_load_mesh(&app, "teapot", &teapot) == 0 && (texture = ex_load_texture(&app, NULL))) {
        float world[16];
        hv_mat4_identity(world);
        ex_set_matrix(effect, "World", world);
        hfx_param_set_texture(hfx_effect_param(effect, "DiffuseTexture"), texture);
        ex_clear(&app, 100 / 255.0f, 149 / 255.0f, 237 / 255.0f);
        if (draw_half(&app, effect, "Textured", 0, &teapot) == 0 && draw_half(&app, effect, "Material", 1, &teapot) == 0)
            rc = ex_save_png(&app, argv[1]) == 0 ? 0 : 1;
    }
    if (texture) app.gl->DeleteTextures(1, &texture);
    hv_gpu_mesh_release(app.gl, &teapot);
    hfx_effect_destroy(effect);
    ex_app_shutdown(&app);
    return rc;
}
