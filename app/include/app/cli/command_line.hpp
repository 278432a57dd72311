// SPDX-License-Identifier: MIT
#pragma once
// The command line (SPEC §6): parses the arguments and runs one subcommand.

namespace sandglass {

/// Runs sandglass with these arguments; returns the process exit code (0 = success). Errors a
/// user can cause are printed as one line on stderr and give a non-zero code.
int runCommandLine(int argc, char** argv);

} // namespace sandglass
