/* device.c: stub until the runtime lands. */
#include <stdlib.h>

#include "hfx/hfx.h"

hfx_device *hfx_device_create_gl(hfx_gl_loader load) { (void)load; return NULL; }
void hfx_device_destroy(hfx_device *dev) { (void)dev; }
void hfx_free(void *p) { free(p); }
