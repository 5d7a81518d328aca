/* example.c: the shared application frame (see example.h). */
#include "example.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int ex_app_init(ex_app *app, int width, int height, int window) {
    char err[256] = "";
    memset(app, 0, sizeof *app);
    app->width = width;
    app->height = height;
    app->ctx = hv_context_create(width, height, window, err, sizeof err);
    if (err[0]) fprintf(stderr, "%s\n", err);
    if (!app->ctx) return -1;
    app->gl = hv_context_gl(app->ctx);
    app->device = hfx_device_create_gl(hv_context_loader(app->ctx));
    if (!app->device) {
        fprintf(stderr, "hfx cannot start on this OpenGL context\n");
        return -1;
    }
    return 0;
}

void ex_app_shutdown(ex_app *app) {
    hfx_device_destroy(app->device);
    hv_context_destroy(app->ctx);
    memset(app, 0, sizeof *app);
}

hfx_effect *ex_load_effect(ex_app *app, const char *path) {
    char full[4096];
    if (path[0] == '/') snprintf(full, sizeof full, "%s", path);
    else snprintf(full, sizeof full, "%s/%s", HFX_SOURCE_DIR, path);
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load(app->device, full, NULL, &errors);
    if (!fx) {
        fprintf(stderr, "%s", errors && *errors ? errors : hfx_device_last_error(app->device));
        fprintf(stderr, "\ncannot load %s\n", full);
    }
    hfx_free(errors);
    return fx;
}

int ex_load_mesh(ex_app *app, const char *name, hv_gpu_mesh *out) {
    hv_mesh m;
    if (hv_mesh_builtin(&m, name) != 0) {
        fprintf(stderr, "no mesh '%s'\n", name);
        return -1;
    }
    int rc = hv_gpu_mesh_upload(app->gl, out, &m);
    hv_mesh_free(&m);
    return rc;
}

unsigned int ex_load_texture(ex_app *app, const char *path) {
    hv_image img;
    char err[512];
    static const unsigned char light[4] = {235, 235, 235, 255}, dark[4] = {200, 90, 40, 255};
    if (path ? hv_image_load(&img, path, err, sizeof err) : hv_image_checker(&img, 256, 8, light, dark)) {
        fprintf(stderr, "%s\n", path ? err : "out of memory");
        return 0;
    }
    unsigned int tex = hv_texture_2d(app->gl, &img);
    hv_image_free(&img);
    return tex;
}

void ex_clear(ex_app *app, float r, float g, float b) {
    const float rgba[4] = {r, g, b, 1.0f};
    hv_clear(app->gl, app->width, app->height, rgba);
    hv_set_default_states(app->gl); /* what XNA's device starts every frame with */
}

void ex_draw(ex_app *app, hfx_pass *pass, const hv_gpu_mesh *m) { hv_draw_mesh(app->gl, m, pass); }

int ex_save_png(ex_app *app, const char *path) {
    hv_image img;
    if (hv_read_image(app->gl, app->width, app->height, &img) != 0) return -1;
    int rc = hv_image_write_png(&img, path);
    hv_image_free(&img);
    if (rc != 0) fprintf(stderr, "cannot write %s\n", path);
    return rc;
}

void ex_camera(const ex_app *app, hv_vec3 eye, hv_vec3 at, float view[16], float projection[16]) {
    hv_mat4_look_at_rh(view, eye, at, hv_vec3_make(0, 1, 0));
    hv_mat4_perspective_fov_rh(projection, 3.14159265f / 4, (float)app->width / (float)app->height, 0.1f, 100.0f);
}

int ex_set_matrix(hfx_effect *fx, const char *name, const float m[16]) {
    int rc = hfx_param_set_matrix(hfx_effect_param(fx, name), m);
    if (rc != HFX_OK) fprintf(stderr, "cannot set matrix '%s' (%d)\n", name, rc);
    return rc;
}

int ex_set_floats(hfx_effect *fx, const char *name, const float *v, size_t n) {
    int rc = hfx_param_set_floats(hfx_effect_param(fx, name), v, n);
    if (rc != HFX_OK) fprintf(stderr, "cannot set '%s' (%d)\n", name, rc);
    return rc;
}

int ex_draw_current_technique(ex_app *app, hfx_effect *fx, const hv_gpu_mesh *m) {
    hfx_technique *t = hfx_effect_current_technique(fx);
    int rc = 0;
    hfx_effect_begin(fx); /* like ID3DXEffect::Begin: the GL state the passes change is saved */
    for (size_t i = 0; i < hfx_technique_pass_count(t) && rc == 0; i++) {
        hfx_pass *pass = hfx_technique_pass(t, i);
        if (hfx_pass_apply(pass) != HFX_OK) {
            fprintf(stderr, "pass %zu of %s: %s\n", i, hfx_technique_name(t), hfx_device_last_error(app->device));
            rc = -1;
        } else {
            ex_draw(app, pass, m);
        }
    }
    hfx_effect_end(fx); /* ... and put back */
    return rc;
}

void ex_additive_blending(ex_app *app, int on) {
    const hv_gl *gl = app->gl;
    if (on) {
        gl->Enable(GL_BLEND);
        gl->BlendEquation(GL_FUNC_ADD);
        gl->BlendFunc(GL_ONE, GL_ONE);
        gl->DepthMask(GL_FALSE);
    } else {
        gl->Disable(GL_BLEND);
        gl->DepthMask(GL_TRUE);
    }
}
