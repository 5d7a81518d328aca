/* context.c: OSMesa (always) and GLFW (when HFX_HAVE_GLFW) contexts. */
#include "context.h"

#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef HFX_HAVE_GLFW
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#endif

struct hv_context {
    OSMesaContext osmesa;
    unsigned char *pixels; /* OSMesa's colour buffer */
#ifdef HFX_HAVE_GLFW
    GLFWwindow *window;
    unsigned char keys[GLFW_KEY_LAST + 1]; /* 1 = went down, not yet reported */
#endif
    hv_gl gl;
};

#ifdef __SANITIZE_ADDRESS__
/* Mesa's OSMesaMakeCurrent leaks a few hundred bytes per context (its framebuffer wrapper),
 * whatever the caller does; LeakSanitizer asks this hook what not to report. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:libOSMesa.so\n"; }
#endif

static void *osmesa_loader(const char *name) {
    OSMESAproc p = OSMesaGetProcAddress(name);
    void *q;
    memcpy(&q, &p, sizeof q);
    return q;
}

static int create_osmesa(hv_context *c, int width, int height, char *err, size_t errlen) {
    static const int attrs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                                OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                                OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    c->osmesa = OSMesaCreateContextAttribs(attrs, NULL);
    c->pixels = malloc((size_t)width * (size_t)height * 4);
    if (!c->osmesa || !c->pixels || !OSMesaMakeCurrent(c->osmesa, c->pixels, GL_UNSIGNED_BYTE, width, height)) {
        snprintf(err, errlen, "OSMesa cannot create a %dx%d OpenGL 3.3 core context", width, height);
        return 0;
    }
    return 1;
}

#ifdef HFX_HAVE_GLFW
static void *glfw_loader(const char *name) {
    GLFWglproc p = glfwGetProcAddress(name);
    void *q;
    memcpy(&q, &p, sizeof q);
    return q;
}

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods) {
    hv_context *c = glfwGetWindowUserPointer(w);
    if (action == GLFW_PRESS && key >= 0 && key <= GLFW_KEY_LAST) c->keys[key] = 1;
}

static int create_window(hv_context *c, int width, int height, char *err, size_t errlen) {
    if (!glfwInit()) {
        snprintf(err, errlen, "no window system (GLFW could not start): drawing headless");
        return 0;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    c->window = glfwCreateWindow(width, height, "hfxview", NULL, NULL);
    if (!c->window) {
        glfwTerminate();
        snprintf(err, errlen, "GLFW could not open an OpenGL 3.3 window: drawing headless");
        return 0;
    }
    glfwSetWindowUserPointer(c->window, c);
    glfwSetKeyCallback(c->window, on_key);
    glfwMakeContextCurrent(c->window);
    glfwSwapInterval(1);
    return 1;
}
#endif

hv_context *hv_context_create(int width, int height, int window, char *err, size_t errlen) {
    hv_context *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    int ok = 0;
#ifdef HFX_HAVE_GLFW
    if (window) ok = create_window(c, width, height, err, errlen);
#else
    if (window) snprintf(err, errlen, "built without GLFW: drawing headless");
#endif
    if (!ok && !create_osmesa(c, width, height, err, errlen)) {
        hv_context_destroy(c);
        return NULL;
    }
    const char *missing = hv_gl_load(&c->gl, hv_context_loader(c));
    if (missing) {
        snprintf(err, errlen, "the OpenGL context lacks %s", missing);
        hv_context_destroy(c);
        return NULL;
    }
    return c;
}

void hv_context_destroy(hv_context *c) {
    if (!c) return;
#ifdef HFX_HAVE_GLFW
    if (c->window) {
        glfwDestroyWindow(c->window);
        glfwTerminate();
    }
#endif
    if (c->osmesa) {
        OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0); /* else Mesa keeps the framebuffer */
        OSMesaDestroyContext(c->osmesa);
    }
    free(c->pixels);
    free(c);
}

hv_gl_loader hv_context_loader(const hv_context *c) {
#ifdef HFX_HAVE_GLFW
    if (c->window) return glfw_loader;
#endif
    return osmesa_loader;
}

const hv_gl *hv_context_gl(const hv_context *c) { return &c->gl; }

int hv_context_is_window(const hv_context *c) {
#ifdef HFX_HAVE_GLFW
    return c->window != NULL;
#else
    return 0;
#endif
}

int hv_context_should_close(hv_context *c) {
#ifdef HFX_HAVE_GLFW
    if (c->window) return glfwWindowShouldClose(c->window) || glfwGetKey(c->window, GLFW_KEY_ESCAPE) == GLFW_PRESS;
#endif
    return 1;
}

int hv_context_key_pressed(hv_context *c, int key) {
#ifdef HFX_HAVE_GLFW
    if (c->window && key >= 0 && key <= GLFW_KEY_LAST && c->keys[key]) {
        c->keys[key] = 0;
        return 1;
    }
#endif
    return 0;
}

void hv_context_present(hv_context *c) {
#ifdef HFX_HAVE_GLFW
    if (c->window) {
        glfwSwapBuffers(c->window);
        glfwPollEvents();
    }
#endif
}
