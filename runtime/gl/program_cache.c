/* program_cache.c: linked GL programs kept on disk (GL_ARB_get_program_binary), so loading an
 * effect again skips the driver's GLSL compiler and linker. Opt-in: the application names a
 * folder with hfx_device_set_program_cache.
 *
 * One file per program, named by a 64-bit FNV-1a hash of everything that decides the binary:
 * both shaders' text, the attribute bindings, and the driver's vendor, renderer and version
 * strings. The file repeats the key and the driver string and carries the binary's length and
 * CRC-32; anything that does not match, and any binary the driver refuses, is a miss: the
 * program is built from its GLSL and the file written again. A cache entry is never trusted.
 *
 * File layout (little-endian u32 words): "HFXB", version 1, the key (two words), the binary
 * format, the binary's length, its CRC-32, the driver string's length; the driver string; the
 * binary. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "gl/gl_int.h"

enum { CACHE_VERSION = 1, HEADER_WORDS = 8, MAX_BINARY = 64 << 20 };
static const char magic[4] = {'H', 'F', 'X', 'B'};

int hfx_device_set_program_cache(hfx_device *dev, const char *dir) {
    if (!dev) return HFX_ERR_NULL;
    if (dev->be != &hfx_gl_backend) return hfx_rt_fail(dev, HFX_ERR_NOT_FOUND, "the program cache is OpenGL's");
    char *copy = NULL;
    if (dir && *dir && !(copy = strdup(dir))) return hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
    free(dev->gl->program_cache);
    dev->gl->program_cache = copy;
    return HFX_OK;
}

/* Is there a cache, and can this driver hand out and take back binaries? */
static int cache_on(const hfx_device *dev) {
    return dev->gl->program_cache && dev->gl->fn.ProgramParameteri && dev->gl->fn.GetProgramBinary && dev->gl->fn.ProgramBinary;
}

int hfx_rt_program_cache_usable(const hfx_device *dev) {
    GLint formats = 0;
    if (!cache_on(dev)) return 0;
    dev->gl->fn.GetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
    return formats > 0;
}

static uint64_t fnv1a(uint64_t h, const void *data, size_t n) {
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

static uint64_t fnv1a_str(uint64_t h, const char *s) { return fnv1a(h, s ? s : "", s ? strlen(s) + 1 : 1); }

/* "vendor|renderer|version": a new driver makes every entry stale. */
static void driver_string(const hfx_device *dev, char *out, size_t cap) {
    const GLubyte *v = dev->gl->fn.GetString(GL_VENDOR), *r = dev->gl->fn.GetString(GL_RENDERER), *ver = dev->gl->fn.GetString(GL_VERSION);
    snprintf(out, cap, "%s|%s|%s", v ? (const char *)v : "", r ? (const char *)r : "", ver ? (const char *)ver : "");
}

static uint64_t program_key(const hfx_fx_program *fp, const char *vs, const char *fs, const char *driver) {
    uint64_t h = fnv1a_str(0xcbf29ce484222325ull, vs);
    h = fnv1a_str(h, fs);
    for (uint32_t a = 0; a < fp->attribute_count; a++) {
        h = fnv1a_str(h, fp->attributes[a].glsl_name);
        h = fnv1a(h, &fp->attributes[a].location, sizeof fp->attributes[a].location);
    }
    return fnv1a_str(h, driver);
}

static char *entry_path(const hfx_device *dev, uint64_t key) {
    size_t n = strlen(dev->gl->program_cache) + 32;
    char *path = malloc(n);
    if (path) snprintf(path, n, "%s/%016llx.hfxbin", dev->gl->program_cache, (unsigned long long)key);
    return path;
}

static uint32_t rd32(const unsigned char *p) { return p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24; }

static void wr32(unsigned char *p, uint32_t v) {
    for (int i = 0; i < 4; i++) p[i] = (unsigned char)(v >> (8 * i));
}

/* The whole file, or NULL (absent, unreadable or absurdly large). */
static unsigned char *read_entry(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    unsigned char *data = NULL;
    long n = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (n >= HEADER_WORDS * 4 && n <= MAX_BINARY && fseek(f, 0, SEEK_SET) == 0 && (data = malloc((size_t)n))) {
        if (fread(data, 1, (size_t)n, f) != (size_t)n) {
            free(data);
            data = NULL;
        }
    }
    fclose(f);
    *size = data ? (size_t)n : 0;
    return data;
}

/* Where the binary starts in a file that matches key and driver in every field; NULL if not. */
static const unsigned char *check_entry(const unsigned char *d, size_t size, uint64_t key, const char *driver,
                                        GLenum *format, uint32_t *length) {
    uint32_t driver_len = rd32(d + 28);
    *format = rd32(d + 16);
    *length = rd32(d + 20);
    if (memcmp(d, magic, 4) != 0 || rd32(d + 4) != CACHE_VERSION || rd32(d + 8) != (uint32_t)key ||
        rd32(d + 12) != (uint32_t)(key >> 32) || driver_len != strlen(driver) || *length == 0 ||
        (uint64_t)HEADER_WORDS * 4 + driver_len + *length != size || memcmp(d + HEADER_WORDS * 4, driver, driver_len) != 0)
        return NULL;
    const unsigned char *bin = d + HEADER_WORDS * 4 + driver_len;
    return crc32(0L, bin, *length) == rd32(d + 24) ? bin : NULL;
}

/* The program from the cache into p->object; HFX_OK on a hit (the object linked). */
static int try_cached(hfx_device *dev, hfx_rt_program *p, uint64_t key, const char *driver) {
    char *path = entry_path(dev, key);
    size_t size = 0;
    unsigned char *data = path ? read_entry(path, &size) : NULL;
    free(path);
    GLenum format = 0;
    uint32_t length = 0;
    const unsigned char *bin = data ? check_entry(data, size, key, driver, &format, &length) : NULL;
    GLint ok = 0;
    if (bin && (p->object = dev->gl->fn.CreateProgram()) != 0) {
        dev->gl->fn.ProgramBinary(p->object, format, bin, (GLsizei)length);
        dev->gl->fn.GetProgramiv(p->object, GL_LINK_STATUS, &ok);
        while (dev->gl->fn.GetError() != GL_NO_ERROR) {} /* a refused binary is a miss, not an error */
        if (!ok) {
            dev->gl->fn.DeleteProgram(p->object);
            p->object = 0;
        }
    }
    free(data);
    return ok ? HFX_OK : HFX_ERR_GL;
}

/* Writes the linked program's binary under a temporary name, then renames it into place, so
 * a reader never sees half a file. Failures only cost the next load its shortcut. */
static void store(hfx_device *dev, const hfx_rt_program *p, uint64_t key, const char *driver) {
    GLint len = 0;
    dev->gl->fn.GetProgramiv(p->object, GL_PROGRAM_BINARY_LENGTH, &len);
    size_t driver_len = strlen(driver), total = HEADER_WORDS * 4 + driver_len + (size_t)len;
    unsigned char *d = len > 0 && len <= MAX_BINARY ? malloc(total) : NULL;
    char *path = d ? entry_path(dev, key) : NULL, *tmp = path ? malloc(strlen(path) + 8) : NULL;
    GLsizei got = 0;
    GLenum format = 0;
    if (tmp) dev->gl->fn.GetProgramBinary(p->object, len, &got, &format, d + HEADER_WORDS * 4 + driver_len);
    if (tmp && got == len) {
        memcpy(d, magic, 4);
        const uint32_t words[] = {CACHE_VERSION, (uint32_t)key, (uint32_t)(key >> 32), format, (uint32_t)len,
                                  (uint32_t)crc32(0L, d + HEADER_WORDS * 4 + driver_len, (uInt)len), (uint32_t)driver_len};
        for (int i = 0; i < 7; i++) wr32(d + 4 + 4 * i, words[i]);
        memcpy(d + HEADER_WORDS * 4, driver, driver_len);
        sprintf(tmp, "%s.tmp", path);
        FILE *f = fopen(tmp, "wb");
        int ok = f && fwrite(d, 1, total, f) == total;
        if (f && fclose(f) != 0) ok = 0;
        if (!ok || rename(tmp, path) != 0) remove(tmp);
    }
    while (dev->gl->fn.GetError() != GL_NO_ERROR) {}
    free(tmp);
    free(path);
    free(d);
}

int hfx_rt_program_cached_link(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp, const char *vs_src,
                               const char *fs_src, int (*link)(hfx_shared *, hfx_rt_program *, const hfx_fx_program *,
                                                               const char *, const char *)) {
    hfx_device *dev = sh->dev;
    if (!cache_on(dev)) return link(sh, p, fp, vs_src, fs_src);
    char driver[512];
    driver_string(dev, driver, sizeof driver);
    uint64_t key = program_key(fp, vs_src, fs_src, driver);
    if (try_cached(dev, p, key, driver) == HFX_OK) return HFX_OK;
    if (dev->cache_only) return hfx_rt_fail(dev, HFX_ERR_NOT_FOUND, "a program is not in the cache");
    int rc = link(sh, p, fp, vs_src, fs_src);
    if (rc == HFX_OK) store(dev, p, key, driver);
    return rc;
}

void hfx_rt_program_binary_hint(hfx_device *dev, GLuint program) {
    if (cache_on(dev)) dev->gl->fn.ProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
}
