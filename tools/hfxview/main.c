/* main.c: hfxview, render a Direct3D 9 effect to a PNG (headless on OSMesa or EGL) or a window.
 * Exit status: 0 ok, 1 the effect failed to load or draw, 2 usage. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bind.h"
#include "context.h"
#include "hfx/hfx.h"
#include "image.h"
#include "mesh.h"
#include "options.h"
#include "render.h"
#include "textures.h"
#ifdef HFX_HAVE_VULKAN_VIEW
#include "vulkan.h"
#endif

enum { EXIT_OK = 0, EXIT_EFFECT = 1, EXIT_USAGE = 2 };

typedef struct viewer {
    hv_options opt;
    hv_mesh mesh;
    hv_context *ctx;
    const hv_gl *gl;
    hfx_device *dev;
    hfx_effect *fx;
    hv_gpu_mesh gpu;
    hv_textures textures;
    hfx_technique *technique;
    hfx_load_options load;   /* the -D / -I the effect was loaded with, for reloads */
    char err[1024];
} viewer;

static int usage_error(const char *msg) {
    fprintf(stderr, "hfxview: %s\n%s", msg, hv_usage());
    return EXIT_USAGE;
}

/* A well-formed command line that does not fit this effect or these files: no usage text. */
static int input_error(const char *msg) {
    fprintf(stderr, "hfxview: %s\n", msg);
    return EXIT_USAGE;
}

/* "dir/name.fx" -> "name.png", in the current folder like fxc's default outputs. */
static char *default_output(const char *input) {
    const char *base = strrchr(input, '/');
    base = base ? base + 1 : input;
    size_t n = strcspn(base, ".");
    char *out = malloc(n + 5);
    if (out) snprintf(out, n + 5, "%.*s.png", (int)n, base);
    return out;
}

/* The compiler's own file(line,col): lines, ending with a newline. */
static void print_errors(const char *errors) {
    if (errors && *errors) fputs(errors, stderr);
    if (errors && *errors && errors[strlen(errors) - 1] != '\n') fputc('\n', stderr);
}

static int load_effect(viewer *v) {
    hfx_load_options *lo = &v->load;
    lo->defines = v->opt.defines;
    lo->define_count = v->opt.define_count;
    lo->include_dirs = v->opt.include_dirs;
    lo->include_dir_count = v->opt.include_dir_count;
    lo->no_preshaders = v->opt.no_preshaders;
    char *errors = NULL;
    v->fx = hfx_effect_load(v->dev, v->opt.input, lo, &errors);
    print_errors(errors);
    if (!v->fx && !(errors && strstr(errors, "error")))
        fprintf(stderr, "%s: error: cannot load the effect: %s\n", v->opt.input, hfx_device_last_error(v->dev));
    hfx_free(errors);
    if (v->fx && hfx_effect_warnings(v->fx) && *hfx_effect_warnings(v->fx))
        fprintf(stderr, "%s", hfx_effect_warnings(v->fx));
    return v->fx ? EXIT_OK : EXIT_EFFECT;
}

/* --list: techniques, passes, and each parameter with how hfxview binds it. */
static void list_effect(viewer *v) {
    hfx_effect *fx = v->fx;
    size_t count = hfx_effect_param_count(fx);
    const char **how = calloc(count ? count : 1, sizeof *how);
    hv_scene scene;
    hv_scene_from_options(&scene, &v->opt);
    if (how) hv_bind_scene_report(fx, &scene, how, count);
    for (size_t i = 0; i < hfx_effect_technique_count(fx); i++) {
        hfx_technique *t = hfx_effect_technique_at(fx, i);
        printf("technique %s\n", hfx_technique_name(t));
        for (size_t k = 0; k < hfx_technique_pass_count(t); k++)
            printf("  pass %zu %s\n", k, hfx_pass_name(hfx_technique_pass(t, k)));
    }
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        hfx_param *p = hfx_effect_param_at(fx, i);
        const char *sem = hfx_param_semantic(p);
        printf("parameter %s", hfx_param_name(p));
        if (hfx_param_elements(p)) printf("[%zu]", hfx_param_elements(p));
        if (sem && *sem) printf(" : %s", sem);
        const char *texture = "texture: --texture, the file its annotations name, or a checkerboard";
        printf("  (%s)\n", how && how[i] ? how[i] : hfx_param_texture_target(p) ? texture : "not bound: the effect's value");
    }
    free(how);
}

/* The first technique that draws something: an effect may include a file whose technique is
 * empty (MagicCarpet's SkyDome.fx includes Common.fx's commented-out one), and a game would
 * set CurrentTechnique to its own. */
static hfx_technique *default_technique(hfx_effect *fx) {
    size_t count = hfx_effect_technique_count(fx);
    for (size_t i = 0; i < count; i++)
        if (hfx_technique_pass_count(hfx_effect_technique_at(fx, i)) > 0) return hfx_effect_technique_at(fx, i);
    return count ? hfx_effect_technique_at(fx, 0) : NULL;
}

static int pick_technique(viewer *v) {
    hfx_effect *fx = v->fx;
    size_t count = hfx_effect_technique_count(fx);
    const char *want = v->opt.technique;
    if (!want || !strcmp(want, "all")) v->technique = default_technique(fx);
    else if (!(v->technique = hfx_effect_technique(fx, want))) {
        char *end;
        unsigned long i = strtoul(want, &end, 10);
        if (*want && !*end && i < count) v->technique = hfx_effect_technique_at(fx, i);
    }
    if (!v->technique) {
        fprintf(stderr, "hfxview: %s has no technique '%s'; it has:", v->opt.input, want ? want : "");
        for (size_t i = 0; i < count; i++) fprintf(stderr, " %s", hfx_technique_name(hfx_effect_technique_at(fx, i)));
        fprintf(stderr, "\n");
        return want ? EXIT_USAGE : EXIT_EFFECT;
    }
    size_t passes = hfx_technique_pass_count(v->technique);
    if (v->opt.pass >= 0 && (size_t)v->opt.pass >= passes) {
        fprintf(stderr, "hfxview: technique %s has %zu pass%s; no pass %d\n", hfx_technique_name(v->technique), passes,
                passes == 1 ? "" : "es", v->opt.pass);
        return EXIT_USAGE;
    }
    return EXIT_OK;
}

/* Binds the scene; then says which numeric parameters no convention recognised (those --set
 * does not name), so that a black picture explains itself. */
static void bind_and_tell(viewer *v, const hv_scene *scene) {
    size_t count = hfx_effect_param_count(v->fx);
    const char **how = calloc(count ? count : 1, sizeof *how);
    if (!how) return (void)hv_bind_scene(v->fx, scene);
    hv_bind_scene_report(v->fx, scene, how, count);
    for (size_t i = 0; i < v->opt.set_count; i++) {
        size_t n = (size_t)(v->opt.sets[i].value - 1 - v->opt.sets[i].name);
        for (size_t k = 0; k < count; k++) {
            const char *name = hfx_param_name(hfx_effect_param_at(v->fx, k));
            if (strlen(name) <= n && !strncmp(name, v->opt.sets[i].name, strlen(name))) how[k] = "--set";
        }
    }
    char list[1024];
    size_t unbound = hv_unbound_list(v->fx, how, list, sizeof list);
    if (unbound)
        fprintf(stderr, "hfxview: %zu parameter%s not bound, left at the effect's values: %s\n", unbound,
                unbound == 1 ? "" : "s", list);
    free(how);
}

/* SpriteEffect and its kin draw in pixels (MatrixTransform): the image's rectangle, unless --mesh. */
static int pick_mesh(viewer *v) {
    if (v->opt.mesh_given || !hv_effect_wants_pixels(v->fx)) return EXIT_OK;
    hv_mesh_free(&v->mesh);
    if (hv_mesh_screen(&v->mesh, v->opt.width, v->opt.height) != 0) return input_error("out of memory building the screen mesh");
    return EXIT_OK;
}

/* The scene's matrices, camera and light, then the --set values over them (GL and --vulkan alike). */
static int bind_scene_and_sets(viewer *v) {
    hv_scene scene;
    hv_scene_from_options(&scene, &v->opt);
    bind_and_tell(v, &scene);
    for (size_t i = 0; i < v->opt.set_count; i++) {
        char name[256];
        size_t n = (size_t)(v->opt.sets[i].value - 1 - v->opt.sets[i].name);
        snprintf(name, sizeof name, "%.*s", (int)n, v->opt.sets[i].name);
        if (hv_set_param(v->fx, name, v->opt.sets[i].value, v->err, sizeof v->err) != 0) return input_error(v->err);
    }
    return EXIT_OK;
}

static int apply_options(viewer *v) {
    int rc = bind_scene_and_sets(v);
    if (rc != EXIT_OK) return rc;
    if (hv_bind_textures(&v->textures, v->gl, v->fx, &v->opt, v->err, sizeof v->err))
        return input_error(v->err);
    return EXIT_OK;
}

static int draw(viewer *v) {
    size_t failed = 0;
    hv_clear(v->gl, v->opt.width, v->opt.height, v->opt.background);
    int rc = hv_draw_technique(v->gl, &v->gpu, v->fx, v->technique, v->opt.pass, v->opt.blend_add, &failed);
    if (rc != HFX_OK) {
        fprintf(stderr, "%s: error: technique %s, pass %zu: %s\n", v->opt.input, hfx_technique_name(v->technique), failed,
                hfx_device_last_error(v->dev));
        return EXIT_EFFECT;
    }
    return EXIT_OK;
}

static int save_png(viewer *v) {
    hv_image img;
    char *path = v->opt.output ? NULL : default_output(v->opt.input);
    const char *out = v->opt.output ? v->opt.output : path;
    int rc = EXIT_OK;
    if (!out || hv_read_image(v->gl, v->opt.width, v->opt.height, &img) != 0) {
        fprintf(stderr, "hfxview: out of memory\n");
        rc = EXIT_EFFECT;
    } else {
        if (hv_image_write_png(&img, out) != 0) {
            fprintf(stderr, "hfxview: cannot write '%s'\n", out);
            rc = EXIT_USAGE;
        }
        hv_image_free(&img);
    }
    free(path);
    return rc;
}

/* --watch: reloads when the effect's files changed (1), keeping the technique by name and
 * binding what the new code added; a broken edit prints its located errors and keeps the
 * effect as it was (0, as when nothing changed). */
static int watch_step(viewer *v) {
    hfx_effect_set_current_technique(v->fx, v->technique);
    char *errors = NULL;
    int rc = hfx_effect_reload_if_changed(v->fx, &v->load, &errors);
    print_errors(errors);
    hfx_free(errors);
    if (rc < 0) fprintf(stderr, "hfxview: %s did not reload; the last good effect stays\n", v->opt.input);
    if (rc != 1) return 0;
    v->technique = hfx_effect_current_technique(v->fx);
    hv_textures_release(&v->textures, v->gl);
    if (apply_options(v) != EXIT_OK) fprintf(stderr, "hfxview: the reloaded effect does not take the options\n");
    fprintf(stderr, "hfxview: reloaded %s\n", v->opt.input);
    return 1;
}

/* Headless --watch: the PNG again after each reload, until the process is stopped; a line
 * on stderr once each is complete, for whoever waits on it. */
static int watch_headless(viewer *v) {
    for (int written = 1;; written++) {
        fprintf(stderr, "hfxview: wrote %s (%d)\n", v->opt.output ? v->opt.output : "the PNG", written);
        while (!watch_step(v)) nanosleep(&(struct timespec){0, 50 * 1000 * 1000}, NULL);
        int rc = draw(v);
        if (rc == EXIT_OK) rc = save_png(v);
        if (rc != EXIT_OK) return rc;
    }
}

static double seconds_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The window loop: T cycles techniques, Left / Right turn the mesh, Escape quits. The clock
 * runs: time parameters (Time, g_fTime, CurrentTime) follow it every frame. */
static int show_window(viewer *v) {
    double start = seconds_now(), last = start;
    while (!hv_context_should_close(v->ctx)) {
        if (v->opt.watch) watch_step(v);
        hv_scene scene;
        double now = seconds_now();
        hv_scene_from_options(&scene, &v->opt);
        scene.time = (float)(now - start), scene.elapsed_time = (float)(now - last), last = now;
        hv_bind_view(v->fx, &scene);
        if (draw(v) != EXIT_OK) return EXIT_EFFECT;
        hv_context_present(v->ctx);
        if (hv_context_key_pressed(v->ctx, 'T')) {
            size_t n = hfx_effect_technique_count(v->fx), i = 0;
            while (i < n && hfx_effect_technique_at(v->fx, i) != v->technique) i++;
            v->technique = hfx_effect_technique_at(v->fx, (i + 1) % n);
            printf("technique %s\n", hfx_technique_name(v->technique));
        }
        int turn = hv_context_key_pressed(v->ctx, 262) - hv_context_key_pressed(v->ctx, 263); /* GLFW arrows */
        v->opt.yaw_degrees += 15.0f * (float)turn; /* the next frame's hv_bind_view turns the matrices */
    }
    return EXIT_OK;
}

#ifdef HFX_HAVE_VULKAN_VIEW
static int write_image(viewer *v, hv_image *img) {
    char *path = v->opt.output ? NULL : default_output(v->opt.input);
    const char *out = v->opt.output ? v->opt.output : path;
    int rc = out && hv_image_write_png(img, out) == 0 ? EXIT_OK : EXIT_USAGE;
    if (rc != EXIT_OK) fprintf(stderr, "hfxview: cannot write '%s'\n", out ? out : "");
    free(path);
    return rc;
}

/* --vulkan: load, bind the scene and --set values, draw, write the PNG; the GL context is never made. */
static int vulkan_steps(viewer *v, hv_vk *g) {
    int rc;
    if ((rc = load_effect(v)) != EXIT_OK) return rc;
    if (v->opt.list) return list_effect(v), EXIT_OK;
    if ((rc = pick_technique(v)) != EXIT_OK || (rc = pick_mesh(v)) != EXIT_OK) return rc;
    if ((rc = bind_scene_and_sets(v)) != EXIT_OK) return rc;
    hv_image img;
    size_t failed = 0;
    if ((rc = hv_vk_render(g, v->fx, v->technique, &v->opt, &v->mesh, &img, &failed)) != HFX_OK) {
        fprintf(stderr, "%s: error: technique %s, pass %zu: %s\n", v->opt.input, hfx_technique_name(v->technique), failed,
                hfx_device_last_error(v->dev));
        return EXIT_EFFECT;
    }
    rc = write_image(v, &img);
    hv_image_free(&img);
    if (getenv("HFXVIEW_PIPELINES")) fprintf(stderr, "hfxview: %zu pipelines\n", hv_vk_pipelines(g));
    return rc;
}

static int run_vulkan(viewer *v) {
    if (v->opt.window || v->opt.watch || v->opt.egl)
        return input_error("--vulkan draws headless (no --window, --watch, --egl)");
    hv_vk *g = NULL;
    int rc = hv_vk_open(&g, v->opt.width, v->opt.height, &v->dev, v->err, sizeof v->err) == 0 ? vulkan_steps(v, g) : EXIT_EFFECT;
    if (!g || !v->dev) fprintf(stderr, "hfxview: %s\n", v->err);
    hfx_effect_destroy(v->fx);
    v->fx = NULL;
    v->dev = NULL; /* hv_vk_close destroys it */
    /* a validation-layer message is a failure, as in the tests: the picture may be wrong */
    if (hv_vk_close(g) > 0 && rc == EXIT_OK) rc = EXIT_EFFECT;
    return rc;
}
#endif

/* One picture of draw_every_technique: OUT.T.png, or OUT.T.P.png for pass P (pass >= 0). */
static int draw_one(viewer *v, const char *out, size_t stem, size_t technique, int pass) {
    char path[1024];
    if (pass < 0) snprintf(path, sizeof path, "%.*s.%zu.png", (int)stem, out, technique);
    else snprintf(path, sizeof path, "%.*s.%zu.%d.png", (int)stem, out, technique, pass);
    v->opt.output = path;
    int rc = draw(v);
    if (rc == EXIT_OK) rc = save_png(v);
    v->opt.output = out;
    return rc;
}

/* --technique all: every technique into OUT.N.png (N its index, OUT the -o path less ".png"),
 * with a line "technique N NAME" for each on stdout; for surveys (scripts/corpus.sh). With
 * --pass each, every pass alone into OUT.N.P.png, each with a line "pass N P NAME": one
 * process for a whole effect (scripts/fx2_oracle.sh). The first failure's status, after
 * trying them all. */
static int draw_every_technique(viewer *v) {
    const char *out = v->opt.output ? v->opt.output : "hfxview.png";
    size_t n = hfx_effect_technique_count(v->fx), stem = strlen(out);
    int worst = EXIT_OK, each = v->opt.pass == HV_PASS_EACH;
    if (stem > 4 && !strcmp(out + stem - 4, ".png")) stem -= 4;
    for (size_t i = 0; i < n; i++) {
        v->technique = hfx_effect_technique_at(v->fx, i);
        printf("technique %zu %s\n", i, hfx_technique_name(v->technique));
        fflush(stdout);
        size_t passes = each ? hfx_technique_pass_count(v->technique) : 1;
        for (size_t p = 0; p < passes; p++) {
            if (each) {
                printf("pass %zu %zu %s\n", i, p, hfx_pass_name(hfx_technique_pass(v->technique, p)));
                fflush(stdout);
                v->opt.pass = (int)p;
            }
            int rc = draw_one(v, out, stem, i, each ? (int)p : -1);
            if (worst == EXIT_OK) worst = rc;
        }
        if (each) v->opt.pass = HV_PASS_EACH;
    }
    return worst;
}

static int run(viewer *v) {
    int rc;
    if (!strcmp(v->opt.mesh, "screen")) {
        if (hv_mesh_screen(&v->mesh, v->opt.width, v->opt.height) != 0) return input_error("out of memory building the screen mesh");
    } else if (hv_mesh_load(&v->mesh, v->opt.mesh, v->err, sizeof v->err) != 0) {
        return input_error(v->err);
    }
    if (v->opt.vulkan) {
#ifdef HFX_HAVE_VULKAN_VIEW
        return run_vulkan(v);
#else
        return input_error("this hfxview was built without Vulkan");
#endif
    }
    int kind = v->opt.window ? HV_CONTEXT_WINDOW : v->opt.egl ? HV_CONTEXT_EGL : HV_CONTEXT_OSMESA;
    v->ctx = hv_context_create(v->opt.width, v->opt.height, kind, v->err, sizeof v->err);
    if (v->err[0]) fprintf(stderr, "hfxview: %s\n", v->err);
    if (!v->ctx) return EXIT_EFFECT;
    v->gl = hv_context_gl(v->ctx);
    v->dev = hfx_device_create_gl(hv_context_loader(v->ctx));
    if (!v->dev) {
        fprintf(stderr, "hfxview: the hfx runtime cannot start on this OpenGL context\n");
        return EXIT_EFFECT;
    }
    if ((rc = load_effect(v)) != EXIT_OK) return rc;
    if (v->opt.list) {
        list_effect(v);
        return EXIT_OK;
    }
    if ((rc = pick_technique(v)) != EXIT_OK || (rc = pick_mesh(v)) != EXIT_OK) return rc;
    if (hv_gpu_mesh_upload(v->gl, &v->gpu, &v->mesh) != 0) {
        fprintf(stderr, "hfxview: cannot upload the mesh\n");
        return EXIT_EFFECT;
    }
    if ((rc = apply_options(v)) != EXIT_OK) return rc;
    if (hv_context_is_window(v->ctx)) {
        if ((rc = show_window(v)) != EXIT_OK) return rc;
        if (!v->opt.output) return EXIT_OK;
        if ((rc = draw(v)) != EXIT_OK) return rc; /* the swapped buffer is gone: draw once more */
        return save_png(v);
    }
    if (v->opt.technique && !strcmp(v->opt.technique, "all")) return draw_every_technique(v);
    if ((rc = draw(v)) != EXIT_OK) return rc;
    if ((rc = save_png(v)) != EXIT_OK || !v->opt.watch) return rc;
    return watch_headless(v);
}

static void cleanup(viewer *v) {
    if (v->gl) {
        hv_textures_release(&v->textures, v->gl);
        hv_gpu_mesh_release(v->gl, &v->gpu);
    }
    hfx_effect_destroy(v->fx);
    hfx_device_destroy(v->dev);
    hv_context_destroy(v->ctx);
    hv_mesh_free(&v->mesh);
}

int main(int argc, char **argv) {
    viewer *v = calloc(1, sizeof *v);
    if (!v) return EXIT_EFFECT;
    hv_options_defaults(&v->opt);
    int rc;
    if (hv_options_parse(&v->opt, argc, argv, v->err, sizeof v->err) != 0) rc = usage_error(v->err);
    else if (v->opt.help) rc = (fputs(hv_usage(), stdout), EXIT_OK);
    else rc = run(v);
    cleanup(v);
    free(v);
    return rc;
}
