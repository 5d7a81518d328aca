/* image.h: RGBA8 images, top row first (as in PNG files and Direct3D textures). Files are read
 * with stb_image (PNG, JPEG, TGA, BMP...) and written as PNG with libpng. */
#ifndef HFXVIEW_IMAGE_H
#define HFXVIEW_IMAGE_H

#include <stddef.h>

typedef struct hv_image {
    int width, height;
    unsigned char *rgba; /* width * height * 4 bytes, top row first */
} hv_image;

int hv_image_load(hv_image *img, const char *path, char *err, size_t errlen); /* 0, or -1 with err */
int hv_image_write_png(const hv_image *img, const char *path);              /* 0, or -1 */
/* A checkerboard of cells x cells squares in two colours: the default texture, visible at a glance. */
int hv_image_checker(hv_image *img, int size, int cells, const unsigned char a[4], const unsigned char b[4]);
void hv_image_free(hv_image *img);

#endif
