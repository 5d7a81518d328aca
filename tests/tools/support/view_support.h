/* view_support.h: for tests that run hfxview and the examples as programs and look at the
 * images they write (read back with stb_image, independently of the writer, libpng). */
#ifndef HFX_VIEW_SUPPORT_H
#define HFX_VIEW_SUPPORT_H

#include <stddef.h>

typedef struct view_png {
    int width, height;
    unsigned char *rgba;
} view_png;

/* $HFX_BUILD_DIR/relative if that file exists (malloc'ed), else NULL. */
char *view_build_path(const char *relative);
/* Runs a shell command with stdout and stderr captured into *output (malloc'ed, may be
 * NULL); returns the exit status, or -1 if it could not run. */
int view_run(const char *command, char **output);
int view_png_read(view_png *img, const char *path);     /* 0, or -1 */
void view_png_free(view_png *img);
const unsigned char *view_png_at(const view_png *img, int x, int y); /* RGBA at column x, row y from the top */
/* |pixel - rgb| <= tol per channel; prints the pixel when it is not. */
int view_pixel_near(const view_png *img, int x, int y, int r, int g, int b, int tol);
/* The largest difference of any channel of any pixel (RGBA), or -1 when the sizes differ;
 * prints the first few pixels that differ by more than 1, and counts them in *count_over_1. */
int view_png_max_difference(const view_png *a, const view_png *b, int *count_over_1);
char *view_format(const char *fmt, ...) __attribute__((format(printf, 1, 2))); /* malloc'ed */
/* hfxview (its path) on an effect's text, written to dir/view.fx: `hfxview FX -o dir/view.png
 * --size 128x128 args`, the image read into *img. 1 when it ran and wrote an image (else 0, the
 * command and its output printed); its output in *out (malloc'ed) unless out is NULL. */
int view_run_effect(const char *hfxview, const char *dir, const char *fx_text, const char *args, view_png *img,
                    char **out);

#endif
