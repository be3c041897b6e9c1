#pragma once
// The compare-side commands: each adds its subcommand to the app and returns the function
// that runs it (core/cli/command.h). app/main.cpp wires them together and catches errors.
#include <string>
#include <vector>

#include "core/cli/cli_fwd.h"

#include "core/cli/command.h"

namespace tp::cli {

CommandRunner addRenderCommand(CLI::App& app);
CommandRunner addInfoCommand(CLI::App& app);
// commandLine: argv as given, recorded in report.json so a run can be repeated.
CommandRunner addCompareCommand(CLI::App& app, std::vector<std::string> commandLine);
CommandRunner addSweepCommand(CLI::App& app, std::vector<std::string> commandLine);
CommandRunner addStressCommand(CLI::App& app, std::vector<std::string> commandLine);
// triptych merge: the shards of one `sweep --shard K/N` into the whole sweep's files.
CommandRunner addMergeCommand(CLI::App& app);
// triptych calibrate: the device's measured ceilings (docs/efficiency.md).
CommandRunner addCalibrateCommand(CLI::App& app, std::vector<std::string> commandLine);

} // namespace tp::cli
