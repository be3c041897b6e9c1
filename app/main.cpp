// triptych: one scene through several lighting pipelines, side by side with a reference.
// Errors end here: one line on stderr and a non-zero exit code (2: bad input, 4: Vulkan
// failure, 3: validation messages with --validate, 5: compare wrote its report but a
// pipeline failed, 6: stress wrote its report and a case failed, 1: anything else), never a crash.
// The composition root: the one file that knows both compare/'s commands and viewer/'s, so
// neither includes the other (docs/architecture.md, "Layers").
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include "compare/commands/commands.h"
#include "core/cli/options.h"
#include "core/gpu/vk_check.h"
#include "core/scene/shadow_settings.h"
#include "viewer/view_command.h"

int main(int argc, char** argv) {
    CLI::App app{"triptych: Forward+, deferred and multipass forward side by side against a "
                 "brute-force reference (Vulkan)"};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Help for every command");
    try {
        // Inside the try: the commands' options come from the registered pipelines' knobs, and
        // a knob named like a command's own option is a one-line error, not a crash.
        std::vector<tp::cli::CommandRunner> commands = {
            tp::cli::addCompareCommand(app, std::vector<std::string>(argv, argv + argc)),
            tp::cli::addSweepCommand(app, std::vector<std::string>(argv, argv + argc)),
            tp::cli::addMergeCommand(app),
            tp::cli::addStressCommand(app, std::vector<std::string>(argv, argv + argc)),
            tp::cli::addRenderCommand(app),
            tp::cli::addInfoCommand(app),
            tp::cli::addCalibrateCommand(app, std::vector<std::string>(argv, argv + argc)),
            tp::cli::addViewCommand(app, std::vector<std::string>(argv, argv + argc))};
        app.parse(argc, argv);
        for (auto& command : commands) {
            int code = command();
            if (code >= 0) return code;
        }
        return 1;
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, like every other error (CLI11 would add a second "Run with --help").
        std::fprintf(stderr, "triptych: %s (see --help)\n", e.what());
        return 2;
    } catch (const tp::cli::UsageError& e) {
        std::fprintf(stderr, "triptych: %s\n", e.what());
        return 2;
    } catch (const tp::ShadowError& e) { // the budget cannot hold the lights (known at the view)
        std::fprintf(stderr, "triptych: %s\n", e.what());
        return 2;
    } catch (const tp::GpuError& e) {
        std::fprintf(stderr, "triptych: Vulkan error: %s\n", e.what());
        return 4;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "triptych: internal error: %s\n", e.what());
        return 1;
    }
}
