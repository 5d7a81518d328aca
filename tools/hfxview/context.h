/* context.h: where hfxview draws: an OpenGL 3.3 core context, headless on OSMesa by default,
 * or a GLFW window when asked for and built with GLFW. */
#ifndef HFXVIEW_CONTEXT_H
#define HFXVIEW_CONTEXT_H

#include <stddef.h>

#include "gl.h"

typedef struct hv_context hv_context;

/* Makes the context current. window: 1 for a GLFW window (falls back to headless with a note
 * in err when impossible), 0 for OSMesa. NULL with err on failure. */
hv_context *hv_context_create(int width, int height, int window, char *err, size_t errlen);
void hv_context_destroy(hv_context *c);
hv_gl_loader hv_context_loader(const hv_context *c); /* for hv_gl_load and hfx_device_create_gl */
const hv_gl *hv_context_gl(const hv_context *c);     /* the loaded entry points */
int hv_context_is_window(const hv_context *c);
int hv_context_should_close(hv_context *c);         /* window closed or Escape pressed; 1 when headless */
int hv_context_key_pressed(hv_context *c, int key); /* a GLFW key went down since the last call */
void hv_context_present(hv_context *c);             /* swap buffers and poll events (window only) */

#endif
