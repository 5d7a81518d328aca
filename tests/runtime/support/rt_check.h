/* rt_check.h: checks the runtime tests share. Static inline on purpose: test.h's counters are
 * per file, so a CHECK compiled into a support .c would never fail the test that calls it. */
#ifndef HFX_TEST_RT_CHECK_H
#define HFX_TEST_RT_CHECK_H

#include "gl_context.h"
#include "test.h"

/* The pixel at (x, y) from the top is (r, g, b, a) within 1/255 (GL rounds to nearest). */
static inline void rt_check_pixel(test_gl *gl, int x, int y, int r, int g, int b, int a) {
    unsigned char px[4];
    test_gl_read(gl, x, y, px);
    CHECK_NEAR(px[0], r, 1);
    CHECK_NEAR(px[1], g, 1);
    CHECK_NEAR(px[2], b, 1);
    CHECK_NEAR(px[3], a, 1);
}

#endif
