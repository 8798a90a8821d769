// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The TRAVEL obstacle source for MRPT's reactive navigators: travel::TravelObstacles (the rules,
// in libtravel's traversability component) on the frame TravelFilter produced - its result and
// the aligned, deskewed cloud the labels refer to (ObstacleFrame::aligned).
#pragma once

#include "travel/traversability/TravelObstacles.hpp"
#include "travel_mrpt/ObstacleSource.hpp"

namespace travel_mrpt {

class TravelObstacleSource : public ObstacleSource {
  public:
    /// The nav section's obstacle keys (travel::TravelObstacles); the memory: setMemory().
    explicit TravelObstacleSource(const travel::NavSection& options = {}) : obstacles_(options) {}
    std::string name() const override { return "travel"; }
    const travel::NavSection& options() const { return obstacles_.options(); }
    /// Throws travel::ConfigError naming the key (NavSection::validate).
    void setOptions(const travel::NavSection& options) { obstacles_.setOptions(options); }

  protected:
    void compute(const ObstacleFrame& frame, ObstaclePoints& out,
                 travel::ObstaclePointCloud& transient) override;

  private:
    travel::TravelObstacles obstacles_;
};

}  // namespace travel_mrpt
