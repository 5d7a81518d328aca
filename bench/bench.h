/* bench.h: what every benchmark program shares (they also link tests/harness for files.h). */
#ifndef HFX_BENCH_H
#define HFX_BENCH_H

#include <stdint.h>
#include <time.h>

/* Seconds on the monotonic clock. */
static inline double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* One input of a front-end benchmark. */
typedef struct source {
    const char *name;
    char *text;
    uint32_t size, lines;
} source;

/* Lines in n bytes of s (a last line without '\n' counts). */
static inline uint32_t count_lines(const char *s, uint32_t n) {
    uint32_t lines = 1;
    for (uint32_t i = 0; i < n; i++) lines += s[i] == '\n';
    return lines;
}

#endif
