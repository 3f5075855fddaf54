#pragma once
// What the adapter checks of a user's MuJoCo model (internal to
// wtc::mujoco): which of a wheel body's geoms MuJoCo would also collide
// with the ground (the geoms of the world and of bodies welded to it).
#include <string>

#include <mujoco/mujoco.h>

namespace wtc::mujoco {

/// The first pair by which MuJoCo would collide a geom of `body` with a
/// geom welded to the world, in words ("geom 'tyre' (contype 1) with world
/// geom 'floor' (conaffinity 1)", or "<pair> 3: geom ... with ..."); empty
/// if there is none (contacts disabled, the bodies excluded, bits that do
/// not meet).
std::string worldCollision(const mjModel& model, int body);

}  // namespace wtc::mujoco
