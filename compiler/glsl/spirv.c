/* spirv.c: the SPIR-V target. See spirv.h; the rules are in docs/conventions.md ("SPIR-V"). */
#include "glsl/spirv.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/sbuf.h"
#include "glsl/glslang.h"
#include "spirv_loc.h"

#ifdef HFX_HAVE_GLSLANG
#include <glslang/Include/glslang_c_interface.h>
#include <glslang/Public/resource_limits_c.h>
#endif

/* --- uniform locations: common/spirv_loc.c, shared with the runtime ----------------------------- */

int32_t hfx_spirv_location(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *glsl_name) {
    return hfx_fx_spirv_location(fx, p, glsl_name);
}

/* --- reflection ------------------------------------------------------------------------------- */

enum { OP_NAME = 5, OP_DECORATE = 71, DEC_BINDING = 33, DEC_LOCATION = 30 };

int hfx_spirv_find(const uint32_t *words, size_t count, const char *name, int32_t *location, int32_t *binding) {
    if (location) *location = -1;
    if (binding) *binding = -1;
    if (!words || count < 5 || words[0] != HFX_SPIRV_MAGIC || !name) return -1;
    size_t len = strlen(name);
    uint32_t id = 0;
    for (size_t i = 5; i < count;) { /* OpName first: it precedes every decoration */
        uint32_t n = words[i] >> 16, op = words[i] & 0xffffu;
        if (n == 0 || i + n > count) return -1;
        if (op == OP_NAME && n >= 3) {
            const char *s = (const char *)&words[i + 2];
            size_t max = (n - 2) * 4;
            if (len < max && memcmp(s, name, len) == 0 && s[len] == 0) {
                id = words[i + 1];
                break;
            }
        }
        i += n;
    }
    if (!id) return 0;
    for (size_t i = 5; i < count;) {
        uint32_t n = words[i] >> 16, op = words[i] & 0xffffu;
        if (n == 0 || i + n > count) return -1;
        if (op == OP_DECORATE && n >= 4 && words[i + 1] == id) {
            if (words[i + 2] == DEC_LOCATION && location) *location = (int32_t)words[i + 3];
            if (words[i + 2] == DEC_BINDING && binding) *binding = (int32_t)words[i + 3];
        }
        i += n;
    }
    return 1;
}

/* Does a UniformConstant variable hold a bool somewhere (a struct member, say)? Strict
 * validators reject that; glslang emits it for a uniform struct with bool members. */
enum { OP_TYPE_BOOL = 20, OP_TYPE_VECTOR = 23, OP_TYPE_MATRIX = 24, OP_TYPE_ARRAY = 28, OP_TYPE_STRUCT = 30,
       OP_TYPE_POINTER = 32, OP_VARIABLE = 59, STORAGE_UNIFORM_CONSTANT = 0 };

/* The OpType* instruction defining `id` (types have their result id in word 1). */
static const uint32_t *type_def(const uint32_t *w, size_t count, uint32_t id) {
    for (size_t i = 5; i < count;) {
        uint32_t n = w[i] >> 16, op = w[i] & 0xffffu;
        if (n == 0 || i + n > count) return NULL;
        if (op >= 19 && op <= 39 && n >= 2 && w[i + 1] == id) return &w[i];
        i += n;
    }
    return NULL;
}

static bool type_has_bool(const uint32_t *w, size_t count, uint32_t type, int depth) {
    const uint32_t *d = depth < 16 ? type_def(w, count, type) : NULL;
    if (!d) return false;
    uint32_t n = d[0] >> 16, op = d[0] & 0xffffu;
    switch (op) {
    case OP_TYPE_BOOL: return true;
    case OP_TYPE_VECTOR: case OP_TYPE_MATRIX: case OP_TYPE_ARRAY:
        return n >= 3 && type_has_bool(w, count, d[2], depth + 1);
    case OP_TYPE_STRUCT:
        for (uint32_t m = 2; m < n; m++)
            if (type_has_bool(w, count, d[m], depth + 1)) return true;
        return false;
    default: return false;
    }
}

static void name_of(const uint32_t *w, size_t count, uint32_t id, char *out, size_t size) {
    snprintf(out, size, "%%%u", id);
    for (size_t i = 5; i < count;) {
        uint32_t n = w[i] >> 16, op = w[i] & 0xffffu;
        if (n == 0 || i + n > count) return;
        if (op == OP_NAME && n >= 3 && w[i + 1] == id) {
            snprintf(out, size, "%.*s", (int)((n - 2) * 4), (const char *)&w[i + 2]);
            return;
        }
        i += n;
    }
}

int hfx_spirv_bool_uniform(const uint32_t *words, size_t count, char *name, size_t name_size) {
    if (!words || count < 5 || words[0] != HFX_SPIRV_MAGIC) return -1;
    for (size_t i = 5; i < count;) {
        uint32_t n = words[i] >> 16, op = words[i] & 0xffffu;
        if (n == 0 || i + n > count) return -1;
        if (op == OP_VARIABLE && n >= 4 && words[i + 3] == STORAGE_UNIFORM_CONSTANT) {
            const uint32_t *ptr = type_def(words, count, words[i + 1]);
            if (ptr && (ptr[0] & 0xffffu) == OP_TYPE_POINTER && (ptr[0] >> 16) >= 4 &&
                type_has_bool(words, count, ptr[3], 0)) {
                if (name && name_size) name_of(words, count, words[i + 2], name, name_size);
                return 1;
            }
        }
        i += n;
    }
    return 0;
}

/* --- glslang ------------------------------------------------------------------------------------ */

#define append_log hfx_glslang_append_log

#ifdef HFX_HAVE_GLSLANG

bool hfx_spirv_available(void) { return true; }
bool hfx_spirv_begin(void) { return hfx_glslang_begin(); }
void hfx_spirv_end(void) { hfx_glslang_end(); }

static const glslang_stage_t stages[HFX_STAGE_COUNT] = {GLSLANG_STAGE_VERTEX, GLSLANG_STAGE_FRAGMENT};
static const char *const stage_names[HFX_STAGE_COUNT] = {"vertex", "fragment"};

#define MESSAGES GLSLANG_MSG_SPV_RULES_BIT

static glslang_shader_t *compile_stage(const char *src, int stage, bool vulkan, char **log) {
    glslang_input_t in;
    memset(&in, 0, sizeof in);
    in.language = GLSLANG_SOURCE_GLSL;
    in.stage = stages[stage];
    in.client = vulkan ? GLSLANG_CLIENT_VULKAN : GLSLANG_CLIENT_OPENGL;
    in.client_version = vulkan ? GLSLANG_TARGET_VULKAN_1_0 : GLSLANG_TARGET_OPENGL_450;
    in.target_language = GLSLANG_TARGET_SPV;
    in.target_language_version = GLSLANG_TARGET_SPV_1_0;
    in.code = src;
    in.default_version = 450;
    in.default_profile = GLSLANG_CORE_PROFILE;
    in.messages = MESSAGES;
    in.resource = glslang_default_resource();
    glslang_shader_t *sh = glslang_shader_create(&in);
    if (!sh) return NULL;
    /* Varyings carry no location in the GLSL: glslang gives them matching ones when linking.
     * Bindings are not auto-mapped: samplers have theirs (the texture unit), and a binding on
     * a loose non-opaque uniform means nothing to OpenGL. */
    if (!vulkan) glslang_shader_set_options(sh, GLSLANG_SHADER_AUTO_MAP_LOCATIONS); /* Vulkan's are explicit */
    if (!glslang_shader_preprocess(sh, &in) || !glslang_shader_parse(sh, &in)) {
        char what[64];
        snprintf(what, sizeof what, "%s shader: ", stage_names[stage]);
        *log = append_log(*log, what, glslang_shader_get_info_log(sh));
        *log = append_log(*log, what, glslang_shader_get_info_debug_log(sh));
        glslang_shader_delete(sh);
        return NULL;
    }
    return sh;
}

/* Both stages of p for `target` (HFX_TARGET_SPIRV or HFX_TARGET_SPIRV_VK). */
static int spirv_program(const hfx_fx_effect *fx, hfx_fx_program *p, int target, char **log) {
    bool vulkan = target == HFX_TARGET_SPIRV_VK;
    if (log) *log = NULL;
    char *dummy = NULL, **lg = log ? log : &dummy;
    glslang_shader_t *sh[HFX_STAGE_COUNT] = {NULL, NULL};
    glslang_program_t *prog = glslang_program_create();
    int rc = prog ? 0 : -1, stages_in = 0;
    for (int s = 0; s < HFX_STAGE_COUNT && rc == 0; s++) {
        const char *src = p->code[s][target].data; /* the printer's GLSL for this target (glsl_spirv.c) */
        if (!src) continue;
        sh[s] = compile_stage(src, s, vulkan, lg);
        if (!sh[s]) rc = -1;
        else glslang_program_add_shader(prog, sh[s]), stages_in++;
    }
    if (rc == 0 && !stages_in) {
        *lg = append_log(*lg, "", "the program has no GLSL to compile");
        rc = -1;
    }
    if (rc == 0 && (!glslang_program_link(prog, MESSAGES) || !glslang_program_map_io(prog))) {
        *lg = append_log(*lg, "link: ", glslang_program_get_info_log(prog));
        *lg = append_log(*lg, "link: ", glslang_program_get_info_debug_log(prog));
        rc = -1;
    }
    for (int s = 0; s < HFX_STAGE_COUNT && rc == 0; s++) {
        if (!sh[s]) continue;
        /* glslang 12 appends each stage's module to the program's words: take the new tail. */
        size_t before = glslang_program_SPIRV_get_size(prog);
        glslang_program_SPIRV_generate(prog, stages[s]);
        *lg = append_log(*lg, "spirv: ", glslang_program_SPIRV_get_messages(prog));
        size_t words = glslang_program_SPIRV_get_size(prog);
        const unsigned *w = glslang_program_SPIRV_get_ptr(prog);
        if (w && before && words > before && w[before] == HFX_SPIRV_MAGIC) {
            w += before;
            words -= before;
        }
        char *data = words && w ? malloc(words * 4 + 1) : NULL; /* +1: code stays NUL-terminated */
        if (!data) {
            *lg = append_log(*lg, "", "SPIR-V generation failed");
            rc = -1;
            break;
        }
        memcpy(data, w, words * 4);
        data[words * 4] = 0;
        free(p->code[s][target].data);
        p->code[s][target].data = data;
        p->code[s][target].size = words * 4;
    }
    if (prog) glslang_program_delete(prog);
    for (int s = 0; s < HFX_STAGE_COUNT; s++)
        if (sh[s]) glslang_shader_delete(sh[s]);
    if (rc != 0)
        for (int s = 0; s < HFX_STAGE_COUNT; s++) {
            free(p->code[s][target].data);
            p->code[s][target].data = NULL;
            p->code[s][target].size = 0;
        }
    free(dummy);
    return rc;
}

int hfx_spirv_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log) {
    return spirv_program(fx, p, HFX_TARGET_SPIRV, log);
}

int hfx_spirv_vk_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log) {
    return spirv_program(fx, p, HFX_TARGET_SPIRV_VK, log);
}

#else /* built without glslang */

bool hfx_spirv_available(void) { return false; }
bool hfx_spirv_begin(void) { return false; }
void hfx_spirv_end(void) {}

int hfx_spirv_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log) {
    (void)fx, (void)p;
    if (log) *log = append_log(NULL, "", "hfx was built without glslang: no SPIR-V");
    return -1;
}

int hfx_spirv_vk_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log) {
    return hfx_spirv_program(fx, p, log);
}

#endif
