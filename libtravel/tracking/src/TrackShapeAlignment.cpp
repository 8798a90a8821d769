// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/tracking/TrackShapeAlignment.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace travel {

void ClusterSamples::build(const PointCloud& cloud, const std::vector<uint32_t>& cluster_id,
                           const Eigen::Matrix3f& aligned_rotation,
                           const std::vector<ClusterSummary>& clusters) {
    const std::size_t n = clusters.size();
    offsets_.assign(n + 1, 0);
    stride_.assign(n, 0);
    for (std::size_t c = 0; c < n; ++c) {
        const ClusterSummary& s = clusters[c];
        const bool sampled = s.id == c + 1 && s.num_points >= kMinPoints &&
                             s.obb_extent.x() >= kMinLength && s.obb_extent.x() <= kMaxLength;
        // Every stride-th point: at most kMaxSamples of them, spread over the whole cluster.
        stride_[c] = sampled ? (s.num_points + kMaxSamples - 1) / kMaxSamples : 0;
        const uint32_t count = sampled ? (s.num_points + stride_[c] - 1) / stride_[c] : 0;
        offsets_[c + 1] = offsets_[c] + count;
    }
    points_.resize(offsets_[n]);
    // countdown_[c]: points of cluster c to skip before the next sample (no division per point).
    countdown_.assign(n, 0);
    filled_.assign(n, 0);
    const std::size_t size = std::min(cluster_id.size(), cloud.size());
    for (std::size_t i = 0; i < size; ++i) {
        const uint32_t id = cluster_id[i];
        if (id == 0 || id > n || stride_[id - 1] == 0) continue;
        const uint32_t c = id - 1;
        if (countdown_[c]-- != 0) continue;
        countdown_[c] = stride_[c] - 1;
        if (offsets_[c] + filled_[c] >= offsets_[c + 1]) continue;
        points_[offsets_[c] + filled_[c]++] =
            aligned_rotation * Eigen::Vector3f(cloud.x[i], cloud.y[i], cloud.z[i]);
    }
    // A cluster_id that disagrees with num_points leaves slots unfilled: no sample then.
    uint32_t kept = 0;
    for (std::size_t c = 0; c < n; ++c) {
        const uint32_t from = offsets_[c];
        const uint32_t count = offsets_[c] + filled_[c] == offsets_[c + 1] ? filled_[c] : 0;
        offsets_[c] = kept;
        std::copy(points_.begin() + from, points_.begin() + from + count, points_.begin() + kept);
        kept += count;
    }
    offsets_[n] = kept;
    points_.resize(kept);
}

namespace {

/// Unit eigenvector of the largest eigenvalue of a symmetric 2x2 matrix.
Eigen::Vector2d largestAxis(const Eigen::Matrix2d& m) {
    const double a = m(0, 0), b = m(0, 1), c = m(1, 1);
    const double largest = 0.5 * (a + c) + std::sqrt(0.25 * (a - c) * (a - c) + b * b);
    if (std::abs(b) <= 1e-12) return a >= c ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1);
    return Eigen::Vector2d(b, largest - a).normalized();
}

}  // namespace

void TrackShape::remember(const std::vector<Eigen::Vector3d>& world,
                          const Eigen::Vector2d& position) {
    view_.assign(world.begin(), world.end());
    position_ = position;
    prepared_ = false;
}

void TrackShape::prepare() {
    prepared_ = true;
    const std::vector<Eigen::Vector3d>& world = view_;
    // Sorted along the view's longest axis: a neighbour search then scans only the points
    // within its reach along that axis, a few of the view's (an x-sort would scan them all
    // for a car lying along y).
    Eigen::Vector2d mean(0, 0);
    for (const Eigen::Vector3d& q : world) mean += q.head<2>();
    mean /= double(std::max<std::size_t>(1, world.size()));
    Eigen::Matrix2d spread = Eigen::Matrix2d::Zero();
    for (const Eigen::Vector3d& q : world)
        spread += (q.head<2>() - mean) * (q.head<2>() - mean).transpose();
    axis_ = largestAxis(spread);
    reference_.resize(world.size());
    for (std::size_t i = 0; i < world.size(); ++i)
        reference_[i] = {world[i].head<2>(), {0, 0}, world[i].z(), axis_.dot(world[i].head<2>())};
    std::sort(reference_.begin(), reference_.end(), [](const Point& a, const Point& b) {
        return a.s < b.s ||
               (a.s == b.s && (a.p.x() < b.p.x() || (a.p.x() == b.p.x() && a.p.y() < b.p.y())));
    });
    faces_ = 0;
    // Face normals: the direction of least spread of the neighbours (2-D PCA).
    constexpr double r2 = kNormalRadius * kNormalRadius;
    for (std::size_t i = 0; i < reference_.size(); ++i) {
        const Eigen::Vector2d& p = reference_[i].p;
        Eigen::Vector2d sum(0, 0);
        Eigen::Matrix2d outer = Eigen::Matrix2d::Zero();
        int count = 0;
        double z_min = reference_[i].z, z_max = z_min;
        const auto add = [&](std::size_t j) {
            const Eigen::Vector2d& q = reference_[j].p;
            if ((q - p).squaredNorm() > r2) return;
            sum += q;
            outer += q * q.transpose();
            ++count;
            z_min = std::min(z_min, reference_[j].z);
            z_max = std::max(z_max, reference_[j].z);
        };
        // The neighbours are searched among the kNeighbourWindow points on either side in
        // the order along the axis: on a face, those are its neighbours; a bush's points, with
        // no face, need no more.
        const std::size_t from = i > kNeighbourWindow ? i - kNeighbourWindow : 0;
        const std::size_t to = std::min(reference_.size(), i + kNeighbourWindow + 1);
        for (std::size_t j = from; j < to; ++j) add(j);
        if (count < kMinNeighbours || z_max - z_min < kMinFaceHeight) continue;
        const Eigen::Vector2d mean = sum / count;
        const Eigen::Matrix2d cov = outer / count - mean * mean.transpose();
        // Eigenvalues and the smallest one's eigenvector of a symmetric 2x2 matrix.
        const double a = cov(0, 0), b = cov(0, 1), c = cov(1, 1);
        const double root = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
        const double smallest = 0.5 * (a + c) - root, largest = 0.5 * (a + c) + root;
        if (smallest > kMaxFlatness * largest || largest < kMinFaceSpread * kMinFaceSpread)
            continue;
        const Eigen::Vector2d n = std::abs(b) > 1e-12 ? Eigen::Vector2d(b, smallest - a)
                                  : a < c             ? Eigen::Vector2d(1, 0)
                                                      : Eigen::Vector2d(0, 1);
        reference_[i].normal = n.normalized();
        ++faces_;
    }
}

bool TrackShape::displacement(const std::vector<Eigen::Vector3d>& world,
                              const Eigen::Vector2d& guess, double guess_sigma, Eigen::Vector2d& d,
                              Eigen::Matrix2d* faces_information) {
    if (!prepared_) prepare();
    // Without faces (a bush, a tree: no point has a normal) d would be the guess: not worth
    // the search.
    if (faces_ < kMinFacePoints || world.empty()) return false;
    // Correspondences farther than `reach` are left out (trimmed ICP): a face seen in only one
    // of the two views has no partner. The first reach covers the centroid's slide between two
    // views (the guess); it then halves down to about the point spacing.
    constexpr double kFirstReach = 1.0, kLastReach = 0.3;
    constexpr int kMaxIterations = 8;
    constexpr double kConverged = 1e-3;  // [m]
    constexpr double kRobustScale = 2 * kPointSigma;
    const std::size_t min_inliers = std::max<std::size_t>(8, world.size() / 2);
    // The guess as a prior on d, in units of one point's weight.
    const double prior = (kPointSigma * kPointSigma) / (guess_sigma * guess_sigma);
    Eigen::Vector2d t = guess;
    Eigen::Matrix2d faces = Eigen::Matrix2d::Zero();  // the last iteration's, in point units
    double reach = kFirstReach;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        // Point-to-line normal equations: sum w n n^T t = sum w n n^T (q - r), plus the prior.
        Eigen::Matrix2d A = prior * Eigen::Matrix2d::Identity();
        Eigen::Vector2d b = prior * guess;
        std::size_t inliers = 0;
        const double reach2 = reach * reach;
        for (const Eigen::Vector3d& point : world) {
            const Eigen::Vector2d q = point.head<2>();
            const Eigen::Vector2d p = q - t;  // where q was in the previous view
            const double along = axis_.dot(p);
            auto it = std::lower_bound(reference_.begin(), reference_.end(), along - reach,
                                       [](const Point& r, double s) { return r.s < s; });
            double best = reach2;
            const Point* partner = nullptr;
            for (; it != reference_.end() && it->s <= along + reach; ++it) {
                const double d2 = (it->p - p).squaredNorm();
                if (d2 < best) best = d2, partner = &*it;
            }
            if (!partner) continue;
            ++inliers;
            const Eigen::Vector2d& n = partner->normal;
            if (n.isZero()) continue;
            // Cauchy weight of the point-to-line residual: a point on a face the other view
            // did not see, matched with a parallel face, counts little.
            const double e = n.dot(p - partner->p) / kRobustScale;
            const double w = 1.0 / (1.0 + e * e);
            A += w * n * n.transpose();
            b += w * n * n.dot(q - partner->p);
        }
        if (inliers < min_inliers) return false;
        faces = A - prior * Eigen::Matrix2d::Identity();
        const Eigen::Vector2d next = A.ldlt().solve(b);
        const double step = (next - t).norm();
        t = next;
        if (step < kConverged) {
            if (reach <= kLastReach) break;
            reach = std::max(kLastReach, 0.5 * reach);
        }
    }
    d = t;
    if (faces_information) *faces_information = faces / (kPointSigma * kPointSigma);
    return true;
}

}  // namespace travel
