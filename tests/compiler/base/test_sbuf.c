/* The text buffer's formatter: hfx_sb_printf writes %s %d %u %c %% itself and hands everything else
 * to snprintf one conversion at a time, so each case is checked against what the C library
 * prints for the same format and arguments (and the plain ones against hand-written text). */
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/sbuf.h"
#include "test.h"

#define CHECK_LIKE_LIBC(expected_text, ...) do { \
        char want_[512]; \
        snprintf(want_, sizeof want_, __VA_ARGS__); \
        sbuf b_ = {0}; \
        hfx_sb_printf(&b_, __VA_ARGS__); \
        CHECK_STR(b_.d ? b_.d : "", want_); \
        CHECK_STR(want_, expected_text); \
        free(b_.d); \
    } while (0)

static void plain_conversions(void) {
    CHECK_LIKE_LIBC("vec4(a, b)", "vec4(%s, %s)", "a", "b");
    CHECK_LIKE_LIBC("x[0] y[4294967295]", "x[%u] y[%u]", 0u, UINT_MAX);
    CHECK_LIKE_LIBC("-2147483648 2147483647", "%d %d", INT_MIN, INT_MAX);
    CHECK_LIKE_LIBC("-9223372036854775808 18446744073709551615", "%lld %llu", LLONG_MIN, ULLONG_MAX);
    CHECK_LIKE_LIBC("7 -7 12", "%zu %ld %lu", (size_t)7, -7L, 12UL);
    CHECK_LIKE_LIBC("c=q 100%", "c=%c %d%%", 'q', 100);
    CHECK_LIKE_LIBC("no conversion at all", "no conversion at all");
    CHECK_LIKE_LIBC("", "%s", "");
}

static void conversions_through_snprintf(void) {
    CHECK_LIKE_LIBC("0.100000001", "%.9g", (double)0.1f);
    CHECK_LIKE_LIBC("1e+20 2.5", "%g %g", 1e20, 2.5);
    CHECK_LIKE_LIBC("0042 ff 0x1f", "%04u %02x %#x", 42u, 255u, 31u);
    CHECK_LIKE_LIBC("[   ab] [ab   ]", "[%5s] [%-5s]", "ab", "ab");
    CHECK_LIKE_LIBC("abc|3.14", "%.*s|%.*g", 3, "abcdef", 3, 3.14159);
    CHECK_LIKE_LIBC("[  -12]", "[%*d]", 5, -12);
    CHECK_LIKE_LIBC("+5 -0.500", "%+d %.3f", 5, -0.5);
}

/* Conversions mixed with text in one format, and arguments consumed in order across both paths. */
static void mixed_in_order(void) {
    CHECK_LIKE_LIBC("uniform vec4 hfx_c[12]; // 0.25 x3", "uniform %s %s[%u]; // %g x%d", "vec4", "hfx_c", 12u, 0.25, 3);
    CHECK_LIKE_LIBC("a1b2.5c3d", "a%db%.1fc%ud", 1, 2.5, 3u);
}

/* A conversion longer than the formatter's line buffer goes through the heap. */
static void long_output(void) {
    char big[2000];
    memset(big, 'x', sizeof big - 1);
    big[sizeof big - 1] = 0;
    sbuf b = {0};
    hfx_sb_printf(&b, "[%1999s]", big);
    CHECK_INT(b.len, 2001);
    CHECK(b.d && b.d[0] == '[' && b.d[1] == 'x' && b.d[2000] == ']');
    free(b.d);
}

static void appends(void) {
    sbuf b = {0};
    for (int i = 0; i < 1000; i++) hfx_sb_printf(&b, "%d,", i % 10);
    CHECK_INT(b.len, 2000);
    CHECK(strncmp(b.d, "0,1,2,3,4,5,6,7,8,9,0,", 22) == 0);
    free(b.d);
}

static void arena_printf_uses_it(void) {
    hfx_arena a;
    hfx_arena_init(&a);
    CHECK_STR(hfx_arena_printf(&a, "hfx_a_%s%u", "TEXCOORD", 3u), "hfx_a_TEXCOORD3");
    CHECK_STR(hfx_arena_printf(&a, "%s", ""), "");
    CHECK_STR(hfx_arena_printf(&a, "%.9g", 1.0 / 3.0), "0.333333333");
    hfx_arena_free(&a);
}

int main(void) {
    RUN(plain_conversions);
    RUN(conversions_through_snprintf);
    RUN(mixed_in_order);
    RUN(long_output);
    RUN(appends);
    RUN(arena_printf_uses_it);
    return test_summary();
}
