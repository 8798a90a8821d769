// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/Pipeline.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include "travel/GroundLabelling.hpp"
#include "travel/NodeFitting.hpp"

namespace travel {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point& t) {
    const Clock::time_point now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - t).count();
    t = now;
    return ms;
}

}  // namespace

Pipeline::Pipeline(const Params& params) : params_(params) {
    params_.validate();
    field_.configure(params_);
}

void Pipeline::process(const PointCloud& cloud, const FrameInput& input, Result& result) {
    if (cloud.y.size() != cloud.x.size() || cloud.z.size() != cloud.x.size())
        throw std::invalid_argument("travel::Pipeline::process: x, y and z differ in size (" +
                                    std::to_string(cloud.x.size()) + ", " +
                                    std::to_string(cloud.y.size()) + ", " +
                                    std::to_string(cloud.z.size()) + ")");
    StageTimings& t = result.timings;
    Clock::time_point clock = Clock::now();
    preprocess(cloud, params_, input, aligned_);
    t.preprocess = msSince(clock);
    field_.embed(aligned_, result.terrain);
    t.embedding = msSince(clock);
    fitNodes(field_, params_, result.terrain);
    t.node_fitting = msSince(clock);
    graph_search_.run(field_, params_, result.terrain);
    t.graph_search = msSince(clock);
    terrain_fitting_.run(field_, params_, result.terrain);
    t.ttmf = msSince(clock);
    result.class_counts = labelPoints(field_, aligned_, params_, result.terrain, result.labels);
    t.labelling = msSince(clock);
    t.ground_total =
        t.preprocess + t.embedding + t.node_fitting + t.graph_search + t.ttmf + t.labelling;

    result.cluster_id.assign(cloud.size(), 0u);
    result.clusters.clear();
    t.range_image = t.horizontal = t.vertical = t.clusters = t.objects_total = 0;
    if (!params_.cluster_objects) return;
    range_image_.build(cloud, aligned_.valid, params_);
    t.range_image = msSince(clock);
    clustering_.horizontal(aligned_, range_image_, result.labels, params_);
    t.horizontal = msSince(clock);
    clustering_.vertical(params_);
    t.vertical = msSince(clock);
    clustering_.assignIds(params_, result.cluster_id);
    clustering_.summarize(field_, result.terrain, result.clusters);
    t.clusters = msSince(clock);
    t.objects_total = t.range_image + t.horizontal + t.vertical + t.clusters;
}

}  // namespace travel
