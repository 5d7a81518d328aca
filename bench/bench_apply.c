/* bench_apply.c: CPU cost of setting N parameters and applying the pass, against a raw GL
 * loop making the same glUniform4fv calls, in the same run on the same OSMesa context.
 * Goal: hfx within 1.1x of raw for N = 1, 10 and 100.
 *
 * The raw loop is what a careful hand-written renderer does: uniform locations and the entry
 * point looked up once, the program bound only when the shadowed binding differs (so neither
 * side calls glUseProgram in the loop), and exactly the changed values uploaded. hfx holds its
 * parameter handles from hfx_effect_param, looked up once too.
 *
 *   ./bench_apply [ITER]          both loops, best of five wall-clock rounds, per-iteration ns
 *                                 and the ratio (noisy on a loaded machine);
 *   ./bench_apply ITER hfx|raw N  one loop alone, for instruction counts, which are stable:
 *       valgrind --tool=callgrind ./bench_apply 200 hfx 100 ... and the same with 1200; the
 *       difference of the two totals / 1000 is the per-iteration count (setup cancels out).
 *       (perf stat -e instructions:u works the same way where perf is available.) */
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

/* One program reading PARAMS float4 uniforms p0..p99. */
static hfx_fx_effect *build(void) {
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
        snprintf(fs + strlen(fs), cap - strlen(fs), "uniform vec4 p%d;\n", i);
    }
    strcat(fs, "void main() { vec4 s = vec4(0.0);\n");
    for (int i = 0; i < PARAMS; i++) snprintf(fs + strlen(fs), cap - strlen(fs), "s += p%d;\n", i);
    strcat(fs, "o = s; }\n");
    fx->programs = calloc(1, sizeof *fx->programs);
    fx->program_count = 1;
    hfx_fx_program *prog = &fx->programs[0];
    const char *vs = "#version 330\nlayout(location = 0) in vec2 P;\nvoid main() { gl_Position = vec4(P, 0.0, 1.0); }\n";
    prog->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330] = (hfx_fx_code){dup(vs), strlen(vs)};
    prog->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330] = (hfx_fx_code){fs, strlen(fs)};
    prog->uniforms = calloc(PARAMS, sizeof *prog->uniforms);
    prog->uniform_count = PARAMS;
    for (int i = 0; i < PARAMS; i++) prog->uniforms[i].param = (uint32_t)i;
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

int main(int argc, char **argv) {
    long iters = argc > 1 ? atol(argv[1]) : 20000;
    test_gl *gl = test_gl_create(16, 16);
    if (!gl) {
        fprintf(stderr, "no OSMesa context\n");
        return 1;
    }
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, build(), NULL, NULL);
    if (!fx) {
        fprintf(stderr, "load failed: %s\n", hfx_device_last_error(dev));
        return 1;
    }
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    hfx_param *params[PARAMS];
    char name[16];
    for (int i = 0; i < PARAMS; i++) {
        snprintf(name, sizeof name, "p%d", i);
        params[i] = hfx_effect_param(fx, name);
    }
    hfx_pass_apply(pass);
    /* the raw loop: the same program, locations looked up once, the same calls */
    GLuint prog = dev->program;
    void(APIENTRYP uniform4fv)(GLint, GLsizei, const GLfloat *) = (void(APIENTRYP)(GLint, GLsizei, const GLfloat *))test_gl_proc("glUniform4fv");
    GLint(APIENTRYP location)(GLuint, const GLchar *) = (GLint(APIENTRYP)(GLuint, const GLchar *))test_gl_proc("glGetUniformLocation");
    GLint loc[PARAMS];
    for (int i = 0; i < PARAMS; i++) {
        snprintf(name, sizeof name, "p%d", i);
        loc[i] = location(prog, name);
    }
    void(APIENTRYP use_program)(GLuint) = (void(APIENTRYP)(GLuint))test_gl_proc("glUseProgram");
    GLuint bound = prog; /* the raw renderer's shadow of the bound program */
    static float values[PARAMS][4];
    if (argc > 3) { /* one loop alone */
        int n = atoi(argv[3]), hfx = strcmp(argv[2], "hfx") == 0;
        if (n < 0 || n > PARAMS) n = PARAMS;
        if (hfx) {
            for (long k = 0; k < iters; k++) {
                for (int i = 0; i < n; i++) {
                    values[i][0] = (float)k;
                    hfx_param_set_floats(params[i], values[i], 4);
                }
                hfx_pass_apply(pass);
            }
        } else {
            for (long k = 0; k < iters; k++) {
                if (bound != prog) use_program(bound = prog);
                for (int i = 0; i < n; i++) {
                    values[i][0] = (float)k;
                    uniform4fv(loc[i], 1, values[i]);
                }
            }
        }
        hfx_effect_destroy(fx);
        hfx_device_destroy(dev);
        test_gl_destroy(gl);
        return 0;
    }
    const int counts[3] = {1, 10, 100};
    printf("set + Apply vs raw glUniform4fv, per iteration (wall clock, best of 5; goal: ratio <= 1.10)\n");
    printf("%-10s %14s %14s %8s\n", "changed", "hfx ns/iter", "raw ns/iter", "ratio");
    for (int c = 0; c < 3; c++) {
        int n = counts[c];
        double best_hfx = 1e30, best_raw = 1e30;
        for (int round = 0; round < 5; round++) { /* best of five: noise only ever adds time */
            double t0 = now();
            for (long k = 0; k < iters; k++) {
                for (int i = 0; i < n; i++) {
                    values[i][0] = (float)k;
                    hfx_param_set_floats(params[i], values[i], 4);
                }
                hfx_pass_apply(pass);
            }
            double t1 = now();
            for (long k = 0; k < iters; k++) {
                if (bound != prog) use_program(bound = prog);
                for (int i = 0; i < n; i++) {
                    values[i][0] = (float)k + 0.5f;
                    uniform4fv(loc[i], 1, values[i]);
                }
            }
            double t2 = now();
            if (t1 - t0 < best_hfx) best_hfx = t1 - t0;
            if (t2 - t1 < best_raw) best_raw = t2 - t1;
        }
        printf("%-10d %14.1f %14.1f %8.3f\n", n, best_hfx / (double)iters * 1e9, best_raw / (double)iters * 1e9,
               best_hfx / best_raw);
    }
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return 0;
}
