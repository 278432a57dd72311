#include "report_files.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace sandbench {

std::string toMarkdown(const Table& table) {
    auto line = [](const std::vector<std::string>& cells) {
        std::string text = "|";
        for (const std::string& cell : cells) text += " " + cell + " |";
        return text + "\n";
    };
    std::string text = line(table.header) + "|";
    for (std::size_t i = 0; i < table.header.size(); ++i) text += "---|";
    text += "\n";
    for (const auto& row : table.rows) text += line(row);
    return text;
}

void writeText(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error(file.string() + ": cannot write");
}

void writeCsv(const Table& table, const std::filesystem::path& file) {
    auto quoted = [](const std::string& cell) {
        if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
        std::string text = "\"";
        for (char c : cell) text += c == '"' ? std::string("\"\"") : std::string(1, c);
        return text + "\"";
    };
    auto line = [&](const std::vector<std::string>& cells) {
        std::string text;
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i > 0) text += ',';
            text += quoted(cells[i]);
        }
        return text + "\n";
    };
    std::string text = line(table.header);
    for (const auto& row : table.rows) text += line(row);
    writeText(file, text);
}

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

bool runGnuplot(const std::filesystem::path& scriptFile, const std::string& script) {
    writeText(scriptFile, script);
    // Scripts name their data and output files relative to their own folder.
    const std::filesystem::path folder = scriptFile.parent_path().empty() ? "." : scriptFile.parent_path();
    const std::string command =
        "cd '" + folder.string() + "' && gnuplot '" + scriptFile.filename().string() + "' >/dev/null 2>&1";
    return std::system(command.c_str()) == 0;
}

} // namespace sandbench
