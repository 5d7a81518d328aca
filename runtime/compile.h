/* compile.h: how the runtime turns .fx source into an effect. The `hfx` library links the
 * compiler (compile_fx.c); `hfx_runtime` links compile_none.c and loads only .hfxo files. */
#ifndef HFX_RUNTIME_COMPILE_H
#define HFX_RUNTIME_COMPILE_H

#include <stddef.h>

#include "effect.h"

/* path: the file to read when data is NULL; name: the name diagnostics use.
 * Returns NULL on failure with *errors (malloc'ed, may be NULL) holding the diagnostics. */
hfx_fx_effect *hfx_rt_compile_fx(const char *path, const void *data, size_t size, const char *name,
                                 const hfx_load_options *opt, char **errors);

#endif
