/* hfxc_session: compiles that share a session give the same effects and messages as compiles on
 * their own, though the headers they include are cut into tokens once; a header edited on disk
 * between two compiles is read anew; a header the lexer finds fault with is never remembered. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "effect.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "test.h"

static char *tmp;

static char *path_of(const char *name) { return test_path_in(tmp, name); }
static void write_text(const char *name, const char *text) { CHECK_INT(test_write_text(tmp, name, text), 0); }

/* One compile's outcome as text: its messages, then its .hfxo bytes in hex ("-" if none). */
static char *outcome(const char *name, hfxc_session *session) {
    char *path = path_of(name);
    hfxc_options opt = {.session = session, .flags = HFXC_NO_SELF_CHECK};
    hfxc_result *r = hfxc_compile_file(path, &opt);
    char *msgs = hfxc_diagnostics_text(r);
    void *data = NULL;
    size_t size = 0;
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (fx && hfx_fx_write_hfxo(fx, &data, &size) != 0) size = 0;
    char *text = malloc(strlen(msgs) + 2 * size + 3);
    size_t at = (size_t)sprintf(text, "%s|", msgs);
    for (size_t i = 0; i < size; i++) at += (size_t)sprintf(text + at, "%02x", ((unsigned char *)data)[i]);
    if (!fx) strcpy(text + at, "-");
    free(data), free(msgs), free(path);
    hfxc_result_free(r);
    return text;
}

#define PS(c) "float4 PS() : COLOR0 { return " c "; }\ntechnique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n"

/* Every root compiled alone, then all in one session in turn (twice): the same outcomes. */
static void shared_headers_change_nothing(void) {
    static const char *const roots[] = {"one.fx", "two.fx", "sub/three.fx", "bad.fx", "one.fx"};
    enum { N = sizeof roots / sizeof roots[0] };
    char *alone[N];
    for (int i = 0; i < N; i++) alone[i] = outcome(roots[i], NULL);
    hfxc_session *s = hfxc_session_new();
    CHECK(s != NULL);
    for (int round = 0; round < 2; round++) {
        for (int i = 0; i < N; i++) {
            char *shared = outcome(roots[i], s);
            CHECK_STR(shared, alone[i]);
            free(shared);
        }
    }
    hfxc_session_free(s);
    CHECK(strstr(alone[3], "comment") != NULL); /* the unterminated comment, each time */
    CHECK(strstr(alone[0], "common.fxh(3,") != NULL); /* a warning located in the header */
    for (int i = 0; i < N; i++) free(alone[i]);
}

/* A header rewritten between two compiles of one session: the second sees the new text. */
static void edited_header_is_read_again(void) {
    hfxc_session *s = hfxc_session_new();
    write_text("edit.fxh", "static const float4 E = 1;\n");
    char *before = outcome("edit.fx", s);
    write_text("edit.fxh", "static const float4 E = float4(0.25, 0.5, 0.75, 1);\n");
    char *after = outcome("edit.fx", s), *alone = outcome("edit.fx", NULL);
    CHECK(strcmp(before, after) != 0);
    CHECK_STR(after, alone);
    write_text("edit.fxh", "static const float4 E = float4(0.25, 0.5, 0.75, 2);\n"); /* same size */
    free(after), free(alone);
    after = outcome("edit.fx", s), alone = outcome("edit.fx", NULL);
    CHECK_STR(after, alone);
    free(before), free(after), free(alone);
    hfxc_session_free(s);
    hfxc_session_free(NULL);
}

int main(void) {
    tmp = test_temp_dir();
    char *sub = path_of("sub");
    CHECK(mkdir(sub, 0777) == 0);
    free(sub);
    write_text("common.fxh", "#ifndef COMMON_FXH\n#define COMMON_FXH\n#pragma not_a_pragma\n"
                             "#ifdef RED\nstatic const float4 C = float4(1, 0, 0, 1);\n#else\n"
                             "static const float4 C = float4(0, 1, 0, \"unterminated\n);\n#endif\n#endif\n");
    write_text("one.fx", "#define RED\n#include \"common.fxh\"\n#include \"common.fxh\"\n" PS("C"));
    write_text("two.fx", "#include \"sub/../common.fxh\"\n" PS("C * 2"));
    write_text("sub/three.fx", "#define RED\n#include \"../common.fxh\"\n" PS("C.bgra"));
    write_text("broken.fxh", "float4 B = 1; /* never closed\n");
    write_text("bad.fx", "#include \"broken.fxh\"\n" PS("B"));
    write_text("edit.fx", "#include \"edit.fxh\"\n" PS("E"));
    RUN(shared_headers_change_nothing);
    RUN(edited_header_is_read_again);
    test_remove_dir(tmp);
    free(tmp);
    return test_summary();
}
