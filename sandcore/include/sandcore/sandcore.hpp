// SPDX-License-Identifier: MIT
#pragma once
// sandcore: the sand engine, in one include. A scene of cells that hold one grain each, stepped
// by local rules (classic or granular), built from a procedural shape, a voxelized mesh or a
// model's sand space; its grains drawn smoothly between steps.

#include "sandcore/display_positions.hpp"  // writeDisplayPositions: where each grain is drawn between two steps
#include "sandcore/hourglass_space.hpp"    // findHourglassSpace, makeHourglassFromMesh: a model's sand space and up axis
#include "sandcore/mesh_shapes.hpp"        // boxes, spheres, tori, lathes as triangle meshes
#include "sandcore/moving_body.hpp"        // MovingBody: blades, boxes, balls that push the sand (Scene::moveBody)
#include "sandcore/physics_settings.hpp"   // classic or granular rules, repose angle, gravity
#include "sandcore/procedural_shapes.hpp"  // procedural hourglass and sculpture masks
#include "sandcore/scene.hpp"              // Scene: step, counters, edits, state hash
#include "sandcore/scenes.hpp"             // hourglass, sculpture and canvas scenes from masks
#include "sandcore/sim_clock.hpp"          // SimClock: steps a second against wall time
#include "sandcore/task_system.hpp"        // TaskSystem: the host's threads for the step
#include "sandcore/triangle_mesh.hpp"      // TriangleMesh, weld, closedness
#include "sandcore/up_axis.hpp"            // turning a mask so its up axis points up
#include "sandcore/voxelizer.hpp"          // voxelize: a mesh's inside as cells
