// libFuzzer target: the camera file (`triptych.camera/1`, core/camera/camera_file.h), parsed
// as readCameraFile parses it. An accepted camera must give a finite view and projection, as
// docs/hostile_input.md promises, and survive cameraToJson and a second read bit for bit; an
// error must be one printable line naming the file. Anything else aborts (a finding).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/camera/camera.h"
#include "core/camera/camera_file.h"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_camera: %s: %s\n", what, tp::printableLine(detail).c_str());
    std::abort();
}

template <class M> bool finite(const M& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const nlohmann::json j = nlohmann::json::parse(data, data + size, nullptr, false);
    if (j.is_discarded()) return 0; // readCameraFile's "not valid JSON"
    tp::Result<tp::Camera> camera = tp::cameraFromJson(j, "fuzz.json");
    if (!camera) {
        const std::string& e = camera.error();
        if (e.rfind("fuzz.json: ", 0) != 0 || e != tp::printableLine(e)) broken("error", e);
        return 0;
    }
    const tp::Camera& c = *camera;
    if (!(c.yfov > 0.0f && c.yfov < 3.14159266f) || !(c.znear > 0.0f) ||
        !(c.zfar == 0.0f || c.zfar > c.znear))
        broken("accepted", "a field outside its documented range");
    if (!finite(tp::viewMatrix(c)) || !finite(tp::viewRotation(c)))
        broken("accepted", "a camera whose view matrix is not finite");
    // The widest and the tallest images --res allows (maxImageDimension2D: 16384 on lavapipe,
    // 32768 at most on the GPUs we know) by one pixel.
    for (float aspect : {1.0f / 32768.0f, 1.0f, 32768.0f}) {
        const glm::mat4 p = tp::reverseZPerspective(c.yfov, aspect, c.znear, c.zfar);
        if (!finite(p)) broken("accepted", "a camera whose projection is not finite");
        if (!(p[0][0] > 0.0f && p[1][1] > 0.0f)) broken("accepted", "a projection turned over");
    }
    tp::Result<tp::Camera> again = tp::cameraFromJson(tp::cameraToJson(c), "again.json");
    if (!again) broken("round trip", again.error());
    if (std::memcmp(&*again, &c, sizeof c) != 0) broken("round trip", "the camera changed");
    return 0;
}
