/* tools/hfxview/teapot.c: Newell's teapot as data and as a mesh. The expected figures are the
 * teapot's own, worked out by hand from the control points (comments below), not read back
 * from the program: the count of distinct control points, the bounding box (the teapot is
 * famously 3.15 high, 4 deep and a little over 6.4 wide), and that normals face out. */
#include <math.h>
#include <string.h>

#include "test.h"

#include "../../tools/hfxview/mesh.c"
#include "../../tools/hfxview/obj.c"
#include "../../tools/hfxview/teapot.c"
#include "../../tools/hfxview/vmath.c"

/* Distinct control points over the 32 patches. Revolved parts: a full ring of radius r > 0 has
 * 12 (4 on the axes, 2 inside each quadrant); the profiles' rows give 17 such rings (knob 0.8
 * and 0.2; lid 0.4, 1.3 at 2.55 and 1.3 at 2.4; rim 1.4, 1.3375, 1.4375, 1.5; body 1.75, 2 at
 * 1.35, 0.9 and 0.45, 1.5 at 0.225 and 0.15; bottom 1.5 at 0.075, 1.425) and 3 rows of radius 0
 * give one point each: 207. Handle and spout: 4 rows of 2 points on y = 0 and 2 mirrored pairs,
 * 6 a row; the two patches of each share a row: 7 rows x 6 = 42 each. The handle's last row
 * starts at (-2, 0, 0.9), a point of the body's r = 2 ring: 207 + 42 + 42 - 1 = 290. */
static void distinct_control_points(void) {
    static float seen[32 * 16][3];
    int n = 0;
    for (int i = 0; i < HV_TEAPOT_PATCHES; i++) {
        float cp[16][3];
        hv_teapot_patch(i, cp);
        for (int k = 0; k < 16; k++) {
            int j = 0;
            while (j < n && memcmp(seen[j], cp[k], sizeof seen[j]) != 0) j++;
            if (j == n) memcpy(seen[n++], cp[k], sizeof seen[0]);
        }
    }
    CHECK_INT(n, 290);
}

/* Neighbouring patches meet: the body's upper patch ends on the row the lower one starts with
 * (ring r = 2 at z = 0.9), and the two halves of the spout meet on y = 0. */
static void patches_meet(void) {
    float upper[16][3], lower[16][3], a[16][3], b[16][3];
    hv_teapot_patch(12, upper); /* profile 3 (body, upper), quadrant 0 */
    hv_teapot_patch(16, lower); /* profile 4 (body, lower), quadrant 0 */
    CHECK(memcmp(upper[12], lower[0], 4 * sizeof upper[0]) == 0);
    CHECK_NEAR(upper[12][0], 2.0, 0);
    CHECK_NEAR(upper[12][2], 0.9, 1e-7);
    hv_teapot_patch(28, a), hv_teapot_patch(29, b); /* spout base, both halves */
    for (int r = 0; r < 4; r++) {
        CHECK(memcmp(a[r * 4], b[r * 4], sizeof a[0]) == 0);         /* first column on y = 0 */
        CHECK(memcmp(a[r * 4 + 3], b[r * 4 + 3], sizeof a[0]) == 0); /* and the last */
        CHECK_NEAR(a[r * 4 + 1][1], -b[r * 4 + 1][1], 0);
    }
}

/* The tessellated surface, y up, in Newell's units. Height: the knob's top (0, 0, 3.15) and the
 * bottom's centre (0, 0, 0) are patch corners. Depth: the body's ring r = 2 at z = 0.9 is a patch
 * edge, its points (0, +-2) corners. Width: the handle's outer edge ends at the corner
 * (-3, 0, 1.8); the spout's tip edge is the Bezier x(t) of 3.3, 3.525, 3.45, 3.2, whose largest
 * value is near t = 0.4: 0.216 * 3.3 + 0.432 * 3.525 + 0.288 * 3.45 + 0.064 * 3.2 = 3.434. */
static void bounding_box(void) {
    hv_mesh m;
    memset(&m, 0, sizeof m);
    hv_teapot_add(&m, 16);
    CHECK(!m.oom);
    float lo[3] = {1e9f, 1e9f, 1e9f}, hi[3] = {-1e9f, -1e9f, -1e9f};
    for (size_t i = 0; i < m.vcount; i++)
        for (int k = 0; k < 3; k++) lo[k] = fminf(lo[k], m.v[i].pos[k]), hi[k] = fmaxf(hi[k], m.v[i].pos[k]);
    CHECK_NEAR(lo[0], -3.0, 1e-5);
    CHECK_NEAR(hi[0], 3.434, 0.002); /* samples at t = 6/16 and 7/16 fall within 0.001 of the top */
    CHECK_NEAR(lo[1], 0.0, 1e-5);
    CHECK_NEAR(hi[1], 3.15, 1e-5);
    CHECK_NEAR(lo[2], -2.0, 1e-5);
    CHECK_NEAR(hi[2], 2.0, 1e-5);
    CHECK_INT(m.vcount, 32 * 17 * 17);
    hv_mesh_free(&m);
}

/* Normals face out: round the body's widest part (away from the handle and spout, which lie
 * within 0.66 of the x axis) they point away from the axis, at the knob's top up, at the
 * bottom's centre down. */
static void normals_face_out(void) {
    hv_mesh m;
    memset(&m, 0, sizeof m);
    hv_teapot_add(&m, 8);
    int body = 0, top = 0, bottom = 0;
    for (size_t i = 0; i < m.vcount; i++) {
        const float *p = m.v[i].pos, *n = m.v[i].normal;
        float r = sqrtf(p[0] * p[0] + p[2] * p[2]);
        if (fabsf(p[1] - 1.1f) < 0.3f && r > 1.95f && fabsf(p[2]) > 1.0f) {
            CHECK((n[0] * p[0] + n[2] * p[2]) / r > 0.9f);
            body++;
        }
        if (r < 1e-4f && fabsf(p[1] - 3.15f) < 1e-4f) {
            CHECK(n[1] > 0.99f);
            top++;
        }
        if (r < 1e-4f && fabsf(p[1]) < 1e-4f) {
            CHECK(n[1] < -0.99f);
            bottom++;
        }
    }
    CHECK(body > 0 && top > 0 && bottom > 0);
    hv_mesh_free(&m);
}

/* --mesh teapot: the same shape centred and scaled into the unit sphere; its proportions stay
 * (width / height = (3.434 + 3) / 3.15 = 2.043, depth / height = 4 / 3.15 = 1.270). */
static void builtin_keeps_the_proportions(void) {
    hv_mesh m;
    CHECK_INT(hv_mesh_builtin(&m, "teapot"), 0);
    float lo[3] = {1e9f, 1e9f, 1e9f}, hi[3] = {-1e9f, -1e9f, -1e9f}, far = 0;
    for (size_t i = 0; i < m.vcount; i++) {
        const float *p = m.v[i].pos;
        for (int k = 0; k < 3; k++) lo[k] = fminf(lo[k], p[k]), hi[k] = fmaxf(hi[k], p[k]);
        far = fmaxf(far, sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    }
    CHECK_NEAR(far, 1.0, 1e-5);
    CHECK_NEAR((hi[0] - lo[0]) / (hi[1] - lo[1]), 2.043, 0.002);
    CHECK_NEAR((hi[2] - lo[2]) / (hi[1] - lo[1]), 1.270, 0.001);
    CHECK_NEAR(lo[1] + hi[1], 0.0, 1e-5); /* height centred */
    hv_mesh_free(&m);
}

int main(void) {
    RUN(distinct_control_points);
    RUN(patches_meet);
    RUN(bounding_box);
    RUN(normals_face_out);
    RUN(builtin_keeps_the_proportions);
    return test_summary();
}
