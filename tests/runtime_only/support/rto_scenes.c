/* rto_scenes.c: see rto_scenes.h. Only hfx.h and GL here: no compiler, no runtime internals. */
#include "rto_scenes.h"

#include <GL/osmesa.h>
#include <png.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "seedmath.h"

typedef struct rto_gl {
    void (*Viewport)(GLint, GLint, GLsizei, GLsizei);
    void (*ClearColor)(GLfloat, GLfloat, GLfloat, GLfloat);
    void (*ClearDepth)(GLdouble);
    void (*Clear)(GLbitfield);
    void (*Enable)(GLenum);
    void (*Disable)(GLenum);
    void (*CullFace)(GLenum);
    void (*FrontFace)(GLenum);
    void (*DepthFunc)(GLenum);
    void (*DepthMask)(GLboolean);
    void (*ColorMask)(GLboolean, GLboolean, GLboolean, GLboolean);
    void (*BlendFunc)(GLenum, GLenum);
    void (*BlendEquation)(GLenum);
    void (*GenVertexArrays)(GLsizei, GLuint *);
    void (*BindVertexArray)(GLuint);
    void (*DeleteVertexArrays)(GLsizei, const GLuint *);
    void (*GenBuffers)(GLsizei, GLuint *);
    void (*BindBuffer)(GLenum, GLuint);
    void (*BufferData)(GLenum, GLsizeiptr, const void *, GLenum);
    void (*DeleteBuffers)(GLsizei, const GLuint *);
    void (*VertexAttribPointer)(GLuint, GLint, GLenum, GLboolean, GLsizei, const void *);
    void (*EnableVertexAttribArray)(GLuint);
    void (*DisableVertexAttribArray)(GLuint);
    void (*DrawArrays)(GLenum, GLint, GLsizei);
    void (*GenTextures)(GLsizei, GLuint *);
    void (*BindTexture)(GLenum, GLuint);
    void (*DeleteTextures)(GLsizei, const GLuint *);
    void (*TexImage2D)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void *);
    void (*TexParameteri)(GLenum, GLenum, GLint);
    void (*PixelStorei)(GLenum, GLint);
    void (*GetIntegerv)(GLenum, GLint *);
    const GLubyte *(*GetString)(GLenum);
    const GLubyte *(*GetStringi)(GLenum, GLuint);
    GLenum (*GetError)(void);
    void (*Finish)(void);
} rto_gl;

typedef struct rto_vertex { float pos[3], normal[3], uv[2]; } rto_vertex;

typedef struct rto_mesh { GLuint vao, vbo; int count; } rto_mesh;

struct rto_ctx {
    OSMesaContext ctx;
    unsigned char *pixels; /* bottom row first */
    rto_gl f;
    hfx_device *dev;
    rto_mesh floor, sphere;
    GLuint texture;
};

/* ISO C has no cast from object pointers to function pointers: through a union. */
#define LOAD(field, name) do { union { void *p; __typeof__(c->f.field) fn; } u_; \
    u_.p = (void *)OSMesaGetProcAddress(name); c->f.field = u_.fn; if (!u_.p) missing++; } while (0)

static int load_gl(rto_ctx *c) {
    int missing = 0;
    LOAD(Viewport, "glViewport");
    LOAD(ClearColor, "glClearColor");
    LOAD(ClearDepth, "glClearDepth");
    LOAD(Clear, "glClear");
    LOAD(Enable, "glEnable");
    LOAD(Disable, "glDisable");
    LOAD(CullFace, "glCullFace");
    LOAD(FrontFace, "glFrontFace");
    LOAD(DepthFunc, "glDepthFunc");
    LOAD(DepthMask, "glDepthMask");
    LOAD(ColorMask, "glColorMask");
    LOAD(BlendFunc, "glBlendFunc");
    LOAD(BlendEquation, "glBlendEquation");
    LOAD(GenVertexArrays, "glGenVertexArrays");
    LOAD(BindVertexArray, "glBindVertexArray");
    LOAD(DeleteVertexArrays, "glDeleteVertexArrays");
    LOAD(GenBuffers, "glGenBuffers");
    LOAD(BindBuffer, "glBindBuffer");
    LOAD(BufferData, "glBufferData");
    LOAD(DeleteBuffers, "glDeleteBuffers");
    LOAD(VertexAttribPointer, "glVertexAttribPointer");
    LOAD(EnableVertexAttribArray, "glEnableVertexAttribArray");
    LOAD(DisableVertexAttribArray, "glDisableVertexAttribArray");
    LOAD(DrawArrays, "glDrawArrays");
    LOAD(GenTextures, "glGenTextures");
    LOAD(BindTexture, "glBindTexture");
    LOAD(DeleteTextures, "glDeleteTextures");
    LOAD(TexImage2D, "glTexImage2D");
    LOAD(TexParameteri, "glTexParameteri");
    LOAD(PixelStorei, "glPixelStorei");
    LOAD(GetIntegerv, "glGetIntegerv");
    LOAD(GetString, "glGetString");
    LOAD(GetStringi, "glGetStringi");
    LOAD(GetError, "glGetError");
    LOAD(Finish, "glFinish");
    return missing == 0;
}

static void *loader(const char *name) { return (void *)OSMesaGetProcAddress(name); }

/* ---- meshes ---- */

static void put(rto_vertex *o, v3 p, v3 n, double u, double v) {
    o->pos[0] = (float)p.x, o->pos[1] = (float)p.y, o->pos[2] = (float)p.z;
    o->normal[0] = (float)n.x, o->normal[1] = (float)n.y, o->normal[2] = (float)n.z;
    o->uv[0] = (float)u, o->uv[1] = (float)v;
}

static v3 pos_of(const rto_vertex *v) { return v3_make(v->pos[0], v->pos[1], v->pos[2]); }

/* Clockwise seen from the side `outward` points to: XNA's front faces. */
static void orient(rto_vertex t[3], v3 outward) {
    v3 a = pos_of(&t[0]), b = pos_of(&t[1]), d = pos_of(&t[2]);
    if (v3_dot(v3_cross(v3_sub(b, a), v3_sub(d, a)), outward) > 0) {
        rto_vertex tmp = t[1];
        t[1] = t[2];
        t[2] = tmp;
    }
}

static void upload(rto_ctx *c, rto_mesh *m, const rto_vertex *v, int count) {
    m->count = count;
    c->f.GenVertexArrays(1, &m->vao);
    c->f.GenBuffers(1, &m->vbo);
    c->f.BindVertexArray(m->vao);
    c->f.BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    c->f.BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(count * sizeof *v), v, GL_STATIC_DRAW);
    c->f.BindVertexArray(0);
}

/* The y = 0 plane from -2 to 2, normal +y, texcoords -0.5 .. 1.5 (CLAMP and WRAP differ). */
static void make_floor(rto_ctx *c) {
    rto_vertex v[6];
    v3 p[4] = {v3_make(-2, 0, -2), v3_make(2, 0, -2), v3_make(2, 0, 2), v3_make(-2, 0, 2)};
    double uv[4][2] = {{-0.5, -0.5}, {1.5, -0.5}, {1.5, 1.5}, {-0.5, 1.5}};
    static const int tri[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) put(&v[i], p[tri[i]], v3_make(0, 1, 0), uv[tri[i]][0], uv[tri[i]][1]);
    orient(v, v3_make(0, 1, 0));
    orient(v + 3, v3_make(0, 1, 0));
    upload(c, &c->floor, v, 6);
}

static void make_sphere(rto_ctx *c) {
    enum { SLICES = 24, STACKS = 12 };
    rto_vertex *v = calloc(SLICES * STACKS * 6, sizeof *v);
    if (!v) return;
    int n = 0;
    for (int j = 0; j < STACKS; j++)
        for (int i = 0; i < SLICES; i++) {
            int ci[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
            static const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int t = 0; t < 2; t++) {
                if ((j == 0 && t == 0) || (j == STACKS - 1 && t == 1)) continue;
                v3 centre = v3_make(0, 0, 0);
                for (int k = 0; k < 3; k++) {
                    const int *q = ci[tri[t][k]];
                    double phi = 2 * SEED_PI * q[0] / SLICES, theta = SEED_PI * q[1] / STACKS;
                    v3 unit = v3_make(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
                    put(&v[n + k], unit, unit, (double)q[0] / SLICES, (double)q[1] / STACKS);
                    centre = v3_add(centre, unit);
                }
                orient(&v[n], centre);
                n += 3;
            }
        }
    upload(c, &c->sphere, v, n);
    free(v);
}

/* An 8 x 8 texture with every texel different. */
static void make_texture(rto_ctx *c) {
    unsigned char t[8 * 8 * 4];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            unsigned char *p = t + (y * 8 + x) * 4;
            p[0] = (unsigned char)(30 + 28 * x);
            p[1] = (unsigned char)(40 + 25 * y);
            p[2] = (unsigned char)(230 - 12 * (x + y));
            p[3] = 255;
        }
    c->f.GenTextures(1, &c->texture);
    c->f.BindTexture(GL_TEXTURE_2D, c->texture);
    c->f.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    c->f.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    c->f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    c->f.BindTexture(GL_TEXTURE_2D, 0);
}

/* ---- contexts ---- */

rto_ctx *rto_ctx_create(rto_profile profile) {
    const int core[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                        OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                        OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    const int compat[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                          OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                          OSMESA_CONTEXT_MINOR_VERSION, 0, 0};
    rto_ctx *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    c->ctx = OSMesaCreateContextAttribs(profile == RTO_COMPAT ? compat : core, NULL);
    c->pixels = calloc(RTO_SIZE * RTO_SIZE, 4);
    if (!c->ctx || !c->pixels || !OSMesaMakeCurrent(c->ctx, c->pixels, GL_UNSIGNED_BYTE, RTO_SIZE, RTO_SIZE) ||
        !load_gl(c)) {
        rto_ctx_destroy(c);
        return NULL;
    }
    c->f.Viewport(0, 0, RTO_SIZE, RTO_SIZE);
    c->dev = hfx_device_create_gl(loader);
    if (!c->dev) {
        rto_ctx_destroy(c);
        return NULL;
    }
    make_floor(c);
    make_sphere(c);
    make_texture(c);
    return c;
}

void rto_ctx_destroy(rto_ctx *c) {
    if (!c) return;
    if (c->dev) {
        c->f.DeleteTextures(1, &c->texture);
        rto_mesh *m[2] = {&c->floor, &c->sphere};
        for (int i = 0; i < 2; i++) {
            c->f.DeleteBuffers(1, &m[i]->vbo);
            c->f.DeleteVertexArrays(1, &m[i]->vao);
        }
        hfx_device_destroy(c->dev);
    }
    if (c->ctx) OSMesaDestroyContext(c->ctx);
    free(c->pixels);
    free(c);
}

hfx_device *rto_device(rto_ctx *c) { return c->dev; }

const char *rto_gl_version(rto_ctx *c) { return (const char *)c->f.GetString(GL_VERSION); }

int rto_has_extension(rto_ctx *c, const char *name) {
    GLint n = 0;
    c->f.GetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; i++) {
        const char *e = (const char *)c->f.GetStringi(GL_EXTENSIONS, (GLuint)i);
        if (e && strcmp(e, name) == 0) return 1;
    }
    return 0;
}

void rto_read(rto_ctx *c, unsigned char *out) {
    c->f.Finish();
    for (int y = 0; y < RTO_SIZE; y++)
        memcpy(out + (size_t)y * RTO_SIZE * 4, c->pixels + (size_t)(RTO_SIZE - 1 - y) * RTO_SIZE * 4, RTO_SIZE * 4);
}

int rto_write_png(rto_ctx *c, const char *path) {
    c->f.Finish();
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = RTO_SIZE;
    img.height = RTO_SIZE;
    img.format = PNG_FORMAT_RGBA;
    return png_image_write_to_file(&img, path, 0, c->pixels, -(png_int_32)(RTO_SIZE * 4), NULL) ? 0 : -1;
}

/* ---- scenes ---- */

typedef struct run {
    rto_ctx *c;
    hfx_effect *fx;
    char *why;
    size_t why_size;
    int failed;
} run;

static void fail(run *r, const char *fmt, ...) {
    if (r->failed++) return; /* the first failure says the most */
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->why, r->why_size, fmt, ap);
    va_end(ap);
}

static hfx_param *param(run *r, const char *name) {
    hfx_param *p = hfx_effect_param(r->fx, name);
    if (!p) fail(r, "no parameter '%s'", name);
    return p;
}

static void check(run *r, int rc, const char *what) {
    if (rc != HFX_OK) fail(r, "setting '%s': %s", what, hfx_device_last_error(r->c->dev));
}

static void set_floats_p(run *r, hfx_param *p, const char *what, const float *v, size_t n) {
    if (p) check(r, hfx_param_set_floats(p, v, n), what);
}
static void set_f(run *r, const char *name, double v) {
    hfx_param *p = param(r, name);
    if (p) check(r, hfx_param_set_float(p, (float)v), name);
}
static void set_b(run *r, const char *name, int v) {
    hfx_param *p = param(r, name);
    if (p) check(r, hfx_param_set_bool(p, v), name);
}
static void set_v3(run *r, const char *name, double x, double y, double z) {
    float v[3] = {(float)x, (float)y, (float)z};
    set_floats_p(r, param(r, name), name, v, 3);
}
static void set_v4(run *r, const char *name, double x, double y, double z, double w) {
    float v[4] = {(float)x, (float)y, (float)z, (float)w};
    set_floats_p(r, param(r, name), name, v, 4);
}
static void set_m(run *r, const char *name, const float m[16]) {
    hfx_param *p = param(r, name);
    if (p) check(r, hfx_param_set_matrix(p, m), name);
}
static void set_tex(run *r, const char *name) {
    hfx_param *p = param(r, name);
    if (p) check(r, hfx_param_set_texture(p, r->c->texture), name);
}
/* array[index].member */
static hfx_param *member(run *r, const char *array, size_t index, const char *name) {
    hfx_param *a = param(r, array), *e = a ? hfx_param_element(a, index) : NULL, *m = e ? hfx_param_member(e, name) : NULL;
    if (a && !m) fail(r, "no '%s[%zu].%s'", array, index, name);
    return m;
}
static void m_f(run *r, const char *array, size_t i, const char *name, double v) {
    hfx_param *p = member(r, array, i, name);
    if (p) check(r, hfx_param_set_float(p, (float)v), name);
}
static void m_i(run *r, const char *array, size_t i, const char *name, int v) {
    hfx_param *p = member(r, array, i, name);
    if (p) check(r, hfx_param_set_int(p, v), name);
}
static void m_v(run *r, const char *array, size_t i, const char *name, double x, double y, double z, double w, size_t n) {
    float v[4] = {(float)x, (float)y, (float)z, (float)w};
    set_floats_p(r, member(r, array, i, name), name, v, n);
}

/* The application state XNA starts a frame with: depth LessEqual, CullCounterClockwise, no blend. */
static void clear(rto_ctx *c, float red, float green, float blue) {
    hfx_device_set_viewport(c->dev, 0, 0, RTO_SIZE, RTO_SIZE);
    c->f.Enable(GL_DEPTH_TEST);
    c->f.DepthFunc(GL_LEQUAL);
    c->f.DepthMask(GL_TRUE);
    c->f.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    c->f.Disable(GL_BLEND);
    c->f.Enable(GL_CULL_FACE);
    c->f.CullFace(GL_BACK);
    c->f.FrontFace(GL_CW);
    c->f.ClearColor(red, green, blue, 1);
    c->f.ClearDepth(1.0);
    c->f.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static void bind_attributes(run *r, hfx_pass *pass, const rto_mesh *m) {
    static const struct { const char *semantic; int size; size_t offset; } attrs[] = {
        {"POSITION0", 3, offsetof(rto_vertex, pos)},
        {"NORMAL0", 3, offsetof(rto_vertex, normal)},
        {"TEXCOORD0", 2, offsetof(rto_vertex, uv)},
    };
    rto_gl *f = &r->c->f;
    f->BindVertexArray(m->vao);
    f->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    for (GLuint i = 0; i < 16; i++) f->DisableVertexAttribArray(i);
    for (size_t i = 0; i < sizeof attrs / sizeof attrs[0]; i++) {
        int loc = hfx_pass_attribute_location(pass, attrs[i].semantic);
        if (loc < 0) {
            if (i == 0) fail(r, "pass '%s' has no POSITION0 input", hfx_pass_name(pass));
            continue;
        }
        f->EnableVertexAttribArray((GLuint)loc);
        f->VertexAttribPointer((GLuint)loc, attrs[i].size, GL_FLOAT, GL_FALSE, sizeof(rto_vertex),
                               (const void *)attrs[i].offset);
    }
}

/* Every pass of the technique over the mesh; additive: the application's BlendState.Additive
 * before the second pass, as an XNA game drawing multi-pass lighting does. */
static int draw(run *r, const char *technique, const rto_mesh *m, int additive) {
    hfx_technique *t = hfx_effect_technique(r->fx, technique);
    if (!t) {
        fail(r, "no technique '%s'", technique);
        return 0;
    }
    hfx_effect_set_current_technique(r->fx, t);
    if (hfx_effect_begin(r->fx) != HFX_OK) fail(r, "hfx_effect_begin: %s", hfx_device_last_error(r->c->dev));
    int drawn = 0;
    for (size_t i = 0; i < hfx_technique_pass_count(t); i++) {
        hfx_pass *pass = hfx_technique_pass(t, i);
        if (additive && i == 1) {
            r->c->f.Enable(GL_BLEND);
            r->c->f.BlendEquation(GL_FUNC_ADD);
            r->c->f.BlendFunc(GL_ONE, GL_ONE);
        }
        if (hfx_pass_apply(pass) != HFX_OK) {
            fail(r, "applying pass %zu of '%s': %s", i, technique, hfx_device_last_error(r->c->dev));
            continue;
        }
        bind_attributes(r, pass, m);
        r->c->f.DrawArrays(GL_TRIANGLES, 0, m->count);
        drawn++;
    }
    r->c->f.BindVertexArray(0);
    if (hfx_effect_end(r->fx) != HFX_OK) fail(r, "hfx_effect_end: %s", hfx_device_last_error(r->c->dev));
    GLenum err = r->c->f.GetError();
    if (err != GL_NO_ERROR) fail(r, "GL error 0x%x after drawing '%s'", err, technique);
    return drawn;
}

/* A perspective camera from eye onto the origin. */
static void camera(float view[16], float proj[16], v3 eye) {
    xm_look_at(view, eye, v3_make(0, 0, 0), v3_make(0, 1, 0));
    xm_perspective_fov(proj, SEED_PI / 4, 1.0, 0.5, 30);
}

static void transforms(run *r, const char *w, const char *v, const char *p, const float world[16], v3 eye) {
    float view[16], proj[16];
    camera(view, proj, eye);
    set_m(r, w, world);
    set_m(r, v, view);
    set_m(r, p, proj);
}

/* tutorial0.fx: tex2D through a CLAMP / LINEAR sampler, on the floor seen at an angle. */
static int scene_tutorial0(run *r) {
    float id[16];
    xm_identity(id);
    transforms(r, "World", "View", "Projection", id, v3_make(0.5, 4, 4));
    set_tex(r, "diffuseTexture");
    clear(r->c, 0.1f, 0.1f, 0.2f);
    return draw(r, "Tut0", &r->c->floor, 0);
}

/* phong.fx: a textured, rotated sphere with diffuse, specular and ambient terms. */
static int scene_phong(run *r) {
    float world[16];
    xm_rotation_y(world, 0.6);
    v3 eye = v3_make(1.2, 1.5, 3.5);
    transforms(r, "World", "View", "Projection", world, eye);
    set_v3(r, "LightDirection", -0.5, -0.8, -0.6);
    set_v4(r, "LightColor", 1, 0.9, 0.8, 1);
    set_v3(r, "camPosition", eye.x, eye.y, eye.z);
    set_v4(r, "SpecularColor", 1, 1, 1, 1);
    set_f(r, "SpecularPower", 12);
    set_f(r, "SpecularIntensity", 0.8);
    set_v4(r, "AmbientColor", 0.2, 0.25, 0.3, 1);
    set_f(r, "AmbientIntensity", 0.5);
    set_f(r, "DiffuseIntensity", 0.9);
    set_tex(r, "DiffuseTexture");
    clear(r->c, 0, 0, 0);
    return draw(r, "Phong", &r->c->sphere, 0);
}

/* spot_specular.fx: a spot with specular and attenuation over the floor, then the sphere on it. */
static int scene_spot_specular(run *r) {
    float id[16], up[16];
    xm_identity(id);
    xm_translation(up, 0.3, 1, -0.2);
    v3 eye = v3_make(0.4, 3.5, 4);
    transforms(r, "world", "view", "projection", id, eye);
    set_f(r, "anguloInterno", 0.35);
    set_f(r, "anguloExterno", 0.7);
    set_f(r, "falloff", 1.5);
    set_v3(r, "posicionLuz", 0.5, 3, 0.5);
    set_v3(r, "blancoLuz", 0, 0, 0);
    set_f(r, "c1", 1);
    set_f(r, "c2", 0.1);
    set_f(r, "c3", 0.05);
    set_f(r, "rango", 6);
    set_b(r, "atenuado", 1);
    set_f(r, "ks", 0.7);
    set_f(r, "n", 16);
    set_v3(r, "posicionCamara", eye.x, eye.y, eye.z);
    set_b(r, "modIluEsp", 1);
    set_tex(r, "texturaModelo");
    clear(r->c, 0, 0, 0);
    int drawn = draw(r, "Texturizado", &r->c->floor, 0);
    set_m(r, "world", up);
    return drawn + draw(r, "Texturizado", &r->c->sphere, 0);
}

/* multilights_repaired.fx: an ambient pass, then six lights added over it (two passes). */
static int scene_multilights(run *r) {
    float id[16];
    xm_identity(id);
    v3 eye = v3_make(0.4, 3, 3.5);
    transforms(r, "world", "view", "projection", id, eye);
    m_v(r, "direccionales", 0, "Direccion", 0.5, -1, 0.2, 0, 3);
    m_v(r, "direccionales", 0, "Color", 0.8, 0.7, 0.6, 1, 4);
    m_i(r, "direccionales", 0, "Encender", 1);
    m_v(r, "direccionales", 1, "Direccion", -1, -0.7, -0.4, 0, 3);
    m_v(r, "direccionales", 1, "Color", 0.3, 0.5, 0.9, 1, 4);
    m_i(r, "direccionales", 1, "Encender", 1);
    m_v(r, "puntuales", 0, "Posicion", -1, 0.6, -1, 0, 3);
    m_v(r, "puntuales", 0, "Color", 0.9, 0.4, 0.2, 1, 4);
    m_i(r, "puntuales", 0, "Encender", 1);
    m_v(r, "puntuales", 1, "Posicion", 1.2, 0.5, 0.8, 0, 3);
    m_v(r, "puntuales", 1, "Color", 0.5, 0.9, 0.5, 1, 4);
    m_f(r, "puntuales", 1, "Rango", 1.6);
    m_f(r, "puntuales", 1, "C1", 1);
    m_f(r, "puntuales", 1, "C2", 0.5);
    m_f(r, "puntuales", 1, "C3", 1.5);
    m_i(r, "puntuales", 1, "Atenuar", 1);
    m_i(r, "puntuales", 1, "Encender", 1);
    m_v(r, "spots", 0, "Posicion", 0, 3, 0, 0, 3);
    m_v(r, "spots", 0, "Blanco", 0, 0, 0, 0, 3);
    m_v(r, "spots", 0, "Color", 1, 1, 0.8, 1, 4);
    m_f(r, "spots", 0, "AnguloInterno", 0.15);
    m_f(r, "spots", 0, "AnguloExterno", 0.35);
    m_f(r, "spots", 0, "Falloff", 1.2);
    m_i(r, "spots", 0, "Encender", 1);
    m_v(r, "spots", 1, "Posicion", -0.8, 1.5, 1, 0, 3);
    m_v(r, "spots", 1, "Blanco", -1, 0, 1.2, 0, 3);
    m_v(r, "spots", 1, "Color", 0.6, 0.6, 1, 1, 4);
    m_f(r, "spots", 1, "AnguloInterno", 0.2);
    m_f(r, "spots", 1, "AnguloExterno", 0.5);
    m_f(r, "spots", 1, "Falloff", 0.8);
    m_f(r, "spots", 1, "Rango", 5);
    m_f(r, "spots", 1, "C1", 1);
    m_f(r, "spots", 1, "C2", 0.1);
    m_f(r, "spots", 1, "C3", 0.1);
    m_i(r, "spots", 1, "Atenuar", 1);
    m_i(r, "spots", 1, "Encender", 1);
    set_b(r, "habiEspec", 1);
    set_f(r, "ks", 0.6);
    set_f(r, "n", 10);
    set_v3(r, "posicionCamara", eye.x, eye.y, eye.z);
    set_tex(r, "texturaModelo");
    clear(r->c, 0, 0, 0);
    return draw(r, "Texturizado", &r->c->floor, 1);
}

/* fxcomposer_empty.fx: white through WorldViewProjection, the pass's CullMode = None. */
static int scene_fxcomposer_empty(run *r) {
    float world[16], view[16], proj[16], wv[16], wvp[16];
    xm_translation(world, 0.2, -0.1, 0);
    camera(view, proj, v3_make(0.5, 1, 3));
    xm_mul(wv, world, view);
    xm_mul(wvp, wv, proj);
    set_m(r, "WorldViewProj", wvp);
    clear(r->c, 0.2f, 0, 0.1f);
    return draw(r, "technique0", &r->c->sphere, 0);
}

static const struct {
    const char *name, *file;
    int (*render)(run *r);
    int passes;
} scenes[] = {
    {"tutorial0", "tutorial0.fx", scene_tutorial0, 1},
    {"phong", "phong.fx", scene_phong, 1},
    {"spot_specular", "spot_specular.fx", scene_spot_specular, 2},
    {"multilights_repaired", "multilights_repaired.fx", scene_multilights, 2},
    {"fxcomposer_empty", "fxcomposer_empty.fx", scene_fxcomposer_empty, 1},
};

int rto_scene_count(void) { return (int)(sizeof scenes / sizeof scenes[0]); }
const char *rto_scene_name(int i) { return scenes[i].name; }
const char *rto_scene_file(int i) { return scenes[i].file; }
int rto_scene_passes(int i) { return scenes[i].passes; }

int rto_scene_render(rto_ctx *c, hfx_effect *fx, int i, char *why, size_t why_size) {
    if (why_size) why[0] = '\0';
    if (!c || !fx || i < 0 || i >= rto_scene_count()) {
        snprintf(why, why_size, "no context, effect or scene");
        return 0;
    }
    run r = {c, fx, why, why_size, 0};
    int drawn = scenes[i].render(&r);
    return r.failed ? 0 : drawn;
}
