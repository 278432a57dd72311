// SPDX-License-Identifier: MIT
#pragma once
// Writing the report: Markdown tables, CSV files and gnuplot PNG plots.

#include <filesystem>
#include <string>
#include <vector>

namespace sandbench {

/// A table: a header row and rows of already formatted cells.
struct Table {
    std::vector<std::string> header; ///< column titles
    std::vector<std::vector<std::string>> rows; ///< one vector of cells per row
};

/// The table as GitHub Markdown.
std::string toMarkdown(const Table& table);
/// Writes the table as CSV (cells with commas or quotes are quoted); throws std::runtime_error on failure.
void writeCsv(const Table& table, const std::filesystem::path& file);
/// Writes text to a file; throws std::runtime_error naming the file on failure.
void writeText(const std::filesystem::path& file, const std::string& text);
/// A number with `decimals` digits after the point.
std::string fixed(double value, int decimals);

/// One line of a plot: (x, y) points, optionally labelled.
struct PlotSeries {
    std::string title;                          ///< legend entry
    std::vector<std::pair<double, double>> points; ///< (x, y) in order
    std::vector<std::string> labels;            ///< empty, or one text per point drawn beside it
};

/// A line plot written as NAME.dat, NAME.gp and NAME.png.
struct LinePlot {
    std::string name;        ///< file stem
    std::string title;       ///< plot title
    std::string xLabel;      ///< x axis
    std::string yLabel;      ///< y axis
    bool logScale = false;   ///< both axes logarithmic
    std::string keyPosition = "right top"; ///< where the legend goes
    std::vector<PlotSeries> series; ///< the lines
};

/// Writes the plot's data and script into folder and runs gnuplot; false when gnuplot fails.
bool writeLinePlot(const std::filesystem::path& folder, const LinePlot& plot);

/// Writes and runs a gnuplot script in its own folder (its `set output` names the PNG there);
/// returns false when gnuplot fails or is missing.
bool runGnuplot(const std::filesystem::path& scriptFile, const std::string& script);

} // namespace sandbench
