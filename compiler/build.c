#include "build.h"

#include <stdlib.h>

hfx_fx_effect *hfx_build_effect(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                const char *source_name, unsigned targets) {
    (void)arena; (void)types; (void)ast; (void)source_name; (void)targets;
    hfx_error(diags, (hfx_loc){0, 0, 0}, X_UNSUPPORTED, "code generation is not implemented yet");
    return NULL;
}
