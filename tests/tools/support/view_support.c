/* view_support.c: see view_support.h. stb_image is compiled in here: the tests do not link
 * libstb, and reading with a different library than hfxview writes with keeps them honest. */
#include "view_support.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

char *view_format(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    char *s = malloc((size_t)n + 1);
    if (!s) return NULL;
    va_start(ap, fmt);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return s;
}

char *view_build_path(const char *relative) {
    const char *build = getenv("HFX_BUILD_DIR");
    if (!build) return NULL;
    char *p = view_format("%s/%s", build, relative);
    if (p && access(p, X_OK) != 0) {
        free(p);
        return NULL;
    }
    return p;
}

int view_run(const char *command, char **output) {
    char *cmd = view_format("( %s ) 2>&1", command);
    FILE *f = cmd ? popen(cmd, "r") : NULL;
    free(cmd);
    if (!f) return -1;
    size_t len = 0, cap = 4096;
    char *buf = malloc(cap);
    size_t n;
    while (buf && (n = fread(buf + len, 1, cap - len - 1, f)) > 0) {
        len += n;
        if (cap - len < 1024) {
            char *b = realloc(buf, cap * 2);
            if (!b) break;
            buf = b;
            cap *= 2;
        }
    }
    if (buf) buf[len] = '\0';
    int status = pclose(f);
    if (output) *output = buf;
    else free(buf);
    return status == -1 ? -1 : (status >> 8) & 0xff;
}

int view_png_read(view_png *img, const char *path) {
    int comp;
    memset(img, 0, sizeof *img);
    img->rgba = stbi_load(path, &img->width, &img->height, &comp, 4);
    return img->rgba ? 0 : -1;
}

void view_png_free(view_png *img) {
    stbi_image_free(img->rgba);
    memset(img, 0, sizeof *img);
}

const unsigned char *view_png_at(const view_png *img, int x, int y) {
    return img->rgba + ((size_t)y * (size_t)img->width + (size_t)x) * 4;
}

int view_pixel_near(const view_png *img, int x, int y, int r, int g, int b, int tol) {
    if (!img->rgba || x < 0 || y < 0 || x >= img->width || y >= img->height) {
        fprintf(stderr, "  pixel (%d, %d) is outside the %dx%d image\n", x, y, img->width, img->height);
        return 0;
    }
    const unsigned char *p = view_png_at(img, x, y);
    int ok = abs(p[0] - r) <= tol && abs(p[1] - g) <= tol && abs(p[2] - b) <= tol;
    if (!ok) fprintf(stderr, "  pixel (%d, %d) = (%d, %d, %d), expected (%d, %d, %d) +- %d\n", x, y, p[0], p[1], p[2], r, g, b, tol);
    return ok;
}

int view_png_max_difference(const view_png *a, const view_png *b, int *count_over_1) {
    if (!a->rgba || !b->rgba || a->width != b->width || a->height != b->height) {
        fprintf(stderr, "  images differ in size: %dx%d and %dx%d\n", a->width, a->height, b->width, b->height);
        return -1;
    }
    int worst = 0, over = 0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            const unsigned char *p = view_png_at(a, x, y), *q = view_png_at(b, x, y);
            int d = 0;
            for (int k = 0; k < 4; k++)
                if (abs(p[k] - q[k]) > d) d = abs(p[k] - q[k]);
            if (d > worst) worst = d;
            if (d <= 1) continue;
            if (over++ < 5)
                fprintf(stderr, "  pixel (%d, %d): (%d, %d, %d, %d) against (%d, %d, %d, %d)\n", x, y, p[0], p[1], p[2], p[3],
                        q[0], q[1], q[2], q[3]);
        }
    if (count_over_1) *count_over_1 = over;
    return worst;
}

int view_run_effect(const char *hfxview, const char *dir, const char *fx_text, const char *args, view_png *img,
                    char **out) {
    char *fx = view_format("%s/view.fx", dir), *png = view_format("%s/view.png", dir), *text = NULL;
    FILE *f = fx ? fopen(fx, "w") : NULL;
    if (f) fputs(fx_text, f), fclose(f);
    char *cmd = view_format("%s %s -o %s --size 128x128 %s", hfxview, fx, png, args);
    int rc = cmd ? view_run(cmd, &text) : -1;
    int ok = rc == 0 && view_png_read(img, png) == 0;
    if (!ok) fprintf(stderr, "%s exited %d:\n%s\n", cmd ? cmd : "hfxview", rc, text ? text : "");
    if (out) *out = text;
    else free(text);
    free(cmd), free(fx), free(png);
    return ok;
}
