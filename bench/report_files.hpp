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

/// Writes and runs a gnuplot script in its own folder (its `set output` names the PNG there);
/// returns false when gnuplot fails or is missing.
bool runGnuplot(const std::filesystem::path& scriptFile, const std::string& script);

} // namespace sandbench
