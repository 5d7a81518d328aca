/* test_d3d9_program.c: a pass's program from fxc bytecode (hfx_codegen_d3d9_program). Until the
 * translator to the IR handles a model, the program is refused with a located X5006 naming it,
 * never handed to a driver half translated. */
#include <stdlib.h>
#include <string.h>

#include "d3d9/d3d9.h"
#include "effect/codegen.h"
#include "test.h"

/* ps_2_0: dcl t0.xy; dcl_2d s0; texld r0, t0, s0; mov oC0, r0 (tokens by hand, d3d9_asm.h's layout). */
static const uint32_t ps20[] = {
    0xffff0200u, 0x0200001fu, 0x80000000u, 0xb0030000u, 0x0200001fu, 0x90000000u, 0xa00f0800u,
    0x03000042u, 0x800f0000u, 0xb0e40000u, 0xa0e40800u, 0x02000001u, 0x800f0800u, 0x80e40000u, 0x0000ffffu};

static void refused_with_location(void) {
    hfx_arena arena;
    hfx_diags diags;
    hfx_arena_init(&arena);
    hfx_diags_init(&diags, &arena, 0);
    uint32_t file = hfx_diags_add_file(&diags, "t.fxb", NULL, "", 0);
    d3d9_input in = {ps20, sizeof ps20, file, 96};
    d3d9_shader *ps = d3d9_decode(&arena, &diags, &in);
    CHECK(ps != NULL);
    hfx_fx_effect fx;
    memset(&fx, 0, sizeof fx);
    hfx_codegen *cg = hfx_codegen_new(&arena, &diags, hfx_types_new(&arena), NULL, &fx,
                                      1u << HFX_TARGET_GLSL330, true, NULL, NULL);
    hfx_fx_program prog;
    CHECK_INT(hfx_codegen_d3d9_program(cg, NULL, ps, false, &prog), -1);
    char *text = hfx_diags_format(&diags, 0);
    CHECK_STR(text, "t.fxb(0,96): error X5006: ps_2_0 bytecode to GLSL is not supported yet\n");
    free(text);
    hfx_fx_program_clear(&prog);
    hfx_arena_free(&arena);
}

int main(void) {
    RUN(refused_with_location);
    return test_summary();
}
