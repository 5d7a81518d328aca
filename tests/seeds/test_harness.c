/* The seed harness checked against itself, without hfx: the XNA matrices against values worked
 * out by hand, and the probes (pixel -> world position, normal, texcoord; the reference
 * bilinear sampler) against what GL rasterizes with a hand-written GLSL program that encodes
 * those values as colours. If this fails, no seed probe can be trusted. */
#include <GL/glcorearb.h>

#include "scene.h"
#include "stripes.h"

static seed_scene *S;

typedef struct glsl_fns {
    PFNGLCREATESHADERPROC CreateShader;
    PFNGLSHADERSOURCEPROC ShaderSource;
    PFNGLCOMPILESHADERPROC CompileShader;
    PFNGLGETSHADERIVPROC GetShaderiv;
    PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog;
    PFNGLCREATEPROGRAMPROC CreateProgram;
    PFNGLATTACHSHADERPROC AttachShader;
    PFNGLBINDATTRIBLOCATIONPROC BindAttribLocation;
    PFNGLLINKPROGRAMPROC LinkProgram;
    PFNGLGETPROGRAMIVPROC GetProgramiv;
    PFNGLUSEPROGRAMPROC UseProgram;
    PFNGLDELETESHADERPROC DeleteShader;
    PFNGLDELETEPROGRAMPROC DeleteProgram;
    PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation;
    PFNGLUNIFORMMATRIX4FVPROC UniformMatrix4fv;
    PFNGLUNIFORM1IPROC Uniform1i;
    PFNGLUNIFORM1FPROC Uniform1f;
    PFNGLUNIFORM2FPROC Uniform2f;
    PFNGLBINDVERTEXARRAYPROC BindVertexArray;
    PFNGLBINDBUFFERPROC BindBuffer;
    PFNGLVERTEXATTRIBPOINTERPROC VertexAttribPointer;
    PFNGLENABLEVERTEXATTRIBARRAYPROC EnableVertexAttribArray;
    PFNGLDRAWARRAYSPROC DrawArrays;
    PFNGLACTIVETEXTUREPROC ActiveTexture;
    PFNGLBINDTEXTUREPROC BindTexture;
    PFNGLTEXPARAMETERIPROC TexParameteri;
} glsl_fns;

static glsl_fns G;

#define LOADG(field, name) do { union { void *p; __typeof__(G.field) fn; } u_; \
    u_.p = seed_gl(S, name); G.field = u_.fn; ok &= u_.p != NULL; } while (0)

static int load_glsl_fns(void) {
    int ok = 1;
    LOADG(CreateShader, "glCreateShader");
    LOADG(ShaderSource, "glShaderSource");
    LOADG(CompileShader, "glCompileShader");
    LOADG(GetShaderiv, "glGetShaderiv");
    LOADG(GetShaderInfoLog, "glGetShaderInfoLog");
    LOADG(CreateProgram, "glCreateProgram");
    LOADG(AttachShader, "glAttachShader");
    LOADG(BindAttribLocation, "glBindAttribLocation");
    LOADG(LinkProgram, "glLinkProgram");
    LOADG(GetProgramiv, "glGetProgramiv");
    LOADG(UseProgram, "glUseProgram");
    LOADG(DeleteShader, "glDeleteShader");
    LOADG(DeleteProgram, "glDeleteProgram");
    LOADG(GetUniformLocation, "glGetUniformLocation");
    LOADG(UniformMatrix4fv, "glUniformMatrix4fv");
    LOADG(Uniform1i, "glUniform1i");
    LOADG(Uniform1f, "glUniform1f");
    LOADG(Uniform2f, "glUniform2f");
    LOADG(BindVertexArray, "glBindVertexArray");
    LOADG(BindBuffer, "glBindBuffer");
    LOADG(VertexAttribPointer, "glVertexAttribPointer");
    LOADG(EnableVertexAttribArray, "glEnableVertexAttribArray");
    LOADG(DrawArrays, "glDrawArrays");
    LOADG(ActiveTexture, "glActiveTexture");
    LOADG(BindTexture, "glBindTexture");
    LOADG(TexParameteri, "glTexParameteri");
    return ok;
}

/* Row vectors times XNA matrices: uploading the row-major array untransposed makes GLSL's
 * column-major M equal to the transpose, so M * v computes v * XNA. The projection is
 * Direct3D's (z' = 2z - w moves depth 0..1 to GL's -1..1) and, when asked, content moves by
 * half a pixel so pixel centres land where Direct3D 9 puts them. */
static const char *VS =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "layout(location = 1) in vec3 nrm;\n"
    "layout(location = 2) in vec2 uv;\n"
    "uniform mat4 world, viewproj;\n"
    "uniform vec2 halfpixel;\n"
    "out vec3 wpos; out vec3 wnrm; out vec2 tc;\n"
    "void main() {\n"
    "  vec4 w = world * vec4(pos, 1.0);\n"
    "  wpos = w.xyz; wnrm = (world * vec4(nrm, 0.0)).xyz; tc = uv;\n"
    "  gl_Position = viewproj * w;\n"
    "  gl_Position.z = 2.0 * gl_Position.z - gl_Position.w;\n"
    "  gl_Position.xy += halfpixel * gl_Position.w;\n"
    "}\n";

/* mode 0: world position mapped from [-2,2] to [0,1]; 1: normal * 0.5 + 0.5; 2: texcoord; 3: texture. */
static const char *FS =
    "#version 330 core\n"
    "in vec3 wpos; in vec3 wnrm; in vec2 tc;\n"
    "uniform int mode; uniform sampler2D tex;\n"
    "out vec4 colour;\n"
    "void main() {\n"
    "  if (mode == 0) colour = vec4((wpos + 2.0) / 4.0, 1.0);\n"
    "  else if (mode == 1) colour = vec4(wnrm * 0.5 + 0.5, 1.0);\n"
    "  else if (mode == 2) colour = vec4(tc, 0.0, 1.0);\n"
    "  else colour = texture(tex, tc);\n"
    "}\n";

static unsigned compile(GLenum stage, const char *src) {
    unsigned sh = G.CreateShader(stage);
    G.ShaderSource(sh, 1, &src, NULL);
    G.CompileShader(sh);
    int ok = 0;
    G.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        G.GetShaderInfoLog(sh, sizeof log, NULL, log);
        fprintf(stderr, "shader: %s\n", log);
    }
    return sh;
}

static unsigned make_program(void) {
    unsigned vs = compile(GL_VERTEX_SHADER, VS), fs = compile(GL_FRAGMENT_SHADER, FS);
    unsigned p = G.CreateProgram();
    G.AttachShader(p, vs);
    G.AttachShader(p, fs);
    G.LinkProgram(p);
    G.DeleteShader(vs);
    G.DeleteShader(fs);
    int ok = 0;
    G.GetProgramiv(p, GL_LINK_STATUS, &ok);
    return ok ? p : 0;
}

static void draw_own(unsigned prog, const seed_mesh *m, const float world[16], int mode, int d3d9) {
    float vp[16];
    xm_mul(vp, seed_view(S), seed_projection(S));
    G.UseProgram(prog);
    G.UniformMatrix4fv(G.GetUniformLocation(prog, "world"), 1, GL_FALSE, world);
    G.UniformMatrix4fv(G.GetUniformLocation(prog, "viewproj"), 1, GL_FALSE, vp);
    G.Uniform1i(G.GetUniformLocation(prog, "mode"), mode);
    G.Uniform1i(G.GetUniformLocation(prog, "tex"), 0);
    G.Uniform2f(G.GetUniformLocation(prog, "halfpixel"), d3d9 ? 1.0f / seed_width(S) : 0.0f,
                d3d9 ? -1.0f / seed_height(S) : 0.0f);
    G.BindVertexArray(m->vao);
    G.BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    G.EnableVertexAttribArray(0);
    G.EnableVertexAttribArray(1);
    G.EnableVertexAttribArray(2);
    G.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(seed_vertex), (const void *)offsetof(seed_vertex, pos));
    G.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(seed_vertex), (const void *)offsetof(seed_vertex, normal));
    G.VertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(seed_vertex), (const void *)offsetof(seed_vertex, uv));
    G.DrawArrays(GL_TRIANGLES, 0, m->count);
    G.BindVertexArray(0);
    G.UseProgram(0);
}

static void matrices_match_xna(void) {
    float m[16];
    /* CreateLookAt((0,10,0), 0, -Z): right = +x, up = -z, forward = -y. */
    xm_look_at(m, v3_make(0, 10, 0), v3_make(0, 0, 0), v3_make(0, 0, -1));
    const float look[16] = {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, -10, 1};
    for (int i = 0; i < 16; i++) CHECK_NEAR(m[i], look[i], 1e-6);
    /* CreatePerspectiveFieldOfView(pi/2, 1, 1, 100): 1/tan(pi/4) = 1, 100/(1-100), 1*100/(1-100). */
    xm_perspective_fov(m, SEED_PI / 2, 1, 1, 100);
    const float persp[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -100.0f / 99, -1, 0, 0, -100.0f / 99, 0};
    for (int i = 0; i < 16; i++) CHECK_NEAR(m[i], persp[i], 1e-6);
    /* Depth 0 at the near plane, 1 at the far plane. */
    double w;
    v3 c = xm_point_w(m, v3_make(0, 0, -1), &w);
    CHECK_NEAR(c.z / w, 0, 1e-6);
    c = xm_point_w(m, v3_make(0, 0, -100), &w);
    CHECK_NEAR(c.z / w, 1, 1e-6);
    /* CreateOrthographic(4, 4, 1, 20) after the top camera: (1, 0, -2) is at x 0.5, y 1, depth 9/19. */
    float view[16], proj[16], vp[16];
    xm_look_at(view, v3_make(0, 10, 0), v3_make(0, 0, 0), v3_make(0, 0, -1));
    xm_orthographic(proj, 4, 4, 1, 20);
    xm_mul(vp, view, proj);
    c = xm_point_w(vp, v3_make(1, 0, -2), &w);
    CHECK_NEAR(c.x / w, 0.5, 1e-6);
    CHECK_NEAR(c.y / w, 1, 1e-6);
    CHECK_NEAR(c.z / w, 9.0 / 19, 1e-6);
    /* RotationY(pi/2) turns +x into -z (right-handed), translation sits in 12..14. */
    xm_rotation_y(m, SEED_PI / 2);
    v3 r = xm_direction(m, v3_make(1, 0, 0));
    CHECK_NEAR(r.x, 0, 1e-6);
    CHECK_NEAR(r.z, -1, 1e-6);
    xm_translation(m, 3, 4, 5);
    r = xm_point(m, v3_make(1, 1, 1));
    CHECK_NEAR(r.x, 4, 1e-6);
    CHECK_NEAR(r.y, 5, 1e-6);
    CHECK_NEAR(r.z, 6, 1e-6);
}

static rgba encode_pos(const seed_surface *s, const void *u) {
    (void)u;
    return rgba_make((s->pos.x + 2) / 4, (s->pos.y + 2) / 4, (s->pos.z + 2) / 4, 1);
}

static rgba encode_normal(const seed_surface *s, const void *u) {
    (void)u;
    return rgba_make(s->normal.x * 0.5 + 0.5, s->normal.y * 0.5 + 0.5, s->normal.z * 0.5 + 0.5, 1);
}

static rgba encode_uv(const seed_surface *s, const void *u) {
    (void)u;
    return rgba_make(s->u, s->v, 0, 1);
}

static void probe_grid(const char *label, const seed_object *obj, seed_shade_fn fn, int step) {
    double worst = 0;
    int misses = 0, n = 0;
    for (int y = step / 2; y < seed_height(S); y += step)
        for (int x = step / 2; x < seed_width(S); x += step) {
            seed_surface surf;
            if (seed_pick(S, obj, 1, x, y, &surf) < 0) continue;
            rgba e = fn(&surf, NULL), g = seed_pixel(S, x, y);
            double d = 255 * maxd(maxd(fabs(e.r - g.r), fabs(e.g - g.g)), fabs(e.b - g.b));
            if (d > 1.01) misses++;
            worst = maxd(worst, d);
            n++;
        }
    printf("  %s: %d probes, worst %.2f/255\n", label, n, worst);
    CHECK(n > 0);
    CHECK_INT(misses, 0);
}

/* Every pixel of a floor under the top camera: the probe's world position and texcoord are
 * what the rasterizer interpolated, under both pixel-centre conventions. */
static void probes_find_what_gl_rasterizes(void) {
    unsigned prog = make_program();
    CHECK(prog != 0);
    if (!prog) return;
    seed_mesh *floor = seed_mesh_floor(S, 2);
    float world[16];
    xm_identity(world);
    seed_object obj = seed_object_at(floor, world);
    for (int d3d9 = 0; d3d9 <= 1; d3d9++) {
        seed_use_d3d9_pixel_centres(S, d3d9);
        seed_camera_top(S, 2);
        seed_clear(S, rgba_make(0, 0, 0, 0));
        draw_own(prog, floor, world, 0, d3d9);
        probe_grid(d3d9 ? "floor position, d3d9 centres" : "floor position, gl centres", &obj, encode_pos, 3);
        seed_clear(S, rgba_make(0, 0, 0, 0));
        draw_own(prog, floor, world, 2, d3d9);
        probe_grid(d3d9 ? "floor uv, d3d9 centres" : "floor uv, gl centres", &obj, encode_uv, 3);
    }
    /* A sphere in perspective: interpolated (unnormalised) normals and positions. */
    seed_mesh *sphere = seed_mesh_sphere(S, 1.5, 16, 12);
    float view[16], proj[16];
    xm_look_at(view, v3_make(0.5, 1.0, 5), v3_make(0, 0, 0), v3_make(0, 1, 0));
    xm_perspective_fov(proj, SEED_PI / 4, 1, 1, 50);
    seed_camera(S, view, proj);
    xm_rotation_y(world, 0.3);
    obj = seed_object_at(sphere, world);
    seed_use_d3d9_pixel_centres(S, 1);
    seed_clear(S, rgba_make(0, 0, 0, 0));
    draw_own(prog, sphere, world, 1, 1);
    probe_grid("sphere normal, d3d9 centres", &obj, encode_normal, 2);
    seed_clear(S, rgba_make(0, 0, 0, 0));
    draw_own(prog, sphere, world, 0, 1);
    probe_grid("sphere position, d3d9 centres", &obj, encode_pos, 2);
    seed_mesh_free(S, sphere);
    seed_mesh_free(S, floor);
    G.DeleteProgram(prog);
    CHECK_SCENE(S);
}

/* The reference bilinear sampler against GL_LINEAR with CLAMP_TO_EDGE and REPEAT. */
static void reference_sampler_matches_gl(void) {
    unsigned prog = make_program();
    CHECK(prog != 0);
    if (!prog) return;
    unsigned char texels[4 * 4 * 4];
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            unsigned char *p = texels + (y * 4 + x) * 4;
            p[0] = (unsigned char)(x * 80);
            p[1] = (unsigned char)(y * 80);
            p[2] = (unsigned char)(255 - 30 * (x + y));
            p[3] = (unsigned char)(255 - 20 * x);
        }
    seed_texture tex = seed_texture_make(S, 4, 4, texels);
    seed_mesh *quad = seed_mesh_quad(S, v3_make(-2, 0, -2), v3_make(4, 0, 0), v3_make(0, 0, 4), v3_make(0, 1, 0),
                                     -0.5, -0.5, 1.5, 1.5);
    seed_object obj = seed_object_at(quad, NULL);
    seed_use_d3d9_pixel_centres(S, 0);
    seed_camera_top(S, 2);
    for (int wrap = 0; wrap <= 1; wrap++) {
        G.ActiveTexture(GL_TEXTURE0);
        G.BindTexture(GL_TEXTURE_2D, tex.gl);
        G.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        G.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        G.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap ? GL_REPEAT : GL_CLAMP_TO_EDGE);
        G.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap ? GL_REPEAT : GL_CLAMP_TO_EDGE);
        seed_clear(S, rgba_make(0, 0, 0, 0));
        draw_own(prog, quad, obj.world, 3, 0);
        double worst = 0;
        for (int y = 1; y < seed_height(S); y += 3)
            for (int x = 1; x < seed_width(S); x += 3) {
                seed_surface surf;
                if (seed_pick(S, &obj, 1, x, y, &surf) < 0) continue;
                rgba e = seed_texture_sample(&tex, surf.u, surf.v, wrap ? SEED_WRAP : SEED_CLAMP);
                rgba g = seed_pixel(S, x, y);
                double d = 255 * maxd(maxd(fabs(e.r - g.r), fabs(e.g - g.g)), maxd(fabs(e.b - g.b), fabs(e.a - g.a)));
                worst = maxd(worst, d);
            }
        printf("  bilinear %s: worst %.2f/255\n", wrap ? "wrap" : "clamp", worst);
        CHECK(worst <= 1.5);
    }
    G.BindTexture(GL_TEXTURE_2D, 0);
    seed_use_d3d9_pixel_centres(S, 1);
    seed_texture_free(S, &tex);
    seed_mesh_free(S, quad);
    G.DeleteProgram(prog);
    CHECK_SCENE(S);
}

/* tutorial0's pixel-centre expectation, met by a renderer that does move content by half a
 * pixel the Direct3D 9 way (this file's shader): pixel x shows the mean of texels x - 1 and x. */
static void half_pixel_emulation_blurs_as_d3d9(void) {
    unsigned prog = make_program();
    CHECK(prog != 0);
    if (!prog) return;
    static unsigned char texels[96 * 96 * 4];
    seed_period3_texels(texels, 96);
    seed_texture tex = seed_texture_make(S, 96, 96, texels);
    seed_mesh *floor = seed_mesh_floor(S, 2);
    float world[16];
    xm_identity(world);
    seed_camera_top(S, 2);
    G.ActiveTexture(GL_TEXTURE0);
    G.BindTexture(GL_TEXTURE_2D, tex.gl);
    G.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    G.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    G.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    G.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    seed_clear(S, rgba_make(0, 0, 0, 0));
    draw_own(prog, floor, world, 3, 1);
    int wrong = 0;
    for (int y = 1; y < 96; y++)
        for (int x = 1; x < 96; x++) {
            rgba g = seed_pixel(S, x, y);
            double r = (seed_period3(x - 1) + seed_period3(x)) / 2, gg = (seed_period3(y - 1) + seed_period3(y)) / 2;
            if (fabs(g.r * 255 - r) > 1 || fabs(g.g * 255 - gg) > 1) wrong++;
        }
    CHECK_INT(wrong, 0);
    G.BindTexture(GL_TEXTURE_2D, 0);
    seed_texture_free(S, &tex);
    seed_mesh_free(S, floor);
    G.DeleteProgram(prog);
    CHECK_SCENE(S);
}

int main(void) {
    RUN(matrices_match_xna);
    S = seed_scene_create(96, 96);
    if (!S || !load_glsl_fns()) {
        fprintf(stderr, "no OSMesa GL 3.3 context\n");
        return 1;
    }
    RUN(probes_find_what_gl_rasterizes);
    RUN(reference_sampler_matches_gl);
    RUN(half_pixel_emulation_blurs_as_d3d9);
    seed_scene_destroy(S);
    return test_summary();
}
