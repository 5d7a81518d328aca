#include "gl_context.h"

#include <GL/osmesa.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>

struct test_gl {
    OSMesaContext ctx;
    unsigned char *pixels; /* OSMesa's colour buffer, bottom row first */
    int width, height;
};

test_gl *test_gl_create(int width, int height) { return test_gl_create_version(width, height, 3, 3); }

test_gl *test_gl_create_version(int width, int height, int major, int minor) {
    const int attrs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, major,
                         OSMESA_CONTEXT_MINOR_VERSION, minor, 0};
    test_gl *gl = calloc(1, sizeof *gl);
    if (!gl) return NULL;
    gl->ctx = OSMesaCreateContextAttribs(attrs, NULL);
    gl->pixels = calloc((size_t)width * height, 4);
    gl->width = width;
    gl->height = height;
    if (!gl->ctx || !gl->pixels || !OSMesaMakeCurrent(gl->ctx, gl->pixels, GL_UNSIGNED_BYTE, width, height)) {
        test_gl_destroy(gl);
        return NULL;
    }
    return gl;
}

void test_gl_destroy(test_gl *gl) {
    if (!gl) return;
    if (gl->ctx) OSMesaDestroyContext(gl->ctx);
    free(gl->pixels);
    free(gl);
}

void *test_gl_loader(const char *name) { return (void *)OSMesaGetProcAddress(name); }
void *test_gl_proc(const char *name) { return (void *)OSMesaGetProcAddress(name); }

void test_gl_read(test_gl *gl, int x, int y, unsigned char rgba[4]) {
    void (*finish)(void) = (void (*)(void))OSMesaGetProcAddress("glFinish");
    if (finish) finish();
    const unsigned char *p = gl->pixels + ((size_t)(gl->height - 1 - y) * gl->width + x) * 4;
    for (int i = 0; i < 4; i++) rgba[i] = p[i];
}

int test_gl_width(const test_gl *gl) { return gl->width; }
int test_gl_height(const test_gl *gl) { return gl->height; }

int test_gl_write_png(test_gl *gl, const char *path) {
    void (*finish)(void) = (void (*)(void))OSMesaGetProcAddress("glFinish");
    if (finish) finish();
    png_image img = {0};
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)gl->width;
    img.height = (png_uint_32)gl->height;
    img.format = PNG_FORMAT_RGBA;
    /* A negative stride writes the bottom-up buffer top row first. */
    int ok = png_image_write_to_file(&img, path, 0, gl->pixels, -(png_int_32)(gl->width * 4), NULL);
    return ok ? 0 : -1;
}
