// The CLI's shared option checks (core/cli/options.h) on hostile values, without a device; the
// commands end to end are in tests/cli/hostile_input.sh.
#include <gtest/gtest.h>
#include <CLI/CLI.hpp>

#include "core/cli/options.h"

using namespace tp::cli;

namespace {

bool seedAccepted(const std::string& text, uint64_t& seed) {
    CLI::App app;
    addSeedOption(app, seed);
    try {
        app.parse(std::vector<std::string>{text, "--seed"}); // reversed: CLI11 pops the back
        return true;
    } catch (const CLI::ParseError&) {
        return false;
    }
}

} // namespace

TEST(HostileCli, SeedIsAWholeNumberThatFits64Bits) {
    uint64_t seed = 0;
    EXPECT_TRUE(seedAccepted("18446744073709551615", seed));
    EXPECT_EQ(seed, UINT64_MAX);
    EXPECT_TRUE(seedAccepted("7", seed));
    EXPECT_EQ(seed, 7u);
    for (const char* bad :
         {"-1", "18446744073709551616", "99999999999999999999", "1e3", "0x10", " 5", "", "abc"})
        EXPECT_FALSE(seedAccepted(bad, seed)) << "'" << bad << "'";
}
