#pragma once
// What the caches on disk (references, calibrations) are keyed by and where they live: the
// running build, the time, and the user's cache folder.
#include <string>

namespace tp::cli {

// The FNV-1a hash of the running binary's bytes, computed once: any rebuild is a new build.
const std::string& buildHash();
// Now, UTC, ISO 8601 to the second.
std::string utcNow();
// $XDG_CACHE_HOME/triptych/SUB, else $HOME/.cache/triptych/SUB; empty when neither is set.
std::string userCacheDir(const std::string& sub);

} // namespace tp::cli
