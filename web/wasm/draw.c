/* draw.c: what the page's "application" does each frame, as an XNA Draw method would: XNA's
 * default states, the camera's matrices into the effect (by name and SAS semantic, hfxview's
 * bind.c), every pass of the technique applied and the mesh drawn. */
#include <GLES3/gl3.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "bind.h"
#include "mesh.h"
#include "session.h"
#include "vmath.h"
#include "webgl.h"

#define PI 3.14159265358979323846f

/* A mipmapped RGBA8 texture, repeat-addressed (the sampler states of a pass override this). */
unsigned hfxw_texture_rgba(const unsigned char *rgba, int width, int height) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    hfxw_gl_note_texture(tex, width, height);
    return tex;
}

/* 8 x 8 squares of 16 texels, white and grey: an untextured effect still shows its mapping. */
static unsigned make_checker(void) {
    enum { N = 128 };
    unsigned char *px = malloc(N * N * 4);
    if (!px) return 0;
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            unsigned char v = ((x / 16) + (y / 16)) % 2 ? 255 : 96;
            unsigned char *p = px + (y * N + x) * 4;
            p[0] = p[1] = p[2] = v, p[3] = 255;
        }
    unsigned tex = hfxw_texture_rgba(px, N, N);
    free(px);
    return tex;
}

int hfxw_draw_init(hfxw_session *s) {
    s->checker = make_checker();
    s->yaw = 0, s->pitch = 20, s->distance = 3;
    s->width = s->height = 512;
    /* XNA's CornflowerBlue, as hfxview clears */
    s->clear[0] = 100 / 255.0f, s->clear[1] = 149 / 255.0f, s->clear[2] = 237 / 255.0f, s->clear[3] = 1;
    char err[128];
    return hfxw_mesh_set(s, "sphere", err, sizeof err);
}

int hfxw_mesh_set(hfxw_session *s, const char *spec, char *err, size_t errlen) {
    hv_mesh m;
    memset(&m, 0, sizeof m);
    if (hv_mesh_load(&m, spec, err, errlen) != 0) {
        hv_mesh_free(&m);
        return -1;
    }
    if (!s->vao) {
        glGenVertexArrays(1, &s->vao);
        glGenBuffers(1, &s->vbo);
        glGenBuffers(1, &s->ibo);
    }
    glBindVertexArray(s->vao);
    glBindBuffer(GL_ARRAY_BUFFER, s->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(m.vcount * sizeof *m.v), m.v, GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s->ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(m.icount * sizeof *m.idx), m.idx, GL_STATIC_DRAW);
    glBindVertexArray(0);
    s->index_count = (int)m.icount;
    hv_mesh_free(&m);
    return 0;
}

/* The orbit camera: eye at `distance` from the origin, yaw about +y, pitch above the ground. */
void hfxw_scene_matrices(const hfxw_session *s, int width, int height, float view[16], float proj[16], float eye[3]) {
    float yaw = s->yaw * PI / 180, pitch = s->pitch * PI / 180;
    hv_vec3 e = hv_vec3_make(s->distance * cosf(pitch) * sinf(yaw), s->distance * sinf(pitch),
                             s->distance * cosf(pitch) * cosf(yaw));
    hv_mat4_look_at_rh(view, e, hv_vec3_make(0, 0, 0), hv_vec3_make(0, 1, 0));
    hv_mat4_perspective_fov_rh(proj, 45 * PI / 180, (float)width / (float)height, 0.1f, 100.0f);
    eye[0] = e.x, eye[1] = e.y, eye[2] = e.z;
}

void hfxw_bind_camera(hfxw_session *s, int width, int height) {
    hv_scene sc;
    memset(&sc, 0, sizeof sc);
    float eye[3];
    hv_mat4_identity(sc.world);
    hfxw_scene_matrices(s, width, height, sc.view, sc.projection, eye);
    sc.eye = hv_vec3_make(eye[0], eye[1], eye[2]);
    sc.at = hv_vec3_make(0, 0, 0);
    sc.light_position = hv_vec3_make(2.5f, 4.0f, 3.0f); /* hfxview's default light */
    sc.light_direction = hv_vec3_normalize(hv_vec3_sub(sc.at, sc.light_position));
    sc.light_color[0] = sc.light_color[1] = sc.light_color[2] = 1;
    sc.width = width, sc.height = height;
    hv_bind_scene(s->fx, &sc);
}

/* Every texture parameter still empty gets the checker. */
void hfxw_bind_default_textures(hfxw_session *s) {
    for (size_t i = 0; i < hfx_effect_param_count(s->fx); i++) {
        hfx_param *p = hfx_effect_param_at(s->fx, i);
        unsigned have = 0;
        if (hfx_param_texture_target(p) != GL_TEXTURE_2D) continue;
        if (hfx_param_get_texture(p, &have) == HFX_OK && !have) hfx_param_set_texture(p, s->checker);
    }
}

typedef struct { const char *semantic; size_t offset; int size; } stream;

static const stream streams[] = {
    {"POSITION0", offsetof(hv_vertex, pos), 3},   {"NORMAL0", offsetof(hv_vertex, normal), 3},
    {"TEXCOORD0", offsetof(hv_vertex, uv), 2},    {"TANGENT0", offsetof(hv_vertex, tangent), 3},
    {"BINORMAL0", offsetof(hv_vertex, binormal), 3},
};

/* The mesh's streams where the applied pass wants them; COLOR0 white as D3D9 supplies it. */
static void bind_attributes(const hfxw_session *s, const hfx_pass *pass) {
    glBindVertexArray(s->vao);
    glBindBuffer(GL_ARRAY_BUFFER, s->vbo);
    for (GLuint i = 0; i < 16; i++) glDisableVertexAttribArray(i);
    for (size_t i = 0; i < sizeof streams / sizeof streams[0]; i++) {
        int loc = hfx_pass_attribute_location(pass, streams[i].semantic);
        if (loc < 0) continue;
        glVertexAttribPointer((GLuint)loc, streams[i].size, GL_FLOAT, GL_FALSE, sizeof(hv_vertex),
                              (const void *)streams[i].offset);
        glEnableVertexAttribArray((GLuint)loc);
    }
    int colour = hfx_pass_attribute_location(pass, "COLOR0");
    if (colour >= 0) glVertexAttrib4f((GLuint)colour, 1, 1, 1, 1);
}

/* XNA's device defaults: depth LessEqual with writes, CullCounterClockwiseFace, opaque. */
static void default_states(void) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);
    glCullFace(GL_BACK);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void hfxw_draw_frame(hfxw_session *s, int width, int height) {
    glViewport(0, 0, width, height);
    hfx_device_set_viewport(s->dev, 0, 0, width, height);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearColor(s->clear[0], s->clear[1], s->clear[2], s->clear[3]);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (!s->fx) return;
    hfxw_bind_camera(s, width, height);
    hfx_technique *t = hfx_effect_technique_at(s->fx, (size_t)s->technique);
    if (!t) return;
    default_states();
    hfx_effect_begin(s->fx);
    for (size_t i = 0; i < hfx_technique_pass_count(t); i++) {
        if (s->pass >= 0 && (size_t)s->pass != i) continue;
        hfx_pass *p = hfx_technique_pass(t, i);
        if (hfx_pass_apply(p) != HFX_OK) break;
        bind_attributes(s, p);
        glDrawElements(GL_TRIANGLES, s->index_count, GL_UNSIGNED_INT, NULL);
    }
    hfx_effect_end(s->fx);
    glBindVertexArray(0);
}
