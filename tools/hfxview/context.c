/* context.c: OSMesa (always), EGL (when HFX_HAVE_EGL) and GLFW (when HFX_HAVE_GLFW) contexts. */
#include "context.h"

#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef HFX_HAVE_EGL
#define EGL_NO_X11 /* no Xlib types in eglplatform.h: only headless platforms are used */
#define MESA_EGL_NO_X11_HEADERS
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif

#ifdef HFX_HAVE_GLFW
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#endif

struct hv_context {
    OSMesaContext osmesa;
    unsigned char *pixels; /* OSMesa's colour buffer */
#ifdef HFX_HAVE_EGL
    EGLDisplay egl_display;
    EGLContext egl_context;
    GLuint fbo, renderbuffers[2]; /* colour RGBA8, depth24 / stencil8 */
#endif
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

#ifdef HFX_HAVE_EGL
static void *egl_loader(const char *name) {
    __eglMustCastToProperFunctionPointerType p = eglGetProcAddress(name);
    void *q;
    memcpy(&q, &p, sizeof q);
    return q;
}

/* `name` is one of the space-separated words of `list`. */
static int has_extension(const char *list, const char *name) {
    size_t n = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)) != NULL; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return 1;
    return 0;
}

/* EGL_MESA_platform_surfaceless first; else the first device of EGL_EXT_device_enumeration
 * (Mesa lists its software device there too). Initialised, or EGL_NO_DISPLAY. */
static EGLDisplay open_egl_display(void) {
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display = (PFNEGLGETPLATFORMDISPLAYEXTPROC)egl_loader("eglGetPlatformDisplayEXT");
    if (!client || !get_display) return EGL_NO_DISPLAY;
    EGLDisplay d = EGL_NO_DISPLAY;
    if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
        d = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, NULL, NULL)) return d;
    }
    PFNEGLQUERYDEVICESEXTPROC query_devices = (PFNEGLQUERYDEVICESEXTPROC)egl_loader("eglQueryDevicesEXT");
    if (query_devices && has_extension(client, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (query_devices(16, devices, &count))
            for (EGLint i = 0; i < count; i++) {
                d = get_display(EGL_PLATFORM_DEVICE_EXT, devices[i], NULL);
                if (d != EGL_NO_DISPLAY && eglInitialize(d, NULL, NULL)) return d;
            }
    }
    return EGL_NO_DISPLAY;
}

static int create_egl(hv_context *c, char *err, size_t errlen) {
    c->egl_display = open_egl_display();
    if (c->egl_display == EGL_NO_DISPLAY) {
        snprintf(err, errlen, "EGL: no headless display (neither EGL_MESA_platform_surfaceless nor an "
                              "EGL_EXT_device_enumeration device could be initialised)");
        return 0;
    }
    const char *ext = eglQueryString(c->egl_display, EGL_EXTENSIONS);
    if (!has_extension(ext, "EGL_KHR_surfaceless_context") || !eglBindAPI(EGL_OPENGL_API)) {
        snprintf(err, errlen, "EGL: the display has no surfaceless desktop OpenGL contexts");
        return 0;
    }
    static const EGLint config_attrs[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = NULL;
    EGLint configs = 0;
    if (!has_extension(ext, "EGL_KHR_no_config_context") &&
        (!eglChooseConfig(c->egl_display, config_attrs, &config, 1, &configs) || configs < 1)) {
        snprintf(err, errlen, "EGL: no configuration for desktop OpenGL");
        return 0;
    }
    static const EGLint context_attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                           EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                           EGL_NONE};
    c->egl_context = eglCreateContext(c->egl_display, config, EGL_NO_CONTEXT, context_attrs);
    if (c->egl_context == EGL_NO_CONTEXT ||
        !eglMakeCurrent(c->egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, c->egl_context)) {
        snprintf(err, errlen, "EGL cannot create an OpenGL 3.3 core context (error 0x%x)", (unsigned)eglGetError());
        return 0;
    }
    return 1;
}

/* The framebuffer object an EGL context draws into (no surface, so no default framebuffer). */
static int create_fbo(hv_context *c, int width, int height, char *err, size_t errlen) {
    const hv_gl *gl = &c->gl;
    gl->GenRenderbuffers(2, c->renderbuffers);
    gl->BindRenderbuffer(GL_RENDERBUFFER, c->renderbuffers[0]);
    gl->RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl->BindRenderbuffer(GL_RENDERBUFFER, c->renderbuffers[1]);
    gl->RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    gl->BindRenderbuffer(GL_RENDERBUFFER, 0);
    gl->GenFramebuffers(1, &c->fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, c->fbo); /* drawing and reading */
    gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, c->renderbuffers[0]);
    gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, c->renderbuffers[1]);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE || gl->GetError() != GL_NO_ERROR) {
        snprintf(err, errlen, "EGL: cannot make a complete %dx%d framebuffer object (status 0x%x)", width, height,
                 (unsigned)status);
        return 0;
    }
    gl->Viewport(0, 0, width, height);
    return 1;
}
#endif

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

hv_context *hv_context_create(int width, int height, int kind, char *err, size_t errlen) {
    hv_context *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    int ok = 0;
    if (kind == HV_CONTEXT_EGL) {
#ifdef HFX_HAVE_EGL
        ok = create_egl(c, err, errlen);
#else
        snprintf(err, errlen, "built without EGL: --egl is not available");
#endif
        if (!ok) {
            hv_context_destroy(c);
            return NULL;
        }
    }
#ifdef HFX_HAVE_GLFW
    if (kind == HV_CONTEXT_WINDOW) ok = create_window(c, width, height, err, errlen);
#else
    if (kind == HV_CONTEXT_WINDOW) snprintf(err, errlen, "built without GLFW: drawing headless");
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
#ifdef HFX_HAVE_EGL
    if (c->egl_context && !create_fbo(c, width, height, err, errlen)) {
        hv_context_destroy(c);
        return NULL;
    }
#endif
    return c;
}

void hv_context_destroy(hv_context *c) {
    if (!c) return;
#ifdef HFX_HAVE_EGL
    if (c->egl_context) {
        if (c->fbo) c->gl.DeleteFramebuffers(1, &c->fbo);
        if (c->renderbuffers[0]) c->gl.DeleteRenderbuffers(2, c->renderbuffers);
        eglMakeCurrent(c->egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(c->egl_display, c->egl_context);
    }
    /* No eglTerminate: Mesa would unload its driver there, and LeakSanitizer could then not
     * name (or suppress) the driver's own leftovers. The display is the process's anyway. */
    if (c->egl_display) eglReleaseThread();
#endif
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
#ifdef HFX_HAVE_EGL
    if (c->egl_context) return egl_loader;
#endif
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

int hv_context_is_egl(const hv_context *c) {
#ifdef HFX_HAVE_EGL
    return c->egl_context != NULL;
#else
    (void)c;
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
