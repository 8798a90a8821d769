// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Point labels (paper eq. 5). With the ground plane (s, d) of the point's node
// (TerrainModel::groundPlane: TTMF's refitted plane of a traversable node) and the signed
// distance e = s.p + d:
//   e < -outlier_dist          -> Outlier (below-ground returns: reflections, multipath)
//   -outlier_dist <= e < eps3  -> Ground
//   otherwise                  -> NonGround
// Points of non-traversable nodes are NonGround. Invalid points stay Invalid. Every point gets
// exactly one class: nothing is dropped (the reference drops out-of-range and outlier points).
//
// Extension of eq. 5 (issue 14, verges): TTMF (Sec. III-D) averages each corner over the planes
// of all reached nodes around it, weighted by w (eq. 1); the heavy, flat road planes pull the
// corners of a verge node down, so a verge rising 0.1-0.5 m beside the road ends up 0.13-0.3 m
// above its refitted plane (80 % of the missed terrain on the dev frames, 2/3 of it on the
// synthetic verges). With label_with_node_plane, a point of a node the search reached (eq. 2
// verified its own plane against its neighbours) is also ground within eps3 of that own plane,
// e = min(e_refit, e_own), but only when the node is clear: no point stands own_plane_clearance
// or more above its own plane. A car, wall, fence or trunk in the node reaches higher, and the
// bases of such objects must not become ground (the unrestricted option lowered the dev-frame
// object coverage 0.933 -> 0.916); grass, verges and kerbs stay below.
// Sub-node handling: a node straddling the foot or the top of an embankment fits one part of it
// (its lowest seeds, Sec. III-B); a point of a clear node that neither plane accepts is also
// ground within [-outlier_dist, eps3) of the own plane of a clear neighbour near it (see
// onClearNeighbourPlane): its height is judged against the verified surface beside it. The
// same holds for the points of a node too sparse for a plane of its own (labelSparseNode).
// Local clearance (clearance_radius): in a reached node that is not clear, a point may still
// use its node's own plane (not the neighbours' planes: asking them for every non-ground point
// of the buildings and cars in such nodes costs too much time, docs/parameters.md) when nothing
// within clearance_radius of it (xy, points of the node and its neighbours) stands
// own_plane_clearance or more above that plane (NearHighPoints).
// The bases to keep out of the ground lie under their object: a wall's, fence's, post's or
// trunk's straight below its face, a car's sills and tyres under its body; a verge a metre
// from a sign post, a tree or a parked car is not the base of anything (the dev frames' missed
// sidewalk and terrain in such nodes stand next to poles, signs and other structures).
// The own plane's band reaches below the refitted plane too (onOwnPlaneOnly, off-road ditches): a
// point the refitted plane puts more than outlier_dist below it is ground when it lies within
// [-outlier_dist, eps3) of its node's own plane, where that plane may label. TTMF lifts the
// refitted plane of a node at a ditch's bottom toward the track beside it; the outlier band is
// for returns from under a surface the scan sees, and the verified own plane is one.
#include "travel/GroundLabelling.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "CpuDispatch.hpp"

namespace travel {
namespace {

using detail::anyLane;
using detail::kLanes;
using detail::LaneMask;
using detail::Lanes;
using detail::loadLanes;

// classifyByPlaneDistance for kLanes points at once: the classes as lane values.
TRAVEL_INTO_CALLER LaneMask classifyLanes(const Lanes& e, float ground_dist, float outlier_dist) {
    const LaneMask outlier = LaneMask{} + static_cast<int32_t>(PointClass::Outlier);
    const LaneMask ground = LaneMask{} + static_cast<int32_t>(PointClass::Ground);
    const LaneMask non_ground = LaneMask{} + static_cast<int32_t>(PointClass::NonGround);
    return e < -outlier_dist ? outlier : e < ground_dist ? ground : non_ground;
}

// True where the node's own plane, verified by the search (eq. 2), puts a point on the ground,
// -outlier_dist <= e_own < eps3, and the refitted plane does not: above its eps3, or more than
// outlier_dist below it. Below: the outlier band is for returns from under a surface the scan
// sees (reflections, multipath), and the own plane is such a surface; TTMF's corners average
// it with the neighbours' planes (eq. 1), which lift a node at a ditch's bottom toward the
// track or field beside it by 0.3-0.6 m.
template <typename T>
TRAVEL_INTO_CALLER auto onOwnPlaneOnly(const T& e_refit, const T& e_own, float ground_dist,
                                       float outlier_dist) {
    return (e_own >= -outlier_dist) & (e_own < ground_dist) &
           ((e_refit >= ground_dist) | (e_refit < -outlier_dist));
}

// eq. 5's signed distance of a point of a clear reached node (label_with_node_plane): e_own
// where the own plane lies lower (min(e, e_own): a point on either surface is ground) or where
// only it makes the point ground (onOwnPlaneOnly); else the refitted plane's e. e_own is
// ignored below -outlier_dist.
template <typename T>
TRAVEL_INTO_CALLER T foldOwnPlane(const T& e_refit, const T& e_own, float ground_dist,
                                  float outlier_dist) {
    const auto own_lower = (e_own >= -outlier_dist) & (e_own < e_refit);
    const auto own_only = onOwnPlaneOnly(e_refit, e_own, ground_dist, outlier_dist);
    return own_lower | own_only ? e_own : e_refit;
}

thread_local std::vector<uint8_t> clear_scratch;     // per node, reused across frames
thread_local std::vector<int32_t> labelled_scratch;  // nodes whose points get labels

// Points per class. One counter per class, each a branch-free sum over all labels: a
// ++counts[label] per point would chain the increments of equal labels through memory. The sums
// run on 16 byte-wide counters a class (16 labels an instruction; 64-bit counters per label
// made the compiler widen every byte to 8), emptied into the totals every 255 blocks, before
// a byte could overflow.
std::array<std::size_t, 4> classCounts(const std::vector<PointClass>& labels) {
    typedef uint8_t Bytes __attribute__((vector_size(16)));  // one SSE2 register
    const uint8_t* l = reinterpret_cast<const uint8_t*>(labels.data());
    const std::size_t n = labels.size();
    std::size_t ground = 0, non_ground = 0, outlier = 0;
    const Bytes is_ground = Bytes{} + static_cast<uint8_t>(PointClass::Ground);
    const Bytes is_non_ground = Bytes{} + static_cast<uint8_t>(PointClass::NonGround);
    const Bytes is_outlier = Bytes{} + static_cast<uint8_t>(PointClass::Outlier);
    std::size_t i = 0;
    while (n - i >= sizeof(Bytes)) {
        Bytes g = {}, ng = {}, o = {};  // per byte lane: labels of the class seen (<= 255)
        const std::size_t blocks = std::min<std::size_t>((n - i) / sizeof(Bytes), 255);
        for (std::size_t b = 0; b < blocks; ++b, i += sizeof(Bytes)) {
            Bytes v;
            std::memcpy(&v, l + i, sizeof v);
            g -= reinterpret_cast<Bytes>(v == is_ground);  // a match is all ones: -(-1)
            ng -= reinterpret_cast<Bytes>(v == is_non_ground);
            o -= reinterpret_cast<Bytes>(v == is_outlier);
        }
        for (std::size_t k = 0; k < sizeof(Bytes); ++k)
            ground += g[k], non_ground += ng[k], outlier += o[k];
    }
    for (; i < n; ++i) {
        ground += l[i] == static_cast<uint8_t>(PointClass::Ground) ? 1 : 0;
        non_ground += l[i] == static_cast<uint8_t>(PointClass::NonGround) ? 1 : 0;
        outlier += l[i] == static_cast<uint8_t>(PointClass::Outlier) ? 1 : 0;
    }
    return {n - ground - non_ground - outlier, ground, non_ground, outlier};
}

// True when no point of [begin, end) stands own_plane_clearance or more above the plane
// (s, d): nothing taller than grass or a kerb stands on the node. Branch-free max on kLanes
// lanes (one chain of dependent maxima per point would wait for each): the maximum of the lanes'
// maxima is the maximum of all (max(h, v) keeps h for a NaN v, in the lanes as in std::max;
// +0 and -0 compare equal, and either is below the clearance or neither is).
TRAVEL_INTO_CALLER bool clearAbovePlane(const float* x, const float* y, const float* z,
                                        uint32_t begin, uint32_t end, float s0, float s1, float s2,
                                        float d, float clearance) {
    const float lowest = -std::numeric_limits<float>::infinity();
    float highest = lowest;
    uint32_t i = begin;
    if (end - begin >= static_cast<uint32_t>(kLanes)) {
        Lanes high = Lanes{} + lowest;
        for (; i + kLanes <= end; i += kLanes) {
            const Lanes e =
                s0 * loadLanes(x + i) + s1 * loadLanes(y + i) + s2 * loadLanes(z + i) + d;
            high = high < e ? e : high;
        }
        for (int l = 0; l < kLanes; ++l) highest = std::max(highest, high[l]);
    }
    for (; i < end; ++i) highest = std::max(highest, s0 * x[i] + s1 * y[i] + s2 * z[i] + d);
    return highest < clearance;
}

// True when (x, y, z) lies within [-outlier_dist, eps3) of the own plane of a clear neighbour
// of node k whose mean is within 0.75 r (xy): the point continues the verified surface next to
// it (a node straddling the top of an embankment fits its lower part; the plateau beyond is its
// neighbour's plane). A triangle's points lie within 0.53 r of its centroid, so 0.75 r reaches
// about a quarter of a cell past them into node k; a plane extrapolated farther (tilted by a
// bump) reaches the feet of bushes (synthetic meadow: 32 bush points as ground unbounded, 1 at
// 0.75 r).
bool onClearNeighbourPlane(const TriGridField& field, const TerrainModel& model,
                           const std::vector<uint8_t>& clear, int k, float x, float y, float z,
                           float ground_dist, float outlier_dist) {
    const float max_dist = 0.75f * field.resolution();
    const float max_dist2 = max_dist * max_dist;
    const TriGridField::Neighbours& nb = field.neighbours(k);
    for (int m = 0; m < nb.count; ++m) {
        const int j = nb.ids[m];
        if (!clear[j]) continue;
        const TriNode& other = model.nodes[j];
        if ((other.mean.head<2>() - Eigen::Vector2f(x, y)).squaredNorm() > max_dist2) continue;
        const float e =
            other.normal.x() * x + other.normal.y() * y + other.normal.z() * z + other.d;
        if (classifyByPlaneDistance(e, ground_dist, outlier_dist) == PointClass::Ground)
            return true;
    }
    return false;
}

// A node with too few points for a plane (NodeClass::Unknown, far nodes crossed by one or two
// rings) that TTMF left without ground: its points are ground when every one of them lies
// within eps3 of a clear neighbour's own plane (onClearNeighbourPlane) and the node spans less
// than own_plane_clearance in z. All or nothing: one point above the band (the bottom of an
// object) keeps the whole node non-ground.
void labelSparseNode(const TriGridField& field, const TerrainModel& model,
                     const std::vector<uint8_t>& clear, int k, const float* x, const float* y,
                     const float* z, const uint32_t* order, float ground_dist, float outlier_dist,
                     float clearance, std::vector<PointClass>& labels) {
    const TriNode& node = model.nodes[k];
    const uint32_t end = node.begin + node.count;
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (uint32_t i = node.begin; i < end; ++i) lo = std::min(lo, z[i]), hi = std::max(hi, z[i]);
    if (!(hi - lo < clearance)) return;
    for (uint32_t i = node.begin; i < end; ++i)
        if (!onClearNeighbourPlane(field, model, clear, k, x[i], y[i], z[i], ground_dist,
                                   outlier_dist))
            return;
    for (uint32_t i = node.begin; i < end; ++i) labels[order[i]] = PointClass::Ground;
}

// The points standing own_plane_clearance or more above a node's own plane near some of its
// points: a bitmap of cells of side clearance_radius / 2 over the box [lo, hi] of those points
// grown by clearance_radius, filled from the points of the node and of its neighbours
// (TriGridField's 14) whose triangles meet that box. near(x, y) reads the 5 x 5 cells around
// (x, y): true for every such point within clearance_radius, false for every one farther than
// 1.8 clearance_radius. Built for few nodes (frame 0: 58, around 966 points), but from many
// points (the neighbours of poles and walls hold tall points): they are read kLanes at a time,
// the node's own only in the blocks labelWithLocalClearance flags, no neighbour's whose
// triangle misses the bitmap.
class NearHighPoints {
  public:
    /// tall_blocks: per block of kLanes points of node k (from its begin), whether one of them
    /// stands `clearance` or more above its plane (the caller's pass found it already).
    TRAVEL_INTO_CALLER void build(const TriGridField& field, const TerrainModel& model, int k,
                                  Eigen::Vector2f lo, Eigen::Vector2f hi, const float* x,
                                  const float* y, const float* z, float radius, float clearance,
                                  const uint8_t* tall_blocks) {
        lo.array() -= radius, hi.array() += radius;
        // Cells of radius / 2, at most kMaxSide a side (a tiny radius: larger cells, still
        // covering the radius in 2 cells).
        cell_ = std::max(0.5f * radius, (hi - lo).maxCoeff() / static_cast<float>(kMaxSide));
        // Cells on a lattice of the frame (not of the box): near() of a point does not depend
        // on which other points asked.
        origin_ = (lo / cell_).array().floor().matrix() * cell_;
        nx_ = std::min(kMaxSide + 1, static_cast<int>((hi.x() - origin_.x()) / cell_) + 1);
        ny_ = std::min(kMaxSide + 1, static_cast<int>((hi.y() - origin_.y()) / cell_) + 1);
        // One spare cell past the map, which markNode's lanes without a cell write.
        high_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
        inv_cell_ = 1.f / cell_;
        int exponent = 0;
        exact_inverse_ = std::frexp(cell_, &exponent) == 0.5f && std::isfinite(inv_cell_);
        const TriNode& node = model.nodes[k];
        plane_ = {node.normal.x(), node.normal.y(), node.normal.z(), node.d};
        clearance_ = clearance;
        // The bitmap's extent with a cell to spare on each side: a point outside it has no cell
        // (mark() would drop it), so the lanes test it before any division.
        extent_ = {origin_.x() - cell_, origin_.y() - cell_,
                   origin_.x() + static_cast<float>(nx_ + 1) * cell_,
                   origin_.y() + static_cast<float>(ny_ + 1) * cell_};
        markNode(model, k, lo, hi, x, y, z, tall_blocks);
        const TriGridField::Neighbours& nb = field.neighbours(k);
        for (int m = 0; m < nb.count; ++m) markNode(model, nb.ids[m], lo, hi, x, y, z, nullptr);
    }
    bool near(float x, float y) const {
        const int cx = static_cast<int>(std::floor((x - origin_.x()) / cell_));
        const int cy = static_cast<int>(std::floor((y - origin_.y()) / cell_));
        for (int iy = std::max(0, cy - 2); iy <= std::min(ny_ - 1, cy + 2); ++iy)
            for (int ix = std::max(0, cx - 2); ix <= std::min(nx_ - 1, cx + 2); ++ix)
                if (high_[static_cast<std::size_t>(iy) * nx_ + ix]) return true;
        return false;
    }

  private:
    // The tall points of node j, when its triangle meets the box [lo, hi] (with tall_blocks,
    // only in the blocks it flags).
    TRAVEL_INTO_CALLER void markNode(const TerrainModel& model, int j, Eigen::Vector2f lo,
                                     Eigen::Vector2f hi, const float* x, const float* y,
                                     const float* z, const uint8_t* tall_blocks) {
        const std::array<Eigen::Vector2f, 3> corners = model.triangleCorners(j);
        Eigen::Vector2f t_lo = corners[0], t_hi = corners[0];
        for (const Eigen::Vector2f& c : corners) t_lo = t_lo.cwiseMin(c), t_hi = t_hi.cwiseMax(c);
        if ((t_lo.array() > hi.array()).any() || (t_hi.array() < lo.array()).any()) return;
        // A neighbour's triangle clear of the bitmap (its box meets the box, its slanted side
        // does not): none of its points has a cell.
        if (!tall_blocks && !triangleMeetsMap(corners)) return;
        const float s0 = plane_[0], s1 = plane_[1], s2 = plane_[2], d = plane_[3];
        const float clearance = clearance_;
        const float x_lo = extent_[0], y_lo = extent_[1], x_hi = extent_[2], y_hi = extent_[3];
        const TriNode& other = model.nodes[j];
        const uint32_t end = other.begin + other.count;
        const float ox = origin_.x(), oy = origin_.y(), cell = cell_, inv_cell = inv_cell_;
        const bool exact_inverse = exact_inverse_;
        const float cells_x = static_cast<float>(nx_), cells_y = static_cast<float>(ny_);
        const LaneMask row = LaneMask{} + nx_, spare = LaneMask{} + nx_ * ny_;
        uint8_t* high = high_.data();
        // kLanes points at a time. Most blocks hold no tall point inside the extent; in the
        // others, each lane finds its cell as mark() does (the same floats: x * 2^-k is x / 2^k
        // exactly) and every lane stores, the lanes without a cell into the spare cell.
        uint32_t i = other.begin;
        for (uint32_t b = 0; i + kLanes <= end; i += kLanes, ++b) {
            if (tall_blocks && !tall_blocks[b]) continue;
            const Lanes px = loadLanes(x + i), py = loadLanes(y + i);
            const Lanes e = s0 * px + s1 * py + s2 * loadLanes(z + i) + d;
            const LaneMask tall =
                (e >= clearance) & (px >= x_lo) & (px < x_hi) & (py >= y_lo) & (py < y_hi);
            if (!anyLane(tall)) continue;
            Lanes gx = px - ox, gy = py - oy;
            if (exact_inverse)
                gx = gx * inv_cell, gy = gy * inv_cell;
            else
                gx = gx / cell, gy = gy / cell;
            const LaneMask in_map =
                tall & (gx >= 0.f) & (gy >= 0.f) & (gx < cells_x) & (gy < cells_y);
            const Lanes zero = Lanes{};
            gx = in_map ? gx : zero, gy = in_map ? gy : zero;  // converted only in range
            const LaneMask cell_id =
                __builtin_convertvector(gy, LaneMask) * row + __builtin_convertvector(gx, LaneMask);
            const LaneMask at = in_map ? cell_id : spare;
            for (int l = 0; l < kLanes; ++l) high[at[l]] = 1;
        }
        for (; i < end; ++i)
            if (s0 * x[i] + s1 * y[i] + s2 * z[i] + d >= clearance) mark(x[i], y[i]);
    }
    // True unless a side of the triangle separates it from the bitmap's cells (grown by 1 cm:
    // a point on a triangle's side may fall into either node).
    bool triangleMeetsMap(const std::array<Eigen::Vector2f, 3>& corners) const {
        const float grow = 0.01f;
        const Eigen::Vector2f lo(origin_.x() - grow, origin_.y() - grow);
        const Eigen::Vector2f hi(origin_.x() + static_cast<float>(nx_) * cell_ + grow,
                                 origin_.y() + static_cast<float>(ny_) * cell_ + grow);
        for (int e = 0; e < 3; ++e) {
            const Eigen::Vector2f& a = corners[e];
            const Eigen::Vector2f edge = corners[(e + 1) % 3] - a;
            Eigen::Vector2f out(edge.y(), -edge.x());  // away from the third corner
            if (out.dot(corners[(e + 2) % 3] - a) > 0.f) out = -out;
            // The map's corner farthest in along `out`.
            const Eigen::Vector2f nearest(out.x() > 0.f ? lo.x() : hi.x(),
                                          out.y() > 0.f ? lo.y() : hi.y());
            if (out.dot(nearest - a) > 0.f) return false;
        }
        return true;
    }
    TRAVEL_INTO_CALLER void mark(float x, float y) {
        const float gx = (x - origin_.x()) / cell_, gy = (y - origin_.y()) / cell_;
        if (gx >= 0.f && gy >= 0.f && gx < static_cast<float>(nx_) && gy < static_cast<float>(ny_))
            high_[static_cast<std::size_t>(gy) * nx_ + static_cast<std::size_t>(gx)] = 1;
    }

    static constexpr int kMaxSide = 64;
    Eigen::Vector2f origin_{0.f, 0.f};
    float cell_ = 1.f;
    float inv_cell_ = 1.f;       // 1 / cell_
    bool exact_inverse_ = true;  // cell_ a power of two: x * inv_cell_ == x / cell_, bit for bit
    int nx_ = 0, ny_ = 0;
    std::array<float, 4> plane_{};   // the node's own plane (s, d)
    float clearance_ = 0.f;          // own_plane_clearance
    std::array<float, 4> extent_{};  // x_lo, y_lo, x_hi, y_hi: the bitmap and a cell around it
    std::vector<uint8_t> high_;
};

thread_local NearHighPoints near_high_scratch;  // reused across nodes and frames
// Points of a node that only its own plane makes Ground (index in the sorted order, e_own).
thread_local std::vector<std::pair<uint32_t, float>> own_only_scratch;
thread_local std::vector<uint8_t> tall_blocks_scratch;  // per block of the node being labelled

// The points of node k, reached but not clear (a pole, sign, trunk, wall or car stands in it):
// eq. 5 against the refitted plane (s, d), and also ground within [-outlier_dist, eps3) of the
// node's own plane where NearHighPoints finds no point own_plane_clearance above that plane
// within clearance_radius (see the header comment). Heights are the refitted plane's, or the
// own plane's for the points that only it makes ground.
TRAVEL_AVX2_CLONES
void labelWithLocalClearance(const TriGridField& field, const TerrainModel& model, int k,
                             const GroundPlane& ground, const float* sx, const float* sy,
                             const float* sz, const uint32_t* order, float ground_dist,
                             float outlier_dist, float clearance_radius, float clearance,
                             NearHighPoints& near_high,
                             std::vector<std::pair<uint32_t, float>>& own_only,
                             std::vector<uint8_t>& tall_blocks, std::vector<PointClass>& labels,
                             std::vector<float>* heights) {
    const TriNode& node = model.nodes[k];
    const float s0 = ground.normal.x(), s1 = ground.normal.y();
    const float s2 = ground.normal.z(), d = ground.d;
    const float o0 = node.normal.x(), o1 = node.normal.y(), o2 = node.normal.z(), od = node.d;
    own_only.clear();
    // The refitted plane's class for every point; the points that only the own plane makes
    // Ground (onOwnPlaneOnly, as foldOwnPlane in labelPoints) are listed.
    const uint32_t end = node.begin + node.count;
    tall_blocks.resize(node.count / kLanes);
    uint32_t i = node.begin;
    for (uint32_t b = 0; i + kLanes <= end; i += kLanes, ++b) {
        const Lanes x = loadLanes(sx + i), y = loadLanes(sy + i), z = loadLanes(sz + i);
        const Lanes e = s0 * x + s1 * y + s2 * z + d;
        const Lanes e_own = o0 * x + o1 * y + o2 * z + od;
        tall_blocks[b] = anyLane(e_own >= clearance);  // NearHighPoints reads no other block
        const LaneMask label = classifyLanes(e, ground_dist, outlier_dist);
        for (int l = 0; l < kLanes; ++l) labels[order[i + l]] = static_cast<PointClass>(label[l]);
        if (heights)
            for (int l = 0; l < kLanes; ++l) (*heights)[order[i + l]] = e[l];
        const LaneMask own_only_lanes = onOwnPlaneOnly(e, e_own, ground_dist, outlier_dist);
        if (anyLane(own_only_lanes))
            for (int l = 0; l < kLanes; ++l)
                if (own_only_lanes[l]) own_only.push_back({i + l, e_own[l]});
    }
    for (; i < end; ++i) {
        const float e = s0 * sx[i] + s1 * sy[i] + s2 * sz[i] + d;
        const float e_own = o0 * sx[i] + o1 * sy[i] + o2 * sz[i] + od;
        labels[order[i]] = classifyByPlaneDistance(e, ground_dist, outlier_dist);
        if (heights) (*heights)[order[i]] = e;
        if (onOwnPlaneOnly(e, e_own, ground_dist, outlier_dist)) own_only.push_back({i, e_own});
    }
    if (own_only.empty()) return;
    Eigen::Vector2f lo(sx[own_only[0].first], sy[own_only[0].first]), hi = lo;
    for (const auto& [j, e_own] : own_only)
        lo = lo.cwiseMin(Eigen::Vector2f(sx[j], sy[j])),
        hi = hi.cwiseMax(Eigen::Vector2f(sx[j], sy[j]));
    near_high.build(field, model, k, lo, hi, sx, sy, sz, clearance_radius, clearance,
                    tall_blocks.data());
    for (const auto& [j, e_own] : own_only) {
        if (near_high.near(sx[j], sy[j])) continue;
        labels[order[j]] = PointClass::Ground;
        if (heights) (*heights)[order[j]] = e_own;
    }
}

}  // namespace

// With AVX2 (CpuDispatch.hpp) the per-point loops run 8 points an instruction.
TRAVEL_AVX2_CLONES
std::array<std::size_t, 4> labelPoints(const TriGridField& field, const AlignedCloud& cloud,
                                       const Params& params, const TerrainModel& model,
                                       std::vector<PointClass>& labels,
                                       std::vector<float>* heights) {
    const std::size_t n = cloud.valid.size();
    if (heights) heights->assign(n, std::numeric_limits<float>::infinity());
    labels.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        labels[i] = cloud.valid[i] ? PointClass::NonGround : PointClass::Invalid;

    const float* sx = field.sx().data();
    const float* sy = field.sy().data();
    const float* sz = field.sz().data();
    const uint32_t* order = field.order().data();
    const float ground_dist = static_cast<float>(params.ground_dist);
    const float outlier_dist = static_cast<float>(params.outlier_dist);
    const float own_plane_clearance = static_cast<float>(params.own_plane_clearance);
    const float clearance_radius = static_cast<float>(params.clearance_radius);
    const bool local_clearance = params.label_with_node_plane && clearance_radius > 0.f;
    // Reached nodes whose own plane may label points (see the header comment), and the nodes
    // whose points the loop below labels (one pass over the nodes with points, embed()'s list,
    // ascending: most nodes are empty, and their cache lines are not read).
    std::vector<uint8_t>& clear = clear_scratch;
    clear.assign(model.nodes.size(), 0);
    std::vector<int32_t>& labelled = labelled_scratch;
    labelled.clear();
    const bool with_node_plane = params.label_with_node_plane;
    for (const uint32_t occupied : field.occupiedNodes()) {
        const int k = static_cast<int>(occupied);
        const TriNode& node = model.nodes[k];
        if (with_node_plane && node.reached)
            clear[k] =
                clearAbovePlane(sx, sy, sz, node.begin, node.begin + node.count, node.normal.x(),
                                node.normal.y(), node.normal.z(), node.d, own_plane_clearance);
        if (node.traversable || (with_node_plane && node.node_class == NodeClass::Unknown))
            labelled.push_back(k);
    }
    for (const int32_t k : labelled) {
        const TriNode& node = model.nodes[k];
        const std::optional<GroundPlane> ground = model.groundPlane(k);
        if (!ground) {  // an Unknown node without ground (see the list above)
            labelSparseNode(field, model, clear, k, sx, sy, sz, order, ground_dist, outlier_dist,
                            own_plane_clearance, labels);
            continue;
        }
        const float s0 = ground->normal.x(), s1 = ground->normal.y();
        const float s2 = ground->normal.z(), d = ground->d;
        // The node's own plane, when the search verified it: a point on either surface is
        // ground (foldOwnPlane).
        const float o0 = node.normal.x(), o1 = node.normal.y(), o2 = node.normal.z();
        const uint32_t end = node.begin + node.count;
        const bool own = clear[k] != 0;
        if (!own && local_clearance && node.reached) {  // see labelWithLocalClearance
            labelWithLocalClearance(field, model, k, *ground, sx, sy, sz, order, ground_dist,
                                    outlier_dist, clearance_radius, own_plane_clearance,
                                    near_high_scratch, own_only_scratch, tall_blocks_scratch,
                                    labels, heights);
            continue;
        }
        const float od = own ? node.d : std::numeric_limits<float>::infinity();
        // kLanes points at a time: the same floats as the scalar loop below (the same products
        // and sums in the same order, no FMA) and the same selections; only the points of a
        // clear node that eq. 5 leaves non-ground ask the neighbours, one by one.
        uint32_t i = node.begin;
        for (; i + kLanes <= end; i += kLanes) {
            const Lanes x = loadLanes(sx + i), y = loadLanes(sy + i), z = loadLanes(sz + i);
            const Lanes e_refit = s0 * x + s1 * y + s2 * z + d;
            const Lanes e_own = o0 * x + o1 * y + o2 * z + od;
            const Lanes e = foldOwnPlane(e_refit, e_own, ground_dist, outlier_dist);
            const LaneMask label = classifyLanes(e, ground_dist, outlier_dist);
            // Most blocks have no point for the neighbours' planes: a plain scatter of labels.
            bool ask = false;
            if (own)
                for (int l = 0; l < kLanes; ++l)
                    ask |= label[l] == static_cast<int32_t>(PointClass::NonGround);
            if (!ask) {
                for (int l = 0; l < kLanes; ++l)
                    labels[order[i + l]] = static_cast<PointClass>(label[l]);
            } else {
                for (int l = 0; l < kLanes; ++l) {
                    PointClass c = static_cast<PointClass>(label[l]);
                    const uint32_t j = i + static_cast<uint32_t>(l);
                    if (c == PointClass::NonGround &&
                        onClearNeighbourPlane(field, model, clear, k, sx[j], sy[j], sz[j],
                                              ground_dist, outlier_dist))
                        c = PointClass::Ground;
                    labels[order[j]] = c;
                }
            }
            if (heights)
                for (int l = 0; l < kLanes; ++l) (*heights)[order[i + l]] = e[l];
        }
        for (; i < end; ++i) {
            const float e_refit = s0 * sx[i] + s1 * sy[i] + s2 * sz[i] + d;
            const float e_own = o0 * sx[i] + o1 * sy[i] + o2 * sz[i] + od;
            const float e = foldOwnPlane(e_refit, e_own, ground_dist, outlier_dist);
            PointClass label = classifyByPlaneDistance(e, ground_dist, outlier_dist);
            if (own && label == PointClass::NonGround &&
                onClearNeighbourPlane(field, model, clear, k, sx[i], sy[i], sz[i], ground_dist,
                                      outlier_dist))
                label = PointClass::Ground;
            labels[order[i]] = label;
            if (heights) (*heights)[order[i]] = e;
        }
    }
    return classCounts(labels);
}

}  // namespace travel
