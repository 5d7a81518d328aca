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

#endif
