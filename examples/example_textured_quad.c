/* example_textured_quad.c: tutorial 0 of the XNA shader tutorial, in C. The XNA code
 *
 *     Tutorial0Effect = Content.Load<Effect>("Effects//Tutorial0Effect");
 *     Tutorial0Effect.CurrentTechnique = Tutorial0Effect.Techniques["Tut0"];
 *     Tutorial0Effect.Parameters["View"].SetValue(camera.View);
 *     Tutorial0Effect.Parameters["Projection"].SetValue(camera.Projection);
 *     Tutorial0Effect.Parameters["diffuseTexture"].SetValue(diffuse);
 *     Tutorial0Effect.Parameters["World"].SetValue(transformation);
 *     Tutorial0Effect.CurrentTechnique.Passes[0].Apply();
 *     GraphicsDevice.DrawIndexedPrimitives(PrimitiveType.TriangleList, ...);
 *
 * becomes the calls below, one for one.
 * usage: example_textured_quad OUT.png [IMAGE]   (no IMAGE: a checkerboard) */
#include <stdio.h>

#include "example.h"

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s OUT.png [IMAGE]\n", argv[0]);
        return 2;
    }
    ex_app app;
    if (ex_app_init(&app, 256, 256, 0) != 0) return 1;
    int rc = 1;
    hv_gpu_mesh quad = {0};
    unsigned int texture = 0;
    hfx_effect *effect = ex_load_effect(&app, "fx/textured.fx");
    if (effect && ex_load_mesh(&app, "quad", &quad) == 0 && (texture = ex_load_texture(&app, argc > 2 ? argv[2] : NULL))) {
        hfx_effect_set_current_technique(effect, hfx_effect_technique(effect, "Textured"));

        float world[16], view[16], projection[16];
        hv_mat4_identity(world);
        ex_camera(&app, hv_vec3_make(0, 0, 3.2f), hv_vec3_make(0, 0, 0), view, projection);
        ex_set_matrix(effect, "View", view);
        ex_set_matrix(effect, "Projection", projection);
        hfx_param_set_texture(hfx_effect_param(effect, "DiffuseTexture"), texture);
        ex_set_matrix(effect, "World", world);

        ex_clear(&app, 100 / 255.0f, 149 / 255.0f, 237 / 255.0f); /* Color.CornflowerBlue */
        hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(effect), 0);
        hfx_effect_begin(effect);
        if (hfx_pass_apply(pass) == HFX_OK) {
            ex_draw(&app, pass, &quad);
            rc = 0;
        } else {
            fprintf(stderr, "Apply failed: %s\n", hfx_device_last_error(app.device));
        }
        hfx_effect_end(effect);
        if (rc == 0) rc = ex_save_png(&app, argv[1]) == 0 ? 0 : 1;
    }
    if (texture) app.gl->DeleteTextures(1, &texture);
    hv_gpu_mesh_release(app.gl, &quad);
    hfx_effect_destroy(effect);
    ex_app_shutdown(&app);
    return rc;
}
