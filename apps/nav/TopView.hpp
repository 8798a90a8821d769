// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Headless top view of a world and a run: terrain shaded by height (with hill shading, so
// ramps and kerbs read at a glance), obstacles of the collision check, start, goal, the
// driven path, and the final footprint (red when the run ended in a collision).
#pragma once

#include <string>

#include "nav/Simulation.hpp"
#include "nav/World.hpp"

namespace mrpt::img {
class CImage;
}

namespace travel::navsim {

struct TopViewOptions {
    double metres_per_pixel = 0.04;
    std::string title;  ///< written top left (empty: none)
};

/// Renders `world` and (when non-null) the run `report` into `out`.
void renderTopView(const World& world, const std::vector<Eigen::Vector2d>& footprint,
                   const RunReport* report, const TopViewOptions& options, mrpt::img::CImage& out);

}  // namespace travel::navsim
