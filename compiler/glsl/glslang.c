/* glslang.c: see glslang.h. */
#include "glsl/glslang.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *hfx_glslang_append_log(char *log, const char *what, const char *more) {
    if (!more || !*more) return log;
    size_t a = log ? strlen(log) : 0, w = strlen(what), b = strlen(more);
    char *p = realloc(log, a + w + b + 2);
    if (!p) return log;
    memcpy(p + a, what, w);
    memcpy(p + a + w, more, b + 1);
    if (b && more[b - 1] != '\n') memcpy(p + a + w + b, "\n", 2);
    return p;
}

#ifdef HFX_HAVE_GLSLANG

#include <glslang/Include/glslang_c_interface.h>
#include <glslang/Public/resource_limits_c.h>

#include <pthread.h>

bool hfx_glslang_available(void) { return true; }

/* glslang builds its built-in symbol tables (per version, profile and stage) when first used
 * and drops them when its process count falls to 0: one reference held for the life of the
 * process keeps them, so each compile does not rebuild them (measured: 49 ms an effect with
 * the rebuild, bench/bench_self_check). The once-flag is the only static state, and glslang's. */
static void pin_process(void) { (void)glslang_initialize_process(); }

bool hfx_glslang_begin(void) {
    static pthread_once_t pinned = PTHREAD_ONCE_INIT;
    pthread_once(&pinned, pin_process);
    return glslang_initialize_process() != 0;
}

void hfx_glslang_end(void) { glslang_finalize_process(); }

/* The version and profile a target's #version line names, for glslang's defaults. */
static void target_version(hfx_target t, int *version, glslang_profile_t *profile) {
    *version = t == HFX_TARGET_GLSLES300 ? 300 : t == HFX_TARGET_GLSL110 ? 110 : 330;
    *profile = t == HFX_TARGET_GLSLES300 ? GLSLANG_ES_PROFILE : t == HFX_TARGET_GLSL110 ? GLSLANG_NO_PROFILE
                                                                                           : GLSLANG_CORE_PROFILE;
}

int hfx_glslang_check(const char *src, int stage, hfx_target target, char **log) {
    glslang_input_t in;
    memset(&in, 0, sizeof in);
    in.language = GLSLANG_SOURCE_GLSL;
    in.stage = stage == 0 ? GLSLANG_STAGE_VERTEX : GLSLANG_STAGE_FRAGMENT;
    in.client = GLSLANG_CLIENT_NONE;
    in.target_language = GLSLANG_TARGET_NONE;
    in.code = src;
    target_version(target, &in.default_version, &in.default_profile);
    in.messages = GLSLANG_MSG_DEFAULT_BIT;
    in.resource = glslang_default_resource();
    glslang_shader_t *sh = glslang_shader_create(&in);
    if (!sh) {
        *log = hfx_glslang_append_log(*log, "", "glslang could not create a shader");
        return -1;
    }
    int ok = glslang_shader_preprocess(sh, &in) && glslang_shader_parse(sh, &in);
    if (!ok) *log = hfx_glslang_append_log(*log, "", glslang_shader_get_info_log(sh));
    glslang_shader_delete(sh);
    return ok ? 0 : -1;
}

#else /* built without glslang: nothing to check with */

bool hfx_glslang_available(void) { return false; }
bool hfx_glslang_begin(void) { return false; }
void hfx_glslang_end(void) {}

int hfx_glslang_check(const char *src, int stage, hfx_target target, char **log) {
    (void)src, (void)stage, (void)target, (void)log;
    return 0;
}

#endif
