#pragma once
// Each triptych command adds its subcommand to the app and returns the function that runs
// it (the exit code). compare/main.cpp wires them together and catches errors.
#include <functional>

#include <CLI/CLI.hpp>

namespace tp::cli {

using CommandRunner = std::function<int()>;

CommandRunner addRenderCommand(CLI::App& app);
CommandRunner addInfoCommand(CLI::App& app);

} // namespace tp::cli
