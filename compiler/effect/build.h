/* build.h: from the checked tree to the compiled effect: parameters, annotations, samplers,
 * techniques, passes and their states (build.c), and one GLSL program per pass through the IR
 * (ir.c, lower/, glsl.c). */
#ifndef HFX_BUILD_H
#define HFX_BUILD_H

#include "parse/ast.h"
#include "effect.h"

/* targets: bits (1 << hfx_target). Returns NULL (with errors in diags) on failure. The effect
 * is malloc'ed (hfx_fx_effect_free), independent of the arena. */
hfx_fx_effect *hfx_build_effect(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                const char *source_name, unsigned targets);
/* fxc's /E entry /T profile: the parameters plus one technique (named after the entry) with one
 * pass "p0" compiling `entry` for `profile` ("vs_3_0", "ps_2_0"...). Same ownership rules. */
hfx_fx_effect *hfx_build_entry_effect(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                      const char *source_name, unsigned targets, const char *entry,
                                      const char *profile);

/* The code targets the printer must make for `requested`: the SPIR-V targets are made from GLSL
 * 330 (its text records both stages' uniforms), so that one is printed too. */
unsigned hfx_build_code_targets(unsigned requested);
/* The SPIR-V step every effect goes through, compiled from source (build.c) or read from an
 * fx_2_0 binary (fx2_states.c): the printer's SPIR-V-mode text of every program (printed with
 * hfx_build_code_targets' targets) through glslang into words for each requested SPIR-V target,
 * failures reported at `at`; the GLSL 330 goes again unless requested. Without glslang the
 * SPIR-V targets stay empty. Call it with the arena's escape off (glslang holds its own memory). */
void hfx_build_spirv(hfx_diags *diags, hfx_loc at, hfx_fx_effect *fx, unsigned requested);
#endif
