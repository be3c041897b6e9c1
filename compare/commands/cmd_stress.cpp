// triptych stress: the command line of the stiff and extreme case suite (docs/stress.md).
#include <cstdio>
#include <CLI/CLI.hpp>

#include "compare/commands/commands.h"
#include "compare/commands/stress_run.h"
#include "core/renderer/renderer.h"

namespace tp::cli {
namespace {

int listCases() {
    for (const stress::StressCase& c : stress::stressCases())
        std::printf("%-26s %ux%u %ux  %s\n%-26s expected: %s\n", c.name.c_str(), c.width, c.height,
                    c.msaa, c.stresses.c_str(), "", c.expectation.c_str());
    return 0;
}

} // namespace

CommandRunner addStressCommand(CLI::App& app, std::vector<std::string> commandLine) {
    auto o = std::make_shared<StressOptions>();
    o->commandLine = std::move(commandLine);
    auto list = std::make_shared<bool>(false);
    CLI::App* cmd = app.add_subcommand(
        "stress", "Run the stiff and extreme cases (tile overflow, mirror spike, beyond fp16, far "
                  "from the origin, ...) "
                  "through the reference and every pipeline; verdicts against derived bounds in "
                  "stress.json and "
                  "stress.html. Exit codes: 0 every case passed, 6 a case failed (the report says "
                  "which and why), "
                  "3 validation messages (--validate), 2 bad input, 4 Vulkan failure");
    cmd->add_flag("--list", *list, "List the cases with what each stresses and expects, then exit");
    cmd->add_option("--case", o->cases,
                    "Comma-separated case names (default: every case; see --list)");
    cmd->add_option("--pipelines", o->pipelines,
                    "Comma-separated pipelines to check against the reference (default: all: " +
                        defaultPipelineList() + ")");
    cmd->add_option(
           "--out", o->out,
           "Output directory (created if missing): CASE/NAME.exr|png, CASE/NAME_diff.exr|png, "
           "stress.json, stress.html")
        ->capture_default_str();
    addDeviceOptions(*cmd, o->device);
    addKnobOptions(
        *cmd,
        o->knobs.knobs); // the error models follow the knobs (e.g. --accum fp16 adds its term)
    return [o, cmd, list]() {
        if (!cmd->parsed()) return -1;
        return *list ? listCases() : runStress(*o);
    };
}

} // namespace tp::cli
