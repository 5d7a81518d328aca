/* example_multilights.c: the book's two-pass multi-light effect (multilights_repaired.fx from
 * the seed corpus): pass "Ambiental" draws the ambient term, then the application switches to
 * additive blending and pass "MultiLuces" adds the lights, which live in arrays of structs:
 *
 *     effect.Parameters["direccionales"].Elements[0].StructureMembers["Color"].SetValue(...)
 *
 * The listing loops to numLuces = 4 over arrays of 2; the program sets numLuces to 2.
 * usage: example_multilights OUT.png [EFFECT.fx] */
#include <stdio.h>

#include "example.h"

static hfx_param *light_member(hfx_effect *fx, const char *array, size_t i, const char *member) {
    return hfx_param_member(hfx_param_element(hfx_effect_param(fx, array), i), member);
}

static void set_lights(hfx_effect *fx) {
    const float white[4] = {1, 1, 1, 1}, down[3] = {0, 0, -1}; /* travelling away from the camera */
    hfx_param_set_floats(light_member(fx, "direccionales", 0, "Direccion"), down, 3);
    hfx_param_set_floats(light_member(fx, "direccionales", 0, "Color"), white, 4);
    hfx_param_set_int(light_member(fx, "direccionales", 0, "Encender"), 1);

    const float warm[4] = {1.0f, 0.55f, 0.2f, 1}, left[3] = {-2.0f, 1.0f, 1.0f};
    hfx_param_set_floats(light_member(fx, "puntuales", 0, "Posicion"), left, 3);
    hfx_param_set_floats(light_member(fx, "puntuales", 0, "Color"), warm, 4);
    hfx_param_set_float(light_member(fx, "puntuales", 0, "Rango"), 10.0f);
    hfx_param_set_float(light_member(fx, "puntuales", 0, "C1"), 1.0f);
    hfx_param_set_float(light_member(fx, "puntuales", 0, "C2"), 0.1f);
    hfx_param_set_int(light_member(fx, "puntuales", 0, "Atenuar"), 1);
    hfx_param_set_int(light_member(fx, "puntuales", 0, "Encender"), 1);

    hfx_param_set_int(hfx_effect_param(fx, "numLuces"), 2);
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s OUT.png [EFFECT.fx]\n", argv[0]);
        return 2;
    }
    const char *path = argc > 2 ? argv[2] : HFX_SEED_DIR "/multilights_repaired.fx";
    ex_app app;
    if (ex_app_init(&app, 256, 256, 0) != 0) return 1;
    int rc = 1;
    hv_gpu_mesh sphere = {0};
    hfx_effect *effect = ex_load_effect(&app, path);
    if (effect && ex_load_mesh(&app, "sphere", &sphere) == 0) {
        hv_vec3 eye = hv_vec3_make(0, 0, 3);
        float world[16], view[16], projection[16], camera[3] = {eye.x, eye.y, eye.z};
        hv_mat4_identity(world);
        ex_camera(&app, eye, hv_vec3_make(0, 0, 0), view, projection);
        ex_set_matrix(effect, "world", world);
        ex_set_matrix(effect, "view", view);
        ex_set_matrix(effect, "projection", projection);
        ex_set_floats(effect, "posicionCamara", camera, 3);
        set_lights(effect);

        hfx_effect_set_current_technique(effect, hfx_effect_technique(effect, "Material"));
        hfx_technique *technique = hfx_effect_current_technique(effect);
        ex_clear(&app, 0, 0, 0);
        rc = 0;
        for (size_t i = 0; i < hfx_technique_pass_count(technique) && rc == 0; i++) {
            hfx_pass *pass = hfx_technique_pass(technique, i);
            ex_additive_blending(&app, i > 0); /* the lights add up on the ambient pass */
            hfx_effect_begin(effect);              /* so the runtime sees the blending just set */
            if (hfx_pass_apply(pass) != HFX_OK) {
                fprintf(stderr, "pass %s: %s\n", hfx_pass_name(pass), hfx_device_last_error(app.device));
                rc = 1;
            } else {
                ex_draw(&app, pass, &sphere);
            }
            hfx_effect_end(effect);
        }
        ex_additive_blending(&app, 0);
        if (rc == 0) rc = ex_save_png(&app, argv[1]) == 0 ? 0 : 1;
    }
    hv_gpu_mesh_release(app.gl, &sphere);
    hfx_effect_destroy(effect);
    ex_app_shutdown(&app);
    return rc;
}
