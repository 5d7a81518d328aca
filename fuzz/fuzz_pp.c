/* The preprocessor alone (lexer, directives, macros, #line, pragmas): the token list must end
 * with exactly one TK_EOF, and turning it back into text (fxc's /P) must work too. Includes
 * name files that do not exist here, so they end in a located X1507. */
#include <stdint.h>
#include <stdlib.h>

#include "base/arena.h"
#include "base/diag.h"
#include "pp/token.h"
#include "fuzz_check.h"

static const char *const defines[] = {"FUZZ", "LIGHTS=4", "F(a)=a a"};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (size > UINT32_MAX / 2) return 0;
    hfx_arena arena;
    hfx_arena_init(&arena);
    hfx_diags diags;
    hfx_diags_init(&diags, &arena, 0);
    hfx_pp_options opt = {defines, 3, NULL, 0, 8, NULL};
    hfx_token *t = hfx_preprocess(&arena, &diags, "fuzz.fx", (const char *)data, (uint32_t)size, &opt);
    while (t && t->kind != TK_EOF) t = t->next;
    fuzz_require(t && !t->next, "the token list does not end with one TK_EOF");
    free(hfx_tokens_to_text(&diags, hfx_preprocess(&arena, &diags, "fuzz.fx", (const char *)data,
                                                    (uint32_t)size, NULL)));
    free(hfx_diags_format(&diags, 1));
    hfx_arena_free(&arena);
    return 0;
}
