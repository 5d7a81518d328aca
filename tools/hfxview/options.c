/* options.c: parsing hfxview's command line into hv_options. Nothing here touches GL. */
#include "options.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *hv_usage(void) {
    return "usage: hfxview EFFECT.fx|EFFECT.hfxo [-o OUT.png] [options]\n"
           "  --technique NAME|N|all    technique to draw (default: the first); all: each to OUT.N.png\n"
           "  --pass all|N|each         draw every pass in order (default) or only pass N; each (with\n"
           "                            --technique all): every pass alone to OUT.N.P.png\n"
           "  --mesh NAME|FILE.obj      sphere (default), plane, quad, cube, torus, teapot, screen (the\n"
           "                            image in pixels, for post-processing), or an OBJ file\n"
           "  --size WxH                image size (default 512x512)\n"
           "  --texture NAME=FILE       image for a texture or sampler parameter (default: a checker)\n"
           "  --set NAME=v1,v2,...      parameter value; NAME may be arr[2] or arr[0].Member\n"
           "  --camera eye=x,y,z,at=x,y,z[,up=x,y,z][,fov=degrees]\n"
           "  --light position=x,y,z[,direction=x,y,z][,color=r,g,b]\n"
           "  --rotate DEGREES          turn the mesh about the y axis\n"
           "  --blend-passes add|none   additive blending from the second pass on\n"
           "  --background r,g,b[,a]    clear colour, 0..1 (default: XNA's CornflowerBlue)\n"
           "  -D NAME[=VALUE], -I DIR   preprocessor defines and include folders\n"
           "  --list                    print the techniques and parameters, render nothing\n"
           "  --window                  show the render in a window (when built with GLFW)\n"
           "  --no-preshaders           keep work on parameters alone in the shaders (to compare)\n"
           "  --watch                   reload when the .fx or an include changes: the window updates\n"
           "                            (errors print, the last good picture stays); headless, the\n"
           "                            PNG is written again after each reload until hfxview is stopped\n"
           "  --egl                     render headless on EGL instead of OSMesa (when built with EGL)\n"
           "  --vulkan                  render headless on a Vulkan device (lavapipe) through hfx_pass_apply_vk\n"
           "Exit status: 0 ok, 1 the effect failed to load or draw, 2 usage.\n";
}

void hv_options_defaults(hv_options *o) {
    memset(o, 0, sizeof *o);
    o->pass = HV_PASS_ALL;
    o->mesh = "sphere";
    o->width = o->height = 512;
    o->eye = hv_vec3_make(0.0f, 1.0f, 3.0f);
    o->at = hv_vec3_make(0.0f, 0.0f, 0.0f);
    o->up = hv_vec3_make(0.0f, 1.0f, 0.0f);
    o->fov_degrees = 45.0f;
    o->light_position = hv_vec3_make(2.5f, 4.0f, 3.0f);
    o->light_color[0] = o->light_color[1] = o->light_color[2] = 1.0f;
    /* XNA's Color.CornflowerBlue, the colour every XNA sample clears to. */
    o->background[0] = 100 / 255.0f;
    o->background[1] = 149 / 255.0f;
    o->background[2] = 237 / 255.0f;
    o->background[3] = 1.0f;
}

int hv_parse_floats(const char *s, float *out, int max) {
    int n = 0;
    if (!s || !*s) return -1;
    for (;;) {
        char *end;
        errno = 0;
        float v = strtof(s, &end);
        if (end == s || errno == ERANGE || !isfinite(v) || n == max) return -1;
        out[n++] = v;
        if (*end == '\0') return n;
        if (*end != ',') return -1;
        s = end + 1;
    }
}

static int parse_int(const char *s, int *out) {
    char *end;
    long v = strtol(s, &end, 10);
    if (end == s || *end || v < 0 || v > 1 << 20) return 0;
    *out = (int)v;
    return 1;
}

static int parse_size(const char *s, int *w, int *h) {
    char *end;
    long a = strtol(s, &end, 10);
    if (end == s || (*end != 'x' && *end != 'X')) return 0;
    const char *t = end + 1;
    long b = strtol(t, &end, 10);
    if (end == t || *end || a < 1 || b < 1 || a > 16384 || b > 16384) return 0;
    *w = (int)a;
    *h = (int)b;
    return 1;
}

static int split_kv(const char *arg, hv_kv *kv) {
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg) return 0;
    kv->name = arg;
    kv->value = eq + 1;
    return 1;
}

/* "key=a,b,c,key2=d,e,f": calls take(key, floats, count) for every key. */
typedef int (*keyed_fn)(hv_options *o, const char *key, size_t keylen, const float *v, int n);

static int parse_keyed(hv_options *o, const char *s, keyed_fn take) {
    while (*s) {
        const char *eq = strchr(s, '=');
        if (!eq || eq == s) return 0;
        float v[4];
        int n = 0;
        const char *p = eq + 1;
        for (;;) { /* numbers up to the next "key=" */
            char *end;
            if (n == 4) return 0;
            v[n++] = strtof(p, &end);
            if (end == p) return 0;
            p = end;
            if (*p == '\0') break;
            if (*p != ',') return 0;
            p++;
            if (strcspn(p, ",=") < strlen(p) && p[strcspn(p, ",=")] == '=') break;
        }
        if (!take(o, s, (size_t)(eq - s), v, n)) return 0;
        s = p;
    }
    return 1;
}

static int key_is(const char *key, size_t len, const char *name) { return strlen(name) == len && !strncmp(key, name, len); }

static int take_camera(hv_options *o, const char *key, size_t len, const float *v, int n) {
    hv_vec3 p = hv_vec3_make(v[0], n > 1 ? v[1] : 0, n > 2 ? v[2] : 0);
    if (key_is(key, len, "fov") && n == 1 && v[0] > 0 && v[0] < 180) o->fov_degrees = v[0];
    else if (n != 3) return 0;
    else if (key_is(key, len, "eye")) o->eye = p;
    else if (key_is(key, len, "at")) o->at = p;
    else if (key_is(key, len, "up")) o->up = p;
    else return 0;
    return 1;
}

static int take_light(hv_options *o, const char *key, size_t len, const float *v, int n) {
    if (n != 3) return 0;
    if (key_is(key, len, "position") || key_is(key, len, "pos")) {
        o->light_position = hv_vec3_make(v[0], v[1], v[2]);
    } else if (key_is(key, len, "direction") || key_is(key, len, "dir")) {
        o->light_direction = hv_vec3_make(v[0], v[1], v[2]);
        o->light_direction_given = 1;
    } else if (key_is(key, len, "color") || key_is(key, len, "colour")) {
        memcpy(o->light_color, v, 3 * sizeof *v);
    } else {
        return 0;
    }
    return 1;
}

static int fail(char *err, size_t errlen, const char *what, const char *arg) {
    snprintf(err, errlen, "%s: '%s'", what, arg);
    return -1;
}

/* The value of option argv[*i]: "--opt VALUE" or "--opt=VALUE". */
static const char *option_value(int argc, char **argv, int *i, const char *name) {
    size_t len = strlen(name);
    if (!strncmp(argv[*i], name, len) && argv[*i][len] == '=') return argv[*i] + len + 1;
    if (strcmp(argv[*i], name)) return NULL;
    if (*i + 1 >= argc) return "";
    return argv[++*i];
}

#define TAKE(name) (v = option_value(argc, argv, &i, name)) != NULL

static int add_kv(hv_kv *list, size_t *count, size_t cap, const char *arg) {
    return *count < cap && split_kv(arg, &list[*count]) ? (++*count, 1) : 0;
}

int hv_options_parse(hv_options *o, int argc, char **argv, char *err, size_t errlen) {
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) o->help = 1;
        else if (!strcmp(a, "--window")) o->window = 1;
        else if (!strcmp(a, "--watch")) o->watch = 1;
        else if (!strcmp(a, "--no-preshaders")) o->no_preshaders = 1;
        else if (!strcmp(a, "--egl")) o->egl = 1;
        else if (!strcmp(a, "--vulkan")) o->vulkan = 1;
        else if (!strcmp(a, "--list")) o->list = 1;
        else if (!strcmp(a, "-o") || TAKE("--output")) {
            if (!strcmp(a, "-o")) v = i + 1 < argc ? argv[++i] : "";
            if (!*v) return fail(err, errlen, "missing output file after", a);
            o->output = v;
        } else if (TAKE("--technique")) {
            if (!*v) return fail(err, errlen, "missing technique after", a);
            o->technique = v;
        } else if (TAKE("--pass")) {
            if (!strcmp(v, "all")) o->pass = HV_PASS_ALL;
            else if (!strcmp(v, "each")) o->pass = HV_PASS_EACH;
            else if (!parse_int(v, &o->pass) || o->pass < 0)
                return fail(err, errlen, "--pass takes 'all', 'each' or a pass number, not", v);
        } else if (TAKE("--mesh")) {
            if (!*v) return fail(err, errlen, "missing mesh after", a);
            o->mesh = v;
            o->mesh_given = 1;
        } else if (TAKE("--size")) {
            if (!parse_size(v, &o->width, &o->height)) return fail(err, errlen, "--size takes WIDTHxHEIGHT, not", v);
        } else if (TAKE("--texture")) {
            if (!add_kv(o->textures, &o->texture_count, 32, v)) return fail(err, errlen, "--texture takes NAME=FILE, not", v);
        } else if (TAKE("--set")) {
            if (!add_kv(o->sets, &o->set_count, 64, v)) return fail(err, errlen, "--set takes NAME=VALUES, not", v);
        } else if (TAKE("--camera")) {
            if (!parse_keyed(o, v, take_camera))
                return fail(err, errlen, "--camera takes eye=x,y,z,at=x,y,z[,up=x,y,z][,fov=deg], not", v);
        } else if (TAKE("--light")) {
            if (!parse_keyed(o, v, take_light))
                return fail(err, errlen, "--light takes position=x,y,z[,direction=x,y,z][,color=r,g,b], not", v);
            o->light_given = 1;
        } else if (TAKE("--rotate")) {
            if (hv_parse_floats(v, &o->yaw_degrees, 1) != 1) return fail(err, errlen, "--rotate takes degrees, not", v);
        } else if (TAKE("--blend-passes")) {
            if (!strcmp(v, "add")) o->blend_add = 1;
            else if (!strcmp(v, "none")) o->blend_add = 0;
            else return fail(err, errlen, "--blend-passes takes 'add' or 'none', not", v);
        } else if (TAKE("--background")) {
            float c[4] = {0, 0, 0, 1};
            int n = hv_parse_floats(v, c, 4);
            if (n < 3) return fail(err, errlen, "--background takes r,g,b[,a] in 0..1, not", v);
            memcpy(o->background, c, sizeof c);
        } else if (!strncmp(a, "-D", 2)) {
            v = a[2] ? a + 2 : (i + 1 < argc ? argv[++i] : "");
            if (!*v || o->define_count == 32) return fail(err, errlen, "bad define", a);
            o->defines[o->define_count++] = v;
        } else if (!strncmp(a, "-I", 2)) {
            v = a[2] ? a + 2 : (i + 1 < argc ? argv[++i] : "");
            if (!*v || o->include_dir_count == 16) return fail(err, errlen, "bad include folder", a);
            o->include_dirs[o->include_dir_count++] = v;
        } else if (a[0] == '-' && a[1]) {
            return fail(err, errlen, "unknown option", a);
        } else if (o->input) {
            return fail(err, errlen, "only one effect file, but also got", a);
        } else {
            o->input = a;
        }
    }
    if (!o->input && !o->help) {
        snprintf(err, errlen, "no effect file given");
        return -1;
    }
    if (o->pass == HV_PASS_EACH && !(o->technique && !strcmp(o->technique, "all")) && !o->list) {
        snprintf(err, errlen, "--pass each writes one picture a pass: it goes with --technique all");
        return -1;
    }
    return 0;
}
