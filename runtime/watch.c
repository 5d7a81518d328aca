/* watch.c: the files an effect was loaded from (the .fx and its includes as the compiler opened
 * them, or the .hfxo) with their modification time and size as last seen, and
 * hfx_effect_reload_if_changed, which compares them with the disk. The check is one stat() per
 * file and allocates nothing while nothing changed, so a program can make it every frame. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "compile.h"
#include "internal.h"

void hfx_rt_files_free(hfx_rt_files *f) {
    for (size_t i = 0; f->paths && i < f->count; i++) free(f->paths[i]);
    free(f->paths);
    f->paths = NULL;
    f->count = 0;
}

/* A missing file is a stamp too (exists = 0): its coming back is a change. */
static hfx_file_stamp stamp_of(const char *path) {
    struct stat st;
    if (stat(path, &st) != 0) return (hfx_file_stamp){0, 0, 0, 0};
    return (hfx_file_stamp){(int64_t)st.st_mtim.tv_sec, (int64_t)st.st_mtim.tv_nsec, (int64_t)st.st_size, 1};
}

static int same_stamp(const hfx_file_stamp *a, const hfx_file_stamp *b) {
    return a->sec == b->sec && a->nsec == b->nsec && a->size == b->size && a->exists == b->exists;
}

void hfx_rt_watch_free(hfx_watch *w) {
    hfx_rt_files_free(&w->files);
    free(w->stamps);
    w->stamps = NULL;
}

/* Takes files (emptied) and stamps each as the disk has it now. Returns 0, or -1 out of memory
 * (the effect then watches nothing). */
int hfx_rt_watch_set(hfx_watch *w, hfx_rt_files *files) {
    hfx_rt_watch_free(w);
    w->files = *files;
    *files = (hfx_rt_files){NULL, 0};
    w->stamps = calloc(w->files.count ? w->files.count : 1, sizeof *w->stamps);
    if (!w->stamps) {
        hfx_rt_files_free(&w->files);
        return -1;
    }
    for (size_t i = 0; i < w->files.count; i++) w->stamps[i] = stamp_of(w->files.paths[i]);
    return 0;
}

/* A clone watches the same files, as last seen by its source. */
int hfx_rt_watch_copy(hfx_watch *to, const hfx_watch *from) {
    size_t n = from->files.count;
    hfx_rt_files f = {calloc(n ? n : 1, sizeof(char *)), 0};
    hfx_file_stamp *stamps = calloc(n ? n : 1, sizeof *stamps);
    for (size_t i = 0; f.paths && stamps && i < n; i++)
        if ((f.paths[i] = hfx_rt_strdup(from->files.paths[i]))) f.count++;
    if (!f.paths || !stamps || f.count != n) {
        hfx_rt_files_free(&f);
        free(stamps);
        return -1;
    }
    if (n) memcpy(stamps, from->stamps, n * sizeof *stamps);
    to->files = f;
    to->stamps = stamps;
    return 0;
}

const char *const *hfx_effect_dependencies(const hfx_effect *fx, size_t *count) {
    if (count) *count = fx ? fx->watch.files.count : 0;
    return fx ? (const char *const *)fx->watch.files.paths : NULL;
}

/* Whether any file differs from its stamp (stops at the first that does). */
static int any_changed(const hfx_watch *w) {
    for (size_t i = 0; i < w->files.count; i++) {
        hfx_file_stamp now = stamp_of(w->files.paths[i]);
        if (!same_stamp(&now, &w->stamps[i])) return 1;
    }
    return 0;
}

/* After a successful reload the new list was stamped after the compile read the files; a file
 * the old list had takes the stamp seen before the compile instead, so an edit saved while the
 * compile ran is still seen as a change next time. */
static void keep_seen_stamps(hfx_watch *now, const hfx_watch *seen) {
    for (size_t i = 0; i < now->files.count; i++)
        for (size_t j = 0; j < seen->files.count; j++)
            if (strcmp(now->files.paths[i], seen->files.paths[j]) == 0) now->stamps[i] = seen->stamps[j];
}

int hfx_effect_reload_if_changed(hfx_effect *fx, const hfx_load_options *opt, char **errors) {
    if (errors) *errors = NULL;
    if (!fx) return HFX_ERR_NULL;
    if (!any_changed(&fx->watch)) return 0;
    hfx_watch seen = {{NULL, 0}, NULL};
    if (hfx_rt_watch_copy(&seen, &fx->watch)) return hfx_rt_fail(fx->dev, HFX_ERR_MEMORY, "out of memory");
    for (size_t i = 0; i < seen.files.count; i++) seen.stamps[i] = stamp_of(seen.files.paths[i]);
    int rc = hfx_effect_reload(fx, NULL, opt, errors);
    if (rc == HFX_OK) keep_seen_stamps(&fx->watch, &seen);
    else memcpy(fx->watch.stamps, seen.stamps, seen.files.count * sizeof *seen.stamps); /* not again until the next edit */
    hfx_rt_watch_free(&seen);
    return rc == HFX_OK ? 1 : rc;
}
