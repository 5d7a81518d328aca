/* example_phong.c: a sphere lit by one directional light with the Phong model (fx/directional.fx,
 * technique Material), its parameters set by name the way an XNA game sets
 * effect.Parameters["LightDirection"].SetValue(new Vector3(...)).
 * usage: example_phong OUT.png */
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
    hv_gpu_mesh sphere = {0};
    hfx_effect *effect = ex_load_effect(&app, "fx/directional.fx");
    if (effect && ex_load_mesh(&app, "sphere", &sphere) == 0) {
        hv_vec3 eye = hv_vec3_make(0, 0, 3);
        float world[16], world_it[16], view[16], projection[16];
        hv_mat4_identity(world);
        hv_mat4_invert(world_it, world);
        hv_mat4_transpose(world_it, world_it);
        ex_camera(&app, eye, hv_vec3_make(0, 0, 0), view, projection);
        ex_set_matrix(effect, "World", world);
        ex_set_matrix(effect, "WorldInverseTranspose", world_it);
        ex_set_matrix(effect, "View", view);
        ex_set_matrix(effect, "Projection", projection);

        const float camera[3] = {eye.x, eye.y, eye.z};
        const float light_direction[3] = {-0.5f, -0.8f, -0.6f}; /* travelling down, left, away */
        const float light_color[4] = {1, 1, 1, 1};
        const float diffuse[4] = {0.9f, 0.72f, 0.45f, 1};
        const float ambient[4] = {0.08f, 0.08f, 0.1f, 1};
        ex_set_floats(effect, "CameraPosition", camera, 3);
        ex_set_floats(effect, "LightDirection", light_direction, 3);
        ex_set_floats(effect, "LightColor", light_color, 4);
        ex_set_floats(effect, "DiffuseColor", diffuse, 4);
        ex_set_floats(effect, "AmbientColor", ambient, 4);
        hfx_param_set_float(hfx_effect_param(effect, "SpecularPower"), 32.0f);

        hfx_effect_set_current_technique(effect, hfx_effect_technique(effect, "Material"));
        ex_clear(&app, 0, 0, 0);
        hfx_technique *technique = hfx_effect_current_technique(effect);
        rc = 0;
        hfx_effect_begin(effect);
        for (size_t i = 0; i < hfx_technique_pass_count(technique) && rc == 0; i++) {
            hfx_pass *pass = hfx_technique_pass(technique, i);
            if (hfx_pass_apply(pass) != HFX_OK) {
                fprintf(stderr, "Apply failed: %s\n", hfx_device_last_error(app.device));
                rc = 1;
            } else {
                ex_draw(&app, pass, &sphere);
            }
        }
        hfx_effect_end(effect);
        if (rc == 0) rc = ex_save_png(&app, argv[1]) == 0 ? 0 : 1;
    }
    hv_gpu_mesh_release(app.gl, &sphere);
    hfx_effect_destroy(effect);
    ex_app_shutdown(&app);
    return rc;
}
