// The interpolants of scene.vert as a fragment stage receives them, and the material at this
// fragment. Include after scene_bindings.glsl and material.glsl.
//
// Where the inputs are interpolated is stated, never left to the driver. Vulkan lets an
// implementation interpolate an input without the `sample` qualifier anywhere in the pixel
// when sample-rate shading is on: lavapipe takes the pixel centre, NVIDIA the sample, so a
// per-sample shader without `sample` inputs gives a different image on each (measured at
// 4x: the reference moved by RMSE 0.095 on the courtyard at 320x180, 256 lights). Hence:
//   default            `sample` inputs: a shader that runs per sample under MSAA evaluates
//                      its own sample (the reference, Forward+, multipass, the blended pass);
//                      at 1x the one sample is the pixel centre, as without the qualifier.
//   TP_INPUTS_AT_PIXEL once per pixel, at the pixel centre (the deferred G-buffer pass:
//                      no sample shading, one value written to every covered sample).
//   TP_INPUTS_AT_CENTER per-sample invocations that all read the pixel centre through
//                      interpolateAtOffset(x, 0): the reference's `center` MSAA shading, the
//                      once-per-pixel shading a pipeline approximates on covered pixels.
//                      evalSampleMaterial() reads the sample's own location besides, through
//                      interpolateAtSample(x, gl_SampleID), for the alpha test.
#if defined(TP_INPUTS_AT_PIXEL) || defined(TP_INPUTS_AT_CENTER)
#define TP_IN in
#else
#define TP_IN sample in
#endif
#ifdef TP_INPUTS_AT_CENTER
#define TP_INPUT(x) interpolateAtOffset(x, vec2(0.0))
#else
#define TP_INPUT(x) x
#endif
// TP_INPUTS_POSITION_ONLY: only the position and the interpolated 1 (the blended depth
// bounds, fed by scene.vert's TP_VERT_POSITION_ONLY variant), no material.
layout(location = 0) TP_IN vec3 inPosition; // camera-relative: world minus the eye (scene.vert)
layout(location = 5) TP_IN float inOne; // 1, interpolated: see scene.vert
#ifndef TP_INPUTS_POSITION_ONLY
// TP_MATERIAL_FROM_INSTANCE: the material from scene_material_vert (the draw's firstInstance),
// not from DrawPush: an indirect call draws meshes of many materials (multipass forward's
// light passes with --light-lists gpu).
#ifdef TP_MATERIAL_FROM_INSTANCE
layout(location = TP_LOCATION_MATERIAL) flat in uint inMaterial;
#define TP_DRAW_MATERIAL inMaterial
#else
#define TP_DRAW_MATERIAL draw.materialIndex
#endif
// The material at an index: the scene's buffer, unless the shader reads a copy of it
// (Forward+'s shading: a uniform buffer on a CPU device, forwardplus/shading.frag).
#ifndef TP_MATERIAL_OF
#define TP_MATERIAL_OF(index) materials[index]
#endif
layout(location = 1) TP_IN vec3 inNormal;
layout(location = 2) TP_IN vec2 inUv;
layout(location = 3) TP_IN vec4 inTangent;
layout(location = 4) TP_IN vec4 inColor;

// The material with every input read through READ (a plain read or an interpolation
// function), each interpolant over the interpolated 1: a no-op (to an ulp) where the device
// interpolates perspective-correctly at the sample; on lavapipe, which takes 1/w at the
// pixel centre for a sample ((a/w)_s / (1/w)_centre), it restores (a/w)_s / (1/w)_s.
#define TP_EVAL_MATERIAL_READ(READ)                                                                    \
    float k = 1.0 / READ(inOne);                                                                      \
    return evalMaterial(TP_MATERIAL_OF(TP_DRAW_MATERIAL), READ(inPosition) * k, READ(inNormal) * k,       \
                        READ(inUv) * k, READ(inTangent) * k, READ(inColor) * k, gl_FrontFacing)

MaterialSample evalFragmentMaterial() { TP_EVAL_MATERIAL_READ(TP_INPUT); }

#ifdef TP_INPUTS_AT_CENTER
// The material at this sample's own location, as the masked depth prepass (prepass_mask.frag,
// `sample` inputs) evaluates it: a pipeline at --msaa-shading pixel shades at the centre but
// takes each sample's coverage from that prepass's per-sample alpha test, so the centre
// reference alpha-tests with this and shades with evalFragmentMaterial(). Not the `sample`
// qualifier on the inputs: lavapipe then reads a plain load of an input that interpolateAtOffset
// also reads at the pixel centre (measured: the centre reference did not change by a bit).
#define TP_AT_SAMPLE(x) interpolateAtSample(x, gl_SampleID)
MaterialSample evalSampleMaterial() { TP_EVAL_MATERIAL_READ(TP_AT_SAMPLE); }
#undef TP_AT_SAMPLE
#endif

#ifdef TP_SAMPLE_COVERAGE
// The material at sample s of this pixel, read as evalSampleMaterial() reads it in sample s's
// own invocation: for a pass that runs once per pixel (TP_INPUTS_AT_PIXEL) but alpha-tests every
// sample (the deferred G-buffer's masked draws under MSAA, gbuffer.frag).
#define TP_AT_SAMPLE_S(x) interpolateAtSample(x, s)
MaterialSample evalMaterialAtSample(int s) { TP_EVAL_MATERIAL_READ(TP_AT_SAMPLE_S); }
#undef TP_AT_SAMPLE_S
#endif
#endif // TP_INPUTS_POSITION_ONLY
