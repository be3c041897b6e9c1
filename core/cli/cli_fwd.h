#pragma once
// CLI11's two types as the headers of commands name them. Debian's CLI11 (2.1) is header-only
// with no precompiled mode: <CLI/CLI.hpp> costs about 7 s of compile time in every
// translation unit that includes it, so only the files that build command lines do.
namespace CLI {
class App;
class Option;
} // namespace CLI
