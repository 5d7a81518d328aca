/* depfile.c: hfxc -MD: a Make / Ninja depfile for each compiled effect, as gcc -MD writes one,
 * so a build system recompiles an effect when the .fx or any file it includes changes. The
 * dependencies are the paths the preprocessor opened (hfxc_dependency_at), the root first. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "base/sbuf.h"

/* Make's escapes, which Ninja's depfile reader also undoes: a space or '#' takes a backslash,
 * '$' is doubled. */
static void put_escaped(sbuf *b, const char *path) {
    for (const char *p = path; *p; p++) {
        if (*p == ' ' || *p == '#') hfx_sb_put(b, "\\");
        if (*p == '$') hfx_sb_put(b, "$");
        hfx_sb_putn(b, p, 1);
    }
}

char *cli_depfile_text(const char *target, const char *const *deps, size_t count, bool phony) {
    sbuf b = {0};
    put_escaped(&b, target);
    hfx_sb_put(&b, ":");
    for (size_t i = 0; i < count; i++) {
        hfx_sb_put(&b, i ? " \\\n " : " ");
        put_escaped(&b, deps[i]);
    }
    hfx_sb_put(&b, "\n");
    for (size_t i = 1; phony && i < count; i++) { /* gcc -MP: every dependency but the root */
        hfx_sb_put(&b, "\n");
        put_escaped(&b, deps[i]);
        hfx_sb_put(&b, ":\n");
    }
    return hfx_sb_take(&b);
}

/* "dir/x.fx" -> "dir/x" + ext (the last dot of the last component goes). */
static char *with_extension(const char *path, const char *ext) {
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    size_t keep = dot && dot > (slash ? slash + 1 : path) ? (size_t)(dot - path) : strlen(path);
    char *s = malloc(keep + strlen(ext) + 1);
    if (!s) return NULL;
    memcpy(s, path, keep);
    strcpy(s + keep, ext);
    return s;
}

/* Without -o, the names hfxc would write next to the input's stem, in the current folder. */
static char *default_output(const char *input) {
    const char *base = strrchr(input, '/');
    return with_extension(base ? base + 1 : input, ".hfxo");
}

bool cli_write_depfile(const cli_options *o, const char *input, const hfxc_result *r, char **error) {
    char *output = cli_output_path(o, input);
    if (!output) output = default_output(input);
    char *path = o->depfile_path ? strdup(o->depfile_path) : output ? with_extension(output, ".d") : NULL;
    size_t n = hfxc_dependency_count(r);
    const char **deps = calloc(n ? n : 1, sizeof *deps);
    for (size_t i = 0; deps && i < n; i++) deps[i] = hfxc_dependency_at(r, i);
    char *text = output && deps ? cli_depfile_text(o->dep_target ? o->dep_target : output, deps, n, o->depfile_phony) : NULL;
    FILE *f = text && path ? fopen(path, "w") : NULL;
    bool ok = f && fputs(text, f) >= 0;
    if (f && fclose(f) != 0) ok = false;
    if (!ok && !*error) {
        size_t len = (path ? strlen(path) : 0) + 64;
        *error = malloc(len);
        if (*error) snprintf(*error, len, "cannot write the depfile '%s'", path ? path : "");
    }
    free(text), free(deps), free(path), free(output);
    return ok;
}
