/* bench_gpu.c: what the shaders hfx emits cost on the GPU, against hand-written GLSL for the same
 * equations (matrices multiplied on the CPU, uniform-only maths on the CPU, no emulation), in the
 * same OSMesa context, alternating, best of `rounds`:
 *   pixel-bound:  a plane filling a 2048 x 2048 target (two triangles);
 *   vertex-bound: the same plane as a 1001 x 1001 grid (2 M triangles) at 256 x 256.
 * Each case also compares the two pictures (largest channel difference, /255): a ratio only
 * counts when they agree (BENCH_GPU_PNG=1 writes the last pair to /tmp). Prints frame times and
 * the ratio hfx / hand-written, for hfx with its preshaders (the default) and without them
 * (HFX load option no_preshaders: the "before" of issue 14) in the same run. Covered: the 003 tutorial's effects (ambient, ambient_textured,
 * directional, point and spot, with and without specular, both techniques; specular and
 * distance attenuation on), tutorial0, fxcomposer_empty, phong and pointlights (eight lights).
 * Not yet: multilights_repaired (two passes blended by the application). Run by hand:
 * bench_gpu [rounds [effect.fx [technique [pixel|vertex]]]]; bench/gpu_instructions.sh runs it under callgrind for exact
 * instruction counts per frame (a shared machine's frame times vary by 10%). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define HAVE_CALLGRIND 1
#endif
#endif
#ifndef HAVE_CALLGRIND
#define RUNNING_ON_VALGRIND 0
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS_AT(label) (void)(label)
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

#include "bench.h"
#include "files.h"
#include "gl_context.h"
#include "gl_fns.h"
#include "hfx/hfx.h"

enum { BIG = 2048, SMALL = 256, GRID = 1001 };

static test_gl *gl;
static const char *only_shape; /* "pixel" or "vertex" to run that case alone */
static test_gl_fns f;
static PFNGLDRAWELEMENTSPROC draw_elements;

/* ---- the scene: a plane at z = 0 seen from (0, 0, 1.5), 90 degrees, light in front ---- */

typedef struct scene { float world[16], view[16], proj[16], eye[3], light[3], target[3]; } scene;

static void identity(float m[16]) {
    memset(m, 0, 16 * sizeof *m);
    m[0] = m[5] = m[10] = m[15] = 1;
}

/* XNA's conventions: row vectors, row-major, translation in 12..14; right-handed. */
static void look_at(float m[16], const float eye[3]) {
    identity(m);
    m[12] = -eye[0];
    m[13] = -eye[1];
    m[14] = -eye[2];
}

static void perspective(float m[16], float fov, float zn, float zf) {
    float ys = 1.0f / tanf(fov / 2);
    memset(m, 0, 16 * sizeof *m);
    m[0] = ys;
    m[5] = ys;
    m[10] = zf / (zn - zf); /* D3D depth 0..1 */
    m[11] = -1;
    m[14] = zn * zf / (zn - zf);
}

static void mul4(float out[16], const float a[16], const float b[16]) {
    float r[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            float s = 0;
            for (int k = 0; k < 4; k++) s += a[i * 4 + k] * b[k * 4 + j];
            r[i * 4 + j] = s;
        }
    memcpy(out, r, sizeof r);
}

static scene make_scene(void) {
    scene s;
    identity(s.world);
    s.eye[0] = 0, s.eye[1] = 0, s.eye[2] = 1.5f;
    look_at(s.view, s.eye);
    perspective(s.proj, 3.14159265f / 2, 0.1f, 100.0f);
    s.light[0] = 0.4f, s.light[1] = 0.3f, s.light[2] = 1.2f;
    s.target[0] = 0, s.target[1] = 0, s.target[2] = 0;
    return s;
}

/* ---- meshes: position (3), normal (3), uv (2) ---- */

typedef struct mesh { GLuint vbo, ibo; GLsizei count; } mesh;

static mesh make_grid(int n, float half) {
    float *v = malloc((size_t)n * n * 8 * sizeof *v);
    GLuint *idx = malloc((size_t)(n - 1) * (n - 1) * 6 * sizeof *idx);
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            float *p = v + ((size_t)y * n + x) * 8, u = (float)x / (float)(n - 1), t = (float)y / (float)(n - 1);
            p[0] = -half + 2 * half * u, p[1] = half - 2 * half * t, p[2] = 0;
            p[3] = 0, p[4] = 0, p[5] = 1;
            p[6] = u * 8, p[7] = t * 8;
        }
    size_t k = 0;
    for (int y = 0; y + 1 < n; y++)
        for (int x = 0; x + 1 < n; x++) { /* clockwise seen from +z: D3D's front faces */
            GLuint a = (GLuint)(y * n + x), b = a + 1, c = a + (GLuint)n, d = c + 1;
            idx[k++] = a, idx[k++] = b, idx[k++] = c, idx[k++] = b, idx[k++] = d, idx[k++] = c;
        }
    mesh m = {0, 0, (GLsizei)k};
    f.GenBuffers(1, &m.vbo);
    f.BindBuffer(GL_ARRAY_BUFFER, m.vbo);
    f.BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)n * n * 8 * sizeof *v), v, GL_STATIC_DRAW);
    f.GenBuffers(1, &m.ibo);
    f.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.ibo);
    f.BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(k * sizeof *idx), idx, GL_STATIC_DRAW);
    free(v);
    free(idx);
    return m;
}

/* A vertex array over m with position, normal and uv at the given locations (-1: unused). */
static GLuint bind_mesh(const mesh *m, int pos, int normal, int uv) {
    GLuint vao;
    f.GenVertexArrays(1, &vao);
    f.BindVertexArray(vao);
    f.BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    f.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
    const int loc[3] = {pos, normal, uv}, size[3] = {3, 3, 2}, offset[3] = {0, 3, 6};
    for (int i = 0; i < 3; i++) {
        if (loc[i] < 0) continue;
        f.VertexAttribPointer((GLuint)loc[i], size[i], GL_FLOAT, GL_FALSE, 8 * sizeof(float),
                              (void *)(size_t)(offset[i] * sizeof(float)));
        f.EnableVertexAttribArray((GLuint)loc[i]);
    }
    return vao;
}

static GLuint make_texture(GLint wrap) {
    enum { T = 256 };
    unsigned char *px = malloc(T * T * 4);
    for (int y = 0; y < T; y++)
        for (int x = 0; x < T; x++) {
            unsigned char *p = px + (y * T + x) * 4, c = ((x / 32) ^ (y / 32)) & 1 ? 230 : 60;
            p[0] = c, p[1] = (unsigned char)(x * 255 / T), p[2] = (unsigned char)(y * 255 / T), p[3] = 255;
        }
    GLuint t;
    f.GenTextures(1, &t);
    f.BindTexture(GL_TEXTURE_2D, t);
    f.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    f.GenerateMipmap(GL_TEXTURE_2D);
    f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR); /* the seeds' sampler_state */
    f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap); /* the effect's AddressU / AddressV */
    f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
    f.BindTexture(GL_TEXTURE_2D, 0);
    free(px);
    return t;
}

/* ---- the hand-written programs ---- */

static const char hand_vs[] =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\nlayout(location = 1) in vec3 normal;\nlayout(location = 2) in vec2 uv;\n"
    "uniform mat4 mvp, world;\n"
    "out vec3 wp, wn;\nout vec2 tc;\n"
    "void main() {\n"
    "  gl_Position = mvp * vec4(pos, 1.0);\n"
    "  wp = (world * vec4(pos, 1.0)).xyz;\n  wn = (world * vec4(normal, 0.0)).xyz;\n  tc = uv;\n}\n";

static const char hand_ambient_vs[] =
    "#version 330 core\nlayout(location = 0) in vec3 pos;\nuniform mat4 mvp;\n"
    "void main() { gl_Position = mvp * vec4(pos, 1.0); }\n";

static const char hand_ambient_fs[] =
    "#version 330 core\nuniform vec4 ambient;\nout vec4 o;\nvoid main() { o = ambient; }\n";

/* 003's lights (Códigos 7-3 to 7-7): DIRECTIONAL (the direction normalised on the CPU: l = -dir),
 * else a point light, with SPOT's cone (cosines on the CPU); SPECULAR adds Código 7-7's term,
 * ATTEN the distance attenuation; TEXTURED multiplies the texture in. The directional effects
 * add the ambient colour before the specular term, the point and spot ones after attenuating. */
static const char hand_light_fs[] =
    "in vec3 wp, wn;\nin vec2 tc;\n"
    "uniform vec3 light, light_dir, cam, spot_dir, atten;\n"
    "uniform vec4 diffuse, ambient, specular;\n"
    "uniform float ks, shininess, range, cos_inner, cos_outer, falloff;\n"
    "uniform sampler2D tex;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "#ifdef DIRECTIONAL\n"
    "  vec3 l = -light_dir;\n"
    "#else\n"
    "  vec3 l = normalize(light - wp);\n"
    "#endif\n"
    "  float d = max(dot(l, wn), 0.0);\n"
    "  vec4 c = diffuse * d;\n"
    "#ifdef DIRECTIONAL\n"
    "  c += ambient;\n"
    "#endif\n"
    "#ifdef SPECULAR\n"
    "  vec3 r = normalize(2.0 * wn * d - l);\n"
    "  c += ks * pow(max(dot(r, normalize(cam - wp)), 0.0), shininess) * specular * d;\n"
    "#endif\n"
    "#ifdef SPOT\n"
    "  float ca = max(dot(spot_dir, l), 0.0);\n"
    "  if (ca < cos_inner && ca > cos_outer) c *= pow((ca - cos_outer) / (cos_inner - cos_outer), falloff);\n"
    "  else if (ca <= cos_outer) c = vec4(0.0);\n"
    "#endif\n"
    "#ifdef ATTEN\n"
    "  float dist = distance(wp, light);\n"
    "  c *= dist <= range ? min(1.0 / (atten.x + atten.y * dist + atten.z * dist * dist), 1.0) : 0.0;\n"
    "#endif\n"
    "#ifndef DIRECTIONAL\n"
    "  c += ambient;\n"
    "#endif\n"
    "#ifdef TEXTURED\n"
    "  c *= texture(tex, tc);\n"
    "#endif\n"
    "  o = vec4(c.rgb, 1.0);\n"
    "}\n";

/* tutorial0.fx: the texture. fxcomposer_empty.fx: white. */
static const char hand_texture_fs[] =
    "in vec3 wp, wn;\nin vec2 tc;\nuniform sampler2D tex;\nout vec4 o;\nvoid main() { o = texture(tex, tc); }\n";
static const char hand_white_fs[] = "out vec4 o;\nvoid main() { o = vec4(1.0); }\n";

/* phong.fx (000 §6): the light direction and the three colour products on the CPU. */
static const char hand_phong_fs[] =
    "in vec3 wp, wn;\nin vec2 tc;\n"
    "uniform vec3 to_light, cam;\nuniform vec4 ambient_term, diffuse_term, specular_term;\n"
    "uniform float shininess;\nuniform sampler2D tex;\nout vec4 o;\n"
    "void main() {\n"
    "  vec3 n = normalize(wn);\n"
    "  float d = clamp(dot(n, to_light), 0.0, 1.0);\n"
    "  vec3 r = normalize(2.0 * d * n - to_light);\n"
    "  float sp = pow(clamp(dot(r, normalize(cam - wp)), 0.0, 1.0), shininess);\n"
    "  o = ambient_term + diffuse_term * texture(tex, tc) * d + specular_term * sp;\n"
    "}\n";

/* pointlights.fx (001): eight lights in a loop; the ambient term (added once per light, as the
 * tutorial does), the diffuse colours and the inverse radii on the CPU. The arrays hold the
 * effect's MaxLights (50), as a port of the effect would: with 8, Mesa bounds the loop by the
 * arrays (a read past the end is undefined in GLSL) and unrolls it for at most 8 lights, a
 * different shader (measured: 1909 M instructions per pixel-bound frame with 8, 2850 M with 50). */
static const char hand_pointlights_fs[] =
    "in vec3 wp, wn;\nin vec2 tc;\n"
    "uniform int count;\nuniform vec3 lpos[50];\nuniform vec4 lcol[50];\nuniform float inv_radius[50];\n"
    "uniform vec4 ambient_sum, specular_term;\nuniform float shininess;\nuniform vec3 cam;\n"
    "uniform sampler2D tex;\nout vec4 o;\n"
    "void main() {\n"
    "  vec3 n = normalize(wn), v = normalize(cam - wp);\n"
    "  vec4 dc = texture(tex, tc), c = ambient_sum;\n"
    "  for (int i = 0; i < count; i++) {\n"
    "    vec3 l = lpos[i] - wp;\n"
    "    float k = 1.0 - clamp(length(l) * inv_radius[i], 0.0, 1.0);\n"
    "    l = normalize(l);\n"
    "    float d = clamp(dot(n, l), 0.0, 1.0);\n"
    "    vec3 r = normalize(2.0 * d * n - l);\n"
    "    c += k * k * lcol[i] * dc * d + specular_term * pow(clamp(dot(r, v), 0.0, 1.0), shininess);\n"
    "  }\n"
    "  o = c;\n"
    "}\n";

/* ambient_textured.fx: the ambient colour, times the texture in Texturizado. */
static const char hand_ambient_tex_fs[] =
    "in vec3 wp, wn;\nin vec2 tc;\nuniform vec4 ambient;\nuniform sampler2D tex;\nout vec4 o;\n"
    "void main() {\n"
    "#ifdef TEXTURED\n"
    "  o = ambient * texture(tex, tc);\n"
    "#else\n"
    "  o = ambient;\n"
    "#endif\n"
    "}\n";

static GLuint compile(GLenum type, const char *const *parts, int n) {
    GLuint s = f.CreateShader(type);
    f.ShaderSource(s, n, parts, NULL);
    f.CompileShader(s);
    GLint ok = 0;
    f.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        f.GetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "hand-written shader: %s\n", log);
    }
    return s;
}

/* BENCH_GPU_HAND_FS=file replaces the hand-written fragment shader (a whole shader, #version
 * included, over the hand-written uniforms and varyings): to try variants of what hfx emits
 * against the same vertex shader and GL state, one difference at a time. BENCH_GPU_HAND_VS
 * replaces the vertex shader (for a varying's width, say). */
static char *hand_override(const char *var) {
    const char *path = getenv(var);
    char *text = path ? test_read_file(path, NULL) : NULL;
    if (path && !text) fprintf(stderr, "cannot read %s\n", path);
    return text;
}

static GLuint hand_program(const char *vs, const char *fs, const char *defines) {
    char *override = hand_override("BENCH_GPU_HAND_FS"), *vs_override = hand_override("BENCH_GPU_HAND_VS");
    const char *vparts[] = {vs_override ? vs_override : vs}, *whole[] = {override ? override : fs}, *fparts[] = {"#version 330 core\n", defines, fs};
    GLuint v = compile(GL_VERTEX_SHADER, vparts, 1), p = f.CreateProgram();
    /* hand_ambient_fs carries its own #version line */
    GLuint s = fs == hand_ambient_fs || override ? compile(GL_FRAGMENT_SHADER, whole, 1)
                                                 : compile(GL_FRAGMENT_SHADER, fparts, 3);
    free(override);
    free(vs_override);
    f.AttachShader(p, v);
    f.AttachShader(p, s);
    f.LinkProgram(p);
    f.DeleteShader(v);
    f.DeleteShader(s);
    return p;
}

static void u1(GLuint p, const char *n, float v) { f.Uniform1fv(f.GetUniformLocation(p, n), 1, &v); }
static void u3(GLuint p, const char *n, const float *v) { f.Uniform3fv(f.GetUniformLocation(p, n), 1, v); }
static void u4(GLuint p, const char *n, const float *v) { f.Uniform4fv(f.GetUniformLocation(p, n), 1, v); }

/* ---- the cases ---- */

typedef struct material {
    float diffuse[4], ambient[4], specular[4], ks, shininess, c[3], range, inner, outer, falloff;
} material;

typedef struct phong_material {
    float light[4], specular[4], ambient[4], power, specular_intensity, ambient_intensity, diffuse_intensity;
} phong_material;

static const phong_material phong = {{0.9f, 0.8f, 0.7f, 1}, {1, 1, 1, 1}, {0.1f, 0.1f, 0.1f, 1}, 16, 0.5f, 0.5f, 1};

static const material mat = {{0.24f, 0.34f, 0.39f, 1}, {0.07f, 0.07f, 0.07f, 1}, {1, 1, 1, 1}, 0.5f, 16,
                             {1, 0.1f, 0.01f}, 20, 0.3f, 0.6f, 2};

enum { LIGHTS = 8 };

/* Eight lights over the plane, in a ring, each its own colour; radius 2.5. */
static void light_ring(float pos[LIGHTS][3], float col[LIGHTS][4]) {
    for (int i = 0; i < LIGHTS; i++) {
        float a = 6.2831853f * (float)i / LIGHTS;
        pos[i][0] = 0.9f * cosf(a), pos[i][1] = 0.9f * sinf(a), pos[i][2] = 0.4f;
        col[i][0] = 0.5f + 0.5f * cosf(a), col[i][1] = 0.5f + 0.5f * sinf(a), col[i][2] = 0.6f, col[i][3] = 1;
    }
}

static const float light_radius = 2.5f;

static void set_hand_pointlights(GLuint p) {
    float pos[LIGHTS][3], col[LIGHTS][4], inv[LIGHTS], amb[4];
    light_ring(pos, col);
    for (int i = 0; i < LIGHTS; i++) {
        inv[i] = 1.0f / light_radius;
        for (int k = 0; k < 4; k++) col[i][k] *= phong.diffuse_intensity;
    }
    for (int k = 0; k < 4; k++) amb[k] = phong.ambient[k] * phong.ambient_intensity * LIGHTS;
    GLint count = LIGHTS;
    f.Uniform1iv(f.GetUniformLocation(p, "count"), 1, &count);
    f.Uniform3fv(f.GetUniformLocation(p, "lpos"), LIGHTS, pos[0]);
    f.Uniform4fv(f.GetUniformLocation(p, "lcol"), LIGHTS, col[0]);
    f.Uniform1fv(f.GetUniformLocation(p, "inv_radius"), LIGHTS, inv);
    u4(p, "ambient_sum", amb);
}

static void set_effect_pointlights(hfx_effect *fx) {
    hfx_param *b = hfx_effect_param(fx, "activeLights");
    if (!b) return;
    float pos[LIGHTS][3], col[LIGHTS][4], radius[LIGHTS];
    light_ring(pos, col);
    for (int i = 0; i < LIGHTS; i++) {
        radius[i] = light_radius;
        hfx_param_set_floats(hfx_param_element(hfx_effect_param(fx, "LightPosition"), (size_t)i), pos[i], 3);
        hfx_param_set_floats(hfx_param_element(hfx_effect_param(fx, "LightColor"), (size_t)i), col[i], 4);
        hfx_param_set_floats(hfx_param_element(hfx_effect_param(fx, "LightRadius"), (size_t)i), &radius[i], 1);
    }
    hfx_param_set_int(b, LIGHTS);
}

/* The hand-written side folds into its matrix what hfx does per vertex: GL's depth range (a GL
 * projection) and D3D9's pixel centres (x + 1 / w, y - 1 / h in clip space, times w, as
 * hfx_pos_fixup), so both draw the same picture. */
static void hand_mvp(const scene *s, int size, float mvp[16]) {
    float m[16], gl_proj[16], centres[16];
    memcpy(gl_proj, s->proj, sizeof gl_proj);
    gl_proj[10] = (100.0f + 0.1f) / (0.1f - 100.0f);
    gl_proj[14] = 2 * 100.0f * 0.1f / (0.1f - 100.0f);
    identity(centres);
    centres[12] = 1.0f / (float)size;
    centres[13] = -1.0f / (float)size;
    mul4(m, s->world, s->view);
    mul4(m, m, gl_proj);
    mul4(mvp, m, centres);
}

static void set_hand_uniforms(GLuint p, const scene *s, GLuint texture, int size) {
    float mvp[16];
    hand_mvp(s, size, mvp);
    f.UseProgram(p);
    f.UniformMatrix4fv(f.GetUniformLocation(p, "mvp"), 1, GL_FALSE, mvp);
    f.UniformMatrix4fv(f.GetUniformLocation(p, "world"), 1, GL_FALSE, s->world);
    float dir[3] = {s->light[0] - s->target[0], s->light[1] - s->target[1], s->light[2] - s->target[2]};
    float len = sqrtf(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (int i = 0; i < 3; i++) dir[i] /= len;
    u3(p, "light", s->light), u3(p, "cam", s->eye), u3(p, "spot_dir", dir), u3(p, "atten", mat.c);
    float light_dir[3] = {-dir[0], -dir[1], -dir[2]}; /* directional: shining from the light to the target */
    u3(p, "light_dir", light_dir);
    u4(p, "diffuse", mat.diffuse), u4(p, "ambient", mat.ambient), u4(p, "specular", mat.specular);
    u1(p, "ks", mat.ks), u1(p, "shininess", mat.shininess), u1(p, "range", mat.range);
    u1(p, "cos_inner", cosf(mat.inner)), u1(p, "cos_outer", cosf(mat.outer)), u1(p, "falloff", mat.falloff);
    float to_light[3] = {dir[0], dir[1], dir[2]}, terms[3][4];
    for (int i = 0; i < 4; i++) {
        terms[0][i] = phong.ambient[i] * phong.ambient_intensity;
        terms[1][i] = phong.light[i] * phong.diffuse_intensity;
        terms[2][i] = phong.specular[i] * phong.specular_intensity;
    }
    u3(p, "to_light", to_light), u4(p, "ambient_term", terms[0]), u4(p, "diffuse_term", terms[1]);
    u4(p, "specular_term", terms[2]), u1(p, "shininess", phong.power);
    set_hand_pointlights(p);
    f.Uniform1i(f.GetUniformLocation(p, "tex"), 0);
    f.ActiveTexture(GL_TEXTURE0);
    f.BindTexture(GL_TEXTURE_2D, texture);
}

static void set_param(hfx_effect *fx, const char *name, const float *v, size_t n) {
    hfx_param *p = hfx_effect_param(fx, name);
    if (p) hfx_param_set_floats(p, v, n);
}

static void set_effect_params(hfx_effect *fx, const scene *s, GLuint texture) {
    hfx_param_set_matrix(hfx_effect_param(fx, "world"), s->world);
    hfx_param_set_matrix(hfx_effect_param(fx, "view"), s->view);
    hfx_param_set_matrix(hfx_effect_param(fx, "projection"), s->proj);
    set_param(fx, "posicionLuz", s->light, 3), set_param(fx, "blancoLuz", s->target, 3);
    float dir[3] = {s->target[0] - s->light[0], s->target[1] - s->light[1], s->target[2] - s->light[2]};
    set_param(fx, "direccionLuz", dir, 3); /* the shader normalises it */
    set_param(fx, "posicionCamara", s->eye, 3);
    set_param(fx, "colorMaterialDifuso", mat.diffuse, 4), set_param(fx, "colorMaterialAmbiental", mat.ambient, 4);
    set_param(fx, "colorMaterialEspecular", mat.specular, 4);
    set_param(fx, "ks", &mat.ks, 1), set_param(fx, "n", &mat.shininess, 1), set_param(fx, "rango", &mat.range, 1);
    set_param(fx, "c1", &mat.c[0], 1), set_param(fx, "c2", &mat.c[1], 1), set_param(fx, "c3", &mat.c[2], 1);
    set_param(fx, "anguloInterno", &mat.inner, 1), set_param(fx, "anguloExterno", &mat.outer, 1);
    set_param(fx, "falloff", &mat.falloff, 1);
    hfx_param *b;
    const char *const upper[3] = {"World", "View", "Projection"};
    const float *mats[3] = {s->world, s->view, s->proj};
    for (int i = 0; i < 3; i++)
        if ((b = hfx_effect_param(fx, upper[i]))) hfx_param_set_matrix(b, mats[i]);
    if ((b = hfx_effect_param(fx, "WorldViewProj"))) {
        float wvp[16];
        mul4(wvp, s->world, s->view);
        mul4(wvp, wvp, s->proj);
        hfx_param_set_matrix(b, wvp);
    }
    set_param(fx, "LightDirection", dir, 3), set_param(fx, "camPosition", s->eye, 3);
    set_param(fx, "LightColor", phong.light, 4), set_param(fx, "SpecularColor", phong.specular, 4);
    set_param(fx, "AmbientColor", phong.ambient, 4), set_param(fx, "SpecularPower", &phong.power, 1);
    set_param(fx, "SpecularIntensity", &phong.specular_intensity, 1);
    set_param(fx, "AmbientIntensity", &phong.ambient_intensity, 1);
    set_param(fx, "DiffuseIntensity", &phong.diffuse_intensity, 1);
    if ((b = hfx_effect_param(fx, "diffuseTexture"))) hfx_param_set_texture(b, texture);
    if ((b = hfx_effect_param(fx, "DiffuseTexture"))) hfx_param_set_texture(b, texture);
    if ((b = hfx_effect_param(fx, "modIluEsp"))) hfx_param_set_bool(b, 1);
    set_effect_pointlights(fx);
    if ((b = hfx_effect_param(fx, "atenuado"))) hfx_param_set_bool(b, 1);
    if ((b = hfx_effect_param(fx, "texturaModelo"))) hfx_param_set_texture(b, texture);
}

typedef struct bench_case { const char *file, *technique, *fs_defines; const char *fs; int clamp; } bench_case;

#define TEX "#define TEXTURED\n"
#define PT "#define ATTEN\n"
#define SP "#define SPOT\n#define ATTEN\n"
#define DIR "#define DIRECTIONAL\n"
#define SPEC "#define SPECULAR\n"
static const bench_case cases[] = {
    {"ambient.fx", "ModeloAmbiental", "", hand_ambient_fs, 0},
    {"ambient_textured.fx", "Material", "", hand_ambient_tex_fs, 0},
    {"ambient_textured.fx", "Texturizado", TEX, hand_ambient_tex_fs, 0},
    {"directional.fx", "Material", DIR, hand_light_fs, 0},
    {"directional.fx", "Texturizado", DIR TEX, hand_light_fs, 0},
    {"directional_specular.fx", "Material", DIR SPEC, hand_light_fs, 0},
    {"directional_specular.fx", "Texturizado", DIR SPEC TEX, hand_light_fs, 0},
    {"point.fx", "Material", PT, hand_light_fs, 0},
    {"point.fx", "Texturizado", PT TEX, hand_light_fs, 0},
    {"point_specular.fx", "Material", PT SPEC, hand_light_fs, 0},
    {"point_specular.fx", "Texturizado", PT SPEC TEX, hand_light_fs, 0},
    {"spot.fx", "Material", SP, hand_light_fs, 0},
    {"spot.fx", "Texturizado", SP TEX, hand_light_fs, 0},
    {"spot_specular.fx", "Material", SP SPEC, hand_light_fs, 0},
    {"spot_specular.fx", "Texturizado", SP SPEC TEX, hand_light_fs, 0},
    {"tutorial0.fx", "Tut0", "", hand_texture_fs, 1},
    {"fxcomposer_empty.fx", "technique0", "", hand_white_fs, 0},
    {"phong.fx", "Phong", "", hand_phong_fs, 1},
    {"pointlights.fx", "PointLights", "", hand_pointlights_fs, 1},
};
enum { CASES = sizeof cases / sizeof *cases };

typedef struct side { hfx_effect *fx; hfx_pass *pass; GLuint program, vao; } side;

/* Seconds for `frames` frames of one side, after glFinish on both ends. */
static double frame_time(hfx_device *dev, side *sd, const mesh *m, int frames) {
    f.Finish();
    double t0 = now();
    for (int i = 0; i < frames; i++) {
        f.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if (sd->fx) {
            hfx_effect_begin(sd->fx);
            hfx_pass_apply(sd->pass);
        } else {
            f.UseProgram(sd->program);
        }
        f.BindVertexArray(sd->vao);
        draw_elements(GL_TRIANGLES, m->count, GL_UNSIGNED_INT, NULL);
        if (sd->fx) hfx_effect_end(sd->fx);
    }
    f.Finish();
    (void)dev;
    return (now() - t0) / frames;
}

/* Largest channel difference between the two sides' pictures of the current viewport. */
static int picture_difference(hfx_device *dev, side *a, side *b, const mesh *m, int w, int h) {
    unsigned char *pa = malloc((size_t)w * h * 4), *pb = malloc((size_t)w * h * 4);
    frame_time(dev, a, m, 1);
    f.ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pa);
    if (getenv("BENCH_GPU_PNG")) test_gl_write_png(gl, "/tmp/bench_gpu_hfx.png");
    frame_time(dev, b, m, 1);
    f.ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pb);
    if (getenv("BENCH_GPU_PNG")) test_gl_write_png(gl, "/tmp/bench_gpu_hand.png");
    int worst = 0;
    for (size_t i = 0; i < (size_t)w * h * 4; i++) {
        int d = abs(pa[i] - pb[i]);
        if (d > worst) worst = d;
    }
    free(pa);
    free(pb);
    return worst;
}

/* One effect's side: loaded with or without preshaders, its parameters set. */
static side effect_side(hfx_device *dev, const bench_case *c, const char *path, int preshaders, const scene *s,
                        GLuint texture) {
    hfx_load_options opt = {0};
    opt.no_preshaders = !preshaders;
    char *errors = NULL;
    side sd = {hfx_effect_load(dev, path, &opt, &errors), NULL, 0, 0};
    if (!sd.fx) printf("%-18s %-15s did not load: %s\n", c->file, c->technique, errors ? errors : "");
    hfx_free(errors);
    if (!sd.fx) return sd;
    set_effect_params(sd.fx, s, texture);
    sd.pass = hfx_technique_pass(hfx_effect_technique(sd.fx, c->technique), 0);
    return sd;
}

static GLuint effect_vao(const side *sd, const mesh *m) {
    return bind_mesh(m, hfx_pass_attribute_location(sd->pass, "POSITION"), hfx_pass_attribute_location(sd->pass, "NORMAL"),
                     hfx_pass_attribute_location(sd->pass, "TEXCOORD0"));
}

/* Best frame time of each side, the sides taking turns. */
static void best_times(hfx_device *dev, side *const *sides, int n, const mesh *m, int rounds, double *best) {
    for (int k = 0; k < n; k++) best[k] = 1e9;
    for (int i = 0; i < rounds; i++)
        for (int k = 0; k < n; k++) {
            double t = frame_time(dev, sides[k], m, 2);
            if (t < best[k]) best[k] = t;
        }
}

/* Under callgrind, times mean nothing but instructions are exact whatever else the machine runs:
 * each side draws one frame to warm up (llvmpipe compiles its shader variants on first use), then
 * one frame between a reset and a dump labelled "effect|technique|case|side", which
 * bench/gpu_instructions.sh turns into a table of ratios. */
static void count_instructions(hfx_device *dev, side *const *sides, int n, const mesh *m, const char *label) {
    static const char *const names[3] = {"hfx", "nopre", "hand"};
    for (int k = 0; k < n; k++) {
        char dump[256];
        snprintf(dump, sizeof dump, "%s|%s", label, names[k]);
        frame_time(dev, sides[k], m, 2); /* twice: one-time work (variants, caches, threads) out of the count */
        CALLGRIND_START_INSTRUMENTATION; /* gpu_instructions.sh starts callgrind with it off: 5x faster */
        CALLGRIND_ZERO_STATS;
        frame_time(dev, sides[k], m, 1);
        CALLGRIND_DUMP_STATS_AT(dump);
        CALLGRIND_STOP_INSTRUMENTATION;
    }
}

static void run_case(hfx_device *dev, const bench_case *c, const mesh *quad, const mesh *grid, const GLuint textures[2],
                     int rounds) {
    GLuint texture = textures[c->clamp];
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", HFX_SEED_DIR, c->file);
    scene s = make_scene();
    side h = effect_side(dev, c, path, 1, &s, texture), h0 = effect_side(dev, c, path, 0, &s, texture);
    if (!h.fx || !h0.fx) { hfx_effect_destroy(h.fx); hfx_effect_destroy(h0.fx); return; }
    int ambient = c->fs == hand_ambient_fs;
    side r = {NULL, NULL, hand_program(ambient ? hand_ambient_vs : hand_vs, c->fs, c->fs_defines), 0};
    const struct { const char *name; const mesh *m; int size; } shapes[2] = {{"pixel", quad, BIG}, {"vertex", grid, SMALL}};
    for (int k = 0; k < 2; k++) {
        if (only_shape && strcmp(only_shape, shapes[k].name) != 0) continue;
        const mesh *m = shapes[k].m;
        h.vao = effect_vao(&h, m);
        h0.vao = effect_vao(&h0, m);
        r.vao = bind_mesh(m, 0, ambient ? -1 : 1, ambient ? -1 : 2);
        hfx_device_set_viewport(dev, 0, 0, shapes[k].size, shapes[k].size);
        set_hand_uniforms(r.program, &s, texture, shapes[k].size);
        int diff = picture_difference(dev, &h, &r, m, shapes[k].size, shapes[k].size);
        side *sides[3] = {&h, &h0, &r};
        double best[3];
        if (RUNNING_ON_VALGRIND) {
            char label[128];
            snprintf(label, sizeof label, "%s|%s|%s", c->file, c->technique, shapes[k].name);
            count_instructions(dev, sides, 3, m, label);
            best[0] = best[1] = best[2] = NAN; /* times under valgrind mean nothing */
        } else {
            best_times(dev, sides, 3, m, rounds, best);
        }
        printf("%-18s %-15s %-6s %9.2f %9.2f %9.2f %7.2fx %7.2fx %5d/255\n", c->file, c->technique, shapes[k].name,
               best[0] * 1e3, best[1] * 1e3, best[2] * 1e3, best[0] / best[2], best[1] / best[2], diff);
        f.DeleteVertexArrays(1, &h.vao);
        f.DeleteVertexArrays(1, &h0.vao);
        f.DeleteVertexArrays(1, &r.vao);
    }
    f.DeleteProgram(r.program);
    hfx_effect_destroy(h.fx);
    hfx_effect_destroy(h0.fx);
}

int main(int argc, char **argv) {
    int rounds = argc > 1 ? atoi(argv[1]) : 5;
    const char *only = argc > 2 ? argv[2] : NULL; /* an effect file name to run alone */
    const char *only_technique = argc > 3 ? argv[3] : NULL;
    only_shape = argc > 4 ? argv[4] : NULL;
    if (!test_seed_dir()) { fprintf(stderr, "the seed effects (../shared/seed-fx) are absent\n"); return 1; }
    gl = test_gl_create(BIG, BIG);
    if (!gl) { fprintf(stderr, "no OSMesa context\n"); return 1; }
    test_gl_fns_load(&f);
    draw_elements = (PFNGLDRAWELEMENTSPROC)test_gl_proc("glDrawElements");
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    mesh quad = make_grid(2, 2.0f), grid = make_grid(GRID, 2.0f);
    GLuint textures[2] = {make_texture(GL_REPEAT), make_texture(GL_CLAMP_TO_EDGE)};
    f.ClearColor(0, 0, 0, 1);
    printf("llvmpipe, ms per frame, best of %d; hfx with preshaders, without, hand-written; ratios to hand-written;\n"
           "diff = largest channel difference of hfx (with) against hand-written\n", rounds);
    printf("%-18s %-15s %-6s %9s %9s %9s %8s %8s %9s\n", "effect", "technique", "case", "hfx", "hfx-nopre", "hand", "ratio",
           "nopre", "diff");
    for (int i = 0; i < CASES; i++)
        if ((!only || strcmp(only, cases[i].file) == 0) && (!only_technique || strcmp(only_technique, cases[i].technique) == 0))
            run_case(dev, &cases[i], &quad, &grid, textures, rounds);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return 0;
}
