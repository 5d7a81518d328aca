/* nftw is XSI: the build names only POSIX 2008. */
#define _XOPEN_SOURCE 700

#include "files.h"

#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "test.h"

char *test_read_file(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 1);
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (!buf) return NULL;
    buf[n] = 0;
    if (size) *size = (size_t)n;
    return buf;
}

const char *test_seed_dir(void) {
    const char *env = getenv("HFX_SEED_DIR");
    const char *dir = env && *env ? env : HFX_SEED_DIR;
    struct stat st;
    return stat(dir, &st) == 0 && S_ISDIR(st.st_mode) ? dir : NULL;
}

char *test_seed_path(const char *file) {
    const char *dir = test_seed_dir();
    if (!dir) return NULL;
    size_t n = strlen(dir) + strlen(file) + 2;
    char *p = malloc(n);
    snprintf(p, n, "%s/%s", dir, file);
    return p;
}

void test_require_seeds(void) {
    if (!test_seed_dir()) test_skip("../shared/seed-fx is absent (a plain clone): seed tests skipped");
}

void test_seeds_or_finish(void) {
    if (test_seed_dir()) return;
    if (test_summary() != 0) exit(1);
    test_skip("../shared/seed-fx is absent (a plain clone): seed effects not checked");
}

char *test_temp_dir(void) {
    char tmpl[] = "/tmp/hfx-test-XXXXXX";
    char *d = mkdtemp(tmpl);
    return d ? strdup(d) : NULL;
}

char *test_path_in(const char *dir, const char *name) {
    size_t n = strlen(dir) + strlen(name) + 2;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/%s", dir, name);
    return p;
}

int test_write_text(const char *dir, const char *name, const char *text) {
    char *p = test_path_in(dir, name);
    FILE *f = p ? fopen(p, "w") : NULL;
    free(p);
    if (!f) return -1;
    int rc = fputs(text, f) < 0 ? -1 : 0;
    return fclose(f) != 0 ? -1 : rc;
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *at) {
    (void)st, (void)flag, (void)at;
    return remove(path);
}

/* Depth first without following links, in process: no shell to quote the path for. */
void test_remove_dir(const char *dir) {
    if (dir && nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS) != 0) fprintf(stderr, "could not remove %s\n", dir);
}
