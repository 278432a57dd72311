// SPDX-License-Identifier: MIT
#include "app/frame_benchmark.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <stdexcept>

namespace sandglass {

std::vector<BenchmarkCase> thesisBenchmarkCases() {
    std::vector<BenchmarkCase> cases;
    for (bool inner : {true, false})
        for (auto [perCell, light] : {std::pair{1, false}, std::pair{20, false}, std::pair{20, true}, std::pair{1, true}})
            for (RenderMode mode : kRenderModes) {
                BenchmarkCase row; // the thesis's look: its light, no studio elements
                row.mode = mode;
                row.grainsPerCell = perCell;
                row.lighting = light;
                row.innerGrains = inner;
                cases.push_back(row);
            }
    return cases;
}

RenderSettings benchmarkRenderSettings(const BenchmarkCase& setup, RenderSettings base) {
    base.mode = setup.mode;
    base.grainsPerCell = setup.grainsPerCell;
    base.lighting = setup.lighting;
    base.innerGrains = setup.innerGrains;
    base.light = setup.light;
    base.ambientOcclusion = setup.occlusion;
    base.shadows = setup.shadows;
    base.toneMapping = setup.toneMapping;
    base.glassEnvironment = setup.environment;
    return base;
}

std::vector<BenchmarkCase> lookBenchmarkCases() {
    const RenderSettings standard;
    BenchmarkCase look{standard.mode,           standard.grainsPerCell, standard.lighting, standard.innerGrains,
                       standard.light,          standard.ambientOcclusion, standard.shadows, standard.toneMapping,
                       standard.glassEnvironment, "default"};
    const RenderSettings thesis = thesisLook();
    std::vector<BenchmarkCase> cases{look};
    cases.push_back({thesis.mode, thesis.grainsPerCell, thesis.lighting, thesis.innerGrains, thesis.light,
                     false, false, false, false, "thesis default"});
    auto without = [&](bool BenchmarkCase::*element, const char* name) {
        BenchmarkCase off = look;
        off.*element = false;
        off.look = name;
        cases.push_back(off);
    };
    without(&BenchmarkCase::occlusion, "AO off");
    without(&BenchmarkCase::shadows, "shadows off");
    without(&BenchmarkCase::toneMapping, "tone mapping off");
    without(&BenchmarkCase::environment, "glass sky off");
    without(&BenchmarkCase::lighting, "grains unlit");
    BenchmarkCase thesisLight = look;
    thesisLight.light = LightRig::Thesis;
    thesisLight.look = "thesis light";
    cases.push_back(thesisLight);
    return cases;
}

namespace {
const char* onOff(bool value) { return value ? "on" : "off"; }

bool hasLooks(const BenchmarkReport& report) {
    return std::any_of(report.rows.begin(), report.rows.end(), [](const BenchmarkRow& row) { return !row.setup.look.empty(); });
}

void writeLookTable(std::ostream& out, const BenchmarkReport& report) {
    out << "\nLook\tMode\tPpC\tfilled\tframe ms\tFPS\tCPU ms\tGPU ms\n";
    for (const BenchmarkRow& row : report.rows) {
        char figures[128];
        std::snprintf(figures, sizeof figures, "%.1f\t%.1f\t%.2f\t%.2f", row.medianFrameMilliseconds,
                      row.framesPerSecond(), row.cpuMillisecondsPerFrame, row.gpuMillisecondsPerFrame);
        out << row.setup.look << '\t' << renderModeShortName(row.setup.mode) << '\t' << row.setup.grainsPerCell << '\t'
            << row.filledCells << '\t' << figures << '\n';
    }
}

void writeRow(std::ostream& out, const BenchmarkRow& row) {
    char figures[192];
    std::snprintf(figures, sizeof figures, "%.1f\t%.0f\t%.0f\t%.2f\t%.2f\t%.3f\t%.2f", row.framesPerSecond(),
                  row.uploadBytesPerFrame, row.movesPerStep, row.cpuMillisecondsPerFrame, row.appCpuMillisecondsPerFrame,
                  row.upkeepMillisecondsPerStep, row.gpuMillisecondsPerFrame);
    out << onOff(row.simulation) << '\t' << onOff(row.gui) << '\t' << renderModeShortName(row.setup.mode) << '\t'
        << row.setup.grainsPerCell << '\t' << row.filledCells << '\t' << onOff(row.setup.lighting) << '\t'
        << (row.setup.innerGrains ? "yes" : "no") << '\t' << figures << '\n';
}
} // namespace

void writeBenchmarkText(std::ostream& out, const std::vector<BenchmarkReport>& reports, const std::string& command) {
    out << "sandglass frame-rate benchmark (SPEC B1, the table form of thesis section 4.3)\n";
    if (!command.empty()) out << "command: " << command << "\n";
    for (const BenchmarkReport& report : reports) {
        out << "\nScene: " << report.scene << "\n";
        out << "GPU (GL_RENDERER): " << report.glRenderer << "\n";
        out << "Driver (GL_VERSION): " << report.glVersion << "\n";
        out << "Framebuffer: " << report.width << "x" << report.height << " pixels\n";
        if (hasLooks(report)) {
            writeLookTable(out, report);
            continue;
        }
        for (bool inner : {true, false}) {
            out << (inner ? "\nWith inner grains:\n\n" : "\nWithout inner grains:\n\n");
            out << "Sim\tGui\tMode\tPpC\tfilled\tLight\tinner\tFPS\tB/frame\tmoves\tCPU ms\tapp ms\tupkeep\tGPU ms\n";
            for (const BenchmarkRow& row : report.rows)
                if (row.setup.innerGrains == inner) writeRow(out, row);
        }
    }
    out << "\nColumns: Sim = simulation running, Gui = panels drawn, Mode = P (points), S (sprites),\n"
           "BB (billboards), PBB (pseudo-billboards), PpC = grains drawn per cell, filled = filled cells,\n"
           "Light = lighting from estimated normals, inner = inner grains drawn, FPS = frames per second,\n"
           "B/frame = grain bytes uploaded per frame, moves = grains moved per step, CPU ms = main-thread CPU\n"
           "time per frame without the steps and the buffer swap (with a software GL it includes vertex processing),\n"
           "app ms = the part of CPU ms outside the draw calls (the application's own work), upkeep = ms per step\n"
           "of inner-flag and normal upkeep plus grain upload, GPU ms = GPU time per frame of the scene's drawing,\n"
           "from the grain upload to the last draw call (timer queries; a GPU-bound frame takes about this long),\n"
           "frame ms = wall time of the median frame, its step included (look rows).\n";
}

void writeBenchmarkCsv(std::ostream& out, const std::vector<BenchmarkReport>& reports) {
    out << "scene,gl_renderer,gl_version,width,height,sim,gui,mode,grains_per_cell,filled_cells,light,inner,frames,"
           "seconds,fps,upload_bytes_per_frame,moves_per_step,cpu_ms_per_frame,app_cpu_ms_per_frame,upkeep_ms_per_step,"
           "gpu_ms_per_frame,median_frame_ms,look\n";
    auto quoted = [](const std::string& text) {
        std::string result = "\"";
        for (char c : text) result += c == '"' ? std::string("\"\"") : std::string(1, c);
        return result + "\"";
    };
    for (const BenchmarkReport& report : reports)
        for (const BenchmarkRow& row : report.rows) {
            char numbers[256];
            std::snprintf(numbers, sizeof numbers, "%d,%.4f,%.2f,%.1f,%.1f,%.3f,%.3f,%.4f,%.4f,%.3f", row.frames,
                          row.seconds, row.framesPerSecond(), row.uploadBytesPerFrame, row.movesPerStep,
                          row.cpuMillisecondsPerFrame, row.appCpuMillisecondsPerFrame, row.upkeepMillisecondsPerStep,
                          row.gpuMillisecondsPerFrame, row.medianFrameMilliseconds);
            out << quoted(report.scene) << ',' << quoted(report.glRenderer) << ',' << quoted(report.glVersion) << ','
                << report.width << ',' << report.height << ',' << onOff(row.simulation) << ',' << onOff(row.gui) << ','
                << renderModeName(row.setup.mode) << ',' << row.setup.grainsPerCell << ',' << row.filledCells << ','
                << onOff(row.setup.lighting) << ',' << (row.setup.innerGrains ? "yes" : "no") << ',' << numbers << ','
                << quoted(row.setup.look) << '\n';
        }
}

void writeBenchmarkFiles(const std::filesystem::path& folder, const std::vector<BenchmarkReport>& reports,
                         const std::string& command) {
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) throw std::runtime_error("cannot create " + folder.string() + ": " + error.message());
    std::ofstream text(folder / "benchmark.txt"), csv(folder / "benchmark.csv");
    if (!text || !csv) throw std::runtime_error("cannot write benchmark files in " + folder.string());
    writeBenchmarkText(text, reports, command);
    writeBenchmarkCsv(csv, reports);
}

} // namespace sandglass
