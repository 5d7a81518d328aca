/* What a compile result must look like, whatever the input (fuzz_check.h). */
#include <stdlib.h>

#include "fuzz_check.h"

static void check_diag(const hfxc_diag *d) {
    fuzz_require(d != NULL, "hfxc_diag_at returned NULL inside the count");
    fuzz_require(d->file && d->message && *d->message, "a diagnostic without file or message");
    /* line 0: a binary input (an fxc effect, shader bytecode), located by the byte offset in col */
    fuzz_require(d->line == 0 || (d->line >= 1 && d->col >= 1), "a diagnostic without a location");
    fuzz_require(d->severity != HFXC_ERROR || d->code != 0, "an error without a number");
}

void fuzz_check_result(const hfxc_result *r) {
    fuzz_require(r != NULL, "hfxc_compile_memory returned NULL");
    size_t n = hfxc_diag_count(r), errors = 0;
    for (size_t i = 0; i < n; i++) {
        check_diag(hfxc_diag_at(r, i));
        errors += hfxc_diag_at(r, i)->severity == HFXC_ERROR;
    }
    int ok = hfxc_result_ok(r);
    fuzz_require(ok == (errors == 0), "hfxc_result_ok disagrees with the errors");
    fuzz_require(!ok || hfxc_result_effect(r) != NULL, "ok without an effect");
    char *text = hfxc_diagnostics_text(r);
    fuzz_require(text != NULL, "no diagnostics text");
    free(text);
}
