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

/* Whether the bytes start like an effect fxc compiled (fx_2_0's magic, XNA's header, .xnb):
 * reading one needs the compiler's back end (bytecode to GLSL), as a .fx does. */
static int fxc_binary(const char *path, const void *data, size_t size) {
    unsigned char head[4] = {0};
    if (data && size >= 4) memcpy(head, data, 4);
    else if (!data && path) {
        FILE *f = fopen(path, "rb");
        if (!f) return 0;
        size_t n = fread(head, 1, 4, f);
        fclose(f);
        if (n < 4) return 0;
    }
    static const unsigned char fx2[4] = {0x01, 0x09, 0xff, 0xfe}, xna[4] = {0xcf, 0x0b, 0xf0, 0xbc};
    return !memcmp(head, fx2, 4) || !memcmp(head, xna, 4) || !memcmp(head, "XNB", 3);
}

hfx_fx_effect *hfx_rt_compile_fx(const char *path, const void *data, size_t size, const char *name,
                                 const hfx_load_options *opt, char **errors) {
    (void)opt;
    int binary = fxc_binary(path, data, size);
    if (errors) {
        const char *fmt = binary ? "%s: an effect compiled by fxc (fx_2_0); this program links hfx_runtime, which "
                                   "loads .hfxo files only: convert it with `hfxc -o X.hfxo X.fxb` or link hfx"
                                 : "%s: this program links hfx_runtime, which loads compiled effects (.hfxo) only; "
                                   "compile the .fx with hfxc or link hfx";
        size_t n = strlen(fmt) + strlen(name ? name : "") + 1;
        *errors = malloc(n);
        if (*errors) snprintf(*errors, n, fmt, name ? name : "");
    }
    return NULL;
}
