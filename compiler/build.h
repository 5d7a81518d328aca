/* build.h: from the checked tree to the compiled effect: parameters, annotations, samplers,
 * techniques, passes and their states (build.c), and one GLSL program per pass through the IR
 * (ir.c, lower/, glsl.c). */
#ifndef HFX_BUILD_H
#define HFX_BUILD_H

#include "ast.h"
#include "effect.h"

/* targets: bits (1 << hfx_target). Returns NULL (with errors in diags) on failure. The effect
 * is malloc'ed (hfx_fx_effect_free), independent of the arena. */
hfx_fx_effect *hfx_build_effect(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                const char *source_name, unsigned targets);

#endif
