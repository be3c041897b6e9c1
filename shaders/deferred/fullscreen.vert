#version 460
// A triangle covering the viewport (vertices 0..2) at depth 0, the reverse-Z far plane:
// the light-volume base pass and the MSAA expand pass (both drawn with culling off).
void main() {
    vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
