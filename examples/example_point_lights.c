/* example_point_lights.c: 1 to 50 point lights in one pass (fx/point_lights.fx), their
 * positions, colours and radii handed over as arrays and refilled every frame, as the XNA
 * point-light tutorial does in Update():
 *
 *     point.Parameters["activeLights"].SetValue(activePointLights);
 *     point.Parameters["LightPosition"].SetValue(LightPosition.ToArray());
 *
 * The lights circle the sphere; the last frame is written out.
 * usage: example_point_lights OUT.png [LIGHTS (1..50, default 8)] [FRAMES (default 12)] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "example.h"

#define MAX_LIGHTS 50

/* Light i of n at time t: spread around the sphere, at varied heights, turning. */
static void place_lights(int n, float t, float pos[][3], float color[][4], float radius[]) {
    for (int i = 0; i < n; i++) {
        float a = 6.2831853f * (float)i / (float)n + t;
        float h = (float)(i % 5) * 0.45f - 0.9f;
        pos[i][0] = 1.6f * cosf(a);
        pos[i][1] = h;
        pos[i][2] = 1.6f * sinf(a);
        /* Hues around the colour wheel, dimmer as there are more lights. */
        float k = 3.0f / (float)(n > 3 ? n : 3), hue = 6.0f * (float)i / (float)n;
        color[i][0] = k * fmaxf(0.0f, fminf(1.0f, fabsf(hue - 3.0f) - 1.0f));
        color[i][1] = k * fmaxf(0.0f, fminf(1.0f, 2.0f - fabsf(hue - 2.0f)));
        color[i][2] = k * fmaxf(0.0f, fminf(1.0f, 2.0f - fabsf(hue - 4.0f)));
        color[i][3] = 1.0f;
        radius[i] = 2.5f;
    }
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s OUT.png [LIGHTS] [FRAMES]\n", argv[0]);
        return 2;
    }
    int lights = argc > 2 ? atoi(argv[2]) : 8, frames = argc > 3 ? atoi(argv[3]) : 12;
    if (lights < 1 || lights > MAX_LIGHTS || frames < 1) {
        fprintf(stderr, "LIGHTS must be 1..%d and FRAMES at least 1\n", MAX_LIGHTS);
        return 2;
    }
    ex_app app;
    if (ex_app_init(&app, 256, 256, 0) != 0) return 1;
    int rc = 1;
    hv_gpu_mesh sphere = {0};
    unsigned int texture = 0;
    hfx_effect *effect = ex_load_effect(&app, "fx/point_lights.fx");
    if (effect && ex_load_mesh(&app, "sphere", &sphere) == 0 && (texture = ex_load_texture(&app, NULL))) {
        hv_vec3 eye = hv_vec3_make(0, 0.5f, 3.2f);
        float world[16], view[16], projection[16], camera[3] = {eye.x, eye.y, eye.z};
        hv_mat4_identity(world);
        ex_camera(&app, eye, hv_vec3_make(0, 0, 0), view, projection);
        ex_set_matrix(effect, "World", world);
        ex_set_matrix(effect, "View", view);
        ex_set_matrix(effect, "Projection", projection);
        ex_set_floats(effect, "CameraPosition", camera, 3);
        hfx_param_set_texture(hfx_effect_param(effect, "DiffuseTexture"), texture);
        rc = 0;
        for (int frame = 0; frame < frames && rc == 0; frame++) { /* Update() + Draw() */
            float pos[MAX_LIGHTS][3] = {{0}}, color[MAX_LIGHTS][4] = {{0}}, radius[MAX_LIGHTS] = {0};
            place_lights(lights, 0.15f * (float)frame, pos, color, radius);
            hfx_param_set_int(hfx_effect_param(effect, "LightCount"), lights);
            ex_set_floats(effect, "LightPosition", &pos[0][0], MAX_LIGHTS * 3); /* the whole arrays */
            ex_set_floats(effect, "LightColor", &color[0][0], MAX_LIGHTS * 4);
            ex_set_floats(effect, "LightRadius", radius, MAX_LIGHTS);
            ex_clear(&app, 0.02f, 0.02f, 0.03f);
            rc = ex_draw_current_technique(&app, effect, &sphere) == 0 ? 0 : 1;
        }
        if (rc == 0) rc = ex_save_png(&app, argv[1]) == 0 ? 0 : 1;
    }
    if (texture) app.gl->DeleteTextures(1, &texture);
    hv_gpu_mesh_release(app.gl, &sphere);
    hfx_effect_destroy(effect);
    ex_app_shutdown(&app);
    return rc;
}
