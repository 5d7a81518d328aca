/* token_cache.h: the tokens of the files a session has already read, so that a header that
 * many effects include is cut into tokens once per session, not once per compile. Owned by
 * the caller (hfxc_session): no global state; one cache must not serve two threads at once. */
#ifndef HFX_TOKEN_CACHE_H
#define HFX_TOKEN_CACHE_H

#include "pp/token.h"

typedef struct hfx_token_cache hfx_token_cache;

hfx_token_cache *hfx_token_cache_new(void); /* NULL when out of memory */
void hfx_token_cache_free(hfx_token_cache *c);
/* The tokens of diags file `file` (its text already read from `real`), in `arena`, as
 * hfx_tokenize_deferred makes them: a copy of the cached list when `real` was cut before with
 * exactly this text, else cut now and remembered (unless the lexer reported something). */
hfx_token *hfx_token_cache_tokenize(hfx_token_cache *c, hfx_arena *arena, hfx_diags *diags, uint32_t file,
                                    const char *real);

#endif
