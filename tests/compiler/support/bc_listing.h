/* bc_listing.h: the bytecode tests' way in: a shader compiled through the library's fxc path
 * (/T profile /E main) and shown as fxc's listing. */
#ifndef HFX_TEST_BC_LISTING_H
#define HFX_TEST_BC_LISTING_H

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "hfx/hfxc.h"

/* The listing of `main` compiled for `profile`, or the messages when it fails (malloc'ed). */
static inline char *bc_listing(const char *src, const char *profile, bool *ok) {
    hfxc_options o = {.entry = "main", .profile = profile};
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "t.fx", &o);
    size_t size = 0;
    const void *code = hfxc_result_bytecode(r, &size);
    *ok = hfxc_result_ok(r) && code;
    char *text = NULL;
    if (*ok) {
        char *diags = NULL;
        text = hfxc_disassemble(code, size, "t.vso", &diags);
        free(diags);
    } else text = hfxc_diagnostics_text(r);
    hfxc_result_free(r);
    return text;
}

#endif
