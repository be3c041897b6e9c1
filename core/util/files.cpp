#include "core/util/files.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace tp {

Status writeTextFile(const std::string& path, const std::string& text) {
    const std::string partial = path + ".partial";
    {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        if (!out) return Error{path + ": cannot open for writing"};
        out << text;
        out.flush();
        if (!out) {
            std::remove(partial.c_str());
            return Error{path + ": write failed"};
        }
    }
    std::error_code ec;
    std::filesystem::rename(partial, path, ec);
    if (ec) {
        std::remove(partial.c_str());
        return Error{path + ": cannot rename into place (" + ec.message() + ")"};
    }
    return {};
}

} // namespace tp
