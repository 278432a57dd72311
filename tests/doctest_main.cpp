// SPDX-License-Identifier: MIT
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "support/temporary_folder.hpp"

#include <cstdlib>

int main(int argc, char** argv) {
    // I4: no test reads or writes the settings of whoever runs the tests. Every window opened
    // here and every sandglass process started from here keeps its settings in a folder of
    // this run, removed at its end; a test of the settings sets its own.
    sandglass::TemporaryFolder config;
    ::setenv("XDG_CONFIG_HOME", config.path().c_str(), 1);
    return doctest::Context(argc, argv).run();
}
