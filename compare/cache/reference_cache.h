#pragma once
// The reference cache (docs/reference-cache.md): the reference's run of one (scene content,
// lights, camera, resolution, MSAA, reference settings, device, triptych build) stored on disk
// and reused, so a user who changes a pipeline's knob and runs `compare` again does not pay for
// the unchanged brute-force reference again. An entry is a folder named by the hash of its
// key: hdr.exr, depth.exr and meta.json (the key in full, the images' hashes, the run's
// timings, memory and counters as they were measured). An entry whose key text differs (a
// hash collision) or whose images do not hash to what meta.json says (a torn write, a disk
// error, an edit) is never trusted: it is rendered again and replaced.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/cli/cli_common.h"

#include "core/runner/frame_runner.h"
#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp {
class GpuContext;
class SceneGpu;
} // namespace tp

namespace tp::cli {

// $XDG_CACHE_HOME/triptych/references, else $HOME/.cache/triptych/references; empty (no
// cache) when neither variable is set.
std::string defaultReferenceCacheDir();
// The folder a run uses: none with --no-reference-cache (`off`), else --reference-cache's, else
// the default.
std::string referenceCacheDir(const std::string& option, bool off);
// --reference-cache DIR and --no-reference-cache, for the commands that render a reference.
void addReferenceCacheOptions(CLI::App& cmd, std::string& dir, bool& off);

// What a key is made of, in full (written to meta.json and compared on load), and its hash
// (the entry's folder name). The triptych build enters as the hash of the running binary:
// any rebuild is a new reference.
struct ReferenceKey {
    std::string text;
    std::string hash;
};
ReferenceKey referenceKey(const GpuContext& ctx, const SceneGpu& scene,
                          const SceneFeatures& features, const RenderSettings& settings);

// How the reference of one run was obtained, for the report and the progress line.
struct ReferenceCacheUse {
    std::string dir;        // empty: the cache was off (--no-reference-cache, or --debug)
    std::string entry;      // the entry's folder
    std::string key;        // its hash
    bool reused = false;    // read from the entry instead of rendered
    bool stored = false;    // rendered and written to the entry
    std::string note;       // why an entry was not reused or not written ("" when nothing odd)
    std::string renderedAt; // reused: when the entry was made (UTC, ISO 8601)
};

// The run of `key` from `dir`, or nothing (absent, mismatched or corrupt: `note` says which).
std::optional<RunResult> loadReference(const std::string& dir, const ReferenceKey& key,
                                       std::string& note, std::string& renderedAt);
// Writes the run as the entry of `key` (into a temporary folder, then renamed into place, so
// a reader never sees half an entry).
Status storeReference(const std::string& dir, const ReferenceKey& key, const RunResult& run);

// report.json / sweep.json: {used, dir, entry, key_fnv1a64, reused, stored, rendered_at,
// note}; a reused run's timings and memory are those of the run that made the entry.
nlohmann::json referenceCacheJson(const ReferenceCacheUse& c);

// The reference renderer's run for these settings: from the cache when `cacheDir` holds a
// valid entry, else rendered (tryRunRenderer) and stored; a note (an entry not trusted or not
// written) is also said on stderr. Debug runs bypass the cache (their
// debug images are not stored).
Result<RunResult> runReferenceCached(GpuContext& ctx, SceneGpu& scene,
                                     const SceneFeatures& features, const RenderSettings& settings,
                                     const RunOptions& options, const std::string& cacheDir,
                                     ReferenceCacheUse& use);

} // namespace tp::cli
