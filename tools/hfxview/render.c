/* render.c: vertex buffers, states and draw calls (see render.h). */
#include "render.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

int hv_gpu_mesh_upload(const hv_gl *gl, hv_gpu_mesh *g, const hv_mesh *m) {
    memset(g, 0, sizeof *g);
    if (!m->vcount || !m->icount) return -1;
    gl->GenVertexArrays(1, &g->vao);
    gl->BindVertexArray(g->vao);
    gl->GenBuffers(1, &g->vbo);
    gl->BindBuffer(GL_ARRAY_BUFFER, g->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(m->vcount * sizeof *m->v), m->v, GL_STATIC_DRAW);
    gl->GenBuffers(1, &g->ibo);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->ibo); /* remembered by the VAO */
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(m->icount * sizeof *m->idx), m->idx, GL_STATIC_DRAW);
    gl->BindVertexArray(0);
    g->index_count = (int)m->icount;
    return gl->GetError() == GL_NO_ERROR ? 0 : -1;
}

void hv_gpu_mesh_release(const hv_gl *gl, hv_gpu_mesh *g) {
    if (g->ibo) gl->DeleteBuffers(1, &g->ibo);
    if (g->vbo) gl->DeleteBuffers(1, &g->vbo);
    if (g->vao) gl->DeleteVertexArrays(1, &g->vao);
    memset(g, 0, sizeof *g);
}

typedef struct { const char *semantic; size_t offset; int size; } vertex_stream;

static const vertex_stream streams[] = {
    {"POSITION0", offsetof(hv_vertex, pos), 3},
    {"NORMAL0", offsetof(hv_vertex, normal), 3},
    {"TEXCOORD0", offsetof(hv_vertex, uv), 2},
    {"TANGENT0", offsetof(hv_vertex, tangent), 3},
    {"BINORMAL0", offsetof(hv_vertex, binormal), 3},
};

void hv_bind_attributes(const hv_gl *gl, const hv_gpu_mesh *g, const hfx_pass *pass) {
    gl->BindVertexArray(g->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, g->vbo);
    for (GLuint i = 0; i < 16; i++) gl->DisableVertexAttribArray(i);
    for (size_t i = 0; i < sizeof streams / sizeof streams[0]; i++) {
        int loc = hfx_pass_attribute_location(pass, streams[i].semantic);
        if (loc < 0) continue;
        gl->VertexAttribPointer((GLuint)loc, streams[i].size, GL_FLOAT, GL_FALSE, sizeof(hv_vertex),
                                (const void *)streams[i].offset);
        gl->EnableVertexAttribArray((GLuint)loc);
    }
    for (size_t i = 0; i < hv_vertex_constant_count; i++) { /* mesh.h */
        const hv_vertex_constant *c = &hv_vertex_constants[i];
        int loc = hfx_pass_attribute_location(pass, c->semantic);
        if (loc >= 0) gl->VertexAttrib4f((GLuint)loc, c->v[0], c->v[1], c->v[2], c->v[3]);
    }
    /* Other texture coordinate sets reuse the first, as a single-UV model would in XNA. */
    for (int set = 1; set < 8; set++) {
        char name[16] = "TEXCOORD0";
        name[8] = (char)('0' + set);
        int loc = hfx_pass_attribute_location(pass, name);
        if (loc < 0) continue;
        gl->VertexAttribPointer((GLuint)loc, 2, GL_FLOAT, GL_FALSE, sizeof(hv_vertex), (const void *)offsetof(hv_vertex, uv));
        gl->EnableVertexAttribArray((GLuint)loc);
    }
}

void hv_draw_mesh(const hv_gl *gl, const hv_gpu_mesh *g, const hfx_pass *pass) {
    hv_bind_attributes(gl, g, pass);
    gl->DrawElements(GL_TRIANGLES, g->index_count, GL_UNSIGNED_INT, NULL);
}

void hv_set_default_states(const hv_gl *gl) {
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LEQUAL);
    gl->DepthMask(GL_TRUE);
    /* D3D culls by winding as seen on screen; clockwise is front, as in XNA. */
    gl->Enable(GL_CULL_FACE);
    gl->FrontFace(GL_CW);
    gl->CullFace(GL_BACK);
    gl->Disable(GL_BLEND);
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void hv_clear(const hv_gl *gl, int width, int height, const float rgba[4]) {
    gl->Viewport(0, 0, width, height);
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl->DepthMask(GL_TRUE);
    gl->ClearColor(rgba[0], rgba[1], rgba[2], rgba[3]);
    gl->ClearDepth(1.0);
    gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* As an XNA Draw method with D3D9 underneath: the device starts from XNA's defaults, set here
 * before hfx_effect_begin, which reads them back so the runtime's shadow matches GL. Between
 * the passes nothing is restored: a pass's render states stay set for the next one, as in
 * D3D9 (states a pass does not name keep the previous pass's values). hfx_effect_end after
 * the last pass restores what begin saved.
 *
 * blend_add is the application changing GL state between two Applies (additive blending
 * and no depth writes, once, before the second pass): docs/runtime.md asks for
 * hfx_device_sync after such a change, which reads the GL state back into the shadow; end
 * still restores what begin saved. */
int hv_draw_technique(const hv_gl *gl, const hv_gpu_mesh *g, hfx_effect *fx, hfx_technique *t, int pass,
                      int blend_add, size_t *failed_pass) {
    size_t count = hfx_technique_pass_count(t);
    int rc = HFX_OK, synced = 0;
    hv_set_default_states(gl);
    hfx_effect_begin(fx);
    for (size_t i = 0; i < count && rc == HFX_OK; i++) {
        if (pass >= 0 && (size_t)pass != i) continue;
        hfx_pass *p = hfx_technique_pass(t, i);
        if (blend_add && i > 0 && !synced) { /* the application's job in XNA multi-pass lighting */
            gl->Enable(GL_BLEND);
            gl->BlendEquation(GL_FUNC_ADD);
            gl->BlendFunc(GL_ONE, GL_ONE);
            gl->DepthMask(GL_FALSE);
            hfx_device_sync(hfx_effect_device(fx));
            synced = 1;
        }
        rc = hfx_pass_apply(p);
        if (rc == HFX_OK) hv_draw_mesh(gl, g, p);
        else if (failed_pass) *failed_pass = i;
    }
    hfx_effect_end(fx);
    gl->BindVertexArray(0);
    return rc;
}

int hv_read_image(const hv_gl *gl, int width, int height, hv_image *out) {
    size_t row = (size_t)width * 4;
    unsigned char *px = malloc(row * (size_t)height);
    if (!px) return -1;
    gl->Finish();
    gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl->ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, px);
    /* The default framebuffer's rows go bottom up, PNG's top down. In a framebuffer object the
     * runtime draws in D3D9's row order (hfx_pos_fixup.z, docs/conventions.md): the first row
     * read is already the top. */
    GLint fbo = 0;
    gl->GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &fbo);
    for (int y = 0; !fbo && y < height / 2; y++) {
        unsigned char *a = px + (size_t)y * row, *b = px + (size_t)(height - 1 - y) * row;
        for (size_t k = 0; k < row; k++) {
            unsigned char s = a[k];
            a[k] = b[k];
            b[k] = s;
        }
    }
    memset(out, 0, sizeof *out);
    out->width = width;
    out->height = height;
    out->rgba = px;
    return 0;
}

static void texture_params(const hv_gl *gl, GLenum target) {
    gl->TexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

unsigned int hv_texture_2d(const hv_gl *gl, const hv_image *img) {
    GLuint tex = 0;
    gl->GenTextures(1, &tex);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* Row 0 of the image is texture row t = 0, which is Direct3D's v = 0: no flip needed. */
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img->width, img->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img->rgba);
    gl->GenerateMipmap(GL_TEXTURE_2D);
    texture_params(gl, GL_TEXTURE_2D);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return tex;
}

/* A cube map from an image of 6 faces (+X, -X, +Y, -Y, +Z, -Z as in DDS files), or from one
 * image repeated on every face. */
unsigned int hv_texture_cube(const hv_gl *gl, const hv_image *img) {
    GLuint tex = 0;
    gl->GenTextures(1, &tex);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_CUBE_MAP, tex);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    size_t stride = hv_image_face_count(img) == 6 ? hv_image_face_bytes(img) : 0;
    for (int face = 0; face < 6; face++)
        gl->TexImage2D((GLenum)(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA8, img->width, img->height, 0,
                       GL_RGBA, GL_UNSIGNED_BYTE, img->rgba + stride * (size_t)face);
    gl->GenerateMipmap(GL_TEXTURE_CUBE_MAP);
    texture_params(gl, GL_TEXTURE_CUBE_MAP);
    gl->BindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return tex;
}

/* A volume texture from an image's slices (one slice for a flat image). */
unsigned int hv_texture_3d(const hv_gl *gl, const hv_image *img) {
    GLuint tex = 0;
    gl->GenTextures(1, &tex);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_3D, tex);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    int depth = img->depth > 1 ? img->depth : 1;
    gl->TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, img->width, img->height, depth, 0, GL_RGBA, GL_UNSIGNED_BYTE, img->rgba);
    gl->GenerateMipmap(GL_TEXTURE_3D);
    texture_params(gl, GL_TEXTURE_3D);
    gl->TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
    gl->BindTexture(GL_TEXTURE_3D, 0);
    return tex;
}
