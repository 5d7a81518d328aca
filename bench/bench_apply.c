/* bench_apply.c: CPU cost of setting N parameters and applying the pass, against a raw GL
 * loop making the same uploads, in the same run on the same OSMesa context. Goals (issue 36):
 * set + Apply within 1.0x of raw at 1 change, packed Apply within 1.5x of raw-range at 10 and 100.
 *
 * Two layouts of the same 100 float4 parameters:
 * - separate: `uniform vec4 p0; ... p99;` (hfxc's default). hfx makes exactly the calls the raw
 *   loop makes (one glUniform4fv per changed parameter), so the ratio is hfx's bookkeeping.
 * - packed: `uniform vec4 hfx_c[100];` (hfxc --pack-uniforms, D3D9's registers). hfx sends the
 *   changed range in one call; the raw loop sets each changed element, one call each, as a
 *   hand-written renderer over that shader does. "raw-range" is the floor for reference: one
 *   call over the range with no bookkeeping at all, the values written in place (one float each).
 * - floor: the calls loop_hfx makes (one set per parameter, one Apply) into functions that do
 *   nothing, then raw-range's one call: what an API of that shape costs at the least, so
 *   floor/range bounds from below what hfx-packed can reach against raw-range.
 * The raw loops look up locations and the entry point once and bind the program only when
 * their shadow of the binding differs (so neither side calls glUseProgram in the loop); hfx
 * holds its parameter handles from hfx_effect_param, looked up once too.
 *
 *   ./bench_apply [ITER]                  every loop: this thread's CPU time (not the wall clock,
 *       which on a shared machine counts other processes' time) and user-space instructions
 *       (perf_event_open) per iteration, best of five rounds after one round not kept
 *   ./bench_apply ITER LOOP N             one loop alone, LOOP = hfx | raw | hfx-packed | raw-packed |
 *       raw-range | floor, for callgrind: valgrind --tool=callgrind --toggle-collect=loop_hfx (or loop_raw,
 *       loop_raw_range) counts the loop alone; ITER 1000 gives instructions x 1000. */
#define _DEFAULT_SOURCE /* syscall, for bench.h's instruction counter */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gl_context.h"
#include "gl/gl_int.h"
#include "bench.h"

#define PARAMS 100

static char *copy_str(const char *s) {
    char *d = malloc(strlen(s) + 1);
    strcpy(d, s);
    return d;
}

/* One program reading PARAMS float4 uniforms: p0..p99, or hfx_c[0..99] when packed. */
static hfx_fx_effect *build(int packed) {
    hfx_fx_effect *fx = calloc(1, sizeof *fx);
    fx->source_name = copy_str("bench.fx");
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
        p->name = copy_str(name);
        p->glsl_name = copy_str(name);
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
    prog->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330] = (hfx_fx_code){copy_str(vs), strlen(vs)};
    prog->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330] = (hfx_fx_code){fs, strlen(fs)};
    prog->uniforms = calloc(PARAMS, sizeof *prog->uniforms);
    prog->uniform_count = PARAMS;
    for (int i = 0; i < PARAMS; i++)
        prog->uniforms[i] = (hfx_fx_uniform_use){.param = (uint32_t)i, .reg = packed ? (uint32_t)i : HFX_NONE};
    prog->reg_count = packed ? PARAMS : 0;
    fx->passes = calloc(1, sizeof *fx->passes);
    fx->pass_count = 1;
    fx->passes[0].name = copy_str("P");
    fx->passes[0].program = 0;
    fx->techniques = calloc(1, sizeof *fx->techniques);
    fx->technique_count = 1;
    fx->techniques[0].name = copy_str("T");
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
    l->prog = dev->gl->program;
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

/* What any API that takes one call per parameter set and one per Apply costs at the least: the
 * same calls as loop_hfx into functions that do nothing, then the one glUniform4fv over the
 * range. Its ratio to raw-range (or raw at 1 change) is the floor for hfx's. */
static __attribute__((noinline)) int empty_set(hfx_param *p, const float *v, size_t n) {
    __asm__ volatile("" : : "r"(p), "r"(v), "r"(n) : "memory");
    return 0;
}
static __attribute__((noinline)) int empty_apply(hfx_pass *p) {
    __asm__ volatile("" : : "r"(p) : "memory");
    return 0;
}

static void loop_floor(layout *l, long iters, int n) {
    uniform4fv_fn uniform4fv = (uniform4fv_fn)test_gl_proc("glUniform4fv");
    for (long k = 0; k < iters; k++) {
        for (int i = 0; i < n; i++) {
            values[i][0] = (float)k + 0.75f;
            empty_set(l->params[i], values[i], 4);
        }
        empty_apply(l->pass);
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
    {"raw-range", 1, loop_raw_range}, {"floor", 1, loop_floor},
};
enum { RUNS = sizeof runs / sizeof runs[0] };

/* A loop's cost per iteration: CPU time of this thread and user-space instructions. */
typedef struct figure {
    double ns, instructions;
} figure;

/* Best of ROUNDS rounds (noise only ever adds), after one round that is not kept (caches, the
 * first glUniform of each value). */
enum { ROUNDS = 5 };
static figure measure(const run *r, layout *l, long iters, int n, int counter) {
    figure best = {1e30, 1e30};
    for (int round = 0; round <= ROUNDS; round++) {
        hfx_pass_apply(l->pass); /* binds its program: the loops never rebind */
        uint64_t i0 = instructions_read(counter);
        double t0 = thread_now();
        r->loop(l, iters, n);
        double t = thread_now() - t0;
        uint64_t i = instructions_read(counter) - i0;
        if (round == 0) continue;
        if (t / (double)iters * 1e9 < best.ns) best.ns = t / (double)iters * 1e9;
        if ((double)i / (double)iters < best.instructions) best.instructions = (double)i / (double)iters;
    }
    return best;
}

static void print_ratio(double a, double b) {
    if (a > 0 && b > 0) printf(" %10.3fx", a / b);
    else printf(" %11s", "-");
}

/* One table: ns (what = 0) or instructions (what = 1) per iteration and the ratios. */
static void print_table(const figure fig[3][RUNS], const int counts[3], int what) {
    printf("%-8s", "changed");
    for (int r = 0; r < RUNS; r++) printf(" %11s", runs[r].name);
    printf(" %11s %11s %11s %11s\n", "hfx/raw", "pk/raw-pk", "pk/range", "floor/range");
    for (int c = 0; c < 3; c++) {
        double v[RUNS];
        for (int r = 0; r < RUNS; r++) v[r] = what ? fig[c][r].instructions : fig[c][r].ns;
        printf("%-8d", counts[c]);
        for (int r = 0; r < RUNS; r++) printf(" %11.1f", v[r]);
        print_ratio(v[0], v[1]), print_ratio(v[2], v[3]), print_ratio(v[2], v[4]), print_ratio(v[5], v[4]);
        printf("\n");
    }
}

int main(int argc, char **argv) {
    long iters = argc > 1 ? atol(argv[1]) : 20000;
    if (iters < 1) iters = 1;
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
        int counter = instructions_open();
        figure fig[3][RUNS];
        for (int c = 0; c < 3; c++)
            for (int r = 0; r < RUNS; r++) fig[c][r] = measure(&runs[r], &lay[runs[r].packed], iters, counts[c], counter);
        printf("set + Apply against raw GL, per iteration, best of %d rounds of %ld (pk: hfx-packed; goals: hfx/raw and "
               "pk/raw-pk <= 1.0 at 1 change, pk/range <= 1.5 at 10 and 100)\n", ROUNDS, iters);
        printf("ns of this thread's CPU time\n");
        print_table(fig, counts, 0);
        if (counter >= 0) {
            printf("instructions (user space, perf_event_open)\n");
            print_table(fig, counts, 1);
            close(counter);
        } else {
            printf("instructions: no counter here (valgrind --tool=callgrind, one loop alone, as above)\n");
        }
    }
    hfx_effect_destroy(lay[0].fx);
    hfx_effect_destroy(lay[1].fx);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return status;
}
