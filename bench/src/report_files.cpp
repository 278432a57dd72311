// SPDX-License-Identifier: MIT
#include "bench/report_files.hpp"

#include "process/child_process.hpp"
#include "scene/file_io.hpp"

#include <cstdio>
#include <vector>
#include <stdexcept>
#include <utility>

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
    // Through a temporary file renamed into place: a failed write leaves an older report intact.
    try {
        sandglass::writeFileAtomically(file, text);
    } catch (const sandglass::FileError& e) {
        throw std::runtime_error(e.what());
    }
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
    // No shell: the folder name may hold quotes or anything else.
    sandglass::ChildCommand command;
    command.arguments = {"gnuplot", scriptFile.filename().string()};
    command.folder = folder;
    return sandglass::ChildProcess(command).wait().succeeded();
}

bool writeLinePlot(const std::filesystem::path& folder, const LinePlot& plot) {
    // One gnuplot data block per series; blocks are separated by two blank lines.
    std::string data, commands;
    for (std::size_t s = 0; s < plot.series.size(); ++s) {
        const PlotSeries& series = plot.series[s];
        for (std::size_t i = 0; i < series.points.size(); ++i) {
            data += fixed(series.points[i].first, 6) + " " + fixed(series.points[i].second, 8);
            data += " \"" + (i < series.labels.size() ? series.labels[i] : std::string()) + "\"\n";
        }
        data += "\n\n";
        const std::string block = (s == 0 ? "'" + plot.name + ".dat'" : std::string("''")) + " index " + std::to_string(s);
        commands += (s == 0 ? "plot " : ", ") + block + " using 1:2 with linespoints title '" + series.title + "'";
        if (!series.labels.empty()) commands += ", '' index " + std::to_string(s) + " using 1:2:3 with labels offset 1,0.7 notitle";
    }
    writeText(folder / (plot.name + ".dat"), data);
    std::string script = "set terminal pngcairo size 800,500\nset output '" + plot.name + ".png'\n";
    script += "set title '" + plot.title + "'\nset xlabel '" + plot.xLabel + "'\nset ylabel '" + plot.yLabel + "'\n";
    script += std::string(plot.logScale ? "set logscale xy\nset format x '%g'\nset format y '%g'\n" : "set yrange [0:*]\n") +
              "set grid\nset key " +
              plot.keyPosition + "\n" + commands + "\n";
    return runGnuplot(folder / (plot.name + ".gp"), script);
}

} // namespace sandbench
