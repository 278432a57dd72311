// SPDX-License-Identifier: MIT
#pragma once
// Painting with sand on the canvas (SPEC P2-P4, P6, P7): mouse samples, already turned into
// canvas columns by picking (P1), release sand in the top row of the upper grid or erase the
// topmost grain of a column of the lower grid. The mouse and the tests use this same path.

#include "scene/compressed_snapshot.hpp"
#include "scene/draft_image.hpp"

#include "sandcore/scene.hpp"

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace sandglass {

/// A column of the canvas: x and z of both grids (they share the footprint).
struct CanvasColumn {
    int x = 0; ///< cells
    int z = 0; ///< cells
    friend bool operator==(const CanvasColumn&, const CanvasColumn&) = default;
};

enum class PaintAction : std::uint8_t { Draw, Erase };
/// P2 mWhere: which surface the mouse points at; sand is released in the top row either way.
enum class PaintTarget : std::uint8_t {
    Top,    ///< PAINT_TOP (default): the release layer, the top row of the upper grid
    Bottom, ///< PAINT_BOTTOM: the floor of the lower grid, where the sand should land
};

/// What a stroke does; the defaults are the thesis's (§3.7).
struct PaintSettings {
    PaintAction action = PaintAction::Draw; ///< draw sand or erase it
    PaintTarget target = PaintTarget::Top;  ///< where picking looks (P2)
    bool thinLines = false;                 ///< thin: a grain only when the column changes; thick (default): every sample
    int brushRadius = 0;                    ///< cells around the picked column that also get sand; 0 = one column
    std::uint32_t color = 0;                ///< RGBA8 of new grains; 0 = the default sand colours
    bool colorFromDraft = false;            ///< P6: new grains take the draft image's colour at their column
};

/// How much undo history a painter keeps (P7). Each stroke keeps the scene's whole state as a
/// CompressedSnapshot (E3: grains, obstacles and counters, zstd; tens of kB for a 256-wide
/// canvas with tens of thousands of grains, where a raw snapshot is about 56 MB); memory caps the
/// history as well as the count.
struct UndoLimits {
    std::size_t maxStrokes = 32;                    ///< most strokes kept (at least 1)
    std::size_t maxBytes = std::size_t(256) << 20;  ///< most bytes the kept undo snapshots use, compressed (256 MiB); the last stroke is kept even when it alone is larger
};

/// Bytes a snapshot's cells, grain records and obstacles use, uncompressed.
std::size_t snapshotBytes(const sandcore::SceneSnapshot& snapshot);

class SandPainter {
public:
    /// A painter whose undo history stays within `limits`.
    explicit SandPainter(UndoLimits limits = {}) : limits_(limits) {}

    /// Starts a stroke at a column: saves the scene for undo, then paints the first sample.
    void beginStroke(sandcore::Scene& scene, CanvasColumn column, const PaintSettings& settings,
                     const DraftImage* draft = nullptr);
    /// A further mouse sample: joins it to the previous one with a line, so fast strokes have no gaps.
    void continueStroke(sandcore::Scene& scene, CanvasColumn column, const PaintSettings& settings,
                        const DraftImage* draft = nullptr);
    /// Ends the stroke (button released).
    void endStroke();
    bool stroking() const { return last_.has_value(); } ///< true between begin and end

    /// Saves the scene for undo as a stroke does, for an edit other than painting (a digger's drag).
    void rememberForUndo(const sandcore::Scene& scene) {
        pushHistory(scene);
        redo_.clear();
    }
    /// P7: puts the scene back to where it was before the last stroke; false when nothing is left to undo.
    bool undo(sandcore::Scene& scene);
    /// E3: takes back the last undo (the scene as it was when undone); false when there is none.
    /// A new stroke forgets what could be redone.
    bool redo(sandcore::Scene& scene);
    /// Strokes that can be undone.
    std::size_t undoDepth() const { return history_.size(); }
    /// Undos that can be redone.
    std::size_t redoDepth() const { return redo_.size(); }
    /// Memory the kept undo snapshots use, compressed, bytes (the limits apply to this).
    std::size_t undoBytes() const { return historyBytes_; }
    /// Memory the kept redo snapshots use, compressed, bytes.
    std::size_t redoBytes() const;
    /// The limits the history is kept within.
    const UndoLimits& undoLimits() const { return limits_; }
    /// Forgets the undo and redo history (the scene was rebuilt or reset).
    void clearHistory() {
        history_.clear();
        redo_.clear();
        historyBytes_ = 0;
    }

    /// Grains added and removed since the stroke began.
    std::int64_t grainsReleased() const { return released_; }
    std::int64_t grainsErased() const { return erased_; } ///< see grainsReleased

private:
    void paintSample(sandcore::Scene& scene, CanvasColumn column, const PaintSettings& settings,
                     const DraftImage* draft);

    std::optional<CanvasColumn> last_;
    UndoLimits limits_;
    void pushHistory(const sandcore::Scene& scene);

    std::deque<CompressedSnapshot> history_;
    std::vector<CompressedSnapshot> redo_;
    std::size_t historyBytes_ = 0; // sum of bytes() over history_
    std::int64_t released_ = 0;
    std::int64_t erased_ = 0;
};

/// The columns on the line from `from` to `to` (both included), in order, each next to the last.
std::vector<CanvasColumn> columnsOnLine(CanvasColumn from, CanvasColumn to);

/// The columns within `radius` cells (Euclidean, of the column centres) of `centre`, inside a
/// footprint of sizeX x sizeZ, in row order.
std::vector<CanvasColumn> brushColumns(CanvasColumn centre, int radius, int sizeX, int sizeZ);

/// Releases one grain in the top row of the upper grid above the column; false when that cell
/// is not EMPTY or the column lies outside the canvas.
bool releaseGrain(sandcore::Scene& scene, CanvasColumn column, std::uint32_t rgba);

/// P4: removes the topmost grain of the column in the lower grid; never an INVALID cell. False
/// when the column holds no grain.
bool eraseTopGrain(sandcore::Scene& scene, CanvasColumn column);

} // namespace sandglass
