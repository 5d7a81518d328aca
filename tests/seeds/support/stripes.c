/* stripes.c: see stripes.h. */
#include "stripes.h"

double seed_period3(int i) {
    static const double p[3] = {0, 128, 255};
    return p[((i % 3) + 3) % 3];
}

void seed_period3_texels(unsigned char *texels, int size) {
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++) {
            unsigned char *p = texels + (y * size + x) * 4;
            p[0] = (unsigned char)seed_period3(x);
            p[1] = (unsigned char)seed_period3(y);
            p[2] = 0;
            p[3] = 255;
        }
}
