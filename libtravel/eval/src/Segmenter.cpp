// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/Segmenter.hpp"

#include <stdexcept>
#include <utility>

#include "travel/Errors.hpp"
#include "travel/Pipeline.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/RangeImage.hpp"
#include "travel/ThreadCpuClock.hpp"
#include "travel/eval/EuclideanClustering.hpp"
#include "travel/eval/GroundPlaneFitting.hpp"
#include "travel/eval/RansacGround.hpp"
#include "travel/eval/ScanLineRun.hpp"

namespace travel::eval {

void renumberClusters(std::vector<uint32_t>& ids, uint32_t max_label, int min_size, int max_size,
                      std::vector<uint32_t>& count, std::vector<uint32_t>& new_id) {
    count.assign(static_cast<std::size_t>(max_label) + 1, 0u);
    for (const uint32_t id : ids) ++count[id];
    // new_id: 0 = not numbered yet; kDropped = outside the size window.
    constexpr uint32_t kDropped = 0xffffffffu;
    new_id.assign(count.size(), 0u);
    new_id[0] = kDropped;
    const auto lo = static_cast<uint32_t>(std::max(min_size, 0));
    const auto hi = static_cast<uint32_t>(std::max(max_size, 0));
    uint32_t next = 0;
    for (uint32_t& id : ids) {
        uint32_t& mapped = new_id[id];
        if (mapped == 0) mapped = count[id] >= lo && count[id] <= hi ? ++next : kDropped;
        id = mapped == kDropped ? 0u : mapped;
    }
}

namespace {

enum class Ground { Tgs, Gpf, Ransac };
enum class Objects { None, TravelAos, Slr, Euclidean };

struct Method {
    const char* name;
    Ground ground;
    Objects objects;
    bool ttmf;
};

constexpr Method kMethods[] = {
    {"travel", Ground::Tgs, Objects::TravelAos, true},
    {"travel-no-ttmf", Ground::Tgs, Objects::TravelAos, false},
    {"tgs", Ground::Tgs, Objects::None, true},
    {"ransac", Ground::Ransac, Objects::None, true},
    {"gpf", Ground::Gpf, Objects::None, true},
    {"gpf+slr", Ground::Gpf, Objects::Slr, true},
    {"tgs+slr", Ground::Tgs, Objects::Slr, true},
    {"tgs+euclidean", Ground::Tgs, Objects::Euclidean, true},
    {"gpf+euclidean", Ground::Gpf, Objects::Euclidean, true},
};

// The baselines take the mount as configured; estimating it is TRAVEL's Pipeline's job.
void rejectAutoMount(const Params& params, const char* method) {
    const std::pair<const char*, const AutoReal*> mount[] = {
        {"sensor_height", &params.sensor_height},
        {"mount_roll_deg", &params.mount_roll_deg},
        {"mount_pitch_deg", &params.mount_pitch_deg}};
    for (const auto& [key, value] : mount)
        if (value->isAuto())
            throw ConfigError(std::string(key) + ": auto is not supported by method '" + method +
                              "' (it does not estimate the mount): give a number");
}

// Every method is timed with the clock of TRAVEL's own stages (ThreadCpuClock.hpp), so that the
// evaluator's speed columns compare like with like.
struct Clock {
    using time_point = double;  // ms
    static time_point now() { return threadCpuMs(); }
};
double msBetween(Clock::time_point a, Clock::time_point b) {
    return b - a;
}

// Every method: one ground stage, then optionally one clustering stage on its NonGround points.
class MethodSegmenter final : public Segmenter {
  public:
    MethodSegmenter(const Method& method, const Params& params) : method_(method), params_(params) {
        params_.ttmf = method.ttmf;
        params_.cluster_objects = method.objects == Objects::TravelAos;
        params_.validate();
        if (method.ground == Ground::Tgs) {
            pipeline_ = std::make_unique<Pipeline>(params_);
            pipeline_->reserve(result_);
        } else {
            rejectAutoMount(params_, method.name);
        }
    }

    // A clone around `settled` (Pipeline::settledCopy()); `params` are another segmenter's.
    MethodSegmenter(const Method& method, const Params& params, Pipeline settled)
        : method_(method), params_(params) {
        pipeline_ = std::make_unique<Pipeline>(std::move(settled));
        pipeline_->reserve(result_);
    }

    const char* name() const override { return method_.name; }

    void segment(const PointCloud& cloud, Segmentation& out) override {
        if (cloud.y.size() != cloud.x.size() || cloud.z.size() != cloud.x.size())
            throw std::invalid_argument(std::string("travel::eval::") + method_.name +
                                        ": x, y and z differ in size");
        const Clock::time_point t0 = Clock::now();
        const AlignedCloud* aligned = &aligned_;
        // The values in use: the pipeline's (estimated `auto` mount) for the tri-grid methods.
        const Params& params = pipeline_ ? pipeline_->params() : params_;
        if (pipeline_) {
            pipeline_->process(cloud, FrameInput{}, result_);
            out.labels = result_.labels;
            aligned = &pipeline_->aligned();
        } else {
            preprocess(cloud, params_, FrameInput{}, aligned_);
            if (method_.ground == Ground::Gpf)
                gpf_.segment(aligned_, params_, out.labels);
            else
                ransac_.segment(aligned_, params_, out.labels);
        }
        const Clock::time_point t1 = Clock::now();
        switch (method_.objects) {
            case Objects::None:
                out.cluster_id.assign(cloud.size(), 0u);
                break;
            case Objects::TravelAos:
                out.cluster_id = result_.cluster_id;
                break;
            case Objects::Slr:
                range_image_.build(cloud, aligned->valid, params);
                slr_.cluster(cloud, *aligned, range_image_, out.labels, params, out.cluster_id);
                break;
            case Objects::Euclidean:
                euclidean_.cluster(*aligned, out.labels, params, out.cluster_id);
                break;
        }
        const Clock::time_point t2 = Clock::now();
        out.stages = pipeline_ ? result_.timings : StageTimings{};
        out.mount = pipeline_ ? result_.mount : MountNote{};
        out.sensor_height = params.sensor_height;
        out.aligned_rotation = aligned->rotation;
        if (method_.objects == Objects::TravelAos)
            out.clusters = result_.clusters;
        else
            out.clusters.clear();
        if (method_.objects == Objects::TravelAos) {
            // The pipeline times its own stages; the copies above are not part of them.
            out.ground_ms = result_.timings.ground_total;
            out.objects_ms = result_.timings.objects_total;
        } else {
            out.ground_ms = msBetween(t0, t1);
            out.objects_ms = method_.objects == Objects::None ? 0.0 : msBetween(t1, t2);
        }
    }

    bool independentFrames() const override { return !pipeline_ || pipeline_->mountSettled(); }

    // Reads only state that segment() leaves alone once independentFrames(): callable while
    // another thread segments with this one.
    std::unique_ptr<Segmenter> clone() const override {
        if (!pipeline_) return std::make_unique<MethodSegmenter>(method_, params_);
        return std::unique_ptr<MethodSegmenter>(
            new MethodSegmenter(method_, params_, pipeline_->settledCopy()));
    }

    void adoptSettledState(const Segmenter& settled) override {
        const auto* other = dynamic_cast<const MethodSegmenter*>(&settled);
        if (!other || std::string(other->method_.name) != method_.name)
            throw std::invalid_argument(std::string("travel::eval::") + method_.name +
                                        ": adoptSettledState from another method");
        if (pipeline_) pipeline_->adoptSettledState(*other->pipeline_);
    }

    const Pipeline* objectPipeline() const override {
        return method_.objects == Objects::TravelAos ? pipeline_.get() : nullptr;
    }

  private:
    Method method_;
    Params params_;
    std::unique_ptr<Pipeline> pipeline_;
    Result result_;
    AlignedCloud aligned_;
    GroundPlaneFitting gpf_;
    RansacGround ransac_;
    RangeImage range_image_;
    ScanLineRun slr_;
    EuclideanClustering euclidean_;
};

}  // namespace

std::vector<std::string> methodNames() {
    std::vector<std::string> names;
    for (const Method& m : kMethods) names.emplace_back(m.name);
    return names;
}

std::unique_ptr<Segmenter> makeSegmenter(const std::string& method, const Params& params) {
    for (const Method& m : kMethods)
        if (method == m.name) return std::make_unique<MethodSegmenter>(m, params);
    std::string valid;
    for (const Method& m : kMethods) valid += (valid.empty() ? "" : ", ") + std::string(m.name);
    throw ConfigError("unknown segmentation method '" + method + "' (valid: " + valid + ")");
}

}  // namespace travel::eval
