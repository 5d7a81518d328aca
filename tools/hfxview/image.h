/* image.h: RGBA8 images, top row first (as in PNG files and Direct3D textures). Files are read
 * with stb_image (PNG, JPEG, TGA, BMP...), DDS files (DXTn, cube maps, volumes) with DevIL,
 * and written as PNG with libpng. */
#ifndef HFXVIEW_IMAGE_H
#define HFXVIEW_IMAGE_H

#include <stddef.h>

typedef struct hv_image {
    int width, height;
    int depth, faces;    /* a volume's slices, a cube map's 6 faces; 0 or 1 for a plain image */
    unsigned char *rgba; /* faces * depth * height * width * 4 bytes, top row first */
} hv_image;

/* Bytes of one face (all its slices) and the number of faces, counting 0 as 1. Inline so that
 * render.c links without the file readers (the web page's module has no libpng or stb). */
static inline size_t hv_image_face_bytes(const hv_image *img) {
    return (size_t)img->width * (size_t)img->height * (size_t)(img->depth > 1 ? img->depth : 1) * 4;
}
static inline int hv_image_face_count(const hv_image *img) { return img->faces > 1 ? img->faces : 1; }

int hv_image_load(hv_image *img, const char *path, char *err, size_t errlen); /* 0, or -1 with err */
int hv_image_write_png(const hv_image *img, const char *path);              /* 0, or -1 */
/* The default texture (checker.c), the same in hfxview and the web page (web/wasm/draw.c) so
 * that their pictures of an effect compare (scripts/corpus.sh compare): 256 x 256 texels of 8 x 8
 * squares, light (235, 235, 235) at (0, 0) and bluish dark grey (90, 90, 100); a cube map has it
 * on every face; volume: 32^3 texels of 4^3 cubes. 0, or -1 when memory ran out. */
int hv_image_default(hv_image *img, int volume);
/* A checkerboard of cells x cells squares in two colours: the default texture, visible at a glance. */
int hv_image_checker(hv_image *img, int size, int cells, const unsigned char a[4], const unsigned char b[4]);
/* A size^3 volume of cells^3 cubes in two colours: the default volume texture. */
int hv_image_checker_3d(hv_image *img, int size, int cells, const unsigned char a[4], const unsigned char b[4]);
void hv_image_free(hv_image *img);

#endif
