#version 460
// Hybrid mode: a listed triangle's id (vis_raster_hw.vert) as the visibility pass writes ids.
layout(location = 0) flat in uint inId;
layout(location = 0) out float outId;
void main() { outId = float(inId); }
