// multipass forward: structs, set-1 bindings and constants shared by C++ and GLSL.
// Included by shared.h; same rules (TP_STRUCT, static_asserts on the C++ side).
#ifndef TP_MULTIPASS_SHARED_H
#define TP_MULTIPASS_SHARED_H
#ifndef TP_GLSL
namespace tp::gpu {
#endif

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
