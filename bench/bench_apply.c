/* bench_apply.c: CPU cost of setting N parameters and applying the pass, against a raw GL
 * loop making the same uploads, in the same run on the same OSMesa context. Goal: hfx within
 * 1.1x of raw for N = 1, 10 and 100.
 *
 * Two layouts of the same 100 float4 parameters:
 * - separate: `uniform vec4 p0; ... p99;` (hfxc's default). hfx makes exactly the calls the raw
 *   loop makes (one glUniform4fv per changed parameter), so the ratio is hfx's bookkeeping.
 * - packed: `uniform vec4 hfx_c[100];` (hfxc --pack-uniforms, D3D9's registers). hfx sends the
 *   changed range in one call; the raw loop sets each changed element, one call each, as a
 *   hand-written renderer over that shader does. "raw range" is the floor for reference: one
 *   call over the range with no bookkeeping at all.
 * The raw loops look up locations and the entry point once and bind the program only when
 * their shadow of the binding differs (so neither side calls glUseProgram in the loop); hfx
 * holds its parameter handles from hfx_effect_param, looked up once too.
 *
 *   ./bench_apply [ITER]                  every loop, best of five wall-clock rounds (noisy on a
 *                                         loaded machine)
 *   ./bench_apply ITER LOOP N             one loop alone, LOOP = hfx | raw | hfx-packed | raw-packed |
 *       raw-range, for instruction counts, which are stable: valgrind --tool=callgrind with ITER
 *       200 and 1200; the difference of the two totals / 1000 is the per-iteration count (setup
 *       cancels out). perf stat -e instructions:u works the same way where perf is available. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gl_context.h"
#include "internal.h"
#include "bench.h"

#define PARAMS 100

static char *dup(const char *s) {
    char *d = malloc(strlen(s) + 1);
    strcpy(d, s);
    return d;
}

/* One program reading PARAMS float4 uniforms: p0..p99, or hfx_c[0..99] when packed. */
static hfx_fx_effect *build(int packed) {
    hfx_fx_effect *fx = calloc(1, sizeof *fx);
    fx->source_name = dup("bench.fx");
    fx->targets = 1u << HFX_TARGET_GLSL330;
    fx->params = calloc(PARAMS, sizeof *fx->params);
    fx->param_count = fx->top_param_count = PARAMS;
    fx->values = calloc(PARAMS * 4, sizeof *fx->values);
    fx->value_words = PARAMS * 4;
    size_t cap = 64 * PARAMS + 512;
    char *fs = malloc(cap), name[16];
    strcpy(fs, "#version 330\nout vec4 o;\n");
    if (packed) snprintf(fs + strlen(fs), cap - strlen(fs), "uniform vec4 %s[%d];\n", HFX_FX_REGS_NAME, PARAMS);
    for (int i = 0; i < PARAMS; i++) {
        snprintf(name, sizeof name, "p%d", i);
        hfx_fx_param *p = &fx->params[i];
        p->name = dup(name);
        p->glsl_name = dup(name);
        p->klass = HFX_CLASS_VECTOR;
        p->type = HFX_TYPE_FLOAT;
        p->rows = 1, p->cols = 4;
        p->parent = HFX_NONE;
        p->offset = (uint32_t)i * 4, p->words = 4;
        p->sampler = HFX_NONE;
        if (!packed) snprintf(fs + strlen(fs), cap - strlen(fs), "uniform vec4 p%d;\n", i);
    }
    strcat(fs, "void main() { vec4 s = vec4(0.0);\n");
    for (int i = 0; i < PARAMS; i++) {
        if (packed) snprintf(fs + strlen(fs), cap - strlen(fs), "s += %s[%d];\n", HFX_FX_REGS_NAME, i);
        else snprintf(fs + strlen(fs), cap - strlen(fs), "s += p%d;\n", i);
    }
    strcat(fs, "o = s; }\n");
    fx->programs = calloc(1, sizeof *fx->programs);
    fx->program_count = 1;
    hfx_fx_program *prog = &fx->programs[0];
    const char *vs = "#version 330\nlayout(location = 0) in vec2 P;\nvoid main() { gl_Position = vec4(P, 0.0, 1.0); }\n";
    prog->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330] = (hfx_fx_code){dup(vs), strlen(vs)};
    prog->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330] = (hfx_fx_code){fs, strlen(fs)};
    prog->uniforms = calloc(PARAMS, sizeof *prog->uniforms);
    prog->uniform_count = PARAMS;
    for (int i = 0; i < PARAMS; i++)
        prog->uniforms[i] = (hfx_fx_uniform_use){.param = (uint32_t)i, .reg = packed ? (uint32_t)i : HFX_NONE};
    prog->reg_count = packed ? PARAMS : 0;
    fx->passes = calloc(1, sizeof *fx->passes);
    fx->pass_count = 1;
    fx->passes[0].name = dup("P");
    fx->passes[0].program = 0;
    fx->techniques = calloc(1, sizeof *fx->techniques);
    fx->technique_count = 1;
    fx->techniques[0].name = dup("T");
    fx->techniques[0].pass_count = 1;
    return fx;
}

typedef void(APIENTRYP uniform4fv_fn)(GLint, GLsizei, const GLfloat *);

/* One layout: the effect, its handles, and the raw loop's locations in the same program. */
typedef struct layout {
    hfx_effect *fx;
    hfx_pass *pass;
    hfx_param *params[PARAMS];
    GLuint prog;
    GLint loc[PARAMS];
} layout;

static int layout_init(layout *l, hfx_device *dev, int packed) {
    l->fx = hfx_rt_effect_from_fx(dev, build(packed), NULL, NULL);
    if (!l->fx) {
        fprintf(stderr, "load failed: %s\n", hfx_device_last_error(dev));
        return 0;
    }
    l->pass = hfx_technique_pass(hfx_effect_current_technique(l->fx), 0);
    hfx_pass_apply(l->pass);
    l->prog = dev->program;
    GLint(APIENTRYP location)(GLuint, const GLchar *) = (GLint(APIENTRYP)(GLuint, const GLchar *))test_gl_proc("glGetUniformLocation");
    char name[32];
    for (int i = 0; i < PARAMS; i++) {
        snprintf(name, sizeof name, "p%d", i);
        l->params[i] = hfx_effect_param(l->fx, name);
        if (packed) snprintf(name, sizeof name, "%s[%d]", HFX_FX_REGS_NAME, i);
        l->loc[i] = location(l->prog, name);
    }
    return 1;
}

static float values[PARAMS][4];

static void loop_hfx(layout *l, long iters, int n) {
    for (long k = 0; k < iters; k++) {
        for (int i = 0; i < n; i++) {
            values[i][0] = (float)k;
            hfx_param_set_floats(l->params[i], values[i], 4);
        }
        hfx_pass_apply(l->pass);
    }
}

/* The raw renderer: its own shadow of the bound program, one call per changed value. */
static void loop_raw(layout *l, long iters, int n) {
    uniform4fv_fn uniform4fv = (uniform4fv_fn)test_gl_proc("glUniform4fv");
    void(APIENTRYP use_program)(GLuint) = (void(APIENTRYP)(GLuint))test_gl_proc("glUseProgram");
    GLuint bound = l->prog;
    for (long k = 0; k < iters; k++) {
        if (bound != l->prog) use_program(bound = l->prog);
        for (int i = 0; i < n; i++) {
            values[i][0] = (float)k + 0.5f;
            uniform4fv(l->loc[i], 1, values[i]);
        }
    }
}

/* The floor for the packed layout: the values written in place, one call over the range. */
static void loop_raw_range(layout *l, long iters, int n) {
    uniform4fv_fn uniform4fv = (uniform4fv_fn)test_gl_proc("glUniform4fv");
    for (long k = 0; k < iters; k++) {
        for (int i = 0; i < n; i++) values[i][0] = (float)k + 0.25f;
        uniform4fv(l->loc[0], n, values[0]);
    }
}

typedef struct run {
    const char *name;
    int packed;
    void (*loop)(layout *, long, int);
} run;

static const run runs[] = {
    {"hfx", 0, loop_hfx}, {"raw", 0, loop_raw}, {"hfx-packed", 1, loop_hfx}, {"raw-packed", 1, loop_raw},
    {"raw-range", 1, loop_raw_range},
};
enum { RUNS = sizeof runs / sizeof runs[0] };

int main(int argc, char **argv) {
    long iters = argc > 1 ? atol(argv[1]) : 20000;
    test_gl *gl = test_gl_create(16, 16);
    if (!gl) {
        fprintf(stderr, "no OSMesa context\n");
        return 1;
    }
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    layout lay[2];
    if (!layout_init(&lay[0], dev, 0) || !layout_init(&lay[1], dev, 1)) return 1;
    int status = 0;
    if (argc > 3) { /* one loop alone */
        int n = atoi(argv[3]), which = -1;
        if (n < 0 || n > PARAMS) n = PARAMS;
        for (int r = 0; r < RUNS; r++)
            if (strcmp(argv[2], runs[r].name) == 0) which = r;
        if (which < 0) {
            fprintf(stderr, "unknown loop '%s'\n", argv[2]);
            status = 2;
        } else {
            layout *l = &lay[runs[which].packed];
            hfx_pass_apply(l->pass); /* bind its program: the loops never rebind */
            runs[which].loop(l, iters, n);
        }
    } else {
        const int counts[3] = {1, 10, 100};
        printf("set + Apply vs raw glUniform4fv, ns per iteration (wall clock, best of 5; goal: hfx / raw <= 1.10)\n");
        printf("%-8s", "changed");
        for (int r = 0; r < RUNS; r++) printf(" %11s", runs[r].name);
        printf(" %11s %11s %11s\n", "hfx/raw", "packed/raw", "packed/sep");
        for (int c = 0; c < 3; c++) {
            double best[RUNS];
            for (int r = 0; r < RUNS; r++) best[r] = 1e30;
            for (int round = 0; round < 5; round++) /* best of five: noise only ever adds time */
                for (int r = 0; r < RUNS; r++) {
                    layout *l = &lay[runs[r].packed];
                    hfx_pass_apply(l->pass);
                    double t0 = now();
                    runs[r].loop(l, iters, counts[c]);
                    double t = now() - t0;
                    if (t < best[r]) best[r] = t;
                }
            printf("%-8d", counts[c]);
            for (int r = 0; r < RUNS; r++) printf(" %11.1f", best[r] / (double)iters * 1e9);
            /* packed/sep: hfx over the packed layout against the raw loop over separate uniforms */
            printf(" %11.3f %11.3f %11.3f\n", best[0] / best[1], best[2] / best[3], best[2] / best[1]);
        }
    }
    hfx_effect_destroy(lay[0].fx);
    hfx_effect_destroy(lay[1].fx);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return status;
}
