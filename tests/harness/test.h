/* test.h: the checks every test program uses. A program runs its TEST functions with RUN,
 * then ends with `return test_summary();`, which prints "N passed, N failed" and returns
 * nonzero on any failure. test_skip() exits 77, which ctest reports as skipped. */
#ifndef HFX_TEST_H
#define HFX_TEST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

__attribute__((unused)) static int test_checks_failed_, test_failed_, test_passed_, test_current_failed_;

#define CHECK(cond) do { if (!(cond)) { \
    fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
    test_current_failed_ = 1; test_checks_failed_++; } } while (0)

#define CHECK_INT(a, b) do { long long a_ = (long long)(a), b_ = (long long)(b); if (a_ != b_) { \
    fprintf(stderr, "%s:%d: %s == %lld, expected %s == %lld\n", __FILE__, __LINE__, #a, a_, #b, b_); \
    test_current_failed_ = 1; test_checks_failed_++; } } while (0)

#define CHECK_STR(a, b) do { const char *a_ = (a), *b_ = (b); \
    if (!a_ || !b_ || strcmp(a_, b_) != 0) { \
    fprintf(stderr, "%s:%d: %s is\n  \"%s\"\nexpected\n  \"%s\"\n", __FILE__, __LINE__, #a, a_ ? a_ : "(null)", b_ ? b_ : "(null)"); \
    test_current_failed_ = 1; test_checks_failed_++; } } while (0)

#define CHECK_CONTAINS(hay, needle) do { const char *h_ = (hay), *n_ = (needle); \
    if (!h_ || !strstr(h_, n_)) { \
    fprintf(stderr, "%s:%d: %s does not contain \"%s\":\n%s\n", __FILE__, __LINE__, #hay, n_, h_ ? h_ : "(null)"); \
    test_current_failed_ = 1; test_checks_failed_++; } } while (0)

#define CHECK_NEAR(a, b, tol) do { double a_ = (a), b_ = (b); if (!(fabs(a_ - b_) <= (tol))) { \
    fprintf(stderr, "%s:%d: %s == %.6g, expected %.6g (tolerance %g)\n", __FILE__, __LINE__, #a, a_, b_, (double)(tol)); \
    test_current_failed_ = 1; test_checks_failed_++; } } while (0)

#define RUN(fn) do { test_current_failed_ = 0; fn(); \
    if (test_current_failed_) { test_failed_++; fprintf(stderr, "FAIL %s\n", #fn); } \
    else { test_passed_++; printf("ok   %s\n", #fn); } } while (0)

static inline int test_summary(void) {
    printf("%d passed, %d failed\n", test_passed_, test_failed_);
    return test_failed_ ? 1 : 0;
}

static inline void test_skip(const char *why) {
    printf("SKIP: %s\n", why);
    exit(77);
}

#endif
