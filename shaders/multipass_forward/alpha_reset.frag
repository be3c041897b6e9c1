#version 460
// Blended light passes use the accumulation target's alpha as the transmittance of the
// layers of one blended draw (blended_pass.cpp). After each such pass this draw, over the
// same mesh with only alpha written, puts it back to 1, the value every other pass keeps.
layout(location = 0) out vec4 outColor;

void main() { outColor = vec4(0.0, 0.0, 0.0, 1.0); }
