/* image.c: image files in and out (see image.h). */
#include "image.h"

#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef HFXVIEW_STB_IMPLEMENTATION /* no libstb to link: compile stb_image here */
#define STB_IMAGE_IMPLEMENTATION
#endif
#include <stb_image.h>

int hv_image_load(hv_image *img, const char *path, char *err, size_t errlen) {
    int comp = 0;
    memset(img, 0, sizeof *img);
    img->rgba = stbi_load(path, &img->width, &img->height, &comp, 4);
    if (!img->rgba) {
        snprintf(err, errlen, "cannot read image '%s': %s", path, stbi_failure_reason());
        return -1;
    }
    return 0;
}

int hv_image_write_png(const hv_image *img, const char *path) {
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = (png_uint_32)img->width;
    png.height = (png_uint_32)img->height;
    png.format = PNG_FORMAT_RGBA;
    if (!png_image_write_to_file(&png, path, 0, img->rgba, (png_int_32)img->width * 4, NULL)) return -1;
    return 0;
}

int hv_image_checker(hv_image *img, int size, int cells, const unsigned char a[4], const unsigned char b[4]) {
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

void hv_image_free(hv_image *img) {
    free(img->rgba); /* stbi_load's buffer comes from malloc too (STBI_MALLOC default) */
    img->rgba = NULL;
    img->width = img->height = 0;
}
