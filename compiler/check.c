#include "check.h"

bool hfx_check(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast) {
    (void)arena; (void)types; (void)ast;
    return diags->errors == 0;
}
