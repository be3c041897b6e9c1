#pragma once
// Paths in the temporary folder that belong to this test process (its pid is in the name), so
// that tests of one binary run side by side by ctest -j never share a file.
#include <filesystem>
#include <string>

#include <unistd.h>

// TMP/triptych_NAME_PID
inline std::filesystem::path testTempPath(const std::string& name) {
    return std::filesystem::temp_directory_path() /
           ("triptych_" + name + "_" + std::to_string(::getpid()));
}

// testTempPath(name), emptied: a test's output folder.
inline std::string freshDir(const std::string& name) {
    std::filesystem::path p = testTempPath(name);
    std::filesystem::remove_all(p);
    return p.string();
}
