/* image.c: image files in and out (see image.h). */
#include "image.h"

#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#ifdef HFXVIEW_STB_IMPLEMENTATION /* no libstb to link: compile stb_image here */
#define STB_IMAGE_IMPLEMENTATION
#endif
#include <stb_image.h>

#ifdef HFXVIEW_HAVE_DEVIL
#include <IL/il.h>
#endif

static int has_extension(const char *path, const char *ext) {
    size_t n = strlen(path), e = strlen(ext);
    return n > e && strcasecmp(path + n - e, ext) == 0;
}

#ifdef HFXVIEW_HAVE_DEVIL
/* Face f of the DevIL image id (all its slices), as RGBA8 rows from the top, into dst. */
static void copy_face(ILuint id, int f, const hv_image *img, unsigned char *dst) {
    ilBindImage(id);
    if (f) ilActiveFace((ILuint)f); /* faces count from the base image, so bind it first */
    ilCopyPixels(0, 0, 0, (ILuint)img->width, (ILuint)img->height, (ILuint)img->depth, IL_RGBA, IL_UNSIGNED_BYTE, dst);
}

/* DDS through DevIL: level 0 of every face and slice; the caller's GL makes the mip chain. */
static int load_dds(hv_image *img, const char *path, char *err, size_t errlen) {
    ilInit();
    ilEnable(IL_ORIGIN_SET);
    ilOriginFunc(IL_ORIGIN_UPPER_LEFT); /* D3D's row order: v = 0 is the first row */
    ILuint id = ilGenImage();
    ilBindImage(id);
    if (!ilLoad(IL_DDS, path)) {
        snprintf(err, errlen, "cannot read image '%s': DevIL error 0x%x", path, (unsigned)ilGetError());
        ilDeleteImage(id);
        return -1;
    }
    img->width = ilGetInteger(IL_IMAGE_WIDTH);
    img->height = ilGetInteger(IL_IMAGE_HEIGHT);
    img->depth = ilGetInteger(IL_IMAGE_DEPTH);
    img->faces = ilGetInteger(IL_NUM_FACES) + 1 == 6 ? 6 : 1;
    img->rgba = malloc(hv_image_face_bytes(img) * (size_t)img->faces);
    for (int f = 0; img->rgba && f < img->faces; f++) copy_face(id, f, img, img->rgba + hv_image_face_bytes(img) * (size_t)f);
    ilDeleteImage(id);
    if (!img->rgba) snprintf(err, errlen, "cannot read image '%s': out of memory", path);
    return img->rgba ? 0 : -1;
}
#else
static int load_dds(hv_image *img, const char *path, char *err, size_t errlen) {
    (void)img;
    snprintf(err, errlen, "cannot read image '%s': hfxview was built without DevIL (libdevil-dev)", path);
    return -1;
}
#endif

int hv_image_load(hv_image *img, const char *path, char *err, size_t errlen) {
    int comp = 0;
    memset(img, 0, sizeof *img);
    if (has_extension(path, ".dds")) return load_dds(img, path, err, errlen);
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

void hv_image_free(hv_image *img) {
    free(img->rgba); /* stbi_load's buffer comes from malloc too (STBI_MALLOC default) */
    memset(img, 0, sizeof *img);
}
