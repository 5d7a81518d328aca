/* floor.h: the scene most seed tests draw (one effect on a textured floor under the top
 * camera) and the lattice of probes that compares its pixels with a reference shader.
 *
 * The helpers that check are static inline on purpose: test.h's counters are static, one set
 * per translation unit, and RUN reads the test file's own, so a CHECK has to expand in the
 * test's file to fail its test. */
#ifndef HFX_SEED_FLOOR_H
#define HFX_SEED_FLOOR_H

#include "scene.h"

typedef struct seed_floor_setup {
    double half;                 /* the floor spans -half..half in x and z */
    double view_half;            /* the top camera sees -view_half..view_half */
    const float *world;          /* where World puts the floor; NULL: identity */
    int tex_width, tex_height;   /* with texels: the texture's size */
    const unsigned char *texels; /* NULL: seed_smooth_texels' 4 x 4 pattern */
    /* The effect's names for World, View, Projection; world_name NULL: set none. */
    const char *world_name, *view_name, *projection_name;
} seed_floor_setup;

/* The lower-case matrix names of the 003 seeds (point.fx, spot.fx...). */
#define SEED_FLOOR_LOWER_NAMES .world_name = "world", .view_name = "view", .projection_name = "projection"

typedef struct seed_floor {
    const char *file;
    hfx_effect *fx;
    seed_mesh *mesh;
    seed_object obj;
    unsigned char texels[64]; /* the smooth pattern; tex points into it, so a seed_floor stays put */
    seed_texture tex;
} seed_floor;

/* The probe pixels (x0 + i step_x, y0 + j step_y) across the whole image, row by row;
 * skip_misses leaves out the pixels whose ray misses the floor. */
typedef struct seed_grid { int x0, step_x, y0, step_y, skip_misses; } seed_grid;

/* Loads `file` (from the seed corpus), makes the texture, the floor, its object and the
 * camera, and sets the matrices. Returns whether the effect loaded; close it either way. */
int seed_floor_open(seed_scene *s, seed_floor *f, const char *file, const seed_floor_setup *setup);

/* Whether the four points `margin` pixels diagonally away from pixel (x, y)'s sample point
 * all hit `obj`: a probe there stays off the silhouette. */
int seed_well_inside(seed_scene *s, const seed_object *obj, int x, int y, double margin);

/* Frees what seed_floor_open made; fails the test when the effect did not load or the
 * harness met a problem. */
static inline void seed_floor_close(seed_scene *s, seed_floor *f) {
    CHECK(f->fx != NULL);
    if (f->fx) hfx_effect_destroy(f->fx);
    seed_texture_free(s, &f->tex);
    seed_mesh_free(s, f->mesh);
    CHECK_SCENE(s);
}

/* Clears to transparent black and draws the floor with `fx` (the floor's own effect or a
 * clone of it), which must take `passes` passes. */
static inline void seed_floor_draw(seed_scene *s, const seed_floor *f, hfx_effect *fx, const char *technique,
                                   seed_blend blend, int passes) {
    seed_clear(s, rgba_make(0, 0, 0, 0));
    CHECK_INT(seed_draw(s, fx, technique, f->mesh, blend), passes);
}

/* Probes every pixel of the grid against the reference `shade`. */
static inline void seed_floor_probe_grid(seed_scene *s, const seed_floor *f, const char *label, seed_grid g,
                                         seed_shade_fn shade, const void *user) {
    for (int y = g.y0; y < seed_height(s); y += g.step_y)
        for (int x = g.x0; x < seed_width(s); x += g.step_x) {
            seed_surface surf;
            if (g.skip_misses && seed_pick(s, &f->obj, 1, x, y, &surf) < 0) continue;
            CHECK_PROBE(seed_probe(s, f->file, label, &f->obj, x, y, shade, user));
        }
}

#endif
