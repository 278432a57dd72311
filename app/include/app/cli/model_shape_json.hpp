// SPDX-License-Identifier: MIT
#pragma once
// SPEC S7-S9 keys of `simulate --json` and `voxelize --json`: parts, vessel, up_axis.

#include "scene/model_parts.hpp"
#include "scene/scene_request.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace sandglass {

/// `parts` as a list of {name, triangles, closed, role}.
nlohmann::ordered_json partsJson(const std::vector<PartSummary>& parts);

/// Adds `parts`, `vessel`, `up_axis`, `up_axis_found`, `sand_space_cells`, `upper_cells` (cells of
/// the upper grid sand may take) and `cavity_milliseconds` of a built scene (an empty list, "solid" and "+y" without a model).
void addModelShapeJson(nlohmann::ordered_json& out, const BuiltScene& built);

} // namespace sandglass
