/* compile_none.c: `hfx_runtime` has no compiler: a .fx load fails with a message saying so. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compile.h"

hfx_fx_effect *hfx_rt_compile_fx_deps(const char *path, const void *data, size_t size, const char *name,
                                      const hfx_load_options *opt, char **errors, hfx_rt_files *deps) {
    if (deps) deps->paths = NULL, deps->count = 0;
    return hfx_rt_compile_fx(path, data, size, name, opt, errors);
}

hfx_fx_effect *hfx_rt_compile_fx(const char *path, const void *data, size_t size, const char *name,
                                 const hfx_load_options *opt, char **errors) {
    (void)path; (void)data; (void)size; (void)opt;
    if (errors) {
        const char *fmt = "%s: this program links hfx_runtime, which loads compiled effects (.hfxo) only; "
                          "compile the .fx with hfxc or link hfx";
        size_t n = strlen(fmt) + strlen(name ? name : "") + 1;
        *errors = malloc(n);
        if (*errors) snprintf(*errors, n, fmt, name ? name : "");
    }
    return NULL;
}
