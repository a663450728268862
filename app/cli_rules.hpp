#pragma once
// Rules every subcommand's command line follows, applied once to the whole command tree
// (main.cpp) so that a command added later follows them too.
#include <CLI/CLI.hpp>

namespace signstim::app {

// Every numeric option (CLI11 type INT, UINT or FLOAT) of `app` and of its subcommands takes
// plain decimal text only: CLI11 2.1 reads "" as 0 (`verb --subject ""` meant arc position
// 0), "0x10" as 16 and "nan" as NaN. Anything else is a usage error naming the flag (exit 1).
void requirePlainNumbers(CLI::App& app);

}  // namespace signstim::app
