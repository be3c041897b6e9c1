#pragma once
// A triptych command: each adds its subcommand to the app and returns the function that runs
// it, the exit code, or -1 when its subcommand was not the one given. The composition root
// (app/main.cpp) adds every command (compare/commands/commands.h, viewer/view_command.h) and catches
// their errors.
#include <functional>

namespace tp::cli {

using CommandRunner = std::function<int()>;

} // namespace tp::cli
