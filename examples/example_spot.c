/* example_spot.c: a spot light shining down on a floor (fx/spot.fx, technique Textured): the
 * cone's inner and outer half-angles and the falloff exponent are plain float parameters.
 * usage: example_spot OUT.png */
#include <stdio.h>

#include "example.h"

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 2;
    }
    ex_app app;
    if (ex_app_init(&app, 256, 256, 0) != 0) return 1;
    int rc = 1;
    hv_gpu_mesh floor_mesh = {0};
    unsigned int texture = 0;
    hfx_effect *effect = ex_load_effect(&app, "fx/spot.fx");
    if (effect && ex_load_mesh(&app, "plane", &floor_mesh) == 0 && (texture = ex_load_texture(&app, NULL))) {
        hv_vec3 eye = hv_vec3_make(0, 2.6f, 2.0f);
        float world[16], view[16], projection[16];
        hv_mat4_scale(world, 1.5f, 1.5f, 1.5f); /* a 3 x 3 floor */
        float world_it[16];
        hv_mat4_invert(world_it, world);
        hv_mat4_transpose(world_it, world_it);
        ex_camera(&app, eye, hv_vec3_make(0, 0, 0), view, projection);
        ex_set_matrix(effect, "World", world);
        ex_set_matrix(effect, "WorldInverseTranspose", world_it);
        ex_set_matrix(effect, "View", view);
        ex_set_matrix(effect, "Projection", projection);

        const float camera[3] = {eye.x, eye.y, eye.z};
        const float light[3] = {0, 4, 0}, target[3] = {0, 0, 0};
        ex_set_floats(effect, "CameraPosition", camera, 3);
        ex_set_floats(effect, "LightPosition", light, 3);
        ex_set_floats(effect, "LightTarget", target, 3);
        hfx_param_set_float(hfx_effect_param(effect, "InnerAngle"), 0.15f);
        hfx_param_set_float(hfx_effect_param(effect, "OuterAngle"), 0.25f);
        hfx_param_set_float(hfx_effect_param(effect, "Falloff"), 2.0f);
        hfx_param_set_texture(hfx_effect_param(effect, "DiffuseTexture"), texture);

        hfx_effect_set_current_technique(effect, hfx_effect_technique(effect, "Textured"));
        ex_clear(&app, 0, 0, 0);
        if (ex_draw_current_technique(&app, effect, &floor_mesh) == 0) rc = ex_save_png(&app, argv[1]) == 0 ? 0 : 1;
    }
    if (texture) app.gl->DeleteTextures(1, &texture);
    hv_gpu_mesh_release(app.gl, &floor_mesh);
    hfx_effect_destroy(effect);
    ex_app_shutdown(&app);
    return rc;
}
