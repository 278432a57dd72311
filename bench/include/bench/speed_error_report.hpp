// SPDX-License-Identifier: MIT
#pragma once
// SPEC B2 / C4: `sandglass bench` writes the speed-against-error report: Markdown, CSV and PNG
// plots in one folder (committed as docs/bench/).

#include "sandcore/scene.hpp"

#include <filesystem>
#include <iosfwd>

namespace sandbench {

struct ReportOptions {
    bool quick = false;                         ///< small resolutions: finishes in under a minute
    std::filesystem::path outDir = "bench-report"; ///< folder for README.md, *.csv and *.png
    std::string commandLine;                    ///< how the report was produced, quoted in it
    sandcore::StepSettings step{1, 2, true, {}}; ///< seed of every drain; threads compared with 1 (default 2)
};

/// Measures everything and writes the report; progress goes to log. Returns true when every
/// check (conservation, thread and sweep hash match, no display drift) passed. Throws
/// std::runtime_error when the folder cannot be written.
bool writeSpeedErrorReport(const ReportOptions& options, std::ostream& log);

} // namespace sandbench
