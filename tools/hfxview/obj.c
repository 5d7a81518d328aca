/* obj.c: a Wavefront OBJ reader (v, vt, vn, f; polygons become fans; negative indices count
 * from the end). Corners that share a position/uv/normal triple share a vertex. Files without
 * normals get smooth ones, taking OBJ's counter-clockwise fronts; texture v is flipped to
 * Direct3D's top-down convention. The result is centred and scaled into the unit sphere. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "mesh.h"

typedef struct { float *data; uint32_t count, cap; int width; } float_list;
typedef struct { long v, t, n; uint32_t index; int used; } corner_slot;

typedef struct {
    float_list pos, uv, nrm;
    corner_slot *slots;  /* open-addressing hash of corner triples -> vertex index */
    size_t slot_cap, slot_used;
    hv_mesh *m;
    int missing_normals; /* some corner has no normal: compute them all */
} obj_reader;

static int list_push(float_list *l, const float *v) {
    if (!hfx_grow((void **)&l->data, (size_t)l->width * sizeof *l->data, l->count, &l->cap, 1024, NULL, NULL)) return 0;
    memcpy(l->data + l->count * (size_t)l->width, v, (size_t)l->width * sizeof *v);
    l->count++;
    return 1;
}

static size_t slot_hash(long v, long t, long n, size_t cap) {
    unsigned long long h = (unsigned long long)v * 73856093ull ^ (unsigned long long)t * 19349663ull ^
                           (unsigned long long)n * 83492791ull;
    return (size_t)(h & (cap - 1));
}

static int slots_grow(obj_reader *r) {
    size_t cap = r->slot_cap ? r->slot_cap * 2 : 4096;
    corner_slot *s = calloc(cap, sizeof *s);
    if (!s) return 0;
    for (size_t i = 0; i < r->slot_cap; i++) {
        if (!r->slots[i].used) continue;
        size_t h = slot_hash(r->slots[i].v, r->slots[i].t, r->slots[i].n, cap);
        while (s[h].used) h = (h + 1) & (cap - 1);
        s[h] = r->slots[i];
    }
    free(r->slots);
    r->slots = s;
    r->slot_cap = cap;
    return 1;
}

/* OBJ indices are 1-based; negative ones count back from the latest element. 0 = absent. */
static long resolve(long i, size_t count) {
    if (i > 0 && (size_t)i <= count) return i;
    if (i < 0 && (size_t)(-i) <= count) return (long)count + i + 1;
    return i == 0 ? 0 : -1;
}

static long corner_vertex(obj_reader *r, long v, long t, long n) {
    if ((r->slot_used + 1) * 2 > r->slot_cap && !slots_grow(r)) return -1;
    size_t h = slot_hash(v, t, n, r->slot_cap);
    while (r->slots[h].used) {
        corner_slot *s = &r->slots[h];
        if (s->v == v && s->t == t && s->n == n) return s->index;
        h = (h + 1) & (r->slot_cap - 1);
    }
    float uv[2] = {0, 0};
    if (t) {
        uv[0] = r->uv.data[(t - 1) * 2];
        uv[1] = 1.0f - r->uv.data[(t - 1) * 2 + 1];
    }
    uint32_t index = hv_mesh_add_vertex(r->m, r->pos.data + (v - 1) * 3, n ? r->nrm.data + (n - 1) * 3 : NULL, uv);
    if (r->m->oom) return -1;
    r->slots[h] = (corner_slot){v, t, n, index, 1};
    r->slot_used++;
    return index;
}

/* "v", "v/t", "v//n" or "v/t/n". */
static int parse_corner(obj_reader *r, const char *s, long *out) {
    long idx[3] = {0, 0, 0};
    size_t counts[3] = {r->pos.count, r->uv.count, r->nrm.count};
    for (int k = 0; k < 3 && *s; k++) {
        if (*s != '/') {
            char *end;
            long i = strtol(s, &end, 10);
            if (end == s) return 0;
            idx[k] = resolve(i, counts[k]);
            if (idx[k] < 0) return 0;
            s = end;
        }
        if (*s == '/') s++;
        else break;
    }
    if (idx[0] == 0) return 0;
    if (!idx[2]) r->missing_normals = 1;
    *out = corner_vertex(r, idx[0], idx[1], idx[2]);
    return *out >= 0;
}

static int parse_floats(const char *s, float *out, int n) {
    for (int i = 0; i < n; i++) {
        char *end;
        out[i] = strtof(s, &end);
        if (end == s) return i;
        s = end;
    }
    return n;
}

static int parse_face(obj_reader *r, char *s) {
    long first = -1, prev = -1;
    int n = 0;
    char *save = NULL;
    for (char *tok = strtok_r(s, " \t\r\n", &save); tok; tok = strtok_r(NULL, " \t\r\n", &save), n++) {
        long v;
        if (!parse_corner(r, tok, &v)) return 0;
        if (n == 0) first = v;
        else if (n >= 2) hv_mesh_add_triangle(r->m, (uint32_t)first, (uint32_t)prev, (uint32_t)v);
        prev = v;
    }
    return n >= 3;
}

static int parse_line(obj_reader *r, char *line) {
    while (isspace((unsigned char)*line)) line++;
    float f[3] = {0, 0, 0};
    if (!strncmp(line, "v ", 2) || !strncmp(line, "v\t", 2))
        return parse_floats(line + 2, f, 3) == 3 && list_push(&r->pos, f);
    if (!strncmp(line, "vt", 2) && isspace((unsigned char)line[2]))
        return parse_floats(line + 3, f, 2) >= 1 && list_push(&r->uv, f);
    if (!strncmp(line, "vn", 2) && isspace((unsigned char)line[2]))
        return parse_floats(line + 3, f, 3) == 3 && list_push(&r->nrm, f);
    if (line[0] == 'f' && isspace((unsigned char)line[1])) return parse_face(r, line + 2);
    return 1; /* comments, groups, materials, smoothing groups: not needed to draw */
}

/* Centre the bounding box on the origin and scale the farthest vertex to distance 1. */
static void fit_unit_sphere(hv_mesh *m) {
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, r2 = 0;
    for (size_t i = 0; i < m->vcount; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], m->v[i].pos[k]);
            hi[k] = fmaxf(hi[k], m->v[i].pos[k]);
        }
    for (size_t i = 0; i < m->vcount; i++) {
        float d2 = 0;
        for (int k = 0; k < 3; k++) {
            float d = m->v[i].pos[k] - (lo[k] + hi[k]) * 0.5f;
            d2 += d * d;
        }
        r2 = fmaxf(r2, d2);
    }
    float s = r2 > 0 ? 1.0f / sqrtf(r2) : 1.0f;
    for (size_t i = 0; i < m->vcount; i++)
        for (int k = 0; k < 3; k++) m->v[i].pos[k] = (m->v[i].pos[k] - (lo[k] + hi[k]) * 0.5f) * s;
}

static void reader_free(obj_reader *r) {
    free(r->pos.data);
    free(r->uv.data);
    free(r->nrm.data);
    free(r->slots);
}

int hv_mesh_load_obj(hv_mesh *m, const char *path, char *err, size_t errlen) {
    memset(m, 0, sizeof *m);
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, errlen, "cannot open mesh '%s' (not a built-in mesh name either)", path);
        return -1;
    }
    obj_reader r = {.pos.width = 3, .uv.width = 2, .nrm.width = 3, .m = m};
    char line[4096];
    int lineno = 0, ok = 1;
    while (ok && fgets(line, sizeof line, f)) {
        lineno++;
        ok = parse_line(&r, line) && !m->oom;
    }
    fclose(f);
    if (ok && m->icount == 0) {
        snprintf(err, errlen, "%s: no faces", path);
        ok = 0;
    } else if (!ok) {
        snprintf(err, errlen, "%s(%d): cannot read this line", path, lineno);
    }
    if (ok) {
        if (r.missing_normals) hv_mesh_compute_normals(m);
        fit_unit_sphere(m);
        hv_mesh_finish(m);
        if (m->oom) {
            snprintf(err, errlen, "%s: out of memory", path);
            ok = 0;
        }
    }
    reader_free(&r);
    if (!ok) hv_mesh_free(m);
    return ok ? 0 : -1;
}
