#pragma once
// Writes a whole file through a temporary name and a rename, so a failed or interrupted
// write never leaves a file that looks complete.
#include <string>

#include "core/util/result.h"

namespace tp {

Status writeTextFile(const std::string& path, const std::string& text);
// A whole file's bytes; the error names the path.
Result<std::string> readWholeFile(const std::string& path);

} // namespace tp
