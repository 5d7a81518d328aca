#include "token.h"

hfx_token *hfx_preprocess(hfx_arena *arena, hfx_diags *diags, const char *name, const char *text,
                          uint32_t size, const hfx_pp_options *opt) {
    (void)opt;
    uint32_t f = hfx_diags_add_file(diags, name, name, text ? text : "", text ? size : 0);
    return hfx_tokenize(arena, diags, f);
}
