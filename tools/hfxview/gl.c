/* gl.c: loading the GL table (see gl.h). */
#include "gl.h"

#include <string.h>

const char *hv_gl_load(hv_gl *gl, hv_gl_loader load) {
    memset(gl, 0, sizeof *gl);
    void *p;
    /* Function and object pointers share a representation on every platform GL runs on (POSIX
     * dlsym relies on it too); memcpy keeps -Wpedantic quiet about the conversion. */
#define HV_GL_LOAD(type, name)                 \
    if (!(p = load("gl" #name))) return "gl" #name; \
    memcpy(&gl->name, &p, sizeof p);
    HV_GL_FUNCTIONS(HV_GL_LOAD)
#undef HV_GL_LOAD
    return NULL;
}
