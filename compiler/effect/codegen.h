/* codegen.h: one GLSL program per pass, through the IR: ir.c builds it from the checked tree,
 * lower/ specialises, folds and cleans it, glsl.c prints it for each target.
 *
 * Contract with build.c: before calling hfx_codegen_program, build.c has filled fx->params
 * (with glsl_name) and fx->samplers, and set `index` of every global uniform hfx_decl to its
 * top-level parameter index (HFX_NONE for static globals, which codegen makes private). */
#ifndef HFX_CODEGEN_H
#define HFX_CODEGEN_H

#include "d3d9/d3d9.h"
#include "parse/ast.h"
#include "effect.h"

typedef struct hfx_codegen hfx_codegen;

/* Do two compile expressions build the same shader (same entry, profile and argument values)? */
typedef bool (*hfx_same_compile_fn)(void *ctx, const hfx_expr *x, const hfx_expr *y);

/* pack: HFXC_PACK_UNIFORMS (effect.h, "hfx_c"). same (with same_ctx): stages are built and
 * lowered once per distinct compile expression and shared by every program that uses them. */
hfx_codegen *hfx_codegen_new(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                             hfx_fx_effect *fx, unsigned targets, bool pack, hfx_same_compile_fn same, void *same_ctx);
/* Some pass of the effect enables the alpha test: pixel shaders writing COLOR0 carry it. */
void hfx_codegen_set_alpha_test(hfx_codegen *cg, bool on);
/* vs, ps: the pass's VertexShader / PixelShader values (EX_COMPILE; NULL when not set).
 * Fills *out (malloc'ed members, freed with the effect); may set fx->samplers[i].dim.
 * Returns 0, or -1 with errors in diags. */
int hfx_codegen_program(hfx_codegen *cg, const hfx_expr *vs, const hfx_expr *ps, bool flat_colors, hfx_fx_program *out);
/* The same from fxc's bytecode (the fx_2_0 reader, per pass): vs, ps decoded by hfx_d3d9_decode (NULL:
 * no shader, the fixed-function stand-in), each translated by hfx_d3d9_to_ir into the IR, lowered,
 * printed for every target (the caller runs glslang's self-check over them, as the fx_2_0 reader
 * does with every program it loads); attributes, samplers and
 * uniforms filled from fx->params / fx->samplers, which the reader has filled (CTAB names are the
 * parameters' names). ast may be NULL in hfx_codegen_new for this use. Returns 0, or -1 with
 * located errors (X5006 for bytecode the translator does not handle). */
int hfx_codegen_d3d9_program(hfx_codegen *cg, const d3d9_shader *vs, const d3d9_shader *ps, bool flat_colors,
                             hfx_fx_program *out);

/* D3D9 bytecode (compiler/bytecode) of one shader of a pass, for h32b's fx_2_0 writer and fxc's
 * /T vs_* | ps_*: `compile` is the stage's EX_COMPILE (its profile names the model); *count words,
 * in the codegen's arena. NULL with located errors. */
const uint32_t *hfx_codegen_bytecode(hfx_codegen *cg, const hfx_expr *compile, bool pixel, uint32_t *count);
/* fxc /T profile /E entry: the entry's bytecode; fx holds the parameters (hfx_build_entry_effect). */
const uint32_t *hfx_codegen_entry_bytecode(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                           hfx_fx_effect *fx, const char *entry, const char *profile, uint32_t *count);

#endif
