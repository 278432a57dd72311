// SPDX-License-Identifier: MIT
// sandglass: real-time 3D sand. Without arguments it opens the window on the default hourglass;
// subcommands run the same simulation headless (see README "Command line").
#include "app/cli/command_line.hpp"

int main(int argc, char** argv) { return sandglass::runCommandLine(argc, argv); }
