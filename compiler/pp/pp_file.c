/* hfx_pp_file.c: reading source files and finding #include'd ones. Effects come from Windows:
 * backslashes are separators and names often differ in case from the file on disk, so a
 * name that is not found exactly is looked up again component by component, ignoring case. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <dirent.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "pp/pp_internal.h"

static uint32_t put_utf8(char *out, uint32_t cp) {
    if (cp < 0x80) { out[0] = (char)cp; return 1; }
    if (cp < 0x800) { out[0] = (char)(0xC0 | cp >> 6); out[1] = (char)(0x80 | (cp & 0x3F)); return 2; }
    if (cp < 0x10000) {
        out[0] = (char)(0xE0 | cp >> 12); out[1] = (char)(0x80 | ((cp >> 6) & 0x3F)); out[2] = (char)(0x80 | (cp & 0x3F));
        return 3;
    }
    out[0] = (char)(0xF0 | cp >> 18); out[1] = (char)(0x80 | ((cp >> 12) & 0x3F));
    out[2] = (char)(0x80 | ((cp >> 6) & 0x3F)); out[3] = (char)(0x80 | (cp & 0x3F));
    return 4;
}

/* fxc and XNA's content pipeline read UTF-16 sources (Visual Studio saves them so): one with a
 * byte-order mark (FF FE little endian, FE FF big endian) becomes UTF-8 behind a UTF-8 mark,
 * which the lexer skips, so columns count as in the original. An unpaired surrogate is U+FFFD.
 * Any other text is returned as it is. */
char *hfx_pp_decode_source(hfx_arena *arena, char *text, uint32_t *size) {
    const unsigned char *u = (const unsigned char *)text;
    uint32_t n = *size;
    bool le = n >= 2 && u[0] == 0xFF && u[1] == 0xFE, be = n >= 2 && u[0] == 0xFE && u[1] == 0xFF;
    if (!le && !be) return text;
    uint32_t units = (n - 2) / 2;
    char *out = hfx_arena_alloc_raw(arena, (size_t)units * 3 + 4); /* a unit gives at most 3 bytes */
    if (!out) return NULL;
    memcpy(out, "\xEF\xBB\xBF", 3);
    uint32_t len = 3;
    for (uint32_t i = 0; i < units; i++) {
        const unsigned char *p = u + 2 + 2 * i;
        uint32_t cp = le ? (uint32_t)(p[0] | p[1] << 8) : (uint32_t)(p[0] << 8 | p[1]);
        if (cp >= 0xD800 && cp < 0xDC00 && i + 1 < units) {
            const unsigned char *q = p + 2;
            uint32_t lo = le ? (uint32_t)(q[0] | q[1] << 8) : (uint32_t)(q[0] << 8 | q[1]);
            if (lo >= 0xDC00 && lo < 0xE000) {
                cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                i++;
            }
        }
        if (cp >= 0xD800 && cp < 0xE000) cp = 0xFFFD;
        len += put_utf8(out + len, cp);
    }
    out[len] = 0;
    *size = len;
    return out;
}

char *hfx_pp_read_file(hfx_arena *arena, const char *path, uint32_t *size) {
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) return NULL;
    if (st.st_size > HFXC_MAX_SOURCE_BYTES) { /* refused before reading: the caller reports the size */
        *size = st.st_size >= (off_t)UINT32_MAX ? UINT32_MAX : (uint32_t)st.st_size;
        return NULL;
    }
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t n = (size_t)st.st_size;
    char *buf = hfx_arena_alloc_raw(arena, n + 1); /* not zeroed: fread fills it, or it is not used */
    size_t got = buf ? fread(buf, 1, n, f) : 0;
    fclose(f);
    if (!buf || got != n) return NULL;
    buf[n] = 0;
    *size = (uint32_t)n;
    return hfx_pp_decode_source(arena, buf, size);
}

char *hfx_pp_dirname(hfx_arena *arena, const char *path) {
    const char *slash = strrchr(path, '/');
    const char *back = strrchr(path, '\\');
    if (back && (!slash || back > slash)) slash = back;
    if (!slash) return hfx_arena_strdup(arena, ".");
    if (slash == path) return hfx_arena_strdup(arena, "/");
    return hfx_arena_strndup(arena, path, (size_t)(slash - path));
}

/* Into a buffer of our own: no malloc'ed string alive while the arena allocates. */
char *hfx_pp_realpath(hfx_arena *arena, const char *path) {
    char buf[PATH_MAX];
    return realpath(path, buf) ? hfx_arena_strdup(arena, buf) : NULL;
}

static bool is_file(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static bool is_dir(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* The entry of `dir` whose name matches `name` ignoring ASCII case, or NULL. */
static char *find_entry_nocase(hfx_arena *arena, const char *dir, const char *name, size_t len) {
    DIR *d = opendir(*dir ? dir : "/");
    if (!d) return NULL;
    char *found = NULL;
    for (struct dirent *e; (e = readdir(d));) {
        if (strlen(e->d_name) == len && strncasecmp(e->d_name, name, len) == 0) {
            found = hfx_arena_strdup(arena, e->d_name);
            break;
        }
    }
    closedir(d);
    return found;
}

/* dir + "/" + rel, where the components of rel may differ in case from the disk. */
static const char *lookup_nocase(hfx_arena *arena, const char *dir, const char *rel) {
    const char *path = dir;
    for (const char *p = rel; *p;) {
        const char *end = strchr(p, '/');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if (len == 0 || (len == 1 && p[0] == '.') || (len == 2 && p[0] == '.' && p[1] == '.')) {
            path = hfx_arena_printf(arena, "%s/%.*s", path, (int)len, p);
        } else {
            const char *exact = hfx_arena_printf(arena, "%s/%.*s", path, (int)len, p);
            bool last = !end;
            if (last ? is_file(exact) : is_dir(exact)) {
                path = exact;
            } else {
                char *entry = find_entry_nocase(arena, path, p, len);
                if (!entry) return NULL;
                path = hfx_arena_printf(arena, "%s/%s", path, entry);
            }
        }
        p += len;
        if (*p == '/') p++;
    }
    return is_file(path) ? path : NULL;
}

static const char *try_dir(hfx_pp *pp, const char *dir, const char *name) {
    if (!dir) return NULL;
    const char *path = strcmp(dir, ".") == 0 ? name : hfx_arena_printf(pp->arena, "%s/%s", dir, name);
    if (is_file(path)) return path;
    return lookup_nocase(pp->arena, dir, name);
}

const char *hfx_pp_find_include(hfx_pp *pp, const char *name, bool angled, const char *including_dir) {
    (void)angled; /* fxc's default handler searches the same places for <x> and "x" */
    char *n = hfx_arena_strdup(pp->arena, name);
    for (char *p = n; *p; p++)
        if (*p == '\\') *p = '/';
    if (n[0] == '/') return is_file(n) ? n : lookup_nocase(pp->arena, "", n + 1);
    const char *found = try_dir(pp, including_dir, n);
    if (!found && pp->root_dir && (!including_dir || strcmp(pp->root_dir, including_dir) != 0))
        found = try_dir(pp, pp->root_dir, n);
    for (uint32_t i = 0; !found && pp->opt && i < pp->opt->include_dir_count; i++) {
        char *dir = hfx_arena_strdup(pp->arena, pp->opt->include_dirs[i]);
        for (char *p = dir; *p; p++)
            if (*p == '\\') *p = '/';
        found = try_dir(pp, dir, n);
    }
    return found;
}
