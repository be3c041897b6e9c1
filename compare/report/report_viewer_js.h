#pragma once
// report.html's flip and magnifier (inline CSS and script; docs/report.md, "Flip and loupe").
#include <string>

namespace tp::cli {

const char* reportViewerStyle();
// A <script> element; it finds the reference as <img id="img-reference"> and each pipeline's
// image as <img class="flip" data-pipeline="NAME">, so it must come after the images.
std::string reportViewerScript();

} // namespace tp::cli
