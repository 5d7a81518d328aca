/* Bad input never crashes or hangs: thousands of inputs made of preprocessor fragments and
 * random bytes (a fixed-seed generator, so failures reproduce) must each come back as a token
 * list ending with TK_EOF, with every error located inside the input. */
#define _GNU_SOURCE /* memmem */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "pp/token.h"

static const char *const fragments[] = {
    "#define ", "#undef ", "#if ", "#ifdef ", "#ifndef ", "#elif ", "#else", "#endif", "#include ",
    "#line ", "#pragma ", "#error ", "#", "##", "F", "G", "X", "Y", "__VA_ARGS__", "__LINE__",
    "__FILE__", "defined", "(", ")", ",", "...", "\n", "\n", "\n", " ", "\t", "\\\n", "\\\r\n",
    "/*", "*/", "//", "\"", "\"s\"", "<", ">", "0", "1", "0x", "1.5e", "/", "%", "-", "!", "?", ":",
    "F(x) x x", "G(a, ...) a ## __VA_ARGS__ #a", "F(F(F(", "\xC3\xA9", "\xEF\xBB\xBF", "\r", "'",
    "\n#define F(x, ...) #x __VA_ARGS__ ## x\n", "\n#define G(a) F(a, a) G\n", "\n#define X X Y\n",
    "\n#define Y(...) , ## __VA_ARGS__\n", "G(1,2,3)", "\n#if defined(F) && F(1)\n", "\n#elif X\n",
    "\n#include <", "\n#pragma pack_matrix(row_major)\n", "\n#pragma once\n", "\n#line 3 \"f\"\n",
    "\n#endif\n", "\n#else\n"};

static uint32_t next_random(uint64_t *state) {
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(*state >> 33);
}

static size_t make_input(uint64_t *state, char *buf, size_t cap) {
    size_t n = 0, parts = 1 + next_random(state) % 60;
    for (size_t i = 0; i < parts; i++) {
        uint32_t r = next_random(state);
        if (r % 10 == 0) {
            if (n + 1 >= cap) break;
            buf[n++] = (char)(next_random(state) & 0xFF);
            continue;
        }
        const char *f = fragments[r % (sizeof fragments / sizeof fragments[0])];
        size_t len = strlen(f);
        if (n + len >= cap) break;
        memcpy(buf + n, f, len);
        n += len;
    }
    return n;
}

static void random_inputs_never_crash(void) {
    uint64_t state = 12345;
    char buf[2048];
    int bad_lists = 0, bad_locs = 0;
    const char *env = getenv("HFX_FUZZ_ITERATIONS"); /* more by hand when hunting */
    int iterations = env && atoi(env) > 0 ? atoi(env) : 5000;
    for (int i = 0; i < iterations; i++) {
        size_t n = make_input(&state, buf, sizeof buf);
        hfx_arena a;
        hfx_arena_init(&a);
        hfx_diags d;
        hfx_diags_init(&d, &a, 0);
        hfx_token *t = hfx_preprocess(&a, &d, "fuzz.fx", buf, (uint32_t)n, NULL);
        size_t count = 0;
        while (t && t->kind != TK_EOF && count < 1000000) { t = t->next; count++; }
        if (!t || t->kind != TK_EOF || t->next) bad_lists++;
        uint32_t lines = 1;
        for (size_t k = 0; k < n; k++) lines += buf[k] == '\n';
        bool renumbered = memmem(buf, n, "line", 4) != NULL; /* #line may move anything */
        for (uint32_t k = 0; k < d.count && !renumbered; k++)
            if (d.items[k].line > lines + 1) bad_locs++;
        free(hfx_tokens_to_text(&d, hfx_preprocess(&a, &d, "fuzz.fx", buf, (uint32_t)n, NULL)));
        hfx_arena_free(&a);
    }
    CHECK_INT(bad_lists, 0);
    CHECK_INT(bad_locs, 0);
}

int main(void) {
    RUN(random_inputs_never_crash);
    return test_summary();
}
