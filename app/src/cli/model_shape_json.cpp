// SPDX-License-Identifier: MIT
#include "app/cli/model_shape_json.hpp"

#include "sandcore/cell_grid.hpp"

#include <algorithm>

namespace sandglass {

nlohmann::ordered_json partsJson(const std::vector<PartSummary>& parts) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const PartSummary& part : parts) {
        nlohmann::ordered_json entry;
        entry["name"] = part.name;
        entry["triangles"] = part.triangles;
        entry["closed"] = part.closed;
        entry["role"] = partRoleName(part.role);
        list.push_back(entry);
    }
    return list;
}

void addModelShapeJson(nlohmann::ordered_json& out, const BuiltScene& built) {
    out["parts"] = partsJson(built.parts);
    out["vessel"] = vesselKindName(built.vessel);
    out["up_axis"] = sandcore::upAxisName(built.upAxis.value_or(sandcore::UpAxis::PlusY));
    out["up_axis_found"] = built.upAxisFound;
    out["sand_space_cells"] = built.sandSpaceCells;
    // The fill's reference: cells of the upper grid sand may take (the upper bulb after carving).
    const auto& upper = built.scene.grid(sandcore::GridLevel::Upper).cells();
    out["upper_cells"] = std::count_if(upper.begin(), upper.end(), [](sandcore::CellValue c) { return c != sandcore::kInvalid; });
    out["cavity_milliseconds"] = built.cavityMilliseconds;
    out["closing_cells"] = built.closingCells;
    out["neck_opened"] = built.neckOpened;
    out["modelled_sand_cells"] = built.modelledSandCells;
    out["note"] = built.note;
}

} // namespace sandglass
