/* floor.c: the floor scene of floor.h (the parts that do not check). */
#include "floor.h"

static void make_texture(seed_scene *s, seed_floor *f, const seed_floor_setup *setup) {
    if (setup->texels) {
        f->tex = seed_texture_make(s, setup->tex_width, setup->tex_height, setup->texels);
        return;
    }
    seed_smooth_texels(f->texels);
    f->tex = seed_texture_make(s, 4, 4, f->texels);
}

int seed_floor_open(seed_scene *s, seed_floor *f, const char *file, const seed_floor_setup *setup) {
    f->file = file;
    f->fx = seed_load(s, file);
    make_texture(s, f, setup);
    f->mesh = seed_mesh_floor(s, setup->half);
    f->obj = seed_object_at(f->mesh, setup->world);
    seed_camera_top(s, setup->view_half);
    if (f->fx && setup->world_name)
        seed_set_transforms(s, f->fx, setup->world_name, setup->view_name, setup->projection_name, f->obj.world);
    return f->fx != NULL;
}

int seed_well_inside(seed_scene *s, const seed_object *obj, int x, int y, double margin) {
    static const int corners[4][2] = {{-1, -1}, {1, 1}, {-1, 1}, {1, -1}};
    seed_surface surf;
    for (int i = 0; i < 4; i++)
        if (seed_pick_offset(s, obj, 1, x, y, corners[i][0] * margin, corners[i][1] * margin, &surf) < 0) return 0;
    return 1;
}
