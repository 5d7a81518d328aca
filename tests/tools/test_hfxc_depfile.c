/* hfxc -MD / -MF / --depfile / -MT / -MP: the depfile text, byte for byte, as gcc writes one
 * (`target: root \` then one dependency a line, Make's escapes), for one input, several inputs
 * into a folder, names with spaces and '$', and what happens on a compile error or a bad call.
 * hfxc runs in a temporary folder, so every path below is relative to it as hfxc opened it. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "files.h"
#include "test.h"
#include "view_support.h"

static char *hfxc, *tmp;

static void write_text(const char *name, const char *text) { CHECK_INT(test_write_text(tmp, name, text), 0); }

static char *read_text(const char *name) {
    char *path = view_format("%s/%s", tmp, name);
    char *text = test_read_file(path, NULL);
    free(path);
    return text;
}

static int hfxc_in_tmp(const char *args, char **out) {
    char *cmd = view_format("cd '%s' && '%s' %s", tmp, hfxc, args);
    int rc = view_run(cmd, out);
    free(cmd);
    return rc;
}

#define PS "float4 PS() : COLOR0 { return Color; }\n" \
           "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n"

/* x.fx includes inc.fxh (its folder) and deep.fxh (found through -I sub), which includes
 * near.fxh from its own folder, sub/; inc.fxh is included twice but listed once. */
static void setup(void) {
    char *sub = view_format("%s/sub", tmp);
    CHECK_INT(mkdir(sub, 0777), 0);
    free(sub);
    write_text("x.fx", "#include \"inc.fxh\"\n#include <deep.fxh>\n#include \"inc.fxh\"\n"
                       "static const float4 Color = A + B;\n" PS);
    write_text("inc.fxh", "#ifndef INC\n#define INC\nfloat4 A = 1;\n#endif\n");
    write_text("sub/deep.fxh", "#include \"near.fxh\"\n");
    write_text("sub/near.fxh", "float4 B = 2;\n");
    write_text("y.fx", "float4 Color = 1;\n" PS);
    write_text("my fx$.fx", "#include \"inc.fxh\"\nstatic const float4 Color = A;\n" PS);
    write_text("broken.fx", "#include \"inc.fxh\"\nfloat4 Color = ;\n" PS);
}

static void md_next_to_the_output(void) {
    char *out = NULL;
    CHECK_INT(hfxc_in_tmp("-MD -I sub -o x.hfxo x.fx", &out), 0);
    char *d = read_text("x.d");
    CHECK_STR(d, "x.hfxo: x.fx \\\n inc.fxh \\\n sub/deep.fxh \\\n sub/near.fxh\n");
    free(d), free(out);
}

static void mf_mt_and_mp(void) {
    char *out = NULL;
    CHECK_INT(hfxc_in_tmp("-MD -MF nowhere/x.deps -I sub x.fx", &out), 1); /* an output that cannot be written */
    CHECK_CONTAINS(out, "hfxc: error: cannot write the depfile 'nowhere/x.deps'");
    free(out);
    CHECK_INT(hfxc_in_tmp("-MD -MP -MF x.deps -MT build/x.hfxo -I sub x.fx", &out), 0);
    char *d = read_text("x.deps");
    CHECK_STR(d, "build/x.hfxo: x.fx \\\n inc.fxh \\\n sub/deep.fxh \\\n sub/near.fxh\n"
                 "\ninc.fxh:\n\nsub/deep.fxh:\n\nsub/near.fxh:\n");
    free(d), free(out);
    /* --depfile FILE is -MD -MF FILE; without -o the target is the input's stem with .hfxo */
    CHECK_INT(hfxc_in_tmp("--depfile y.dep y.fx", &out), 0);
    d = read_text("y.dep");
    CHECK_STR(d, "y.hfxo: y.fx\n");
    free(d), free(out);
}

static void many_inputs_into_a_folder(void) {
    char *out = NULL;
    CHECK_INT(hfxc_in_tmp("-q -MD -I sub -o fx/ x.fx y.fx", &out), 0);
    char *dx = read_text("fx/x.d"), *dy = read_text("fx/y.d");
    CHECK_STR(dx, "fx/x.hfxo: x.fx \\\n inc.fxh \\\n sub/deep.fxh \\\n sub/near.fxh\n");
    CHECK_STR(dy, "fx/y.hfxo: y.fx\n");
    free(dx), free(dy), free(out);
    /* one -MF for two depfiles is a usage error */
    CHECK_INT(hfxc_in_tmp("-MF both.d -o fx/ x.fx y.fx", &out), 2);
    CHECK_CONTAINS(out, "-MF / --depfile names one depfile");
    free(out);
}

/* Make's escapes: a space takes a backslash, '$' doubles; '#' takes a backslash too. */
static void escaped_names(void) {
    char *out = NULL;
    CHECK_INT(hfxc_in_tmp("-MD -MT 'out#1.hfxo' -o 'my fx$.hfxo' 'my fx$.fx'", &out), 0);
    char *d = read_text("my fx$.d");
    CHECK_STR(d, "out\\#1.hfxo: my\\ fx$$.fx \\\n inc.fxh\n");
    free(d), free(out);
}

/* A failed compile writes no depfile (there is no output for it to describe). */
static void no_depfile_on_errors(void) {
    char *out = NULL;
    CHECK_INT(hfxc_in_tmp("-MD -o broken.hfxo broken.fx", &out), 1);
    CHECK_CONTAINS(out, "broken.fx(2,16): error X3000");
    char *d = read_text("broken.d");
    CHECK(d == NULL);
    free(d), free(out);
}

int main(void) {
    hfxc = view_build_path("compiler/hfxc");
    if (!hfxc) test_skip("hfxc is not built");
    tmp = test_temp_dir();
    setup();
    RUN(md_next_to_the_output);
    RUN(mf_mt_and_mp);
    RUN(many_inputs_into_a_folder);
    RUN(escaped_names);
    RUN(no_depfile_on_errors);
    test_remove_dir(tmp);
    free(tmp), free(hfxc);
    return test_summary();
}
