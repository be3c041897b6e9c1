// A surface source's per-sample images (the tiled lighting's readers, deferred's light volumes):
// TP_SURFACE_TEX, the sampler type of an image with one texel per sample (multisampled under
// TP_MSAA), and FETCH(t, p, s), sample s of pixel p (sample 0 of a single-sample image).
#ifndef TP_SURFACE_IMAGES_GLSL
#define TP_SURFACE_IMAGES_GLSL
#ifdef TP_MSAA
#define TP_SURFACE_TEX sampler2DMS
#define FETCH(t, p, s) texelFetch(t, p, int(s))
#else
#define TP_SURFACE_TEX sampler2D
#define FETCH(t, p, s) texelFetch(t, p, 0)
#endif
#endif
