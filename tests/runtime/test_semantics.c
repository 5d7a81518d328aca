/* test_semantics.c: HLSL's meaning, one row a case. Each row of tests/runtime/semantics/ (one .tbl file a topic)
 * is a small pixel shader (an expression, or a block that writes R) and the float4 Direct3D
 * gives for it, derived by hand from Microsoft's documentation (the table says how where it is
 * not obvious). The row is compiled twice: once with the inputs A, B, I, M as parameters set
 * through the runtime (the GPU computes), once with the same values as static consts (the
 * compiler may fold), a third time in the vertex shader (rows that only a pixel shader can
 * run excepted), and a fourth with the parameters again but preshaders on (work on parameters
 * alone runs on the CPU through common/eval_code; the first run keeps it on the GPU): all must
 * give the documented value. Rows that expect an error name the
 * fxc code that the compile must report. The format is described in semantics/README. */
#include <GL/glcorearb.h>
#include <dirent.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "gl_context.h"
#include "hfx/hfxc.h"
#include "rt_support.h"
#include "test.h"

enum { MAX_EXPECT = 4 };

typedef struct row {
    const char *file;
    int line;
    char *globals, *body;              /* body: an expression, or a { block } writing R */
    char error[16];                    /* "X3013" when the row must not compile */
    int count;                         /* expected components, 1..4 */
    double expect[MAX_EXPECT];         /* NAN: the component must be a NaN */
    double tol;
    int modes;                         /* MODE_UNIFORM | MODE_CONST | MODE_VERTEX */
} row;

/* MODE_VERTEX: the row in the vertex shader (parameters), its R passed on flat to the pixel shader.
 * MODE_UNIFORM runs without preshaders (the GPU computes); MODE_PRESHADER with them. */
enum { MODE_UNIFORM = 1, MODE_CONST = 2, MODE_VERTEX = 4, MODE_PRESHADER = 8, MODE_FX2 = 16 };
/* MODE_FX2: the parameters' source compiled as `hfxc /T fx_2_0` does (D3D9 bytecode), written as
 * fx_2_0, loaded back through fx_2_0's reader (bytecode -> IR -> GLSL) and drawn: the round trip. */

static int count_of(const char *s, const char *word) {
    int n = 0;
    for (const char *at = strstr(s, word); at; at = strstr(at + 1, word)) n++;
    return n;
}

/* What only a pixel shader has: rows naming these do not run in the vertex shader. Sampling
 * with an explicit level (tex2Dlod...) is vertex texture fetch, which vs_3_0 has. */
static bool pixel_only(const char *body) {
    static const char *const words[] = {"ddx", "ddy", "fwidth", "clip", "discard"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (strstr(body, words[i])) return true;
    return count_of(body, "tex") != count_of(body, "lod(");
}

typedef struct runner {
    test_gl *gl;
    tgl g;
    hfx_device *dev;
    GLuint fbo, target, quad, quad_buffer;
    GLuint tex2d, texcube, tex3d, tex1d; /* the textures of T2, TC, T3 and T1D (see README) */
    int rows, failures;
    int runs[5];                    /* per mode: parameters, static const, vertex shader, preshaders, fx_2_0 */
    int fx2_refused;                /* MODE_FX2 runs the bytecode writer refused */
} runner;

/* The inputs every row may read; values chosen so that no two components are equal and signs vary. */
static const float input_a[4] = {0.5f, -1.5f, 2.0f, -4.0f};
static const float input_b[4] = {0.25f, 3.0f, -0.75f, 1.0f};
static const int input_i[4] = {3, -7, 2, 0};
static const float input_m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}; /* M._11, M._12, ... */

/* Samplers every row may read, the same in both modes; textures in make_textures. */
#define SAMPLERS \
    "texture T2; texture TC; texture T3; texture T1D;\n" \
    "sampler1D S1 = sampler_state { Texture = <T1D>; MinFilter = Point; MagFilter = Point; MipFilter = None; AddressU = Clamp; };\n" \
    "sampler2D S2 = sampler_state { Texture = <T2>; MinFilter = Point; MagFilter = Point; MipFilter = Point; AddressU = Clamp; AddressV = Clamp; };\n" \
    "sampler2D S2L = sampler_state { Texture = <T2>; MinFilter = Linear; MagFilter = Linear; MipFilter = Point; AddressU = Clamp; AddressV = Clamp; };\n" \
    "sampler2D S2W = sampler_state { Texture = <T2>; MinFilter = Point; MagFilter = Point; MipFilter = Point; AddressU = Wrap; AddressV = Mirror; };\n" \
    "sampler2D S2N = sampler_state { Texture = <T2>; MinFilter = Point; MagFilter = Point; MipFilter = None; };\n" \
    "sampler2D S2B = sampler_state { Texture = <T2>; MinFilter = Point; MagFilter = Point; AddressU = Border; AddressV = Border; BorderColor = 0xFF4080C0; };\n" \
    "samplerCUBE SC = sampler_state { Texture = <TC>; MinFilter = Point; MagFilter = Point; MipFilter = None; };\n" \
    "sampler3D S3 = sampler_state { Texture = <T3>; MinFilter = Point; MagFilter = Point; MipFilter = None; AddressW = Clamp; };\n"

static const char uniform_inputs[] = "float4 A; float4 B; int4 I; float4x4 M; bool T1; bool F1; half2 H; int N1;\n" SAMPLERS;
static const char const_inputs[] =
    "static const float4 A = float4(0.5, -1.5, 2.0, -4.0);\n"
    "static const float4 B = float4(0.25, 3.0, -0.75, 1.0);\n"
    "static const int4 I = int4(3, -7, 2, 0);\n"
    "static const float4x4 M = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};\n"
    "static const bool T1 = true; static const bool F1 = false; static const half2 H = half2(0.75, -2.5);\n"
    "static const int N1 = -9;\n" SAMPLERS;

static char *trim(char *s) {
    while (*s == ' ' || *s == '\t') s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r' || s[n - 1] == '\n')) s[--n] = 0;
    return s;
}

/* A number, nan, inf or -inf. There is no "not checked" value: a row must state what Direct3D
 * gives for every component it writes, or it could not fail. */
static int parse_value(const char *tok, double *v) {
    if (strcmp(tok, "nan") == 0) { *v = NAN; return 1; }
    if (strcmp(tok, "inf") == 0) { *v = INFINITY; return 1; }
    if (strcmp(tok, "-inf") == 0) { *v = -INFINITY; return 1; }
    char *end;
    *v = strtod(tok, &end);
    return *end == 0 && end != tok;
}

/* The part after "=>": values (or "error X####"), then ~tolerance, @u / @c, and a // comment. */
static int parse_expect(row *r, char *s) {
    char *comment = strstr(s, "//");
    if (comment) *comment = 0;
    r->tol = 1e-5;
    r->modes = MODE_UNIFORM | MODE_CONST | MODE_VERTEX | MODE_PRESHADER;
    bool no_fx2 = false;
    for (char *tok = strtok(s, " \t"); tok; tok = strtok(NULL, " \t")) {
        if (strcmp(tok, "error") == 0) {
            char *code = strtok(NULL, " \t");
            if (!code || strlen(code) >= sizeof r->error) return 0;
            strcpy(r->error, code);
        } else if (tok[0] == '~') {
            r->tol = strtod(tok + 1, NULL);
        } else if (strcmp(tok, "@u") == 0) {
            r->modes = MODE_UNIFORM | MODE_VERTEX | MODE_PRESHADER;
        } else if (strcmp(tok, "@c") == 0) {
            r->modes = MODE_CONST;
        } else if (strcmp(tok, "@nofx2") == 0) {
            no_fx2 = true;
        } else {
            if (r->count == MAX_EXPECT || !parse_value(tok, &r->expect[r->count])) return 0;
            r->count++;
        }
    }
    if (r->error[0] || pixel_only(r->body)) r->modes &= ~MODE_VERTEX;
    if (!r->error[0] && !no_fx2 && (r->modes & MODE_UNIFORM)) r->modes |= MODE_FX2; /* errors: the front end's, once */
    return r->error[0] || r->count > 0;
}

/* "globals ;; body => expected": returns 0 for a malformed row. */
static int parse_row(row *r, char *line) {
    char *arrow = strstr(line, "=>");
    if (!arrow) return 0;
    *arrow = 0;
    char *split = strstr(line, ";;");
    char *body = line;
    if (split) {
        *split = 0;
        r->globals = strdup(trim(line));
        body = split + 2;
    } else {
        r->globals = strdup("");
    }
    r->body = strdup(trim(body));
    return parse_expect(r, arrow + 2);
}

static char *row_source(const row *r, int mode) {
    static const char *const masks[] = {"", "x", "xy", "xyz", "xyzw"};
    const char *inputs = mode == MODE_CONST ? const_inputs : uniform_inputs;
    size_t n = strlen(inputs) + strlen(r->globals) + strlen(r->body) + 512;
    char *src = malloc(n);
    const char *tail = r->body[0] == '{' ? "" : ";";
    char assign[16] = "";
    if (r->body[0] != '{') snprintf(assign, sizeof assign, "R.%s = ", masks[r->count ? r->count : 1]);
    if (mode == MODE_VERTEX)
        snprintf(src, n,
                 "%s%s\n"
                 "struct VO { float4 p : POSITION; nointerpolation float4 r : TEXCOORD0; };\n"
                 "VO VS(float4 p : POSITION) {\n float4 R = 0;\n %s%s%s\n VO o; o.p = p; o.r = R; return o;\n}\n"
                 "float4 PS(nointerpolation float4 r : TEXCOORD0) : COLOR { return r; }\n"
                 "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n",
                 inputs, r->globals, assign, r->body, tail);
    else
        snprintf(src, n,
                 "%s%s\n"
                 "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                 "float4 PS() : COLOR {\n float4 R = 0;\n %s%s%s\n return R;\n}\n"
                 "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n",
                 inputs, r->globals, assign, r->body, tail);
    return src;
}

static void set_inputs(runner *t, hfx_effect *fx) {
    hfx_param *p;
    if ((p = hfx_effect_param(fx, "T2"))) hfx_param_set_texture(p, t->tex2d);
    if ((p = hfx_effect_param(fx, "TC"))) hfx_param_set_texture(p, t->texcube);
    if ((p = hfx_effect_param(fx, "T3"))) hfx_param_set_texture(p, t->tex3d);
    if ((p = hfx_effect_param(fx, "T1D"))) hfx_param_set_texture(p, t->tex1d);
    if ((p = hfx_effect_param(fx, "A"))) hfx_param_set_floats(p, input_a, 4);
    if ((p = hfx_effect_param(fx, "B"))) hfx_param_set_floats(p, input_b, 4);
    if ((p = hfx_effect_param(fx, "I"))) hfx_param_set_ints(p, input_i, 4);
    if ((p = hfx_effect_param(fx, "M"))) hfx_param_set_matrix(p, input_m);
    if ((p = hfx_effect_param(fx, "T1"))) hfx_param_set_bool(p, 1);
    if ((p = hfx_effect_param(fx, "F1"))) hfx_param_set_bool(p, 0);
    if ((p = hfx_effect_param(fx, "N1"))) hfx_param_set_int(p, -9);
    static const float h[2] = {0.75f, -2.5f};
    if ((p = hfx_effect_param(fx, "H"))) hfx_param_set_floats(p, h, 2);
}

static int near(double got, double want, double tol) {
    if (isnan(want)) return isnan(got);
    if (isinf(want)) return got == want;
    return fabs(got - want) <= tol * fmax(1.0, fabs(want));
}

static void report(const row *r, int mode, const char *what, const char *src) {
    fprintf(stderr, "%s:%d: [%s] %s: %s\n%s", r->file, r->line,
            mode == MODE_UNIFORM ? "parameters" : mode == MODE_CONST ? "static const"
            : mode == MODE_VERTEX ? "vertex shader" : mode == MODE_FX2 ? "via fx_2_0" : "preshaders",
            r->body, what, getenv("HFX_SEMANTICS_VERBOSE") ? src : "");
}

/* Draws the row's effect into the 1x1 float target and returns its pixel. */
static int draw(runner *t, hfx_effect *fx, float px[4]) {
    set_inputs(t, fx);
    t->g.ClearColor(-7, -7, -7, -7);
    t->g.Clear(GL_COLOR_BUFFER_BIT);
    if (hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, "T"), 0)) != HFX_OK) return 0;
    t->g.BindVertexArray(t->quad);
    t->g.DrawArrays(GL_TRIANGLES, 0, 6);
    t->g.ReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, px);
    return t->g.GetError() == GL_NO_ERROR;
}

static int check_values(const row *r, int mode, const float px[4], const char *src) {
    for (int i = 0; i < r->count; i++)
        if (!near(px[i], r->expect[i], r->tol)) {
            char msg[256];
            snprintf(msg, sizeof msg, "got (%.9g, %.9g, %.9g, %.9g), component %d expected %.9g\n", px[0], px[1], px[2],
                     px[3], i, r->expect[i]);
            report(r, mode, msg, src);
            return 0;
        }
    return 1;
}

static int check_error(const row *r, int mode, hfx_effect *fx, const char *errors, const char *src) {
    char want[32];
    snprintf(want, sizeof want, "error %s", r->error);
    if (fx) { report(r, mode, "compiled, expected an error\n", src); return 0; }
    if (!errors || !strstr(errors, want)) {
        char msg[1024];
        snprintf(msg, sizeof msg, "expected %s, got:\n%s", want, errors ? errors : "(no message)\n");
        report(r, mode, msg, src);
        return 0;
    }
    return 1;
}

/* MODE_FX2's load: NULL with *refused set when the bytecode writer refuses the shader (a gap of
 * the D3D9 back end, counted and listed, not a wrong value); other failures in *errors. */
static hfx_effect *load_via_fx2(runner *t, const char *src, char **errors, bool *refused) {
    hfxc_options co = {.flags = HFXC_PACK_UNIFORMS | HFXC_NO_PRESHADERS | HFXC_D3D9_BYTECODE};
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "row.fx", &co);
    hfx_effect *fx = NULL;
    size_t size = 0;
    void *data = hfxc_result_fx2(r, 0, &size, errors);
    *refused = !hfxc_result_effect(r); /* the writer itself refusing is a failure */
    if (data) {
        hfx_load_options opt = {0};
        opt.no_preshaders = true;
        char *e = NULL;
        fx = hfx_effect_load_memory(t->dev, data, size, "row.fxo", &opt, &e);
        *errors = e ? strdup(e) : NULL;
        hfx_free(e);
    }
    free(data);
    hfxc_result_free(r);
    return fx;
}

static int run_mode(runner *t, const row *r, int mode) {
    char *src = row_source(r, mode == MODE_FX2 ? MODE_UNIFORM : mode), *errors = NULL;
    hfx_load_options opt = {0};
    opt.no_preshaders = mode != MODE_PRESHADER;
    bool refused = false;
    hfx_effect *fx = mode == MODE_FX2 ? load_via_fx2(t, src, &errors, &refused)
                                      : hfx_effect_load_memory(t->dev, src, strlen(src), "row.fx", &opt, &errors);
    if (refused) {
        t->fx2_refused++;
        if (getenv("HFX_SEMANTICS_VERBOSE")) report(r, mode, errors ? errors : "refused\n", src);
        free(errors); /* hfxc's text: malloc'ed */
        free(src);
        return 1;
    }
    int ok;
    float px[4] = {0};
    if (r->error[0]) ok = check_error(r, mode, fx, errors, src);
    else if (!fx) { report(r, mode, errors ? errors : "load failed\n", src); ok = 0; }
    else if (!draw(t, fx, px)) { report(r, mode, "apply or draw failed\n", src); ok = 0; }
    else ok = check_values(r, mode, px, src);
    if (fx) hfx_effect_destroy(fx);
    if (mode == MODE_FX2) free(errors);
    else hfx_free(errors);
    free(src);
    return ok;
}

static void run_row(runner *t, row *r) {
    int ok = 1;
    for (int mode = MODE_UNIFORM, k = 0; mode <= MODE_FX2; mode <<= 1, k++)
        if (r->modes & mode) ok &= run_mode(t, r, mode), t->runs[k]++;
    t->rows++;
    if (!ok) t->failures++;
}

static void run_line(runner *t, const char *file, int line_no, char *line) {
    char *s = trim(line);
    if (!*s || s[0] == '#' || strncmp(s, "==", 2) == 0) return;
    row r = {.file = file, .line = line_no};
    if (!parse_row(&r, s)) {
        fprintf(stderr, "%s:%d: malformed row\n", file, line_no);
        t->failures++;
    } else {
        run_row(t, &r);
    }
    free(r.globals);
    free(r.body);
}

static void run_file(runner *t, const char *dir, const char *name) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    char *text = test_read_file(path, NULL);
    CHECK(text != NULL);
    if (!text) return;
    int line_no = 0;
    for (char *line = text, *next; line; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = 0;
        run_line(t, name, ++line_no, line);
    }
    free(text);
}

static int by_name(const struct dirent **a, const struct dirent **b) { return strcmp((*a)->d_name, (*b)->d_name); }

static int is_table(const struct dirent *e) {
    size_t n = strlen(e->d_name);
    return n > 4 && strcmp(e->d_name + n - 4, ".tbl") == 0;
}

static void make_target(runner *t) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    t->g.GenTextures(1, &t->target);
    t->g.BindTexture(GL_TEXTURE_2D, t->target);
    t->g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, NULL);
    t->g.GenFramebuffers(1, &t->fbo);
    t->g.BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
    t->g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->target, 0);
    CHECK_INT(t->g.CheckFramebufferStatus(GL_FRAMEBUFFER), GL_FRAMEBUFFER_COMPLETE);
    t->quad = tgl_triangles(&t->g, quad, 6, &t->quad_buffer);
    t->g.Viewport(0, 0, 1, 1);
    hfx_device_sync(t->dev);
}

/* T2: 2x2 RGBA32F, texel (x, y) of row y (v = 0 is the first row, as in D3D and GL) is
 * (0.1 + 0.2x, 0.3 + 0.4y, 0.9, 1); its 1x1 level 1 is (0.5, 0.5, 0.5, 0.5). TC: 1x1 faces,
 * face f (+X, -X, +Y, -Y, +Z, -Z) is (0.1f, 1 - 0.1f, 0.25, 1). T3: 1x1x2, slice z is (z, 0.5, 0.75, 1).
 * T1D: a 2x1 2D texture (D3D9's 1D textures are 2D ones a texel high): (0.2, 0.4, 0.6, 0.8), (0.9, 0.7, 0.5, 0.3). */
static void make_textures(runner *t) {
    static const float level0[16] = {0.1f, 0.3f, 0.9f, 1, 0.3f, 0.3f, 0.9f, 1, 0.1f, 0.7f, 0.9f, 1, 0.3f, 0.7f, 0.9f, 1};
    static const float level1[4] = {0.5f, 0.5f, 0.5f, 0.5f};
    static const float slices[8] = {0, 0.5f, 0.75f, 1, 1, 0.5f, 0.75f, 1};
    t->g.GenTextures(1, &t->tex2d);
    t->g.BindTexture(GL_TEXTURE_2D, t->tex2d);
    t->g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 2, 2, 0, GL_RGBA, GL_FLOAT, level0);
    t->g.TexImage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, level1);
    t->g.GenTextures(1, &t->texcube);
    t->g.BindTexture(GL_TEXTURE_CUBE_MAP, t->texcube);
    for (int f = 0; f < 6; f++) {
        float texel[4] = {0.1f * (float)f, 1 - 0.1f * (float)f, 0.25f, 1};
        t->g.TexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, texel);
    }
    t->g.GenTextures(1, &t->tex3d);
    t->g.BindTexture(GL_TEXTURE_3D, t->tex3d);
    t->g.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, 1, 1, 2, 0, GL_RGBA, GL_FLOAT, slices);
    static const float row[8] = {0.2f, 0.4f, 0.6f, 0.8f, 0.9f, 0.7f, 0.5f, 0.3f};
    t->g.GenTextures(1, &t->tex1d);
    t->g.BindTexture(GL_TEXTURE_2D, t->tex1d);
    t->g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 2, 1, 0, GL_RGBA, GL_FLOAT, row);
    hfx_device_texture_changed(t->dev, t->tex1d);
    hfx_device_texture_changed(t->dev, t->tex2d);
    hfx_device_texture_changed(t->dev, t->texcube);
    hfx_device_texture_changed(t->dev, t->tex3d);
    hfx_device_sync(t->dev);
}

static void free_target(runner *t) {
    GLuint tex[4] = {t->tex2d, t->texcube, t->tex3d, t->tex1d};
    t->g.DeleteTextures(4, tex);
    t->g.DeleteBuffers(1, &t->quad_buffer);
    t->g.DeleteVertexArrays(1, &t->quad);
    t->g.DeleteFramebuffers(1, &t->fbo);
    t->g.DeleteTextures(1, &t->target);
}

/* One table, which must hold rows: a table that runs none (emptied, or every row turned into a
 * comment) would otherwise pass. */
static void run_table(runner *t, const char *dir, const char *name) {
    int before = t->rows + t->failures;
    run_file(t, dir, name);
    int ran = t->rows + t->failures - before;
    if (ran == 0) fprintf(stderr, "%s: no rows run\n", name);
    CHECK(ran > 0);
}

/* Every table; HFX_SEMANTICS_TABLE=name.tbl runs one, and a name that matches no table fails
 * (a misspelled name would run nothing and pass). */
static void semantics_tables(runner *t) {
    const char *dir = HFX_SOURCE_DIR "/tests/runtime/semantics";
    const char *only = getenv("HFX_SEMANTICS_TABLE");
    struct dirent **names;
    int n = scandir(dir, &names, is_table, by_name), matched = 0;
    CHECK(n > 0);
    for (int i = 0; i < n; i++) {
        if (!only || strcmp(only, names[i]->d_name) == 0) run_table(t, dir, names[i]->d_name), matched++;
        free(names[i]);
    }
    free(names);
    if (!matched) fprintf(stderr, "HFX_SEMANTICS_TABLE=%s: no such table in %s\n", only ? only : "", dir);
    CHECK(matched > 0);
    CHECK(t->rows > 0);
    printf("%d rows, %d failed (runs: %d with parameters, %d with static consts, %d in the vertex shader, %d with "
           "preshaders, %d via fx_2_0 of which %d refused by the bytecode writer)\n", t->rows, t->failures, t->runs[0],
           t->runs[1], t->runs[2], t->runs[3], t->runs[4], t->fx2_refused);
    CHECK_INT(t->failures, 0);
}

static runner t;

static void all_rows(void) { semantics_tables(&t); }

int main(void) {
    t.gl = test_gl_create(4, 4);
    if (!t.gl) test_skip("no OSMesa context");
    tgl_load(&t.g);
    t.dev = hfx_device_create_gl(test_gl_loader);
    make_target(&t);
    make_textures(&t);
    RUN(all_rows);
    free_target(&t);
    hfx_device_destroy(t.dev);
    test_gl_destroy(t.gl);
    return test_summary();
}
