/* spirv.h: the SPIR-V target (HFX_TARGET_SPIRV), for OpenGL 4.6 / ARB_gl_spirv. The GLSL
 * printer's SPIR-V mode (glsl/glsl_spirv.c: #version 450, explicit uniform locations and sampler
 * bindings, bool uniforms as int) leaves each program's GLSL text in code[stage][target], and it
 * is compiled here by
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

/* Replaces the GLSL text in code[stage][HFX_TARGET_SPIRV] of both stages of p by the SPIR-V
 * words (malloc'ed, size in bytes); on failure the code is freed. Between hfx_spirv_begin and hfx_spirv_end. Returns 0, or -1 with
 * glslang's messages in *log (malloc'ed, may be NULL). */
int hfx_spirv_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log);

/* Vulkan (HFX_TARGET_SPIRV_VK): the printer's Vulkan mode prints the loose uniforms of both stages gathered
 * into one std140 block `hfx_block` that both declare (set 0, binding HFX_VK_BINDING_BLOCK; the
 * runtime reads the members' offsets from the module), samplers at HFX_VK_BINDING_SAMPLER0 + their index in
 * p->samplers, and no depth remap (Vulkan's clip depth is D3D's 0..1). Compiled for Vulkan 1.0. */
int hfx_spirv_vk_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log);

/* The location the SPIR-V of program p gives the uniform `glsl_name`: p->uniforms in their order
 * (sorted by parameter) take GL's locations one after the other (1 per scalar, vector, matrix;
 * arrays and structs 1 per element / member; none for a packed one), then hfx_c (p->reg_count
 * locations, HFXC_PACK_UNIFORMS), then p->samplers in unit order (1 each, binding =
 * unit), then hfx_pos_fixup, hfx_alpha_func, hfx_alpha_ref. -1 for any other name (the rare
 * other uniform follows those, in first-appearance order; hfx_spirv_find reads it). */
int32_t hfx_spirv_location(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *glsl_name);

/* Reflection: the Location and Binding decorations (-1 when absent) of the variable OpName'd
 * `name` in a module. Returns 1 when found, 0 when not, -1 when `words` is not SPIR-V. */
int hfx_spirv_find(const uint32_t *words, size_t count, const char *name, int32_t *location, int32_t *binding);

/* 1 (and the variable's name) when a UniformConstant variable of the module holds a bool: a
 * uniform struct with bool members, which the printer's SPIR-V mode leaves bool and strict
 * validators (spirv-val) reject; 0 when none does, -1 when `words` is not SPIR-V. */
int hfx_spirv_bool_uniform(const uint32_t *words, size_t count, char *name, size_t name_size);

#endif
