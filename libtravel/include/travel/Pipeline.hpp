// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The TRAVEL pipeline: composes the stages, owns every buffer and reuses it across frames.
// One instance per thread; instances share nothing.
//
//   Pipeline travel(params);            // validates params (throws ConfigError)
//   travel.process(cloud, {}, result);  // result.labels[i] for every input point i
#pragma once

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/RangeImage.hpp"
#include "travel/Result.hpp"
#include "travel/RunClustering.hpp"
#include "travel/TerrainModelFitting.hpp"
#include "travel/TraversableGraphSearch.hpp"
#include "travel/TriGridField.hpp"

namespace travel {

class Pipeline {
  public:
    explicit Pipeline(const Params& params);

    const Params& params() const { return params_; }

    /// Traversable ground segmentation (TGS) of one frame, then (params.cluster_objects)
    /// above-ground object segmentation (AOS) of its non-ground points.
    void process(const PointCloud& cloud, const FrameInput& input, Result& result);

    /// The aligned coordinates of the last frame (sensor-centred, gravity-aligned).
    const AlignedCloud& aligned() const { return aligned_; }
    /// Rings and columns of the last frame (valid when params.cluster_objects).
    const RangeImage& rangeImage() const { return range_image_; }

  private:
    Params params_;
    AlignedCloud aligned_;
    TriGridField field_;
    TraversableGraphSearch graph_search_;
    TerrainModelFitting terrain_fitting_;
    RangeImage range_image_;
    RunClustering clustering_;
};

}  // namespace travel
