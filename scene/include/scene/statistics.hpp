// SPDX-License-Identifier: MIT
#pragma once
// Small statistics for timings reported by the command line and the benchmark.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sandglass {

/// The median of a series (the upper of the two middle values for an even count); 0 when empty.
inline double medianOf(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

/// The median of a long series in bounded memory: exact (medianOf) for the first kExactSamples
/// values, then from a histogram of logarithmic bins 0.5% wide, so a run of 10^9 steps keeps
/// about 40 KB instead of every value.
class StreamingMedian {
public:
    static constexpr std::size_t kExactSamples = std::size_t(1) << 16; ///< values kept exactly
    static constexpr double kSmallest = 1e-6;                          ///< values below fall in the first bin
    static constexpr double kBinRatio = 1.005;                         ///< upper / lower edge of a bin

    /// Adds one non-negative value.
    void add(double value) {
        ++count_;
        if (bins_.empty()) {
            exact_.push_back(value);
            if (exact_.size() <= kExactSamples) return;
            bins_.assign(kBins, 0);
            for (double kept : exact_) ++bins_[binOf(kept)];
            exact_ = {};
            return;
        }
        ++bins_[binOf(value)];
    }
    /// The median of every value added; 0 when none.
    double median() const {
        if (bins_.empty()) return medianOf(exact_);
        const std::uint64_t wanted = count_ / 2;
        std::uint64_t seen = 0;
        for (std::size_t bin = 0; bin < kBins; ++bin) {
            seen += bins_[bin];
            if (seen > wanted) return kSmallest * std::pow(kBinRatio, double(bin) + 0.5); // the bin's middle
        }
        return 0.0;
    }
    std::uint64_t count() const { return count_; } ///< values added

private:
    static constexpr std::size_t kBins = 5000; // 1e-6 * 1.005^5000 covers up to about 7e4
    static std::size_t binOf(double value) {
        if (!(value > kSmallest)) return 0;
        const double bin = std::log(value / kSmallest) / std::log(kBinRatio);
        return std::min(kBins - 1, std::size_t(bin));
    }
    std::vector<double> exact_;
    std::vector<std::uint64_t> bins_;
    std::uint64_t count_ = 0;
};

} // namespace sandglass
