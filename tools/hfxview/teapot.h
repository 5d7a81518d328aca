/* teapot.h: the Utah teapot (Newell's 32 bicubic Bezier patches) for hfxview's --mesh teapot. */
#ifndef HFXVIEW_TEAPOT_H
#define HFXVIEW_TEAPOT_H

#include "mesh.h"

enum { HV_TEAPOT_PATCHES = 32 };

/* Patch i's 4 x 4 control points (row-major) in Newell's units: z up, bottom at z = 0. */
void hv_teapot_patch(int i, float cp[16][3]);
/* Every patch as a (divisions + 1)^2 vertex grid with outward normals, y up (x, z, -y), in
 * Newell's units (the caller centres and scales). */
void hv_teapot_add(hv_mesh *m, int divisions);

#endif
