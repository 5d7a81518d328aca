/* device_core.c: what every device has, whatever its back end: the last error's message,
 * load-time warnings, and destruction through the back end's table. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

int hfx_rt_fail(hfx_device *dev, int code, const char *fmt, ...) {
    if (!dev) return code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(dev->error, sizeof dev->error, fmt, ap);
    va_end(ap);
    return code;
}

/* A load-time note about the effect (a state GL honours only in part), with the state's
 * position: hfx_effect_warnings returns them all. */
void hfx_shared_warn(hfx_shared *sh, const hfx_fx_state *st, const char *fmt, ...) {
    char msg[512], line[700];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const char *name = sh->fx->source_name ? sh->fx->source_name : "effect";
    if (st && st->line)
        snprintf(line, sizeof line, "%s(%u,%u): warning: %s\n", name, (unsigned)st->line, (unsigned)st->col, msg);
    else
        snprintf(line, sizeof line, "%s: warning: %s\n", name, msg);
    size_t n = strlen(line);
    char *w = realloc(sh->warnings, sh->warnings_len + n + 1);
    if (!w) return;
    memcpy(w + sh->warnings_len, line, n + 1);
    sh->warnings = w;
    sh->warnings_len += n;
}

void hfx_device_destroy(hfx_device *dev) {
    if (dev) dev->be->device_destroy(dev);
}

const char *hfx_device_last_error(const hfx_device *dev) { return dev ? dev->error : "no device"; }

const char *hfx_result_string(int code) {
    switch (code) {
    case HFX_OK: return "no error";
    case HFX_ERR_NULL: return "a NULL handle or pointer";
    case HFX_ERR_TYPE: return "wrong type for this parameter";
    case HFX_ERR_COUNT: return "wrong number of values";
    case HFX_ERR_NOT_FOUND: return "unknown name or index";
    case HFX_ERR_GL: return "OpenGL refused";
    case HFX_ERR_LOAD: return "the effect did not compile or the file is not valid";
    case HFX_ERR_MEMORY: return "out of memory";
    case HFX_ERR_VULKAN: return "Vulkan refused";
    case HFX_ERR_STATE: return "a call out of order";
    default: return "unknown result";
    }
}

void hfx_free(void *p) { free(p); }
