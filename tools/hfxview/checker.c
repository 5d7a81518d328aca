/* checker.c: the default textures, apart from image.c's file readers so that the web page's
 * module (which has no libpng or stb) builds the same ones (see image.h). */
#include <stdlib.h>
#include <string.h>

#include "image.h"

static const unsigned char light[4] = {235, 235, 235, 255}, dark[4] = {90, 90, 100, 255};

int hv_image_checker(hv_image *img, int size, int cells, const unsigned char a[4], const unsigned char b[4]) {
    memset(img, 0, sizeof *img);
    img->width = img->height = size;
    img->rgba = malloc((size_t)size * (size_t)size * 4);
    if (!img->rgba) return -1;
    int cell = size / (cells > 0 ? cells : 1);
    if (cell < 1) cell = 1;
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++)
            memcpy(img->rgba + ((size_t)y * size + x) * 4, ((x / cell + y / cell) & 1) ? b : a, 4);
    return 0;
}

int hv_image_checker_3d(hv_image *img, int size, int cells, const unsigned char a[4], const unsigned char b[4]) {
    memset(img, 0, sizeof *img);
    img->width = img->height = img->depth = size;
    img->rgba = malloc(hv_image_face_bytes(img));
    if (!img->rgba) return -1;
    int cell = size / (cells > 0 ? cells : 1);
    if (cell < 1) cell = 1;
    unsigned char *p = img->rgba;
    for (int z = 0; z < size; z++)
        for (int y = 0; y < size; y++)
            for (int x = 0; x < size; x++, p += 4) memcpy(p, ((x / cell + y / cell + z / cell) & 1) ? b : a, 4);
    return 0;
}

int hv_image_default(hv_image *img, int volume) {
    return volume ? hv_image_checker_3d(img, 32, 4, light, dark) : hv_image_checker(img, 256, 8, light, dark);
}
