/* gl_fns.c: see gl_fns.h. */
#include "gl_fns.h"

#include "gl_context.h"

int test_gl_fns_load(test_gl_fns *f) {
    int missing = 0;
    /* through a union: ISO C has no cast from an object pointer to a function pointer */
#define TEST_GL_FN_LOAD_(type, name) \
    { union { void *p; type fn; } u_; u_.p = test_gl_proc("gl" #name); f->name = u_.fn; missing += !u_.p; }
    TEST_GL_FNS(TEST_GL_FN_LOAD_)
#undef TEST_GL_FN_LOAD_
    return missing;
}
