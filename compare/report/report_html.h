#pragma once
// report.html: one self-contained page made from report.json and the PNGs beside it
// (embedded as base64 data URIs; inline CSS, SVG and script; no network). The script only
// adds flip and a magnifier to the images (compare/report/report_viewer_js.h); without it the page
// reads the same.
#include <string>

#include <nlohmann/json.hpp>

#include "core/util/result.h"

namespace tp::cli {

// `report` follows schema triptych.report/2; PNGs named in its "files" lists are read from
// outDir. Fails (naming the file) when a PNG cannot be read.
Result<std::string> reportHtml(const nlohmann::json& report, const std::string& outDir);

std::string base64(const std::string& bytes);

// The CSS every triptych page starts with (tables, figures, notes); pages append their own.
const char* reportPageStyle();

} // namespace tp::cli
