/* stripes.h: the texture of the half-pixel tests. Red repeats 0, 128, 255 along u and green
 * along v, so the mean of two neighbouring texels differs from either texel and from the mean
 * of the next pair: a half-texel shift either way shows in every pixel. */
#ifndef HFX_SEED_STRIPES_H
#define HFX_SEED_STRIPES_H

/* Texel i's red (of column i) or green (of row i) in 0..255: 0, 128, 255, 0... for any i. */
double seed_period3(int i);
/* size x size RGBA8 texels, row 0 first: (period3(x), period3(y), 0, 255). */
void seed_period3_texels(unsigned char *texels, int size);

#endif
