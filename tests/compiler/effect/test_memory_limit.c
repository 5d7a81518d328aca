/* Memory bounded by the input (hfxc.h: HFXC_MAX_SOURCE_BYTES, HFXC_MEMORY_FLOOR,
 * HFXC_MEMORY_PER_BYTE): large generated sources, each compiled in a child process whose peak
 * resident memory (getrusage) must stay within HFXC_MEMORY_FLOOR + HFXC_MEMORY_PER_BYTE times
 * the source size, plus a little for the process itself; and each must end with the exact
 * located error. 10 MiB of '(' once peaked at 845 MB (80 times its size); a page of nested
 * macros at 665 MB (2400 times). Under ASan (shadow memory, quarantine) only the errors are
 * checked. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hfx/hfxc.h"
#include "test.h"

#if defined(__SANITIZE_ADDRESS__)
#define MEASURED 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MEASURED 0
#endif
#endif
#ifndef MEASURED
#define MEASURED 1
#endif

enum { MiB = 1 << 20, SLACK = 8 * MiB /* the process's own growth: stdio, malloc arenas */ };

typedef char *(*make_fn)(size_t size);

static char *repeat(const char *head, const char *unit, size_t size, const char *tail) {
    size_t h = strlen(head), u = strlen(unit), t = strlen(tail), n = (size - h - t) / u;
    char *s = malloc(h + n * u + t + 1), *p = s;
    memcpy(p, head, h), p += h;
    for (size_t i = 0; i < n; i++, p += u) memcpy(p, unit, u);
    memcpy(p, tail, t + 1);
    return s;
}

static char *parens(size_t size) { return repeat("", "(", size, ""); }
static char *floats(size_t size) { return repeat("float4 x = {", "1,", size, "};"); }
static char *idents(size_t size) { return repeat("", "a ", size, ""); }
static char *comment(size_t size) { return repeat("//", "x", size, "\n"); }
static char *macros(size_t size) {
    return repeat("#define A(x) x x\n", "A(A(A(A(A(A(A(A(1))))))))\n", size, "");
}

typedef struct report {
    long before_kb, peak_kb; /* resident memory before the compile, and its high-water mark */
    char first[512];         /* the first diagnostic line, or "ok" */
} report;

static void child(make_fn make, size_t size, int fd) {
    report r;
    memset(&r, 0, sizeof r);
    char *src = make(size);
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    r.before_kb = u.ru_maxrss;
    hfxc_result *res = hfxc_compile_memory(src, strlen(src), "big.fx", NULL);
    getrusage(RUSAGE_SELF, &u);
    r.peak_kb = u.ru_maxrss;
    char *text = hfxc_diagnostics_text(res);
    const char *first = hfxc_result_ok(res) ? "ok" : text;
    snprintf(r.first, sizeof r.first, "%.*s", (int)strcspn(first, "\n"), first);
    ssize_t n = write(fd, &r, sizeof r);
    _exit(n == (ssize_t)sizeof r ? 0 : 1);
}

/* Compiles make(size) in a child; checks its memory and its first diagnostic line. */
static void bounded(make_fn make, size_t size, const char *first) {
    int fds[2];
    CHECK_INT(pipe(fds), 0);
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) child(make, size, fds[1]);
    close(fds[1]);
    report r;
    memset(&r, 0, sizeof r);
    CHECK_INT(read(fds[0], &r, sizeof r), sizeof r);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK_INT(status, 0);
    CHECK_STR(r.first, first);
    long used = (r.peak_kb - r.before_kb) * 1024, allowed = HFXC_MEMORY_FLOOR + (long)HFXC_MEMORY_PER_BYTE * (long)size + SLACK;
    printf("  %zu bytes: peak %ld MiB over the %ld MiB before (allowed %ld MiB)\n", size, used / MiB, r.before_kb / 1024, allowed / MiB);
    if (MEASURED) CHECK(used <= allowed);
}

static void ten_mib_of_parens_is_refused_at_once(void) {
    bounded(parens, 10 * MiB, "big.fx(1,1): error X9002: the source is 10485760 bytes: hfx compiles source files of up to 8 MiB");
}

static void dense_tokens_stop_at_the_limit(void) {
    const char *limit = "big.fx(1,1): error X9001: out of memory: compiling this source needs more than 192 MiB "
                        "(hfx allows 32 MiB plus 40 times the size of the source files)";
    bounded(parens, 4 * MiB, limit);
    bounded(floats, 4 * MiB, limit);
}

static void big_sources_within_the_limit(void) {
    bounded(idents, 4 * MiB, "big.fx(1,1): error X3000: unrecognized identifier 'a'");
    bounded(comment, 4 * MiB, "ok");
}

static void macro_expansion_is_bounded_by_the_source(void) {
    bounded(macros, 256 * 1024, "big.fx(1,1): error X9001: out of memory: compiling this source needs more than 41 MiB "
                                "(hfx allows 32 MiB plus 40 times the size of the source files)");
}

int main(void) {
    RUN(ten_mib_of_parens_is_refused_at_once);
    RUN(dense_tokens_stop_at_the_limit);
    RUN(big_sources_within_the_limit);
    RUN(macro_expansion_is_bounded_by_the_source);
    return test_summary();
}
