#pragma once
// The pieces report_html.cpp and report_error_html.cpp share: cell and outcome helpers, and the
// error sections the page is assembled from. Internal to compare/.
#include <string>

#include <nlohmann/json.hpp>

namespace tp::cli::html {

std::string esc(const nlohmann::json& j);        // XML-escaped text of a value
std::string numberCell(const nlohmann::json& j); // <td>number</td>, "inf" for null
double frameMedian(const nlohmann::json& outcome);
bool ok(const nlohmann::json& outcome);
// A pooled FLIP value of a pipeline, null when FLIP was not measured.
nlohmann::json flipValue(const nlohmann::json& p, const char* kind, const char* key);

std::string summaryTable(const nlohmann::json& r);
bool hasCenterReference(const nlohmann::json& r);
std::string twoReferences(const nlohmann::json& r);
std::string errorPlot(const nlohmann::json& r);
std::string flipSection(const nlohmann::json& r);

} // namespace tp::cli::html
