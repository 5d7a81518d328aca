/* spirv_loc.h: the uniform locations of a program's SPIR-V (docs/conventions.md, "SPIR-V"), as
 * pure computations on the compiled effect. The compiler writes them into the SPIR-V (through
 * hfx_spirv_location); the runtime drives the uniforms by them, since ARB_gl_spirv programs have
 * no uniform names to look up. One implementation, so the two cannot drift apart. */
#ifndef HFX_COMMON_SPIRV_LOC_H
#define HFX_COMMON_SPIRV_LOC_H

#include <stddef.h>
#include <stdint.h>

#include "effect.h"

/* Vulkan (HFX_TARGET_SPIRV_VK): descriptor set 0 holds the program's uniform block (both
 * stages declare the same one), then its samplers in p->samplers' order. */
enum { HFX_VK_BINDING_BLOCK = 0, HFX_VK_BINDING_SAMPLER0 = 1 };

/* The known internal uniforms, in their order after the samplers. */
enum { HFX_SPIRV_POS_FIXUP, HFX_SPIRV_ALPHA_FUNC, HFX_SPIRV_ALPHA_REF, HFX_SPIRV_KNOWN_COUNT };

/* Order: p->uniforms not packed, hfx_c (p->reg_count), samplers, known internal, any other. */

/* Locations parameter i takes in GL's default uniform block: 1 per scalar, vector, matrix or
 * sampler; array elements and struct members one after the other. */
uint64_t hfx_fx_param_locations(const hfx_fx_effect *fx, uint32_t i);

/* The index in p->uniforms of the uniform parameter whose GLSL name is name[0..len), with its
 * location in *loc; -1 when none, and *loc = the end of the uniforms (where samplers start).
 * Packed parameters (HFXC_PACK_UNIFORMS) are skipped: they take no location; hfx_c takes
 * p->reg_count locations right after the unpacked ones, so the end counts them too. */
int64_t hfx_fx_spirv_uniform(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *name, size_t len,
                             uint64_t *loc);
uint64_t hfx_fx_spirv_regs_location(const hfx_fx_effect *fx, const hfx_fx_program *p); /* location of hfx_c[0] */
/* 1 when name[0..len) is hfx_c and p packs parameters into it. */
int hfx_fx_spirv_is_regs(const hfx_fx_program *p, const char *name, size_t len);
/* The index in p->samplers of the sampler named name[0..len), or -1. */
int64_t hfx_fx_spirv_sampler(const hfx_fx_program *p, const char *name, size_t len);
/* HFX_SPIRV_POS_FIXUP... for a known internal uniform's name, or -1. */
int64_t hfx_fx_spirv_known(const char *name, size_t len);

/* The location of uniform `glsl_name` in program p's SPIR-V, or -1 (see hfx_spirv_location). */
int32_t hfx_fx_spirv_location(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *glsl_name);

#endif
