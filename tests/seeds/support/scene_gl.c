/* scene_gl.c: the seed scene drawn with OpenGL on OSMesa (see scene_gpu.h). */
#include <GL/glcorearb.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_fns.h"
#include "scene_gpu.h"

typedef struct gl_part {
    test_gl *gl;
    test_gl_fns f;
} gl_part;

static test_gl_fns *fns(seed_scene *s) { return &((gl_part *)s->gpu)->f; }

int seed_gpu_open(seed_scene *s, int major, int minor) {
    gl_part *g = calloc(1, sizeof *g);
    if (!g) return 0;
    s->gpu = g;
    g->gl = test_gl_create_version(s->width, s->height, major, minor);
    if (!g->gl || test_gl_fns_load(&g->f) != 0) return 0;
    s->dev = hfx_device_create_gl(test_gl_loader);
    if (!s->dev) fprintf(stderr, "  harness: hfx_device_create_gl returned NULL\n");
    g->f.Viewport(0, 0, s->width, s->height);
    return 1;
}

void seed_gpu_close(seed_scene *s) {
    gl_part *g = s->gpu;
    if (s->dev) hfx_device_destroy(s->dev);
    if (g) test_gl_destroy(g->gl);
    free(g);
}

void *seed_gl(seed_scene *s, const char *name) { (void)s; return test_gl_proc(name); }

void seed_set_culling(seed_scene *s, int on) {
    test_gl_fns *f = fns(s);
    if (on) {
        f->Enable(GL_CULL_FACE);
        f->CullFace(GL_BACK);
        f->FrontFace(GL_CW);
    } else {
        f->Disable(GL_CULL_FACE);
    }
}

void seed_clear(seed_scene *s, rgba c) {
    test_gl_fns *f = fns(s);
    f->Viewport(0, 0, s->width, s->height);
    f->Enable(GL_DEPTH_TEST);
    f->DepthFunc(GL_LEQUAL);
    f->DepthMask(GL_TRUE);
    f->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    f->Disable(GL_BLEND);
    seed_set_culling(s, 1);
    f->ClearColor((float)c.r, (float)c.g, (float)c.b, (float)c.a);
    f->ClearDepth(1.0);
    f->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void seed_gpu_mesh_upload(seed_scene *s, seed_mesh *m) {
    test_gl_fns *f = fns(s);
    f->GenVertexArrays(1, &m->vao);
    f->GenBuffers(1, &m->vbo);
    f->BindVertexArray(m->vao);
    f->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    f->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(m->count * sizeof *m->v), m->v, GL_STATIC_DRAW);
    f->BindVertexArray(0);
}

void seed_gpu_mesh_free(seed_scene *s, seed_mesh *m) {
    fns(s)->DeleteBuffers(1, &m->vbo);
    fns(s)->DeleteVertexArrays(1, &m->vao);
}

int seed_gpu_set_texture(seed_scene *s, hfx_param *p, const seed_texture *t) {
    (void)s;
    return hfx_param_set_texture(p, t->gl);
}

void seed_gpu_read(seed_scene *s, int x, int y, unsigned char rgba[4]) { test_gl_read(((gl_part *)s->gpu)->gl, x, y, rgba); }

int seed_gpu_write_png(seed_scene *s, const char *path) { return test_gl_write_png(((gl_part *)s->gpu)->gl, path); }

static void bind_attributes(seed_scene *s, hfx_pass *pass, const seed_mesh *m) {
    static const struct { const char *semantic; int size; size_t offset; } attrs[] = {
        {"POSITION0", 3, offsetof(seed_vertex, pos)},
        {"NORMAL0", 3, offsetof(seed_vertex, normal)},
        {"TEXCOORD0", 2, offsetof(seed_vertex, uv)},
    };
    test_gl_fns *f = fns(s);
    f->BindVertexArray(m->vao);
    f->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    for (GLuint i = 0; i < 16; i++) f->DisableVertexAttribArray(i);
    for (size_t i = 0; i < sizeof attrs / sizeof attrs[0]; i++) {
        int loc = hfx_pass_attribute_location(pass, attrs[i].semantic);
        if (loc < 0) {
            if (i == 0) seed_note(s, "pass '%s' has no POSITION0 input", hfx_pass_name(pass));
            continue;
        }
        f->EnableVertexAttribArray((GLuint)loc);
        f->VertexAttribPointer((GLuint)loc, attrs[i].size, GL_FLOAT, GL_FALSE, sizeof(seed_vertex),
                               (const void *)attrs[i].offset);
    }
}

int seed_draw(seed_scene *s, hfx_effect *fx, const char *technique, const seed_mesh *m, seed_blend blend) {
    if (!fx || !m) return 0;
    hfx_technique *t = technique ? hfx_effect_technique(fx, technique) : hfx_effect_current_technique(fx);
    if (!t) {
        seed_note(s, "no technique '%s'", technique ? technique : "(current)");
        return 0;
    }
    test_gl_fns *f = fns(s);
    hfx_effect_set_current_technique(fx, t);
    if (hfx_effect_begin(fx) != HFX_OK) seed_note(s, "hfx_effect_begin: %s", hfx_device_last_error(s->dev));
    int drawn = 0;
    for (size_t i = 0; i < hfx_technique_pass_count(t); i++) {
        hfx_pass *pass = hfx_technique_pass(t, i);
        if (blend == SEED_BLEND_ADD_AFTER_FIRST && i == 1) {
            /* The application's BlendState.Additive, set before Apply as an XNA game does. */
            f->Enable(GL_BLEND);
            f->BlendEquation(GL_FUNC_ADD);
            f->BlendFunc(GL_ONE, GL_ONE);
        }
        if (hfx_pass_apply(pass) != HFX_OK) {
            seed_note(s, "applying pass %zu: %s", i, hfx_device_last_error(s->dev));
            continue;
        }
        bind_attributes(s, pass, m);
        f->DrawArrays(GL_TRIANGLES, 0, m->count);
        drawn++;
    }
    f->BindVertexArray(0);
    if (hfx_effect_end(fx) != HFX_OK) seed_note(s, "hfx_effect_end: %s", hfx_device_last_error(s->dev));
    GLenum err = f->GetError();
    if (err != GL_NO_ERROR) seed_note(s, "GL error 0x%x after drawing", err);
    return drawn;
}

seed_texture seed_texture_make(seed_scene *s, int width, int height, const unsigned char *texels) {
    seed_texture t = {width, height, texels, 0, NULL};
    test_gl_fns *f = fns(s);
    f->GenTextures(1, &t.gl);
    f->BindTexture(GL_TEXTURE_2D, t.gl);
    f->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    f->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    f->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    f->BindTexture(GL_TEXTURE_2D, 0);
    return t;
}

void seed_texture_free(seed_scene *s, seed_texture *t) {
    if (t->gl) fns(s)->DeleteTextures(1, &t->gl);
    t->gl = 0;
}
