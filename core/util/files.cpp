#include "core/util/files.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tp {

Result<std::string> readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{path + ": cannot be read"};
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) return Error{path + ": read failed"};
    return ss.str();
}

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
