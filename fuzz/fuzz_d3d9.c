/* D3D9 shader bytecode (compiler/d3d9): decode and validate any bytes; a shader that decodes
 * has no error and prints its listing; one that does not has at least one located error (line
 * 0, column inside the input). The translator to the IR and the program builder (GLSL for every
 * target) run on every decoded shader. */
#include <stdint.h>
#include <stdlib.h>

#include "base/arena.h"
#include "base/diag.h"
#include "d3d9/d3d9.h"
#include "fuzz_check.h"
#include "effect/codegen.h"
#include "ir/ir.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (size > UINT32_MAX / 2) return 0;
    hfx_arena arena;
    hfx_arena_init(&arena);
    hfx_diags diags;
    hfx_diags_init(&diags, &arena, HFXC_NO_SELF_CHECK); /* speed; fuzz_diff is the harness that runs glslang */
    d3d9_input in = {data, (uint32_t)size, hfx_diags_add_file(&diags, "fuzz.vso", NULL, "", 0), 16};
    d3d9_shader *s = hfx_d3d9_decode(&arena, &diags, &in);
    fuzz_require(s ? diags.errors == 0 : diags.errors > 0, "decode's result and its errors disagree");
    for (uint32_t i = 0; i < diags.count; i++)
        fuzz_require(diags.items[i].line == 0 && diags.items[i].col >= 16 && diags.items[i].col <= 16 + size,
                     "a bytecode error located outside the input");
    if (s) {
        sbuf b = {0};
        b.arena = &arena;
        hfx_d3d9_disassemble(s, &b);
        fuzz_require(b.oom || (b.d && b.len > 0), "an empty listing");
        ir_ctx c = {&arena, &diags, hfx_types_new(&arena), NULL, NULL};
        uint32_t before = diags.errors;
        struct ir_shader *sh = hfx_d3d9_to_ir(&c, s, true);
        fuzz_require(sh ? diags.errors == before : diags.errors > before, "to_ir's result and its errors disagree");
        /* the whole program path: lowering, interface, registers, GLSL for every target */
        hfx_fx_effect fx = {0};
        unsigned targets = (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300) | (1u << HFX_TARGET_GLSL110);
        hfx_codegen *cg = hfx_codegen_new(&arena, &diags, c.types, NULL, &fx, targets, size & 1, NULL, NULL);
        hfx_fx_program prog;
        before = diags.errors;
        int rc = hfx_codegen_d3d9_program(cg, s->stage == D3D9_VS ? s : NULL, s->stage == D3D9_PS ? s : NULL, false, &prog);
        fuzz_require(rc == 0 ? diags.errors == before : diags.errors > before, "the program's result and its errors disagree");
        hfx_fx_program_clear(&prog);
    }
    free(hfx_diags_format(&diags, 1));
    hfx_arena_free(&arena);
    return 0;
}
