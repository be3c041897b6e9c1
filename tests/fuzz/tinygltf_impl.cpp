// tinygltf and stb_image compiled into the fuzz targets with the sanitizers and coverage (the
// main build links Debian's uninstrumented libtinygltf and libstb instead).
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
