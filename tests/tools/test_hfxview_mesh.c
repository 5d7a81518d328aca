/* hfxview's meshes: vertex and index counts from the grid sizes, unit normals and tangents,
 * clockwise front faces (XNA's convention) checked on screen, and the OBJ reader. */
#include "test.h"

#include <unistd.h>

#include "files.h"

#include "../../tools/hfxview/mesh.c"
#include "../../tools/hfxview/obj.c"
#include "../../tools/hfxview/teapot.c"
#include "../../tools/hfxview/vmath.c"

static int unit(const float *v) { return fabsf(sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1.0f) < 1e-4f; }

/* Every property a drawable mesh must have; counts failures rather than flooding stderr. */
static void check_mesh(const char *what, const hv_mesh *m) {
    size_t bad_normal = 0, bad_tangent = 0, bad_uv = 0, bad_index = 0, bad_winding = 0;
    for (size_t i = 0; i < m->vcount; i++) {
        const hv_vertex *v = &m->v[i];
        bad_normal += !unit(v->normal);
        float d = v->normal[0] * v->tangent[0] + v->normal[1] * v->tangent[1] + v->normal[2] * v->tangent[2];
        bad_tangent += !unit(v->tangent) || !unit(v->binormal) || fabsf(d) > 1e-3f;
        bad_uv += v->uv[0] < -1e-6f || v->uv[0] > 1 + 1e-6f || v->uv[1] < -1e-6f || v->uv[1] > 1 + 1e-6f;
    }
    for (size_t t = 0; t + 2 < m->icount; t += 3) {
        int ok = 1;
        for (int k = 0; k < 3; k++) ok &= m->idx[t + k] < m->vcount;
        if (!ok) {
            bad_index++;
            continue;
        }
        hv_vec3 a = vpos(m, m->idx[t]), b = vpos(m, m->idx[t + 1]), c = vpos(m, m->idx[t + 2]);
        hv_vec3 n = hv_vec3_add(hv_vec3_add(vnorm(m, m->idx[t]), vnorm(m, m->idx[t + 1])), vnorm(m, m->idx[t + 2]));
        bad_winding += hv_vec3_dot(hv_vec3_cross(hv_vec3_sub(b, a), hv_vec3_sub(c, a)), n) >= 0;
    }
    if (bad_normal || bad_tangent || bad_uv || bad_index || bad_winding)
        fprintf(stderr, "%s: %zu bad normals, %zu bad tangents, %zu bad uvs, %zu bad indices, %zu bad windings\n", what,
                bad_normal, bad_tangent, bad_uv, bad_index, bad_winding);
    CHECK(bad_normal == 0);
    CHECK(bad_tangent == 0);
    CHECK(bad_uv == 0);
    CHECK(bad_index == 0);
    CHECK(bad_winding == 0);
    CHECK(m->icount % 3 == 0);
}

static void sphere_counts_and_radius(void) {
    hv_mesh m;
    CHECK_INT(hv_mesh_builtin(&m, "sphere"), 0);
    /* 48 x 24 quads on a 49 x 25 grid; the 2 x 48 pole quads collapse to one triangle each. */
    CHECK_INT(m.vcount, 49 * 25);
    CHECK_INT(m.icount, 3 * (48 * 24 * 2 - 2 * 48));
    check_mesh("sphere", &m);
    float worst = 0;
    for (size_t i = 0; i < m.vcount; i++) worst = fmaxf(worst, fabsf(hv_vec3_length(vpos(&m, (uint32_t)i)) - 1));
    CHECK(worst < 1e-5f);
    hv_mesh_free(&m);
}

static void every_builtin_is_well_formed(void) {
    for (int i = 0; hv_mesh_names[i]; i++) {
        hv_mesh m;
        CHECK_INT(hv_mesh_builtin(&m, hv_mesh_names[i]), 0);
        CHECK(m.vcount > 0 && m.icount > 0);
        check_mesh(hv_mesh_names[i], &m);
        hv_mesh_free(&m);
    }
    hv_mesh m;
    CHECK_INT(hv_mesh_builtin(&m, "dodecahedron"), -1);
    hv_mesh_free(&m);
}

static void plane_cube_torus_counts(void) {
    hv_mesh m;
    hv_mesh_builtin(&m, "plane");
    CHECK_INT(m.vcount, 17 * 17);
    CHECK_INT(m.icount, 16 * 16 * 6);
    for (size_t i = 0; i < m.vcount; i++) CHECK(m.v[i].normal[1] > 0.999f && m.v[i].pos[1] == 0.0f);
    hv_mesh_free(&m);
    hv_mesh_builtin(&m, "cube");
    CHECK_INT(m.vcount, 24);
    CHECK_INT(m.icount, 36);
    hv_mesh_free(&m);
    hv_mesh_builtin(&m, "torus");
    CHECK_INT(m.vcount, 49 * 25);
    CHECK_INT(m.icount, 48 * 24 * 6);
    float worst = 0; /* every point 0.3 from the ring of radius 0.7 in the xy plane */
    for (size_t i = 0; i < m.vcount; i++) {
        const float *p = m.v[i].pos;
        float ring = sqrtf(p[0] * p[0] + p[1] * p[1]) - 0.7f;
        worst = fmaxf(worst, fabsf(sqrtf(ring * ring + p[2] * p[2]) - 0.3f));
    }
    CHECK(worst < 1e-5f);
    hv_mesh_free(&m);
    hv_mesh_builtin(&m, "teapot");
    for (size_t i = 0; i < m.vcount; i++) CHECK(hv_vec3_length(vpos(&m, (uint32_t)i)) <= 1.0f + 1e-4f);
    hv_mesh_free(&m);
}

/* Seen from the default camera (on +z looking down -z, x right, y up), a front face must run
 * clockwise on screen: negative signed area with y pointing up. */
static void quad_is_clockwise_on_screen_and_uv_top_left(void) {
    hv_mesh m;
    hv_mesh_builtin(&m, "quad");
    CHECK_INT(m.vcount, 4);
    CHECK_INT(m.icount, 6);
    for (size_t t = 0; t < m.icount; t += 3) {
        const float *a = m.v[m.idx[t]].pos, *b = m.v[m.idx[t + 1]].pos, *c = m.v[m.idx[t + 2]].pos;
        float area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        CHECK(area < 0);
    }
    for (size_t i = 0; i < m.vcount; i++) {
        const hv_vertex *v = &m.v[i];
        if (v->pos[0] < 0 && v->pos[1] > 0) CHECK(v->uv[0] == 0 && v->uv[1] == 0); /* top left: (0, 0) */
        if (v->pos[0] > 0 && v->pos[1] < 0) CHECK(v->uv[0] == 1 && v->uv[1] == 1);
        CHECK_NEAR(v->tangent[0], 1, 1e-5);  /* u grows to the right */
        CHECK_NEAR(v->binormal[1], -1, 1e-5); /* v grows downwards */
    }
    hv_mesh_free(&m);
}

static char *write_temp(const char *dir, const char *name, const char *text) {
    char *path = malloc(strlen(dir) + strlen(name) + 2);
    sprintf(path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    return path;
}

static void obj_square_without_normals(void) {
    char *dir = test_temp_dir();
    /* A 2 x 2 square in the xy plane, counter-clockwise from +z (OBJ's front), one quad face. */
    char *path = write_temp(dir, "square.obj",
                            "# square\nv 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                            "g square\nusemtl none\nf 1/1 2/2 3/3 4/4\n");
    hv_mesh m;
    char err[256] = "";
    CHECK_INT(hv_mesh_load(&m, path, err, sizeof err), 0);
    CHECK_INT(m.vcount, 4);
    CHECK_INT(m.icount, 6);
    check_mesh("square.obj", &m);
    for (size_t i = 0; i < m.vcount; i++) {
        CHECK_NEAR(m.v[i].normal[2], 1, 1e-5);
        /* Centred and scaled: the corner (2,2) is now at (1,1)/sqrt(2). */
        CHECK_NEAR(fabsf(m.v[i].pos[0]), 0.70710678, 1e-5);
        CHECK_NEAR(fabsf(m.v[i].pos[1]), 0.70710678, 1e-5);
        /* OBJ's v runs up, Direct3D's down: the bottom-left corner (vt 0 0) gets v = 1. */
        if (m.v[i].pos[0] < 0 && m.v[i].pos[1] < 0) CHECK_NEAR(m.v[i].uv[1], 1, 1e-6);
    }
    hv_mesh_free(&m);
    remove(path);
    rmdir(dir);
    free(path);
    free(dir);
}

static void obj_negative_indices_normals_and_sharing(void) {
    char *dir = test_temp_dir();
    char *path = write_temp(dir, "tri.obj",
                            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 2\n"
                            "f -4//1 -3//1 -2//1\nf 2//1 4//1 3//1\n");
    hv_mesh m;
    char err[256] = "";
    CHECK_INT(hv_mesh_load(&m, path, err, sizeof err), 0);
    CHECK_INT(m.vcount, 4); /* the shared corners 2 and 3 are one vertex each */
    CHECK_INT(m.icount, 6);
    check_mesh("tri.obj", &m);
    hv_mesh_free(&m);
    remove(path);
    rmdir(dir);
    free(path);
    free(dir);
}

static void obj_errors(void) {
    char *dir = test_temp_dir();
    char *bad = write_temp(dir, "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    char *none = write_temp(dir, "none.obj", "v 0 0 0\n");
    hv_mesh m;
    char err[512], want[512];
    CHECK_INT(hv_mesh_load(&m, bad, err, sizeof err), -1);
    snprintf(want, sizeof want, "%s(4): cannot read this line", bad);
    CHECK_STR(err, want);
    CHECK_INT(hv_mesh_load(&m, none, err, sizeof err), -1);
    snprintf(want, sizeof want, "%s: no faces", none);
    CHECK_STR(err, want);
    CHECK_INT(hv_mesh_load(&m, "/nonexistent/x.obj", err, sizeof err), -1);
    CHECK_STR(err, "cannot open mesh '/nonexistent/x.obj' (not a built-in mesh name either)");
    remove(bad);
    remove(none);
    rmdir(dir);
    free(bad);
    free(none);
    free(dir);
}

int main(void) {
    RUN(sphere_counts_and_radius);
    RUN(every_builtin_is_well_formed);
    RUN(plane_cube_torus_counts);
    RUN(quad_is_clockwise_on_screen_and_uv_top_left);
    RUN(obj_square_without_normals);
    RUN(obj_negative_indices_normals_and_sharing);
    RUN(obj_errors);
    return test_summary();
}
