#include "glsl_check.h"

#include <glslang/Include/glslang_c_interface.h>
#include <glslang/Public/resource_limits_c.h>
#include <stdlib.h>
#include <string.h>

static char *join_log(char *log, const char *more) {
    if (!more || !*more) return log;
    size_t a = log ? strlen(log) : 0, b = strlen(more);
    char *p = realloc(log, a + b + 1);
    if (!p) return log;
    memcpy(p + a, more, b + 1);
    return p;
}

static glslang_shader_t *compile(const char *src, int stage, char **log, int *ok) {
    static int initialised; /* glslang's own process state; tests are single threaded */
    if (!initialised) {
        glslang_initialize_process();
        initialised = 1;
    }
    glslang_input_t in;
    memset(&in, 0, sizeof in);
    in.language = GLSLANG_SOURCE_GLSL;
    in.stage = stage ? GLSLANG_STAGE_FRAGMENT : GLSLANG_STAGE_VERTEX;
    in.client = GLSLANG_CLIENT_NONE;
    in.client_version = GLSLANG_TARGET_OPENGL_450;
    in.target_language = GLSLANG_TARGET_NONE;
    in.code = src;
    in.default_version = 110;
    in.default_profile = GLSLANG_NO_PROFILE;
    in.messages = GLSLANG_MSG_DEFAULT_BIT;
    in.resource = glslang_default_resource();
    glslang_shader_t *sh = glslang_shader_create(&in);
    *ok = glslang_shader_preprocess(sh, &in) && glslang_shader_parse(sh, &in);
    if (log) {
        *log = join_log(*log, glslang_shader_get_info_log(sh));
        *log = join_log(*log, glslang_shader_get_info_debug_log(sh));
    }
    return sh;
}

int test_glsl_compile(const char *src, int stage, char **log) {
    int ok;
    if (log) *log = NULL;
    glslang_shader_t *sh = compile(src, stage, log, &ok);
    glslang_shader_delete(sh);
    return ok;
}

int test_glsl_link(const char *vs, const char *fs, char **log) {
    int ok_v, ok_f, ok = 0;
    if (log) *log = NULL;
    glslang_shader_t *v = compile(vs, 0, log, &ok_v);
    glslang_shader_t *f = compile(fs, 1, log, &ok_f);
    if (ok_v && ok_f) {
        glslang_program_t *p = glslang_program_create();
        glslang_program_add_shader(p, v);
        glslang_program_add_shader(p, f);
        ok = glslang_program_link(p, GLSLANG_MSG_DEFAULT_BIT);
        if (log) *log = join_log(*log, glslang_program_get_info_log(p));
        glslang_program_delete(p);
    }
    glslang_shader_delete(v);
    glslang_shader_delete(f);
    return ok;
}
