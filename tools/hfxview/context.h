/* context.h: where hfxview draws: an OpenGL 3.3 core context, headless on OSMesa by default,
 * headless on EGL (surfaceless, into a framebuffer object) when asked for and built with EGL,
 * or a GLFW window when asked for and built with GLFW. */
#ifndef HFXVIEW_CONTEXT_H
#define HFXVIEW_CONTEXT_H

#include <stddef.h>

#include "gl.h"

typedef struct hv_context hv_context;

/* What hv_context_create makes (0 and 1 keep the old meaning of its `window` flag). */
enum {
    HV_CONTEXT_OSMESA = 0, /* OSMesa's own buffer: the default framebuffer */
    HV_CONTEXT_WINDOW = 1, /* a GLFW window (falls back to OSMesa with a note in err when impossible) */
    HV_CONTEXT_EGL = 2     /* headless EGL (surfaceless or device platform), drawing into a framebuffer
                            * object with RGBA8 colour and depth24 / stencil8 renderbuffers, left bound
                            * for drawing and reading; the hfx runtime flips y there (D3D9's row order),
                            * so hv_read_image does not flip its rows. No fallback: NULL with err. */
};

/* Makes the context current. kind: HV_CONTEXT_*. NULL with err on failure. */
hv_context *hv_context_create(int width, int height, int kind, char *err, size_t errlen);
void hv_context_destroy(hv_context *c);
hv_gl_loader hv_context_loader(const hv_context *c); /* for hv_gl_load and hfx_device_create_gl */
const hv_gl *hv_context_gl(const hv_context *c);     /* the loaded entry points */
int hv_context_is_window(const hv_context *c);
int hv_context_is_egl(const hv_context *c);
int hv_context_should_close(hv_context *c);         /* window closed or Escape pressed; 1 when headless */
int hv_context_key_pressed(hv_context *c, int key); /* a GLFW key went down since the last call */
void hv_context_present(hv_context *c);             /* swap buffers and poll events (window only) */

#endif
