/* bench.h: what every benchmark program shares (they also link tests/harness for files.h). */
#ifndef HFX_BENCH_H
#define HFX_BENCH_H

#include <stdint.h>
#include <time.h>
/* The instruction counter needs syscall(): a benchmark that reads it defines _DEFAULT_SOURCE first. */
#if defined(__linux__) && defined(_DEFAULT_SOURCE)
#define BENCH_COUNTERS 1
#include <linux/perf_event.h>
#include <string.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

/* Seconds on the monotonic clock. */
static inline double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Seconds of CPU this thread has run: on a shared machine the wall clock also counts the time
 * other processes held the core, which only ever adds to a loop's figure. */
static inline double thread_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* A counter of the instructions this thread retires in user space (perf_event_open), -1 where the
 * kernel or the machine has none; instruction counts do not depend on what else the machine runs. */
static inline int instructions_open(void) {
#ifdef BENCH_COUNTERS
    struct perf_event_attr a;
    memset(&a, 0, sizeof a);
    a.size = sizeof a;
    a.type = PERF_TYPE_HARDWARE;
    a.config = PERF_COUNT_HW_INSTRUCTIONS;
    a.exclude_kernel = 1;
    a.exclude_hv = 1;
    return (int)syscall(SYS_perf_event_open, &a, 0, -1, -1, 0);
#else
    return -1;
#endif
}

/* The counter's value now (0 without one). */
static inline uint64_t instructions_read(int fd) {
    (void)fd;
    uint64_t n = 0;
#ifdef BENCH_COUNTERS
    if (fd >= 0 && read(fd, &n, sizeof n) != (ssize_t)sizeof n) n = 0;
#endif
    return n;
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
