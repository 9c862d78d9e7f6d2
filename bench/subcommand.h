// opal-bench is one executable with subcommands (`opal-bench basis`, ...). Each subcommand
// lives in its own file, parses its own arguments (CLI11) and returns the process exit
// code; main.cpp only lists them. To add one: define `Subcommand xyzSubcommand()` in
// bench/xyz_bench.cpp, declare it below and add it to the table in main.cpp.
#pragma once

#include <string_view>

namespace opal::bench {

struct Subcommand {
    std::string_view name;
    std::string_view description;
    // argv[0] is the subcommand's name; the rest are its arguments.
    int (*run)(int argc, char** argv);
};

Subcommand basisSubcommand();
Subcommand bakeSubcommand();
Subcommand relightSubcommand();
Subcommand transferRowSubcommand();
Subcommand accuracySubcommand();
Subcommand shadowFieldSubcommand();
Subcommand compareSubcommand();
Subcommand errorSourcesSubcommand();

}  // namespace opal::bench
