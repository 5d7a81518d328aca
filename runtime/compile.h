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

/* Files a compile read (hfxc_dependency_at): malloc'ed paths in a malloc'ed array. */
typedef struct hfx_rt_files {
    char **paths;
    size_t count;
} hfx_rt_files;

void hfx_rt_files_free(hfx_rt_files *f);
/* hfx_rt_compile_fx that also hands back, in *deps (may be NULL), the files the compile read. */
hfx_fx_effect *hfx_rt_compile_fx_deps(const char *path, const void *data, size_t size, const char *name,
                                      const hfx_load_options *opt, char **errors, hfx_rt_files *deps);

#endif
