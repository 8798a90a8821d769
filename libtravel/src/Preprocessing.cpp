// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Pre-processing (paper Sec. III-A). The paper assumes an upright, motion-free scan; we make it
// so: deskew with per-point times and a constant-velocity model, then rotate by roll/pitch.
#include "travel/Preprocessing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "CpuDispatch.hpp"

namespace travel {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

/// Same roll and pitch, zero yaw: Rz(-yaw) * R for R = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Matrix3d withoutYaw(const Eigen::Matrix3d& R) {
    const double yaw = std::atan2(R(1, 0), R(0, 0));
    return Eigen::AngleAxisd(-yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * R;
}

/// The self filter: an axis-aligned box in the vehicle frame (the sensor's axes after the mount
/// rotation, origin at the sensor) that holds the own vehicle's body. Given in vehicle axes
/// because a vehicle's footprint is (length along x, width along y, whatever the sensor's yaw,
/// e.g. nuScenes' -90 deg), and tested on the point before deskew and levelling: the body moves
/// with the sensor, not with the world. Strict bounds: an empty box (min = max) is off.
struct SelfBox {
    float min_x, max_x, min_y, max_y, min_z, max_z;
    /// Squared range of the box's farthest corner (+ rounding margin): farther points are out.
    float reach2;

    explicit SelfBox(const Params& params)
        : min_x(static_cast<float>(params.self_box_min_x)),
          max_x(static_cast<float>(params.self_box_max_x)),
          min_y(static_cast<float>(params.self_box_min_y)),
          max_y(static_cast<float>(params.self_box_max_y)),
          min_z(static_cast<float>(params.self_box_min_z)),
          max_z(static_cast<float>(params.self_box_max_z)) {
        const auto far2 = [](float lo, float hi) { return std::max(lo * lo, hi * hi); };
        reach2 = (far2(min_x, max_x) + far2(min_y, max_y) + far2(min_z, max_z)) * 1.0001f;
    }
    bool empty() const { return !(min_x < max_x && min_y < max_y && min_z < max_z); }
    /// (vx, vy, vz) in the vehicle frame, r2 its squared range. Bitwise &, no branch: the
    /// loops over all points vectorise. False for NaN.
    TRAVEL_INTO_CALLER bool contains(float r2, float vx, float vy, float vz) const {
        return (r2 < reach2) & (vx > min_x) & (vx < max_x) & (vy > min_y) & (vy < max_y) &
               (vz > min_z) & (vz < max_z);
    }
};

/// The points without deskew: validity and rotation per point, branch-free (the loop
/// vectorises). kRotate = false copies the coordinates unchanged (R = I: a product by 1 and sums
/// with 0 would turn -0 into +0). The same values as the general loop in preprocess(), for a
/// frame without levelling: then R = R_mount and the rotated point is in the vehicle frame, where
/// the self box is tested (no second rotation). kSelfBox = false: no box, no test. kNodes: also
/// each point's tri-grid node (out.node, sized n), from the coordinates and validity in
/// registers.
template <bool kRotate, bool kSelfBox, bool kNodes>
TRAVEL_INTO_CALLER std::size_t alignWithoutDeskew(const PointCloud& cloud, const Eigen::Matrix3f& R,
                                                  float min_r2, float max_r2,
                                                  const SelfBox& self_box,
                                                  const NodeLocator& locator, AlignedCloud& out) {
    const std::size_t n = cloud.size();
    const float* cx = cloud.x.data();
    const float* cy = cloud.y.data();
    const float* cz = cloud.z.data();
    float* ox = out.x.data();
    float* oy = out.y.data();
    float* oz = out.z.data();
    uint8_t* valid = out.valid.data();
    uint32_t* node = kNodes ? out.node.data() : nullptr;
    const float r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2), r10 = R(1, 0), r11 = R(1, 1);
    const float r12 = R(1, 2), r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2);
    const SelfBox box = self_box;  // local copies: the stores below cannot alias them
    const NodeLocator nodeOf = locator;
    std::size_t num_valid = 0;
    // The output arrays are not the input cloud's: without this GCC would version the loop on
    // more run-time alias tests than it allows (10) and leave it scalar.
#pragma GCC ivdep
    for (std::size_t i = 0; i < n; ++i) {
        const float px = cx[i], py = cy[i], pz = cz[i];
        const float r2 = px * px + py * py + pz * pz;
        const float ax = kRotate ? r00 * px + r01 * py + r02 * pz : px;
        const float ay = kRotate ? r10 * px + r11 * py + r12 * pz : py;
        const float az = kRotate ? r20 * px + r21 * py + r22 * pz : pz;
        // As in preprocess(): finite (NaN and inf propagate into r2), not zero, in the window,
        // not the own vehicle.
        const bool ok = (std::fabs(r2) <= std::numeric_limits<float>::max()) & (r2 > 0.f) &
                        (r2 >= min_r2) & (r2 <= max_r2) &
                        !(kSelfBox & box.contains(r2, ax, ay, az));
        ox[i] = ok ? ax : 0.f, oy[i] = ok ? ay : 0.f, oz[i] = ok ? az : 0.f;
        valid[i] = ok ? 1 : 0;
        if (kNodes) node[i] = nodeOf(ax, ay, ok);
        num_valid += ok ? 1 : 0;
    }
    return num_valid;
}

/// alignWithoutDeskew() for the frame's case: rotation or copy, self box or none, nodes or none.
TRAVEL_INTO_CALLER std::size_t alignDispatch(bool rotate, bool box, bool nodes,
                                             const PointCloud& cloud, const Eigen::Matrix3f& R,
                                             float min_r2, float max_r2, const SelfBox& self_box,
                                             const NodeLocator& locator, AlignedCloud& out) {
#define TRAVEL_ALIGN(kRotate, kSelfBox, kNodes) \
    alignWithoutDeskew<kRotate, kSelfBox, kNodes>(cloud, R, min_r2, max_r2, self_box, locator, out)
    if (nodes) {
        if (box) return rotate ? TRAVEL_ALIGN(true, true, true) : TRAVEL_ALIGN(false, true, true);
        return rotate ? TRAVEL_ALIGN(true, false, true) : TRAVEL_ALIGN(false, false, true);
    }
    if (box) return rotate ? TRAVEL_ALIGN(true, true, false) : TRAVEL_ALIGN(false, true, false);
    return rotate ? TRAVEL_ALIGN(true, false, false) : TRAVEL_ALIGN(false, false, false);
#undef TRAVEL_ALIGN
}

}  // namespace

Eigen::Matrix3d mountRotation(const Params& params) {
    return (Eigen::AngleAxisd(params.mount_yaw_deg * kDegToRad, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(params.mount_pitch_deg * kDegToRad, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(params.mount_roll_deg * kDegToRad, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

bool isUsableAttitude(const Eigen::Matrix3d& R) {
    return R.allFinite() && (R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-3 &&
           R.determinant() > 0;
}

bool isUsableGravity(const Eigen::Vector3d& g) {
    return g.allFinite() && (g.array() != 0.0).any();
}

Eigen::Matrix3d alignmentRotation(const Params& params, const FrameInput& input) {
    const Eigen::Matrix3d R_mount = mountRotation(params);
    Eigen::Matrix3d R_level = Eigen::Matrix3d::Identity();
    if (params.align_attitude) {
        // As a bad gravity vector below, an attitude that is no rotation (NaN, zero, a
        // reflection) is not used: it would move every point, or all of them to the origin.
        if (input.vehicle_attitude && isUsableAttitude(*input.vehicle_attitude)) {
            R_level = withoutYaw(*input.vehicle_attitude);
        } else if (input.gravity_in_sensor && isUsableGravity(*input.gravity_in_sensor)) {
            // Roll and pitch (ZYX convention, as for vehicle_attitude) that map the measured
            // gravity onto -z: for R = Ry(pitch) Rx(roll), R^T (0,0,-1) is
            // (sin p, -sin r cos p, -cos r cos p). (The minimal rotation between the two
            // vectors would differ from this by a small yaw and rotate the grid.)
            // Only the direction counts: a vector whose squared length leaves the normal doubles
            // (finite, but longer than ~1e154 or shorter than ~1e-154) is scaled by its largest
            // component first, as normalized() would make it zero (upside down: roll -pi).
            Eigen::Vector3d gravity = *input.gravity_in_sensor;
            const double length2 = gravity.squaredNorm();
            if (!(length2 >= std::numeric_limits<double>::min() &&
                  length2 <= std::numeric_limits<double>::max()))
                gravity /= gravity.cwiseAbs().maxCoeff();
            const Eigen::Vector3d g = R_mount * gravity.normalized();
            const double pitch = std::atan2(g.x(), std::hypot(g.y(), g.z()));
            const double roll = std::atan2(-g.y(), -g.z());
            R_level = (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                          .toRotationMatrix();
        }
    }
    return R_level * R_mount;
}

// With AVX2 (CpuDispatch.hpp) the node loop runs 8 points an instruction.
TRAVEL_AVX2_CLONES
void locateNodes(const TriGridGeometry& grid, const AlignedCloud& cloud,
                 std::vector<uint32_t>& node) {
    const std::size_t n = cloud.x.size();
    node.resize(n);
    const float* x = cloud.x.data();
    const float* y = cloud.y.data();
    const uint8_t* valid = cloud.valid.data();
    uint32_t* out = node.data();
    const NodeLocator nodeOf(grid);
    for (std::size_t i = 0; i < n; ++i) out[i] = nodeOf(x[i], y[i], valid[i] != 0);
}

// With AVX2 (CpuDispatch.hpp) the alignment loop runs 8 points an instruction.
TRAVEL_AVX2_CLONES
void preprocess(const PointCloud& cloud, const Params& params, const FrameInput& input,
                AlignedCloud& out, const TriGridGeometry* grid) {
    const std::size_t n = cloud.size();
    out.x.resize(n), out.y.resize(n), out.z.resize(n), out.valid.resize(n);
    out.node.resize(grid ? n : 0);
    out.node_grid = grid ? *grid : TriGridGeometry{};
    out.rotation = alignmentRotation(params, input).cast<float>();
    const Eigen::Matrix3f& R = out.rotation;

    const bool deskew = params.deskew && cloud.hasTime() && input.linear_velocity &&
                        input.angular_velocity && input.linear_velocity->allFinite() &&
                        input.angular_velocity->allFinite();
    const Eigen::Vector3f v =
        deskew ? Eigen::Vector3f(input.linear_velocity->cast<float>()) : Eigen::Vector3f::Zero();
    const Eigen::Vector3f w =
        deskew ? Eigen::Vector3f(input.angular_velocity->cast<float>()) : Eigen::Vector3f::Zero();
    const float w_norm = w.norm();
    const Eigen::Vector3f w_axis =
        w_norm > 0 ? Eigen::Vector3f(w / w_norm) : Eigen::Vector3f::UnitZ();
    const float t_ref = static_cast<float>(input.reference_time);

    const float min_r2 = static_cast<float>(params.min_range * params.min_range);
    const float max_r2 = static_cast<float>(params.max_range * params.max_range);
    const SelfBox self_box(params);
    // Sensor -> vehicle, for the self box; R itself when nothing levels the frame (R_level = I).
    const Eigen::Matrix3d R_mount = mountRotation(params);
    const bool levelled = !(R_mount * R.cast<double>().transpose()).isIdentity(1e-6);
    const Eigen::Matrix3f to_vehicle = R_mount.cast<float>();
    const bool rotate = !R.isIdentity(0.f);
    if (!deskew && (self_box.empty() || !levelled)) {
        // Without a grid the loop finds no nodes; a one-cell stand-in keeps 1 / resolution finite.
        const NodeLocator locator(grid ? *grid : TriGridGeometry{1.f, 1, 0.f});
        out.num_valid = alignDispatch(rotate, !self_box.empty(), grid != nullptr, cloud, R, min_r2,
                                      max_r2, self_box, locator, out);
        return;
    }
    const float r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2), r10 = R(1, 0), r11 = R(1, 1);
    const float r12 = R(1, 2), r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2);
    std::size_t num_valid = 0;
    for (std::size_t i = 0; i < n; ++i) {
        float px = cloud.x[i], py = cloud.y[i], pz = cloud.z[i];
        const float r2 = px * px + py * py + pz * pz;
        // r2 is finite iff all coordinates are (NaN and inf propagate); zero = no return.
        bool self_return = false;  // the body moves with the sensor: tested before deskew
        if (!self_box.empty()) {
            const Eigen::Vector3f v = to_vehicle * Eigen::Vector3f(px, py, pz);
            self_return = self_box.contains(r2, v.x(), v.y(), v.z());
        }
        const bool ok =
            std::isfinite(r2) && r2 > 0.f && r2 >= min_r2 && r2 <= max_r2 && !self_return;
        out.valid[i] = ok;
        num_valid += ok;
        if (!ok) {
            out.x[i] = out.y[i] = out.z[i] = 0.f;
            continue;
        }
        if (deskew) {
            const float dt = cloud.time[i] - t_ref;
            if (std::isfinite(dt)) {
                // Sensor pose at the point's time relative to the reference pose, constant
                // velocity: p_ref = R(w dt) p + v dt.
                const Eigen::Vector3f q =
                    Eigen::AngleAxisf(w_norm * dt, w_axis) * Eigen::Vector3f(px, py, pz) + v * dt;
                px = q.x(), py = q.y(), pz = q.z();
            }
        }
        if (rotate) {
            out.x[i] = r00 * px + r01 * py + r02 * pz;
            out.y[i] = r10 * px + r11 * py + r12 * pz;
            out.z[i] = r20 * px + r21 * py + r22 * pz;
        } else {
            out.x[i] = px, out.y[i] = py, out.z[i] = pz;
        }
        if (deskew) {
            // A bad time (e.g. absolute instead of relative) can move a point anywhere: the
            // moved point must still be inside the range window [min_range, max_range] (and
            // off the origin), else it is invalid.
            const float m2 = out.x[i] * out.x[i] + out.y[i] * out.y[i] + out.z[i] * out.z[i];
            if (!(std::isfinite(m2) && m2 > 0.f && m2 >= min_r2 && m2 <= max_r2)) {
                out.valid[i] = 0, --num_valid;
                out.x[i] = out.y[i] = out.z[i] = 0.f;
            }
        }
    }
    out.num_valid = num_valid;
    if (grid) locateNodes(*grid, out, out.node);
}

bool hasSelfBox(const Params& params) {
    return !SelfBox(params).empty();
}

void markSelfReturns(const PointCloud& cloud, const Params& params, std::vector<uint8_t>& is_self) {
    const SelfBox self_box(params);
    if (self_box.empty()) {
        is_self.clear();
        return;
    }
    const std::size_t n = cloud.size();
    is_self.resize(n);
    const Eigen::Matrix3f to_vehicle = mountRotation(params).cast<float>();
    for (std::size_t i = 0; i < n; ++i) {
        const float px = cloud.x[i], py = cloud.y[i], pz = cloud.z[i];
        const Eigen::Vector3f v = to_vehicle * Eigen::Vector3f(px, py, pz);
        is_self[i] = self_box.contains(px * px + py * py + pz * pz, v.x(), v.y(), v.z());
    }
}

}  // namespace travel
