/* bench_web_compile.c: the native side of the web page's compile-time figure. Compiles a
 * seed as the page does (hfx_web.c's hfxw_compile: GLSL ES 300 only, packed uniforms, no
 * glslang self-check, from a file), `rounds` times after as many warm-up compiles, and prints
 * the mean time per compile; then the same with the self-check, as hfxc runs by default. The
 * page's figure comes from hfxw_compile_bench, the same loop in WebAssembly (tests/web).
 * Run by hand: bench_web_compile [file.fx] [rounds]. */
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "hfx/hfx.h"
#include "hfx/hfxc.h"

static double mean_ms(const char *path, unsigned flags, int rounds) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSLES300;
    o.flags = flags;
    double t0 = 0;
    for (int i = 0; i < 2 * rounds; i++) {
        if (i == rounds) t0 = now();
        hfxc_result *r = hfxc_compile_file(path, &o);
        if (!r || !hfxc_result_ok(r)) {
            fprintf(stderr, "%s does not compile\n", path);
            exit(1);
        }
        hfxc_result_free(r);
    }
    return (now() - t0) * 1e3 / rounds;
}

int main(int argc, char **argv) {
    const char *path = argc > 1 ? argv[1] : HFX_SEED_DIR "/spot_specular.fx";
    int rounds = argc > 2 ? atoi(argv[2]) : 200;
    if (rounds < 1) rounds = 1;
    printf("%s, mean of %d compiles after %d warm-up:\n", path, rounds, rounds);
    printf("  as the page compiles (GLSL ES 300, packed, no self-check): %.3f ms\n",
           mean_ms(path, HFXC_PACK_UNIFORMS | HFXC_NO_SELF_CHECK, rounds));
    printf("  with glslang's self-check (hfxc's default):                 %.3f ms\n",
           mean_ms(path, HFXC_PACK_UNIFORMS, rounds));
    return 0;
}
