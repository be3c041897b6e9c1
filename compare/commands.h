#pragma once
// Each triptych command adds its subcommand to the app and returns the function that runs
// it (the exit code). compare/main.cpp wires them together and catches errors.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace tp::cli {

using CommandRunner = std::function<int()>;

CommandRunner addRenderCommand(CLI::App& app);
CommandRunner addInfoCommand(CLI::App& app);
// commandLine: argv as given, recorded in report.json so a run can be repeated.
CommandRunner addCompareCommand(CLI::App& app, std::vector<std::string> commandLine);
CommandRunner addSweepCommand(CLI::App& app, std::vector<std::string> commandLine);
CommandRunner addStressCommand(CLI::App& app, std::vector<std::string> commandLine);
// viewer/view_command.cpp: the interactive viewer (commandLine: to find this program for export).
CommandRunner addViewCommand(CLI::App& app, std::vector<std::string> commandLine);

} // namespace tp::cli
