// The compute clear of a colour image (core/passes/image_clear.h), for C++ and GLSL.
#ifndef TP_IMAGE_CLEAR_H
#define TP_IMAGE_CLEAR_H

#define TP_IC_BINDING_IMAGE 0 // set 1: the image, as a storage image
#define TP_IC_GROUP 8         // 8 x 8 invocations a workgroup, a pixel each
// Specialization constants: the samples, and the clear value's four channels as float bits.
#define TP_IC_SPEC_SAMPLES 0
#define TP_IC_SPEC_VALUE 1 // 1..4: r, g, b, a

#endif
