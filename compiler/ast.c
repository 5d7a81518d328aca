#include "ast.h"

#include <string.h>
#include <stdlib.h>

char *hfx_ast_dump(const hfx_ast *ast) {
    (void)ast;
    return strdup("");
}
