// opal-bench: speed and accuracy benchmarks, one subcommand each (see subcommand.h).
#include "bench/subcommand.h"

#include <array>
#include <span>
#include <cstdio>
#include <string_view>

namespace {

void printUsage(std::FILE* out, std::span<const opal::bench::Subcommand> subcommands) {
    std::fprintf(out, "usage: opal-bench <subcommand> [options]   (opal-bench <subcommand> --help)\n\nsubcommands:\n");
    for (const opal::bench::Subcommand& s : subcommands)
        std::fprintf(out, "  %-13.*s %.*s\n", static_cast<int>(s.name.size()), s.name.data(),
                     static_cast<int>(s.description.size()), s.description.data());
}

}  // namespace

int main(int argc, char** argv) {
    const std::array subcommands = {opal::bench::basisSubcommand(), opal::bench::bakeSubcommand(),
                                    opal::bench::relightSubcommand(), opal::bench::transferRowSubcommand(),
                                    opal::bench::accuracySubcommand(),
                                    opal::bench::shadowFieldSubcommand(), opal::bench::compareSubcommand(),
                                    opal::bench::errorSourcesSubcommand()};
    if (argc < 2) {
        printUsage(stderr, subcommands);
        return 2;
    }
    const std::string_view name = argv[1];
    if (name == "-h" || name == "--help" || name == "help") {
        printUsage(stdout, subcommands);
        return 0;
    }
    for (const opal::bench::Subcommand& s : subcommands)
        if (s.name == name) return s.run(argc - 1, argv + 1);
    std::fprintf(stderr, "opal-bench: unknown subcommand '%s'\n\n", argv[1]);
    printUsage(stderr, subcommands);
    return 2;
}
