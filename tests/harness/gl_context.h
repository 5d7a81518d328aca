/* gl_context.h: a headless OpenGL 3.3 core context on OSMesa (llvmpipe) for tests. */
#ifndef HFX_TEST_GL_CONTEXT_H
#define HFX_TEST_GL_CONTEXT_H

typedef struct test_gl test_gl;

test_gl *test_gl_create(int width, int height);   /* made current; NULL if OSMesa refuses */
/* The same with another core profile version (4.5: ARB_gl_spirv on llvmpipe). */
test_gl *test_gl_create_version(int width, int height, int major, int minor);
void test_gl_destroy(test_gl *gl);
void *test_gl_loader(const char *name);           /* an hfx_gl_loader */
void *test_gl_proc(const char *name);             /* same, for calling GL from a test */
/* Pixel at column x, row y counted from the top of the image (as in a PNG), after glFinish. */
void test_gl_read(test_gl *gl, int x, int y, unsigned char rgba[4]);
int test_gl_width(const test_gl *gl);
int test_gl_height(const test_gl *gl);
int test_gl_write_png(test_gl *gl, const char *path); /* 0 on success; for looking at failures */

#endif
