/* Writes the fx_2_0 harness's seeds into a folder: the hand-built test effects of
 * tests/compiler/support/fx2_builder.h (with and without the shader selector). No fetched
 * binary is ever a seed: CI uses only what the repository builds. */
#include <stdio.h>
#include <stdlib.h>

#include "fx2_builder.h"

static int write(const char *dir, const char *name, const uint8_t *data, size_t size) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size) return 1;
    return fclose(f) != 0;
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: fx2_seed DIR\n");
        return 2;
    }
    int bad = 0;
    for (int selector = 0; selector < 2; selector++) {
        size_t size;
        uint8_t *f = fxb_sample_file(&size, NULL, selector);
        bad |= write(argv[1], selector ? "sample_selector.fxb" : "sample.fxb", f, size);
        free(f);
    }
    return bad;
}
