/* draw.c: what the page's "application" does each frame, as an XNA Draw method would: the
 * camera's matrices into the effect (by name and SAS semantic, hfxview's bind.c), then
 * hfxview's own drawing (render.c: XNA's default states, every pass applied in order with its
 * own states, the mesh drawn; with blend_add the application's additive blending from the
 * second pass on, as hfxview --blend-passes add and XNA multi-pass lighting do)
 * through its GL table loaded over WebGL 2, so the page and hfxview draw alike. */
#include <emscripten.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bind.h"
#include "image.h"
#include "mesh.h"
#include "options.h"
#include "session.h"
#include "textures.h"
#include "vmath.h"
#include "webgl.h"

#define PI 3.14159265358979323846f

/* hv_texture_2d, noted for the runtime's level-size queries (webgl.h). */
unsigned hfxw_texture_rgba(hfxw_session *s, const unsigned char *rgba, int width, int height) {
    hv_image img = {width, height, 0, 0, (unsigned char *)rgba};
    unsigned tex = hv_texture_2d(&s->gl, &img);
    hfxw_gl_note_texture(tex, width, height);
    return tex;
}

/* hfxview's default textures (image.h), texel for texel: an untextured effect still shows its
 * mapping, and the page's picture of it is hfxview's. kind: 2, 6 (cube) or 3 (volume). */
static unsigned make_default(hfxw_session *s, int kind) {
    hv_image img;
    if (hv_image_default(&img, kind == 3) != 0) return 0;
    unsigned tex = kind == 3 ? hv_texture_3d(&s->gl, &img) : kind == 6 ? hv_texture_cube(&s->gl, &img)
                                                                       : hfxw_texture_rgba(s, img.rgba, img.width, img.height);
    free(img.rgba);
    return tex;
}

int hfxw_draw_init(hfxw_session *s) {
    if (hv_gl_load(&s->gl, hfxw_gl_proc)) return -1;
    hv_options o;
    hv_options_defaults(&o);
    memcpy(s->clear, o.background, sizeof s->clear); /* XNA's CornflowerBlue, as hfxview clears */
    s->checker = make_default(s, 2), s->cube = make_default(s, 6), s->volume = make_default(s, 3);
    s->yaw = 0, s->pitch = 20, s->distance = 3;
    s->width = s->height = 512;
    char err[128];
    return hfxw_mesh_set(s, "auto", err, sizeof err);
}

/* m onto the GPU in place of the session's mesh. */
static int mesh_upload(hfxw_session *s, hv_mesh *m, int rc) {
    if (rc == 0) {
        hv_gpu_mesh_release(&s->gl, &s->mesh);
        rc = hv_gpu_mesh_upload(&s->gl, &s->mesh, m);
    }
    hv_mesh_free(m);
    return rc;
}

/* spec: "auto" (hfxview's choice for each effect, hfxw_mesh_fit), a built-in name or an .obj path. */
int hfxw_mesh_set(hfxw_session *s, const char *spec, char *err, size_t errlen) {
    s->mesh_auto = !strcmp(spec, "auto");
    s->mesh_screen_w = s->mesh_screen_h = 0;
    if (s->mesh_auto) spec = "sphere";
    hv_mesh m;
    memset(&m, 0, sizeof m);
    int rc = mesh_upload(s, &m, hv_mesh_load(&m, spec, err, errlen));
    return rc || !s->mesh_auto ? rc : hfxw_mesh_fit(s, s->width, s->height);
}

int hfxw_mesh_fit(hfxw_session *s, int width, int height) {
    if (!s->mesh_auto) return 0;
    int screen = s->fx && hv_effect_wants_pixels(s->fx);
    if (screen ? s->mesh_screen_w == width && s->mesh_screen_h == height : !s->mesh_screen_w) return 0;
    hv_mesh m;
    memset(&m, 0, sizeof m);
    char err[128];
    int rc = mesh_upload(s, &m, screen ? hv_mesh_screen(&m, width, height) : hv_mesh_load(&m, "sphere", err, sizeof err));
    s->mesh_screen_w = rc == 0 && screen ? width : 0;
    s->mesh_screen_h = rc == 0 && screen ? height : 0;
    return rc;
}

/* The orbit camera's eye: at `distance` from the origin, yaw about +y, pitch above the ground. */
static hv_vec3 orbit_eye(const hfxw_session *s) {
    float yaw = s->yaw * PI / 180, pitch = s->pitch * PI / 180;
    return hv_vec3_make(s->distance * cosf(pitch) * sinf(yaw), s->distance * sinf(pitch),
                        s->distance * cosf(pitch) * cosf(yaw));
}

/* hfxview's scene with its defaults (World the identity, 45 degrees of view, its light),
 * looking at the origin from the orbit camera. */
static void scene_of(const hfxw_session *s, int width, int height, hv_scene *sc) {
    hv_options o;
    hv_options_defaults(&o);
    o.eye = orbit_eye(s);
    o.width = width, o.height = height;
    hv_scene_from_options(sc, &o);
    /* the clock runs on the page, unless fixed (hfxw_set_clock) */
    sc->time = (float)(s->clock_s >= 0 ? s->clock_s : (emscripten_get_now() - s->start_ms) / 1000.0);
}

void hfxw_bind_scene(hfxw_session *s, int width, int height) {
    hv_scene sc;
    s->start_ms = emscripten_get_now();
    scene_of(s, width, height, &sc);
    free((void *)s->bound);
    s->bound_count = hfx_effect_param_count(s->fx);
    s->bound = calloc(s->bound_count ? s->bound_count : 1, sizeof *s->bound);
    if (!s->bound) s->bound_count = 0;
    hv_bind_scene_report(s->fx, &sc, s->bound, s->bound_count);
}

/* Each frame: the camera's matrices and position and the clock only, so that a light or
 * material the user set (to zero too) in the panel stays as set. */
static void bind_view(hfxw_session *s, int width, int height) {
    hv_scene sc;
    scene_of(s, width, height, &sc);
    hv_bind_view(s->fx, &sc);
}

/* The parameters hfxview gives a texture (textures.h: every texture parameter, samplers only
 * when no texture parameter could feed them), still empty, get its default of their kind. */
void hfxw_bind_default_textures(hfxw_session *s) {
    int samplers_too = hv_effect_samplers_take_textures(s->fx);
    for (size_t i = 0; i < hfx_effect_param_count(s->fx); i++) {
        hfx_param *p = hfx_effect_param_at(s->fx, i);
        unsigned have = 0;
        if (!hv_param_takes_texture(p, samplers_too)) continue;
        hv_tex_kind kind = hv_texture_kind(p);
        unsigned tex = kind == HV_TEX_CUBE ? s->cube : kind == HV_TEX_3D ? s->volume : s->checker;
        if (hfx_param_get_texture(p, &have) == HFX_OK && !have) hfx_param_set_texture(p, tex);
    }
}

void hfxw_draw_frame(hfxw_session *s, int width, int height) {
    hv_clear(&s->gl, width, height, s->clear);
    hfx_device_set_viewport(s->dev, 0, 0, width, height);
    if (!s->fx) return;
    hfxw_mesh_fit(s, width, height); /* the screen rectangle follows the canvas */
    bind_view(s, width, height);
    hfx_technique *t = hfx_effect_technique_at(s->fx, (size_t)s->technique);
    if (t) hv_draw_technique(&s->gl, &s->mesh, s->fx, t, s->pass, s->blend_add, NULL);
}
