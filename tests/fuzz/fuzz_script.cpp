// libFuzzer target: the viewer's script language (viewer/script.h), read and checked as
// `triptych view --script FILE` reads it before anything runs; no GPU. readScript takes a
// path, so each input is written to a file first (in /dev/shm when there is one). An accepted
// script must be lines of whitespace-free words in increasing line order; an error must be one
// printable line naming the file. Anything else aborts (a finding).
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/scene/scene.h"
#include "viewer/script.h"

namespace {

std::string gPath;

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_script: %s: %s\n", what, tp::printableLine(detail).c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::is_directory("/dev/shm", ec)
                                          ? "/dev/shm"
                                          : std::filesystem::temp_directory_path();
    gPath = (dir / ("fuzz_script_" + std::to_string(::getpid()) + ".txt")).string();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    {
        std::ofstream out(gPath, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
        if (!out) broken("setup", "cannot write " + gPath);
    }
    tp::Result<std::vector<tp::view::ScriptLine>> lines = tp::view::readScript(gPath);
    std::filesystem::remove(gPath);
    if (!lines) {
        const std::string& e = lines.error();
        const bool names =
            e.rfind(gPath + ":", 0) == 0 || e.rfind("--script " + gPath + ":", 0) == 0;
        if (!names || e != tp::printableLine(e)) broken("error", e);
        return 0;
    }
    int previous = 0;
    for (const tp::view::ScriptLine& line : *lines) {
        if (line.number <= previous) broken("accepted", "line numbers out of order");
        previous = line.number;
        if (line.words.empty()) broken("accepted", "an empty line kept");
        for (const std::string& w : line.words)
            if (w.empty() || w.find_first_of(" \t\n\v\f\r#") != std::string::npos)
                broken("accepted", "a word holding a space or a comment: '" + w + "'");
    }
    return 0;
}
