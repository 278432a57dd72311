// SPDX-License-Identifier: MIT
#pragma once
// Command-line numbers checked where they enter: every numeric option is read as text and
// converted exactly (no wrap-around of -1 into a huge unsigned, no saturation of too many
// digits, no NaN or infinity), then checked against its range, with one line naming the option.

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

namespace sandglass {

/// The number `text` stands for, or a CLI::ValidationError naming `option` when it is not a
/// number of type T (trailing characters, out of T's range, NaN, infinite) or lies outside min..max.
template <class T> T parseCheckedNumber(const std::string& option, const std::string& text, T min, T max) {
    T value{};
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (first != last && *first == '+') ++first; // from_chars takes no plus sign
    const auto [end, error] = std::from_chars(first, last, value);
    auto describe = [](T bound) {
        if constexpr (std::is_floating_point_v<T>) {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%g", double(bound));
            return std::string(buffer);
        } else {
            return std::to_string(bound);
        }
    };
    const std::string range = describe(min) + ".." + describe(max);
    if (first == last || error == std::errc::invalid_argument || end != last)
        throw CLI::ValidationError(option, "wants a number in " + range + ", got '" + text + "'");
    if (error == std::errc::result_out_of_range)
        throw CLI::ValidationError(option, "must lie in " + range + ", got " + text);
    if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(value)) throw CLI::ValidationError(option, "must be a finite number, got " + text);
    if (!(value >= min && value <= max)) throw CLI::ValidationError(option, "must lie in " + range + ", got " + text);
    return value;
}

/// Adds a numeric option whose text is converted and checked by parseCheckedNumber.
template <class T>
CLI::Option* addNumberOption(CLI::App& command, const std::string& name, T& value, T min, T max, const std::string& help) {
    const std::string option = name.substr(0, name.find(','));
    CLI::Option* added = command.add_option_function<std::string>(
        name, [&value, option, min, max](const std::string& text) { value = parseCheckedNumber(option, text, min, max); },
        help);
    added->type_name(std::is_floating_point_v<T> ? "FLOAT" : "INT");
    return added;
}

/// As addNumberOption, for an option that takes several numbers.
template <class T>
CLI::Option* addNumberListOption(CLI::App& command, const std::string& name, std::vector<T>& values, T min, T max,
                                 const std::string& help) {
    const std::string option = name.substr(0, name.find(','));
    CLI::Option* added = command.add_option_function<std::vector<std::string>>(
        name,
        [&values, option, min, max](const std::vector<std::string>& texts) {
            values.clear();
            for (const std::string& text : texts) values.push_back(parseCheckedNumber(option, text, min, max));
        },
        help);
    added->type_name(std::is_floating_point_v<T> ? "FLOAT ..." : "INT ...");
    return added;
}

} // namespace sandglass
