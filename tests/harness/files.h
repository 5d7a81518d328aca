/* files.h: reading test inputs. */
#ifndef HFX_TEST_FILES_H
#define HFX_TEST_FILES_H

#include <stddef.h>

char *test_read_file(const char *path, size_t *size);   /* malloc'ed, NUL-terminated; NULL if absent */
const char *test_seed_dir(void);                        /* ../shared/seed-fx, or NULL when absent */
char *test_seed_path(const char *file);                 /* malloc'ed; NULL when the corpus is absent */
void test_require_seeds(void);                          /* skips the test (exit 77) when absent */
void test_seeds_or_finish(void);                        /* seeds absent: ends the test (failed, or skipped) */
char *test_temp_dir(void);                              /* a fresh folder under /tmp; malloc'ed */
char *test_path_in(const char *dir, const char *name);  /* "dir/name", malloc'ed */
int test_write_text(const char *dir, const char *name, const char *text); /* dir/name := text; 0 when written */
void test_remove_dir(const char *dir);                  /* the folder and all in it; says when it cannot */

#endif
