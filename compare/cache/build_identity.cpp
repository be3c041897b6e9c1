#include "compare/cache/build_identity.h"

#include <cstdlib>
#include <ctime>
#include <fstream>
#include <vector>

#include "compare/cache/scene_hash.h"

namespace tp::cli {

const std::string& buildHash() {
    static const std::string hash = [] {
        Fnv1a64 h;
        std::ifstream in("/proc/self/exe", std::ios::binary);
        std::vector<char> chunk(1 << 20);
        while (in) {
            in.read(chunk.data(), std::streamsize(chunk.size()));
            h.bytes(chunk.data(), size_t(in.gcount()));
        }
        return h.hex();
    }();
    return hash;
}

std::string utcNow() {
    const std::time_t t = std::time(nullptr);
    char out[32];
    std::strftime(out, sizeof out, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    return out;
}

std::string userCacheDir(const std::string& sub) {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::string(xdg) + "/triptych/" + sub;
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::string(home) + "/.cache/triptych/" + sub;
    return "";
}

} // namespace tp::cli
