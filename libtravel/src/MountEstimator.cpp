// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/MountEstimator.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "CpuDispatch.hpp"
#include "FastAtan2.hpp"
#include "Prefault.hpp"

namespace travel {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
// Candidate bins: 2 deg sectors x 1 m rings up to 40 m (farther ground is sparse and may bend).
constexpr int kSectors = 180;
constexpr double kBinLength = 1.0;
constexpr double kMaxCandidateRange = 40.0;
constexpr int kRansacIterations = 300;
constexpr double kRansacInlierDist = 0.1;      // m, range noise plus small unevenness
constexpr double kRefitDist[] = {0.1, 0.06};   // m, successive least-squares bands
constexpr double kMaxTiltFromPriorDeg = 30.0;  // steeper planes are walls, not ground
constexpr std::size_t kMinInliers = 100;

// The bins of a point at (u, v): hypot(u, v) / kBinLength and the azimuth in sectors,
// (atan2(v, u) + pi) / 2 pi * kSectors; only their integer parts are used. The libm calls cost
// more than the rest of the estimate, so cheap approximations are used wherever their error
// cannot change the integer part (the exact call is made within kEdge of a bin edge, or for
// NaN): the same bins as the exact calls, at a fraction of the cost.
double ringPosition(double u, double v) {
    constexpr double kEdge = 1e-9;  // sqrt(u^2 + v^2) is within a few ulps of hypot(u, v)
    const double approx = std::sqrt(u * u + v * v) / kBinLength;
    const double frac = approx - std::floor(approx);
    if (frac >= kEdge && frac <= 1.0 - kEdge) return approx;
    return std::hypot(u, v) / kBinLength;
}
double sectorPosition(double u, double v) {
    // fastAtan2's error, and float rounding of u and v (1e-7 rad), in sectors.
    constexpr double kEdge = 2 * detail::kFastAtan2MaxError / (2 * M_PI) * kSectors;
    const double approx = (detail::fastAtan2(static_cast<float>(v), static_cast<float>(u)) + M_PI) /
                          (2 * M_PI) * kSectors;
    const double frac = approx - std::floor(approx);
    if (frac >= kEdge && frac <= 1.0 - kEdge) return approx;
    return (std::atan2(v, u) + M_PI) / (2 * M_PI) * kSectors;
}

constexpr int32_t kNoBin = -1;     // outside [min_range, max_range], NaN, or excluded
constexpr int32_t kExactBin = -2;  // near a bin edge: binned with the exact calls

// a.p as Eigen's a.dot(p) computes it: (a0 p0 + a1 p1) + a2 p2.
TRAVEL_INTO_CALLER double dot3(const double* a, double x, double y, double z) {
    return (a[0] * x + a[1] * y) + a[2] * z;
}
TRAVEL_INTO_CALLER double planeDistance(const double* n, double d, double x, double y, double z) {
    return dot3(n, x, y, z) + d;
}

// The bin of every stride-th point i = k stride (in bins[k]) as ringPosition() and
// sectorPosition() give it (the same approximations and edge margins), without branches:
// kNoBin for points left out, kExactBin for points within the approximations' error of a bin
// edge (the caller bins those with the exact calls). u, v and r^2 are computed as Eigen's dot
// products and squaredNorm compute them.
TRAVEL_AVX2_CLONES
void approximateBins(const float* xs, const float* ys, const float* zs, const uint8_t* excluded,
                     std::size_t m, std::size_t stride, const double* e1, const double* e2,
                     double min_r2, double max_r2, int num_rings, int32_t* bins) {
    constexpr double kRingEdge = 1e-9;
    constexpr double kSectorEdge = 2 * detail::kFastAtan2MaxError / (2 * M_PI) * kSectors;
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = k * stride;
        const double x = xs[i], y = ys[i], z = zs[i];
        const double r2 = (x * x + y * y) + z * z;
        const bool used = (r2 >= min_r2) & (r2 <= max_r2) & !(excluded && excluded[i]);
        const double u = dot3(e1, x, y, z), v = dot3(e2, x, y, z);
        // Points left out get 0 (no NaN or out-of-range value converted to int).
        const double ring = used ? std::sqrt(u * u + v * v) / kBinLength : 0.0;
        const float angle = detail::fastAtan2(static_cast<float>(v), static_cast<float>(u));
        const double sector = used ? (angle + M_PI) / (2 * M_PI) * kSectors : 0.0;
        const int ring_index = static_cast<int>(ring), sector_index = static_cast<int>(sector);
        const double ring_frac = ring - ring_index, sector_frac = sector - sector_index;
        const bool exact = (ring_frac < kRingEdge) | (ring_frac > 1.0 - kRingEdge) |
                           (sector_frac < kSectorEdge) | (sector_frac > 1.0 - kSectorEdge);
        const int bin =
            std::min(num_rings - 1, ring_index) * kSectors + std::min(sector_index, kSectors - 1);
        bins[k] = !used ? kNoBin : (exact ? kExactBin : bin);
    }
}

// How many of the m points are within `band` of the plane n.p + d = 0 (RANSAC's inlier count).
TRAVEL_AVX2_CLONES
std::size_t countWithin(const double* xs, const double* ys, const double* zs, std::size_t m,
                        const double* normal, double d, double band) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < m; ++i)
        count += std::fabs(planeDistance(normal, d, xs[i], ys[i], zs[i])) < band;
    return count;
}

// The used points i = k stride (bins[k] != kNoBin) within `band` of the plane, in input order,
// into `selected`; returns how many.
TRAVEL_AVX2_CLONES
std::size_t selectWithin(const float* xs, const float* ys, const float* zs, const int32_t* bins,
                         std::size_t m, std::size_t stride, const double* normal, double d,
                         double band, int32_t* selected) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = k * stride;
        const double dist = planeDistance(normal, d, xs[i], ys[i], zs[i]);
        selected[count] = static_cast<int32_t>(i);
        count += (bins[k] != kNoBin) & (std::fabs(dist) < band);
    }
    return count;
}

// Plane n.p + d = 0 through the points within `band` of the previous plane (PCA); false when
// fewer than 3 points.
template <class ForEachPoint>
bool refitPlane(ForEachPoint&& for_each, Eigen::Vector3d& n, double& d, double band,
                std::size_t& count) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    // The sums of p p^T's six distinct entries, in scalars (Eigen's `outer += p * p.transpose()`
    // goes through a temporary in memory and stalls on it; each entry is the same product and
    // sum either way).
    double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
    count = 0;
    for_each([&](const Eigen::Vector3d& p) {
        if (std::fabs(n.dot(p) + d) >= band) return;
        sum += p;
        xx += p.x() * p.x(), xy += p.x() * p.y(), xz += p.x() * p.z();
        yy += p.y() * p.y(), yz += p.y() * p.z(), zz += p.z() * p.z();
        ++count;
    });
    if (count < 3) return false;
    Eigen::Matrix3d outer;
    outer << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    const Eigen::Vector3d mean = sum / static_cast<double>(count);
    const Eigen::Matrix3d cov = outer / static_cast<double>(count) - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Eigen::Vector3d normal = eig.eigenvectors().col(0);  // smallest eigenvalue first
    if (normal.dot(n) < 0) normal = -normal;
    n = normal;
    d = -n.dot(mean);
    return true;
}

// Thousands separated by commas: 12345 -> "12,345".
std::string grouped(std::size_t value) {
    std::string digits = std::to_string(value), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string fixed2(double value) {
    if (std::fabs(value) < 0.005) value = 0.0;  // "0.00", not "-0.00"
    char text[32];
    std::snprintf(text, sizeof(text), "%.2f", value);
    return text;
}

}  // namespace

MountNote estimatedMountNote(const Params& configured, const GroundPlaneEstimate& ground,
                             std::size_t frame) {
    MountNote note;
    note.kind = MountNote::Kind::Estimated;
    note.frame = frame;
    note.ground = ground;
    std::string what;
    const auto add = [&](const std::string& text) { what += (what.empty() ? "" : ", ") + text; };
    if (configured.sensor_height.isAuto())
        add("sensor_height auto: " + fixed2(autoSensorHeight(ground)) + " m");
    if (configured.mount_roll_deg.isAuto())
        add("mount_roll_deg auto: " + fixed2(ground.roll_deg) + " deg");
    if (configured.mount_pitch_deg.isAuto())
        add("mount_pitch_deg auto: " + fixed2(ground.pitch_deg) + " deg");
    note.message = what + " (from frame " + std::to_string(frame) + ", " +
                   grouped(ground.num_inliers) + " ground points)";
    return note;
}

MountNote notFoundMountNote(const Params& configured, std::size_t frame) {
    MountNote note;
    note.kind = MountNote::Kind::NotFound;
    note.frame = frame;
    note.message = "no ground plane found in frames 0 to " + std::to_string(frame) +
                   ": the auto mount values keep their fallbacks (sensor_height " +
                   fixed2(configured.sensor_height.value) + " m, mount_roll_deg " +
                   fixed2(configured.mount_roll_deg.value) + ", mount_pitch_deg " +
                   fixed2(configured.mount_pitch_deg.value) + "); set them in the configuration";
    return note;
}

MountNote checkedMountNote(const Params& configured, const GroundPlaneEstimate& ground,
                           const Eigen::Matrix3d& sensor_to_aligned, std::size_t frame,
                           const MountAnglesSource& angles) {
    MountNote note;
    if (!ground.found) return note;
    std::string what;
    const AutoReal& h = configured.sensor_height;
    // A base frame is said below; a height to set would be the base frame's (0 or less).
    const bool base_frame = ground.height < kBaseFrameMaxHeight;
    if (!base_frame && !h.isAuto() && std::fabs(ground.height - h.value) > kMountHeightTolerance) {
        what = "sensor_height is " + fixed2(h.value) + " m but the ground is " +
               fixed2(ground.height) +
               " m below the sensor: set sensor_height: " + fixed2(ground.height) + " or auto";
    }
    const AutoReal& roll = configured.mount_roll_deg;
    const AutoReal& pitch = configured.mount_pitch_deg;
    const double tilt_deg =
        std::acos(std::clamp((sensor_to_aligned * ground.normal).z(), -1.0, 1.0)) * kRadToDeg;
    if ((!roll.isAuto() || !pitch.isAuto()) && tilt_deg > kMountTiltToleranceDeg) {
        what += std::string(what.empty() ? "" : "; ") + "the ground is tilted by " +
                fixed2(tilt_deg) + " deg with mount_roll_deg " + fixed2(roll.value) +
                ", mount_pitch_deg " + fixed2(pitch.value);
        if (angles.name.empty()) {
            what += ": set mount_roll_deg: " + fixed2(ground.roll_deg) +
                    ", mount_pitch_deg: " + fixed2(ground.pitch_deg) + " or auto";
        } else {
            what += " from " + angles.name + ": correct it to roll " + fixed2(ground.roll_deg) +
                    " deg, pitch " + fixed2(ground.pitch_deg) + " deg" +
                    (angles.remedy.empty() ? "" : ", or " + angles.remedy);
        }
    }
    if (base_frame) {
        what += std::string(what.empty() ? "" : "; ") + "the points' origin is within " +
                fixed2(kBaseFrameMaxHeight) + " m of the ground (" + fixed2(ground.height) +
                " m above it): a base frame, not the sensor's; objects split there, since their "
                "ranges and ring elevations are measured from the origin: give the points in the "
                "sensor frame and its height above the ground as sensor_height";
    }
    if (what.empty()) return note;
    note.kind = MountNote::Kind::Mismatch;
    note.frame = frame;
    note.ground = ground;
    // A check may use every stride-th point only (Pipeline): say so, the count is of those.
    note.message = what + " (measured on frame " + std::to_string(frame) + ", " +
                   grouped(ground.num_inliers) + " ground points" +
                   (ground.stride > 1 ? " in a 1-in-" + std::to_string(ground.stride) + " sample"
                                      : std::string()) +
                   ")";
    return note;
}

void mountAnglesFromNormal(const Eigen::Vector3d& n, double& roll_deg, double& pitch_deg) {
    roll_deg = std::atan2(n.y(), n.z()) * kRadToDeg;
    pitch_deg = std::atan2(-n.x(), std::hypot(n.y(), n.z())) * kRadToDeg;
}

double firstGroundRingRadius(double sensor_height, double lowest_elevation_deg,
                             double tgf_resolution) {
    if (!(lowest_elevation_deg < 0.0) || !(sensor_height > 0.0)) return 0.0;
    return sensor_height / std::tan(-lowest_elevation_deg / kRadToDeg) + 0.5 * tgf_resolution;
}

void MountEstimator::reserve(std::size_t points) {
    const std::size_t bins = static_cast<std::size_t>(kSectors) *
                             static_cast<std::size_t>(std::ceil(kMaxCandidateRange / kBinLength));
    detail::prefault(bin_point_, bins), detail::prefault(bin_height_, bins);
    detail::prefault(candidates_, bins), detail::prefault(candidate_x_, bins);
    detail::prefault(candidate_y_, bins), detail::prefault(candidate_z_, bins);
    detail::prefault(point_bin_, points), detail::prefault(selected_, points);
}

GroundPlaneEstimate MountEstimator::estimate(const PointCloud& cloud,
                                             const Eigen::Vector3d& prior_up, double min_range,
                                             double max_range, const uint8_t* excluded,
                                             std::size_t stride) {
    GroundPlaneEstimate out;
    const Eigen::Vector3d up = prior_up.normalized();
    // Any two directions completing `up` to an orthonormal basis.
    const Eigen::Vector3d e1 = up.unitOrthogonal();
    const Eigen::Vector3d e2 = up.cross(e1);
    const double max_r = std::min(max_range, kMaxCandidateRange);
    const int num_rings = static_cast<int>(std::ceil(max_r / kBinLength));
    bin_point_.assign(static_cast<std::size_t>(kSectors) * std::max(num_rings, 1), -1);
    bin_height_.assign(bin_point_.size(), 0.f);

    const std::size_t n = cloud.size();
    const double min_r2 = min_range * min_range, max_r2 = max_r * max_r;
    stride = std::max<std::size_t>(stride, 1);
    const std::size_t m = (n + stride - 1) / stride;  // points used: i = k stride, k < m
    point_bin_.resize(m);
    approximateBins(cloud.x.data(), cloud.y.data(), cloud.z.data(), excluded, m, stride, e1.data(),
                    e2.data(), min_r2, max_r2, num_rings, point_bin_.data());
    for (std::size_t k = 0; k < m; ++k) {
        int32_t bin = point_bin_[k];
        if (bin == kNoBin) continue;
        const std::size_t i = k * stride;
        const Eigen::Vector3d p(cloud.x[i], cloud.y[i], cloud.z[i]);
        if (bin == kExactBin) {
            const double u = e1.dot(p), v = e2.dot(p);
            const int ring = std::min(num_rings - 1, static_cast<int>(ringPosition(u, v)));
            const int sector = std::clamp(static_cast<int>(sectorPosition(u, v)), 0, kSectors - 1);
            bin = ring * kSectors + sector;
        }
        const double h = up.dot(p);
        if (bin_point_[bin] < 0 || h < bin_height_[bin]) {
            bin_point_[bin] = static_cast<int32_t>(i);
            bin_height_[bin] = static_cast<float>(h);
        }
    }
    candidates_.clear();
    for (const int32_t i : bin_point_) {
        if (i >= 0) candidates_.emplace_back(cloud.x[i], cloud.y[i], cloud.z[i]);
    }
    out.num_candidates = candidates_.size();
    if (candidates_.size() < 3) return out;
    candidate_x_.resize(candidates_.size()), candidate_y_.resize(candidates_.size());
    candidate_z_.resize(candidates_.size());
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
        candidate_x_[k] = candidates_[k].x(), candidate_y_[k] = candidates_[k].y();
        candidate_z_[k] = candidates_[k].z();
    }

    // RANSAC, seeded: a 64-bit LCG (Knuth's MMIX constants), the same on every platform.
    uint64_t state = 0x9E3779B97F4A7C15ull;
    const auto next = [&](std::size_t bound) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<std::size_t>((state >> 33) % bound);
    };
    const double min_up = std::cos(kMaxTiltFromPriorDeg / kRadToDeg);
    std::size_t best_count = 0;
    Eigen::Vector3d best_n = up;
    double best_d = 0;
    const std::size_t num_candidates = candidates_.size();
    for (int it = 0; it < kRansacIterations; ++it) {
        const Eigen::Vector3d& a = candidates_[next(num_candidates)];
        const Eigen::Vector3d& b = candidates_[next(num_candidates)];
        const Eigen::Vector3d& c = candidates_[next(num_candidates)];
        Eigen::Vector3d normal = (b - a).cross(c - a);
        const double len = normal.norm();
        if (!(len > 1e-9)) continue;
        normal /= len;
        if (normal.dot(up) < 0) normal = -normal;
        if (normal.dot(up) < min_up) continue;
        const double d = -normal.dot(a);
        // The origin above the ground, or near it (a base frame, which the check reports:
        // kBaseFrameMaxHeight), not under it.
        if (!(d > -kBaseFrameMaxHeight)) continue;
        const std::size_t count =
            countWithin(candidate_x_.data(), candidate_y_.data(), candidate_z_.data(),
                        num_candidates, normal.data(), d, kRansacInlierDist);
        if (count > best_count) best_count = count, best_n = normal, best_d = d;
    }
    if (best_count < 3) return out;

    const auto candidate_points = [&](auto&& visit) {
        for (const auto& p : candidates_) visit(p);
    };
    std::size_t count = 0;
    if (!refitPlane(candidate_points, best_n, best_d, kRansacInlierDist, count)) return out;
    // The refits on all used points: those within the band listed first (a loop without
    // branches), then summed in input order.
    selected_.resize(m);
    for (const double band : kRefitDist) {
        const std::size_t num_selected =
            selectWithin(cloud.x.data(), cloud.y.data(), cloud.z.data(), point_bin_.data(), m,
                         stride, best_n.data(), best_d, band, selected_.data());
        const auto points_within = [&](auto&& visit) {
            for (std::size_t k = 0; k < num_selected; ++k) {
                const int32_t i = selected_[k];
                visit(Eigen::Vector3d(cloud.x[i], cloud.y[i], cloud.z[i]));
            }
        };
        if (!refitPlane(points_within, best_n, best_d, band, count)) return out;
    }
    out.normal = best_n;
    out.height = best_d;
    out.num_inliers = count;
    out.stride = stride;
    mountAnglesFromNormal(best_n, out.roll_deg, out.pitch_deg);
    out.found = count * stride >= kMinInliers && best_d > -kBaseFrameMaxHeight;
    return out;
}

}  // namespace travel
