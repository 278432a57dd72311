// SPDX-License-Identifier: MIT
#include "bench/granular_report.hpp"

#include "bench/plausibility.hpp"
#include "bench/report_files.hpp"
#include "scene/hex.hpp"

#include "sandcore/pile_slopes.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>

namespace sandbench {

using sandcore::GridLevel;
using sandcore::PhysicsLevel;

namespace {

sandcore::StepSettings granularStep(const ReportOptions& options, float gravity, float repose = 33.0f) {
    sandcore::StepSettings step = options.step;
    step.physics.level = PhysicsLevel::Granular;
    step.physics.gravity = gravity;
    step.physics.reposeDegrees = repose;
    return step;
}

// PH2's measure: the mean over each 22.5-degree sector of a cone (5 rays), at most this far from
// the angle asked in every sector of every cone.
constexpr double kSectorTolerance = 2.0;

std::string reposePart(const ReportOptions& options, std::ostream& log, bool& passed) {
    const int grains = options.quick ? 12000 : 40000, width = options.quick ? 70 : 120, height = options.quick ? 35 : 50;
    const int seeds = options.quick ? 1 : 4;
    const float gravity = sandcore::PhysicsSettings{}.gravity;
    const float asked[] = {25.0f, 33.0f, 40.0f};
    Table table{{"asked (deg)", "cones", "sectors: mean", "min", "max", "worst sector (off by)", "within 2 deg"}, {}};
    Table csv{{"asked", "seed", "direction (deg)", "sector mean (deg)", "one ray (deg)"}, {}};
    LinePlot plot{"repose", "Poured cones: the 16 direction sectors of each cone", "direction out of the peak (deg)",
                  "angle (deg)", false, "right top", {}};
    for (float angle : asked) {
        double sum = 0, lowest = 90, highest = 0, worstOff = -1;
        std::string worst;
        int count = 0;
        for (int seed = 1; seed <= seeds; ++seed) {
            log << "granular: cone of " << grains << " grains at " << angle << " deg, seed " << seed << "\n";
            sandcore::StepSettings step = granularStep(options, gravity, angle);
            step.seed = std::uint64_t(seed);
            sandcore::Scene scene = sandcore::makeCanvasScene({{width, 4, width}, {width, height, width}}, step);
            for (int added = 0; added < grains;) {
                added += scene.addGrain(GridLevel::Upper, sandcore::pourCell(scene)) >= 0 ? 1 : 0;
                scene.step();
            }
            while (!scene.settled()) scene.step();
            passed = passed && scene.grainCount() == grains;
            const sandcore::PileSlopes rays = sandcore::measurePileSlopes(scene.grid(GridLevel::Lower));
            sandcore::PileSlopeSettings sectorRays;
            sectorRays.raysPerDirection = 5;
            const sandcore::PileSlopes sectors = sandcore::measurePileSlopes(scene.grid(GridLevel::Lower), sectorRays);
            PlotSeries series{"asked " + fixed(angle, 0) + ", seed " + std::to_string(seed), {}, {}};
            for (std::size_t d = 0; d < sectors.degrees.size(); ++d) {
                const double direction = 360.0 * double(d) / double(sectors.degrees.size()), degrees = sectors.degrees[d];
                csv.rows.push_back({fixed(angle, 0), std::to_string(seed), fixed(direction, 1), fixed(degrees, 2),
                                    fixed(rays.degrees[d], 2)});
                series.points.push_back({direction, degrees});
                sum += degrees;
                ++count;
                lowest = std::min(lowest, degrees);
                highest = std::max(highest, degrees);
                if (std::abs(degrees - angle) > worstOff) {
                    worstOff = std::abs(degrees - angle);
                    worst = fixed(degrees, 2) + " (seed " + std::to_string(seed) + ", " + fixed(direction, 1) + " deg)";
                }
            }
            if (seed == 1) plot.series.push_back(std::move(series));
        }
        const bool within = count > 0 && worstOff <= kSectorTolerance;
        passed = passed && within;
        table.rows.push_back({fixed(angle, 0), std::to_string(seeds), fixed(sum / std::max(count, 1), 2), fixed(lowest, 2),
                              fixed(highest, 2), worst + ", " + fixed(worstOff, 2), within ? "yes" : "**no**"});
    }
    writeCsv(csv, options.outDir / "repose.csv");
    passed = writeLinePlot(options.outDir, plot) && passed;
    return "Repose (PH2): the angle of repose is measured per direction sector: a cone of " + std::to_string(grains) +
           " grains poured one a step at the centre of a " + std::to_string(width) + "-cell canvas floor (g = " +
           fixed(gravity, 2) + " cells/step^2, seeds 1-" + std::to_string(seeds) + "), left to settle; along each of "
           "16 directions out of the peak a least-squares line over the flank between 15% and 85% of the peak's height "
           "(`sandcore::measurePileSlopes`), and each direction taken as the mean of 5 rays over its 22.5-degree "
           "sector (`PileSlopeSettings::raysPerDirection`: one ray reads the flank's grain-sized roughness). The "
           "worst sector is the one farthest from the angle asked over all the cones; every sector must lie within " +
           fixed(kSectorTolerance, 0) + " degrees. repose.csv holds every sector and its single ray.\n\n" +
           toMarkdown(table) + "\n![repose](repose.png)\n\n";
}

std::string fallPart(const ReportOptions& options, bool& passed) {
    Table table{{"g (cells/step^2)", "height (cells)", "steps", "sqrt(2h/g)", "error"}, {}};
    for (float g : {0.02f, 0.5f, 2.7f})
        for (int h : {10, 50, 200}) {
            sandcore::Scene scene(sandcore::SceneShape{}, sandcore::CellGrid({3, 1, 3}),
                                  sandcore::CellGrid({3, h + 1, 3}), {}, granularStep(options, g));
            const auto& grid = scene.grid(GridLevel::Lower);
            const auto id = std::size_t(scene.addGrain(GridLevel::Lower, grid.index(1, h, 1)));
            int steps = 0;
            while (grid.coordinate(scene.grains().place[id].cell).y > 0 && steps < 100000) {
                scene.step();
                ++steps;
            }
            const double expected = std::sqrt(2.0 * h / g);
            const double error = double(steps) - expected;
            passed = passed && std::abs(error) <= std::max(1.0, 0.05 * expected);
            table.rows.push_back({fixed(g, 2), std::to_string(h), std::to_string(steps), fixed(expected, 2),
                                  fixed(error, 2) + " steps (" + fixed(100.0 * error / expected, 1) + "%)"});
        }
    writeCsv(table, options.outDir / "fall_time.csv");
    return "Fall time (PH3): one grain dropped from rest onto the floor of a 3x3 column; the step at which it "
           "lands against sqrt(2h/g). A grain moves its mean speed v + g/2 each step, so its path is g n^2 / 2 "
           "at whole steps.\n\n" + toMarkdown(table) + "\n";
}

// Beverloo's exponent the discharge over the necks must give, and the steadiness of each drain.
constexpr double kBeverlooExponent = 2.5, kExponentTolerance = 0.3, kMostDischargeCv = 0.05;
// The middle of a drain: from 10% to 90% of the sand passed, in 20 parts.
constexpr double kMiddleFrom = 0.1, kMiddleTo = 0.9;
constexpr int kMiddleParts = 20;

std::string neckPart(const ReportOptions& options, std::ostream& log, bool& passed) {
    const int height = options.quick ? 64 : 128;
    const float gravity = sandcore::PhysicsSettings{}.gravity;
    const std::vector<float> necks = options.quick ? std::vector<float>{2.0f, 3.0f, 4.0f}
                                                   : std::vector<float>{2.0f, 3.0f, 4.0f, 6.0f, 8.0f};
    Table table{{"neck (cells across)", "open cells", "D (cells)", "model rate", "measured rate (grains/step)",
                 "measured / model", "CV (20 parts)", "CV (10-step windows)", "steps"}, {}};
    LinePlot overDrain{"necks", "Discharge over the drain (mean of 20 steps)", "share of the sand drained",
                       "grains per step", false, "right top", {}};
    LinePlot law{"beverloo", "Discharge against neck diameter", "D - 1.5 (cells)", "grains per step", true,
                 "left top", {}};
    PlotSeries measuredSeries{"measured", {}, {}}, modelSeries{"C sqrt(g) (D - 1.5)^2.5", {}, {}};
    double sx = 0, sy = 0, sxx = 0, sxy = 0, worstCv = 0;
    for (float neck : necks) {
        log << "granular: hourglass of height " << height << ", neck " << 2 * neck << " cells across\n";
        sandcore::Scene scene = sandcore::makeHourglassScene(sandcore::makeHourglassMask({height, neck, 0.0f}), {},
                                                             granularStep(options, gravity));
        const std::int64_t grains = scene.grainCount();
        const auto& upper = scene.grid(GridLevel::Upper);
        std::int64_t open = 0;
        for (int z = 0; z < upper.size().z; ++z)
            for (int x = 0; x < upper.size().x; ++x) open += upper.at(x, 0, z) != sandcore::kInvalid ? 1 : 0;
        const double diameter = 2.0 * std::sqrt(double(open) / M_PI);
        const DischargeSeries series = recordDischarge(scene, 2'000'000);
        passed = passed && scene.grainCount() == grains;
        const MiddleDischarge middle = middleDischarge(series, kMiddleParts, kMiddleFrom, kMiddleTo);
        const double cv = coefficientOfVariation(middle.partRates);
        const double windowCv = coefficientOfVariation(windowedDischargeRates(series, 10, kMiddleFrom, kMiddleTo));
        worstCv = std::max({worstCv, cv, windowCv});
        table.rows.push_back({fixed(2 * neck, 0), std::to_string(open), fixed(diameter, 2), fixed(scene.neckFlowRate(), 3),
                              fixed(middle.rate, 3), fixed(middle.rate / scene.neckFlowRate(), 3),
                              fixed(100.0 * cv, 2) + "%", fixed(100.0 * windowCv, 2) + "%",
                              std::to_string(series.grainsPerStep.size())});
        PlotSeries drain{"neck " + fixed(2 * neck, 0) + " across", {}, {}};
        std::int64_t drained = 0, windowGrains = 0;
        for (std::size_t i = 0; i < series.grainsPerStep.size(); ++i) {
            drained += series.grainsPerStep[i];
            windowGrains += series.grainsPerStep[i];
            if (i % 20 == 19) {
                drain.points.push_back({double(drained) / double(series.grainsAtStart), double(windowGrains) / 20.0});
                windowGrains = 0;
            }
        }
        overDrain.series.push_back(std::move(drain));
        const double x = std::log(diameter - 1.5), y = std::log(middle.rate);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        measuredSeries.points.push_back({diameter - 1.5, middle.rate});
        modelSeries.points.push_back({diameter - 1.5, scene.neckFlowRate()});
    }
    const double n = double(necks.size());
    const double exponent = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    passed = passed && std::abs(exponent - kBeverlooExponent) <= kExponentTolerance && worstCv <= kMostDischargeCv;
    law.series = {measuredSeries, modelSeries};
    writeCsv(table, options.outDir / "necks.csv");
    passed = writeLinePlot(options.outDir, overDrain) && writeLinePlot(options.outDir, law) && passed;
    return "Discharge (PH4): procedural hourglasses of height " + std::to_string(height) + " with necks of " +
           std::to_string(necks.size()) + " widths at the default gravity, g = " + fixed(gravity, 2) +
           " cells/step^2, drained until nothing moves. The measured rate is over the middle 80% of the drain: from "
           "the step after the one at whose end 10% of the sand has passed to the step at whose end 90% has; the CV is "
           "that of the rates of its " + std::to_string(kMiddleParts) + " runs of equal steps (`middleDischarge`), and "
           "that of 10-step windows while 10% to 90% of the sand has passed (SPEC PH4's). The "
           "neck is modelled (`neck_flow.hpp`): the cells carry no stress, so with gravity alone the rate would follow "
           "the supply around the neck, not the neck. The model lets through C sqrt(g) (D - k)^2.5 grains a step "
           "(C = 0.58, k = 1.5 cells, a cell being one grain; Mankoc et al. 2007), D from the neck row's open cells, "
           "and the cells carry that flow: the sand dives into the draining column from its sides, the grain over an "
           "emptied neck cell follows at once, and the grains leave the neck fast enough to stay apart and glance off "
           "slower ones (docs/engine.md, Discharge). The agreement shows that the cells deliver what the model asks, "
           "not that they explain it.\n\n" + toMarkdown(table) + "\nFitted exponent n of Q = c (D - 1.5)^n over the " +
           std::to_string(necks.size()) + " necks: **" + fixed(exponent, 3) + "** (Beverloo: 2.5; required within " +
           fixed(kExponentTolerance, 1) + ", and every CV at most " + fixed(100.0 * kMostDischargeCv, 0) +
           "%).\n\n![discharge over the drain](necks.png)\n![Beverloo](beverloo.png)\n\n";
}

std::string costPart(const ReportOptions& options, std::ostream& log, bool& passed) {
    const int height = options.quick ? 96 : 248;
    Table table{{"physics", "grains", "steps", "ms per step (mean over the drain)", "moves per step",
                 "vs classic", "discharge, middle 80% (grains/step)", "CV", "neck model (grains/step)", "state hash"},
                {}};
    const PhysicsLevel levels[] = {PhysicsLevel::Classic, PhysicsLevel::Granular};
    log << "granular: cost of the " << height << "-cell hourglass, " << std::size(levels) << " drains in turns\n";
    const std::vector<DrainCost> costs = drainsInTurns(height, options.step, levels);
    double granularRate = 0;
    for (const DrainCost& cost : costs) {
        const bool granular = cost.level == PhysicsLevel::Granular;
        passed = passed && cost.conserved;
        const MiddleDischarge middle = middleDischarge(cost.discharge, kMiddleParts, kMiddleFrom, kMiddleTo);
        table.rows.push_back({granular ? "granular" : "classic", std::to_string(cost.grains), std::to_string(cost.steps),
                              fixed(cost.msPerStep, 3), fixed(cost.movesPerStep, 0), fixed(cost.msPerStep / costs[0].msPerStep, 2) + "x",
                              fixed(middle.rate, 1), fixed(100.0 * coefficientOfVariation(middle.partRates), 1) + "%",
                              granular ? fixed(cost.neckModelRate, 1) : "-", sandglass::toHex16(cost.hash)});
        if (granular) granularRate = middle.rate;
    }
    writeCsv(table, options.outDir / "cost.csv");
    return "Cost (PH6): the procedural hourglass of height " + std::to_string(height) + " drained until nothing "
           "moves, " + std::to_string(options.step.threads) + " threads, sleeping grains skipped, both levels in this one "
           "process and in turns (after each " + std::to_string(kGranularStepsPerTurn) + " granular steps, "
           "classic steps until it has passed as large a share of its sand), so load from elsewhere slows all alike; the "
           "time is that of the steps alone; \"vs classic\" is against the first row. Granular against classic: **" +
           fixed(costs[1].msPerStep / costs[0].msPerStep, 2) + "x**. The discharge is over the middle 80% of the "
           "drain, as above. The granular drain passes " + fixed(granularRate, 1) + " grains a step of the " +
           fixed(costs[1].neckModelRate, 1) + " its neck model asks (" + fixed(100.0 * granularRate / std::max(costs[1].neckModelRate, 1e-9), 0) +
           "%)" + (granularRate >= 0.97 * costs[1].neckModelRate ? std::string(".")
                   : std::string(": at this neck's width the heap under the stream sheds the sand more slowly than the "
                                 "neck passes it, so the stream stands on it and fills the cells under the neck "
                                 "(docs/engine.md, Discharge).")) + "\n\n" +
           toMarkdown(table) + "\n";
}

} // namespace

std::vector<DrainCost> drainsInTurns(int height, const sandcore::StepSettings& step, std::span<const PhysicsLevel> levels) {
    struct Drain {
        sandcore::Scene scene;
        DrainCost cost;
        double seconds = 0, moves = 0;
    };
    std::vector<Drain> drains;
    drains.reserve(levels.size());
    for (const PhysicsLevel level : levels) {
        sandcore::StepSettings settings = step;
        settings.physics.level = level;
        Drain& drain = drains.emplace_back(Drain{
            sandcore::makeHourglassScene(
                sandcore::makeHourglassMask({height, sandcore::defaultNeckRadius(height), 0.0f}), {}, settings),
            {}});
        drain.cost.level = level;
        drain.cost.grains = drain.scene.grainCount();
        drain.cost.discharge.grainsAtStart = drain.scene.counters().grainsUpper;
    }
    constexpr std::uint64_t kMaxSteps = 1'000'000;
    auto done = [&](const Drain& d) { return d.scene.settled() || d.scene.counters().stepsDone >= kMaxSteps; };
    auto drained = [](const Drain& d) {
        return double(d.scene.counters().grainsLower) / double(std::max<std::int64_t>(d.cost.grains, 1));
    };
    auto stepOnce = [](Drain& d) {
        const std::int64_t before = d.scene.counters().grainsLower;
        const auto start = std::chrono::steady_clock::now();
        d.scene.step();
        d.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        d.moves += double(d.scene.counters().movesLastStep);
        d.cost.discharge.grainsPerStep.push_back(d.scene.counters().grainsLower - before);
    };
    auto granular = [](const Drain& d) { return d.cost.level == PhysicsLevel::Granular; };
    const auto pace = std::find_if(drains.begin(), drains.end(), granular);
    auto allDone = [&] { return std::all_of(drains.begin(), drains.end(), done); };
    while (!allDone()) {
        for (Drain& d : drains) {
            if (pace != drains.end() && !granular(d)) continue;
            for (int i = 0; i < kGranularStepsPerTurn && !done(d); ++i) stepOnce(d);
        }
        if (pace == drains.end()) continue;
        for (Drain& d : drains)
            if (!granular(d))
                while (!done(d) && (done(*pace) || drained(d) <= drained(*pace))) stepOnce(d);
    }
    std::vector<DrainCost> costs;
    for (Drain& d : drains) {
        const double steps = double(std::max<std::uint64_t>(d.scene.counters().stepsDone, 1));
        d.cost.steps = d.scene.counters().stepsDone;
        d.cost.msPerStep = 1000.0 * d.seconds / steps;
        d.cost.movesPerStep = d.moves / steps;
        d.cost.hash = d.scene.stateHash();
        d.cost.conserved = d.scene.grainCount() == d.cost.grains;
        d.cost.neckModelRate = d.scene.neckFlowRate();
        costs.push_back(std::move(d.cost));
    }
    return costs;
}

std::array<DrainCost, 2> drainCostInTurns(int height, const sandcore::StepSettings& step) {
    const PhysicsLevel levels[] = {PhysicsLevel::Classic, PhysicsLevel::Granular};
    std::vector<DrainCost> costs = drainsInTurns(height, step, levels);
    return {std::move(costs[0]), std::move(costs[1])};
}

GranularSection granularSection(const ReportOptions& options, std::ostream& log) {
    GranularSection section;
    bool passed = true;
    const std::string repose = reposePart(options, log, passed);
    const std::string fall = fallPart(options, passed);
    const std::string necks = neckPart(options, log, passed);
    const std::string cost = costPart(options, log, passed);
    section.passed = passed;
    section.markdown = "## Granular physics\n\n`--physics granular` (SPEC PH1-PH7): slides up to 3 columns away "
                       "against a calibrated threshold dithered by blue noise; gravity with multi-cell falls; the hourglass's "
                       "neck at Beverloo's rate.\n\n" + repose + fall + necks + cost;
    return section;
}

} // namespace sandbench
