/* check.h: type checking (check.c, with intrinsics.c): resolves names, overloads and
 * intrinsics, inserts implicit conversions, reports fxc's errors and warnings. */
#ifndef HFX_CHECK_H
#define HFX_CHECK_H

#include <stdbool.h>

#include "ast.h"

/* Decorates the tree in place (see the invariants in ast.h). Returns true when no error. */
bool hfx_check(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast);

#endif
