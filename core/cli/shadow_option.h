#pragma once
// --shadows as text (docs/shadows.md): parsed here, at the command line's boundary, into the
// typed ShadowSettings (core/scene/shadow_settings.h) that everything below reads; written
// back the same way for reports and cache keys.
#include <string>

#include "core/scene/shadow_settings.h"

namespace tp {

// "none", "all", or N in 1..65536 into `base` (its budget and cache kept); a one-line
// cli::UsageError otherwise.
ShadowSettings parseShadowCount(const std::string& text, ShadowSettings base = {});
std::string shadowCountText(const ShadowSettings& s);

} // namespace tp
