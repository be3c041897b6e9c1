// Writes the hostile scenes (tests/cli/hostile_scenes.h) into DIR, with DIR/CASES.tsv: one line
// per case, tab-separated: folder, scene path, error|warning, what the message must contain,
// what is hostile about it. Usage: make_hostile_scenes DIR
#include <cstdio>
#include <exception>
#include <fstream>

#include "tests/cli/hostile_scenes.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_hostile_scenes DIR\n");
        return 2;
    }
    try {
        const std::filesystem::path root = argv[1];
        std::vector<tp::hostile::Case> cases = tp::hostile::writeHostileScenes(root);
        std::ofstream tsv(root / "CASES.tsv");
        for (const tp::hostile::Case& c : cases)
            tsv << c.name << '\t' << c.scene << '\t'
                << (c.expect == tp::hostile::Expect::Error ? "error" : "warning") << '\t'
                << c.mention << '\t' << c.what << '\n';
        if (!tsv) throw std::runtime_error("cannot write CASES.tsv");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_hostile_scenes: %s\n", e.what());
        return 1;
    }
    return 0;
}
