/* spirv.h: the SPIR-V target (HFX_TARGET_SPIRV), for OpenGL 4.6 / ARB_gl_spirv. Each program's
 * GLSL 330 (which the builder asks the code generator for) is rewritten for SPIR-V (#version
 * 450, explicit uniform locations and sampler bindings, bool uniforms as int) and compiled by
 * glslang (client OpenGL 450, SPIR-V 1.0), both stages linked together so the varyings get
 * matching locations. docs/conventions.md ("SPIR-V") has the location rules.
 *
 * Thread safety: glslang's process state is reference counted under its own lock (glslang 12:
 * ShInitialize / ShFinalize take the global lock, which is set up with pthread_once), so every
 * compilation brackets its work with hfx_spirv_begin / hfx_spirv_end and no state of ours is
 * shared. */
#ifndef HFX_SPIRV_H
#define HFX_SPIRV_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "effect.h"

#define HFX_SPIRV_MAGIC 0x07230203u

bool hfx_spirv_available(void);   /* false when the compiler was built without glslang */
bool hfx_spirv_begin(void);       /* glslang_initialize_process; false when it failed */
void hfx_spirv_end(void);         /* glslang_finalize_process, once per successful begin */

/* The GLSL the SPIR-V is compiled from: code[stage][HFX_TARGET_GLSL330] of p rewritten as above.
 * malloc'ed; NULL when the program has no GLSL 330 for that stage or out of memory. */
char *hfx_spirv_glsl(const hfx_fx_effect *fx, const hfx_fx_program *p, int stage);

/* Fills code[stage][HFX_TARGET_SPIRV] (malloc'ed words, size in bytes) for both stages of p
 * from its GLSL 330 code. Between hfx_spirv_begin and hfx_spirv_end. Returns 0, or -1 with
 * glslang's messages in *log (malloc'ed, may be NULL). */
int hfx_spirv_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log);

/* The uniform location the SPIR-V gives top-level parameter `param` (HFX_NONE-free rule, the
 * same in every program of the effect), or -1 when it is not a uniform. */
int32_t hfx_spirv_param_location(const hfx_fx_effect *fx, uint32_t param);

/* Reflection: the Location and Binding decorations (-1 when absent) of the variable OpName'd
 * `name` in a module. Returns 1 when found, 0 when not, -1 when `words` is not SPIR-V. */
int hfx_spirv_find(const uint32_t *words, size_t count, const char *name, int32_t *location, int32_t *binding);

#endif
