// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The TRAVEL obstacle source for MRPT's reactive navigators: travel::TravelObstacles (the rules,
// in libtravel's traversability component) on the frame TravelFilter produced - its result and
// the aligned, deskewed cloud the labels refer to (ObstacleFrame::aligned).
#pragma once

#include "travel/traversability/TravelObstacles.hpp"
#include "travel_mrpt/ObstacleSource.hpp"

namespace travel_mrpt {

using travel::TravelObstacleOptions;

class TravelObstacleSource : public ObstacleSource {
  public:
    explicit TravelObstacleSource(const TravelObstacleOptions& options = {})
        : obstacles_(options) {}
    std::string name() const override { return "travel"; }
    const TravelObstacleOptions& options() const { return obstacles_.options(); }
    /// Throws std::invalid_argument on negative heights or radius.
    void setOptions(const TravelObstacleOptions& options) { obstacles_.setOptions(options); }

  protected:
    void compute(const ObstacleFrame& frame, ObstaclePoints& out) override;

  private:
    travel::TravelObstacles obstacles_;
};

}  // namespace travel_mrpt
