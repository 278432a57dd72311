#pragma once
// SPEC PH2-PH6 in the speed-against-error report: the granular level's repose angle asked
// against measured in 16 directions, fall time against sqrt(2h/g), the discharge over several
// necks with its fitted Beverloo exponent, and its cost against classic.

#include "bench/speed_error_report.hpp"

#include <iosfwd>
#include <string>

namespace sandbench {

/// One section of the report.
struct GranularSection {
    std::string markdown; ///< the section's text, tables and plot links
    bool passed = true;   ///< conservation held and every plot was drawn
};

/// Measures the granular level and writes repose.csv, fall_time.csv, necks.csv, cost.csv and
/// their plots into options.outDir; progress goes to log.
GranularSection granularSection(const ReportOptions& options, std::ostream& log);

} // namespace sandbench
