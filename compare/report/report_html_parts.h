#pragma once
// The pieces report_html.cpp and report_error_html.cpp share: cell and outcome helpers, and the
// error sections the page is assembled from. Internal to compare/.
#include <string>

#include <nlohmann/json.hpp>

#include "core/util/result.h"

namespace tp::cli::html {

std::string esc(const nlohmann::json& j);        // XML-escaped text of a value
std::string numberCell(const nlohmann::json& j); // <td>number</td>, "inf" for null
double frameMedian(const nlohmann::json& outcome);
bool ok(const nlohmann::json& outcome);
// <td> of a run's joules per frame; "&ndash;" with the reason as its title when unknown.
std::string joulesCell(const nlohmann::json& run);
// A pooled FLIP value of a pipeline, null when FLIP was not measured.
nlohmann::json flipValue(const nlohmann::json& p, const char* kind, const char* key);

// <figure> of the PNG outDir/file inlined as a data URI, with its caption; `attributes`: more
// of the <img> tag, e.g. the hooks of the flip script (report_viewer_js.h).
Result<std::string> figure(const std::string& outDir, const std::string& file,
                           const std::string& caption, const std::string& attributes = "");

std::string summaryTable(const nlohmann::json& r);
bool hasCenterReference(const nlohmann::json& r);
std::string twoReferences(const nlohmann::json& r);
bool hasShadowMapReference(const nlohmann::json& r);
std::string shadowReferences(const nlohmann::json& r);
std::string errorPlot(const nlohmann::json& r);
std::string flipSection(const nlohmann::json& r);
std::string efficiencySection(const nlohmann::json& r); // report_efficiency_html.cpp
std::string energySection(const nlohmann::json& r);     // report_html.cpp
std::string pathSection(const nlohmann::json& r);       // report_path_html.cpp

} // namespace tp::cli::html
