#pragma once
// `triptych view`: the interactive viewer's command (docs/viewer.md).
#include <string>
#include <vector>

#include "core/cli/cli_fwd.h"

#include "core/cli/command.h"

namespace tp::cli {

// commandLine: argv as given, to find this program for export (it runs render and compare).
CommandRunner addViewCommand(CLI::App& app, std::vector<std::string> commandLine);

} // namespace tp::cli
