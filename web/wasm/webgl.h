/* webgl.h: the GL loader the runtime gets in the browser. WebGL 2 is GLES 3.0 less a few
 * things; the runtime's table (runtime/gl.h) is GL 3.3 core. Most entry points are WebGL 2's
 * own (emscripten_webgl_get_proc_address); the rest, and queries of state WebGL 2 does not
 * have (polygon mode, provoking vertex, clip distances, per-buffer colour masks, sample
 * masks, texture level sizes), are answered here with what a WebGL 2 context fixes them at. */
#ifndef HFX_WEB_WEBGL_H
#define HFX_WEB_WEBGL_H

/* An hfx_gl_loader: "glName" -> entry point, or NULL when neither WebGL 2 nor a stand-in has it. */
void *hfxw_gl_proc(const char *name);

/* The level-0 size of a texture the page made with a full mip chain, for the runtime's
 * GL_TEXTURE_WIDTH / HEIGHT queries (glGetTexLevelParameteriv is not in WebGL 2). */
void hfxw_gl_note_texture(unsigned texture, int width, int height);

#endif
