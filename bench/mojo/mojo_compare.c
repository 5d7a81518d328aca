/* mojo_compare: what FNA draws from an fx_2_0 effect (MojoShader's effect framework and GLSL)
 * against what hfx draws from the effect's source, in one OSMesa context (compatibility
 * profile: MojoShader's glsl120 needs it), with hfxview's mesh, camera, parameter bindings and
 * textures on both sides. Run by hand; built only with -DMOJOSHADER_DIR (bench/mojo/README.md).
 *
 *   mojo_compare [--vary NAME=FIRST..LAST] [--out DIR] [--bench N] [--frame xna|begin-end] [--profile P]
 *                EFFECT.fxo SOURCE.fx [hfxview options: --size, --mesh, --set, -D, -I...]
 *
 * For every technique that has a pass (and every value of --vary's parameter, XNA's ShaderIndex),
 * prints `alike|DIFFER max=M over=K technique variant`: M the largest channel difference
 * (/255), K the pixels more than 2/255 apart (`SKIP` for a pass without a vertex shader, which
 * FNA draws with the one bound before); --out DIR writes both pictures of a difference.
 * --bench N: each side draws N frames between a reset and a dump labelled
 * "effect|technique|variant|side" under callgrind, and prints `count LABEL INSTRUCTIONS` from the
 * kernel's counter (bench/mojo_instructions.sh); hfx's frames as --frame says (bench_frame:
 * xna, the default, as FNA draws; begin-end, with hfx_effect_begin / end around the draw). Exit: 0 all alike, 1 a difference,
 * 2 usage, 3 MojoShader refused the effect, 4 hfx did not load the source. */
#define _GNU_SOURCE 1 /* syscall (perf_event_open) */
#include "gl.h" /* glcorearb.h before osmesa.h, as context.c does */
#ifndef GLAPIENTRY
#define GLAPIENTRY APIENTRY
#endif
#ifndef GLAPI
#define GLAPI extern
#endif

#include <GL/osmesa.h>
#include <linux/perf_event.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define HAVE_CALLGRIND 1
#endif
#endif
#ifndef HAVE_CALLGRIND
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS_AT(label) (void)(label)
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

#include "bind.h"
#include "image.h"
#include "mojo_side.h"
#include "options.h"
#include "render.h"
#include "textures.h"

enum { EXIT_ALIKE = 0, EXIT_DIFFER = 1, EXIT_USAGE = 2, EXIT_MOJO = 3, EXIT_HFX = 4 };

typedef struct run {
    const char *fxo, *out_dir, *profile, *vary;
    int first, last, bench;
    int begin_end;            /* --frame begin-end: hfx's benchmark frames save and restore state */
    hv_options opt;
    OSMesaContext osmesa;
    unsigned char *pixels;
    hv_gl gl;
    hfx_device *dev;
    hfx_effect *fx;
    hv_mesh mesh;
    hv_gpu_mesh gpu;
    hv_textures textures;
    mj_side *mojo;
    PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation;
    PFNGLUNIFORM4FPROC Uniform4f;
    int perf;                 /* the calling thread's user-space instruction counter, or -1 */
    char err[1024];
} run;

static void *osmesa_loader(const char *name) {
    OSMESAproc p = OSMesaGetProcAddress(name);
    void *q;
    memcpy(&q, &p, sizeof q);
    return q;
}

static int usage(const char *msg) {
    fprintf(stderr, "mojo_compare: %s\nusage: mojo_compare [--vary NAME=FIRST..LAST] [--out DIR] [--bench N] "
                    "[--frame xna|begin-end] [--profile P] EFFECT.fxo SOURCE.fx [hfxview options]\n", msg);
    return EXIT_USAGE;
}

/* Our options first, then EFFECT.fxo; the rest is hfxview's command line. */
static int parse(run *r, int argc, char **argv) {
    int i = 1;
    r->profile = "glsl120";
    for (; i + 1 < argc && !strncmp(argv[i], "--", 2); i += 2) {
        if (!strcmp(argv[i], "--out")) r->out_dir = argv[i + 1];
        else if (!strcmp(argv[i], "--profile")) r->profile = argv[i + 1];
        else if (!strcmp(argv[i], "--bench")) r->bench = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--frame") && (!strcmp(argv[i + 1], "xna") || !strcmp(argv[i + 1], "begin-end")))
            r->begin_end = !strcmp(argv[i + 1], "begin-end");
        else if (!strcmp(argv[i], "--frame")) return usage("--frame xna|begin-end");
        else if (!strcmp(argv[i], "--vary")) {
            const char *eq = strchr(argv[i + 1], '=');
            if (!eq || sscanf(eq + 1, "%d..%d", &r->first, &r->last) != 2) return usage("--vary NAME=FIRST..LAST");
            r->vary = argv[i + 1];
        } else break;
    }
    if (i >= argc) return usage("no EFFECT.fxo");
    r->fxo = argv[i];
    hv_options_defaults(&r->opt);
    r->opt.width = r->opt.height = 128;
    argv[i] = argv[0];
    if (hv_options_parse(&r->opt, argc - i, argv + i, r->err, sizeof r->err) != 0) return usage(r->err);
    return r->opt.input ? EXIT_ALIKE : usage("no SOURCE.fx");
}

/* A compatibility-profile context: MojoShader's GLSL 1.20 with hfx's GLSL 3.30 beside it. */
static int make_context(run *r) {
    static const int attrs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                                OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                                OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    r->osmesa = OSMesaCreateContextAttribs(attrs, NULL);
    r->pixels = malloc((size_t)r->opt.width * (size_t)r->opt.height * 4);
    if (!r->osmesa || !r->pixels ||
        !OSMesaMakeCurrent(r->osmesa, r->pixels, GL_UNSIGNED_BYTE, r->opt.width, r->opt.height))
        return fprintf(stderr, "mojo_compare: no OSMesa compatibility context\n"), -1;
    const char *missing = hv_gl_load(&r->gl, osmesa_loader);
    if (missing) return fprintf(stderr, "mojo_compare: no %s\n", missing), -1;
    void *p = osmesa_loader("glGetUniformLocation"), *q = osmesa_loader("glUniform4f");
    memcpy(&r->GetUniformLocation, &p, sizeof p);
    memcpy(&r->Uniform4f, &q, sizeof q);
    r->dev = hfx_device_create_gl(osmesa_loader);
    return r->dev && p && q ? 0 : -1;
}

static int load_source(run *r) {
    hfx_load_options lo = {0};
    lo.defines = r->opt.defines;
    lo.define_count = r->opt.define_count;
    lo.include_dirs = r->opt.include_dirs;
    lo.include_dir_count = r->opt.include_dir_count;
    lo.no_preshaders = r->opt.no_preshaders;
    char *errors = NULL;
    r->fx = hfx_effect_load(r->dev, r->opt.input, &lo, &errors);
    if (!r->fx) fprintf(stderr, "%s%s: error: %s\n", errors ? errors : "", r->opt.input, hfx_device_last_error(r->dev));
    hfx_free(errors);
    return r->fx ? 0 : -1;
}

/* hfxview's scene: mesh (the screen rectangle for effects that draw in pixels), bindings,
 * --set values, textures. */
static int prepare(run *r) {
    int pixels = !r->opt.mesh_given && hv_effect_wants_pixels(r->fx);
    if ((pixels ? hv_mesh_screen(&r->mesh, r->opt.width, r->opt.height)
                : hv_mesh_load(&r->mesh, r->opt.mesh, r->err, sizeof r->err)) != 0 ||
        hv_gpu_mesh_upload(&r->gl, &r->gpu, &r->mesh) != 0)
        return fprintf(stderr, "mojo_compare: no mesh: %s\n", r->err), -1;
    hv_scene scene;
    hv_scene_from_options(&scene, &r->opt);
    hv_bind_scene(r->fx, &scene);
    for (size_t i = 0; i < r->opt.set_count; i++) {
        char name[256];
        size_t n = (size_t)(r->opt.sets[i].value - 1 - r->opt.sets[i].name);
        snprintf(name, sizeof name, "%.*s", (int)n, r->opt.sets[i].name);
        if (hv_set_param(r->fx, name, r->opt.sets[i].value, r->err, sizeof r->err) != 0)
            return fprintf(stderr, "mojo_compare: %s\n", r->err), -1;
    }
    return hv_bind_textures(&r->textures, &r->gl, r->fx, &r->opt, r->err, sizeof r->err) == 0 ? 0 : -1;
}

/* hfx moves what it draws half a pixel right and down, to D3D9's pixel centres (hfx_pos_fixup.xy,
 * docs/conventions.md); MojoShader, as FNA runs it, leaves GL's. For pictures, that offset is
 * set to zero after each Apply, so that only the shaders differ (VPOS keeps .w, the height). */
static void gl_pixel_centres(run *r) {
    GLint program = 0;
    r->gl.GetIntegerv(GL_CURRENT_PROGRAM, &program);
    GLint loc = program ? r->GetUniformLocation((GLuint)program, "hfx_pos_fixup") : -1;
    if (loc >= 0) r->Uniform4f(loc, 0, 0, 0, (float)r->opt.height);
}

/* hv_draw_technique's passes, with GL's pixel centres. */
static int draw_technique(run *r, hfx_technique *t) {
    int rc = HFX_OK;
    hv_set_default_states(&r->gl);
    hfx_effect_begin(r->fx);
    for (size_t i = 0; i < hfx_technique_pass_count(t) && rc == HFX_OK; i++) {
        hfx_pass *p = hfx_technique_pass(t, i);
        if ((rc = hfx_pass_apply(p)) != HFX_OK) break;
        gl_pixel_centres(r);
        hv_draw_mesh(&r->gl, &r->gpu, p);
    }
    hfx_effect_end(r->fx);
    r->gl.BindVertexArray(0);
    return rc;
}

/* A benchmark frame as an engine draws: the vertex arrays were bound once for the pass's
 * program (bind_once), so each frame is Apply and the draw call; hfxview's drawing looks every
 * attribute up by semantic on every draw, which cost more than the shaders' difference.
 * As FNA draws (XNA 4's EffectPass.Apply, no Begin / End: FNA3D begins MojoShader's effect
 * without saving state, as the MojoShader side does here), nothing is restored after the draw:
 * hfx_device_sync, because the application set GL state itself (docs/runtime.md), then Apply.
 * hfx_effect_begin / end would put the application's program, textures and samplers back every
 * frame, and each change of those makes llvmpipe copy its ~33 KB fragment state at the next
 * clear and draw (1.8% of SpriteEffect's frame; --frame begin-end measures it). */
static int bench_frame(run *r, hfx_technique *t) {
    int rc = HFX_OK, begin_end = r->begin_end;
    hv_set_default_states(&r->gl);
    if (begin_end) hfx_effect_begin(r->fx);
    else hfx_device_sync(r->dev);
    r->gl.BindVertexArray(r->gpu.vao);
    for (size_t i = 0; i < hfx_technique_pass_count(t) && rc == HFX_OK; i++)
        if ((rc = hfx_pass_apply(hfx_technique_pass(t, i))) == HFX_OK)
            r->gl.DrawElements(GL_TRIANGLES, r->gpu.index_count, GL_UNSIGNED_INT, NULL);
    if (begin_end) hfx_effect_end(r->fx);
    r->gl.BindVertexArray(0);
    return rc;
}

/* The first pass's attributes in the mesh's vertex array object, for bench_frame (the stock
 * effects have one pass a technique). */
static void bind_once(run *r, hfx_technique *t) {
    hfx_effect_begin(r->fx);
    hfx_pass *p = hfx_technique_pass(t, 0);
    if (hfx_pass_apply(p) == HFX_OK) hv_bind_attributes(&r->gl, &r->gpu, p);
    hfx_effect_end(r->fx);
    r->gl.BindVertexArray(0);
}

/* img: a picture (GL's pixel centres), else a benchmark frame. */
static int draw_hfx(run *r, hfx_technique *t, hv_image *img) {
    hv_clear(&r->gl, r->opt.width, r->opt.height, r->opt.background);
    int rc = img ? draw_technique(r, t) : bench_frame(r, t);
    if (rc != HFX_OK) snprintf(r->err, sizeof r->err, "hfx: %s", hfx_device_last_error(r->dev));
    return rc == HFX_OK && (!img || hv_read_image(&r->gl, r->opt.width, r->opt.height, img) == 0) ? 0 : -1;
}

static int draw_mojo(run *r, hfx_technique *t, size_t ti, int hfx_states, hv_image *img) {
    hv_clear(&r->gl, r->opt.width, r->opt.height, r->opt.background);
    int rc = mj_draw(r->mojo, &r->gl, r->fx, t, ti, &r->gpu, hfx_states, r->err, sizeof r->err);
    if (rc != 0) return rc;
    return !img || hv_read_image(&r->gl, r->opt.width, r->opt.height, img) == 0 ? 0 : -1;
}

/* The largest channel difference and how many pixels differ by more than 2/255. */
static int compare(const hv_image *a, const hv_image *b, int *over) {
    int max = 0;
    *over = 0;
    for (size_t i = 0; i < (size_t)a->width * (size_t)a->height; i++) {
        int worst = 0;
        for (int c = 0; c < 4; c++) {
            int d = abs(a->rgba[i * 4 + c] - b->rgba[i * 4 + c]);
            if (d > worst) worst = d;
        }
        if (worst > 2) ++*over;
        if (worst > max) max = worst;
    }
    return max;
}

static void save(run *r, const hv_image *img, size_t ti, int variant, const char *side) {
    char path[1024];
    snprintf(path, sizeof path, "%s/t%zu_v%d_%s.png", r->out_dir, ti, variant, side);
    hv_image_write_png(img, path);
}

/* A counter of the instructions the calling thread retires in user space (the kernel's
 * perf_event_open; -1 where perf_event_paranoid forbids it): llvmpipe shades on the calling
 * thread with LP_NUM_THREADS=0. Within a few in 10^4 of callgrind's count from run to run, and
 * a hundred times faster. */
static int open_counter(void) {
    struct perf_event_attr a;
    memset(&a, 0, sizeof a);
    a.size = sizeof a;
    a.type = PERF_TYPE_HARDWARE;
    a.config = PERF_COUNT_HW_INSTRUCTIONS;
    a.disabled = 1;
    a.exclude_kernel = 1;
    a.exclude_hv = 1;
    return (int)syscall(SYS_perf_event_open, &a, 0, -1, -1, 0);
}

/* Under callgrind or perf: two frames to warm up (llvmpipe compiles on first use), then `bench` frames
 * counted on their own: each side's Apply (hfx's; MojoShader's CommitChanges and ProgramReady),
 * attributes and draw, with XNA's default states (the stock effects' passes set none), and no
 * call into the other side. */
static void count(run *r, hfx_technique *t, size_t ti, int variant, int mojo) {
    char label[512];
    snprintf(label, sizeof label, "%s|%s|%d|%s", r->opt.input, hfx_technique_name(t), variant, mojo ? "mojo" : "hfx");
    mj_reset(r->mojo); /* after the other side's draws */
    hfx_device_sync(r->dev);
    if (!mojo) bind_once(r, t);
    /* xna frames leave the effect's program and units bound: one Begin / End around them, not
     * counted, hands the other side the GL state the begin-end frames leave */
    int around = !mojo && !r->begin_end;
    if (around) hfx_effect_begin(r->fx);
    for (int i = 0; i < 2; i++) mojo ? draw_mojo(r, t, ti, 0, NULL) : draw_hfx(r, t, NULL);
    r->gl.Finish();
    if (r->perf >= 0) ioctl(r->perf, PERF_EVENT_IOC_RESET, 0), ioctl(r->perf, PERF_EVENT_IOC_ENABLE, 0);
    CALLGRIND_START_INSTRUMENTATION;
    CALLGRIND_ZERO_STATS;
    for (int i = 0; i < r->bench; i++) mojo ? draw_mojo(r, t, ti, 0, NULL) : draw_hfx(r, t, NULL);
    r->gl.Finish();
    CALLGRIND_DUMP_STATS_AT(label);
    CALLGRIND_STOP_INSTRUMENTATION;
    uint64_t n = 0;
    if (r->perf >= 0 && ioctl(r->perf, PERF_EVENT_IOC_DISABLE, 0) == 0 && read(r->perf, &n, sizeof n) == sizeof n)
        printf("count %s %llu\n", label, (unsigned long long)n);
    if (around) hfx_effect_end(r->fx);
}

static int one(run *r, hfx_technique *t, size_t ti, int variant) {
    hv_image a = {0}, b = {0};
    int rc = draw_hfx(r, t, &a) != 0 || mj_copy_params(r->mojo, r->fx, r->err, sizeof r->err) != 0 ? -1
                                                                                            : draw_mojo(r, t, ti, 1, &b),
        over = 0;
    const char *name = *hfx_technique_name(t) ? hfx_technique_name(t) : "(unnamed)";
    if (rc == -2) printf("SKIP %s %zu %s %d: %s\n", r->opt.input, ti, name, variant, r->err);
    else if (rc != 0) printf("FAIL %s %zu %s %d: %s\n", r->opt.input, ti, name, variant, r->err);
    else {
        int max = compare(&a, &b, &over);
        rc = over ? 1 : 0;
        printf("%s max=%d over=%d %s %zu %s %d\n", rc ? "DIFFER" : "alike", max, over, r->opt.input, ti, name, variant);
        if (rc && r->out_dir) save(r, &a, ti, variant, "hfx"), save(r, &b, ti, variant, "mojo");
    }
    hv_image_free(&a);
    hv_image_free(&b);
    if (rc >= 0 && r->bench > 0) count(r, t, ti, variant, 0), count(r, t, ti, variant, 1); /* pictures told apart above */
    return rc;
}

static int set_variant(run *r, int v) {
    if (!r->vary) return 0;
    char name[256], value[32];
    snprintf(name, sizeof name, "%.*s", (int)(strchr(r->vary, '=') - r->vary), r->vary);
    snprintf(value, sizeof value, "%d", v);
    return hv_set_param(r->fx, name, value, r->err, sizeof r->err);
}

static int techniques(run *r) {
    int worst = EXIT_ALIKE;
    size_t n = hfx_effect_technique_count(r->fx);
    if (n != mj_technique_count(r->mojo))
        printf("note: hfx has %zu techniques, MojoShader %zu\n", n, mj_technique_count(r->mojo));
    for (size_t ti = 0; ti < n && ti < mj_technique_count(r->mojo); ti++) {
        hfx_technique *t = hfx_effect_technique_at(r->fx, ti);
        if (!hfx_technique_pass_count(t)) continue;
        for (int v = r->vary ? r->first : 0; v <= (r->vary ? r->last : 0); v++) {
            if (set_variant(r, v) != 0) return fprintf(stderr, "mojo_compare: %s\n", r->err), EXIT_USAGE;
            int rc = one(r, t, ti, v);
            if (rc != 0) worst = EXIT_DIFFER;
        }
    }
    return worst;
}

static void finish(run *r) {
    mj_destroy(r->mojo);
    hv_textures_release(&r->textures, &r->gl);
    if (r->gpu.vao) hv_gpu_mesh_release(&r->gl, &r->gpu);
    hv_mesh_free(&r->mesh);
    if (r->fx) hfx_effect_destroy(r->fx);
    if (r->dev) hfx_device_destroy(r->dev);
    if (r->osmesa) {
        OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext(r->osmesa);
    }
    free(r->pixels);
    if (r->perf >= 0) close(r->perf);
}

int main(int argc, char **argv) {
    static run r;
    int rc = parse(&r, argc, argv);
    if (rc != EXIT_ALIKE) return rc;
    r.perf = r.bench > 0 ? open_counter() : -1;
    if (make_context(&r) != 0) rc = EXIT_USAGE;
    else if (load_source(&r) != 0) rc = EXIT_HFX;
    else if (prepare(&r) != 0) rc = EXIT_USAGE;
    else if (!(r.mojo = mj_create(r.profile, osmesa_loader, r.opt.width, r.opt.height, r.err, sizeof r.err)) ||
             mj_load(r.mojo, r.fxo, r.err, sizeof r.err) != 0) {
        printf("MOJO-FAIL %s: %s\n", r.opt.input, r.err);
        rc = EXIT_MOJO;
    } else rc = techniques(&r);
    finish(&r);
    return rc;
}
