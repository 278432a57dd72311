#pragma once
// Small statistics for timings reported by the command line and the benchmark.

#include <algorithm>
#include <vector>

namespace sandglass {

/// The median of a series (the upper of the two middle values for an even count); 0 when empty.
inline double medianOf(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

} // namespace sandglass
