// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Breadth-first traversable graph search (B-TGS, paper Sec. III-C).
//
// Decisions where the paper and the reference code leave room (travel-algorithm.md Sec. 3):
// * Start node: the terrain node of highest weight whose mean is within seed_search_radius
//   (xy) of the sensor and within seed_height_tolerance of -sensor_height. If there is
//   none, nothing is traversable: a scan without plausible ground under the sensor (e.g. every
//   point above it) must not produce ground.
// * Edge test (eq. 2) is symmetric, and a node is reached if ANY reached neighbour has a
//   traversable edge to it. A failed edge does not mark the node as rejected, so the result is
//   the connected component of the seed in the graph of traversable edges: independent of the
//   visiting order (the reference rejects on the first failed edge, so order matters).
// * Epsilons (our reading of eq. 2, chosen on SemanticKITTI, see README "Design decisions"):
//   eps1 bounds the displacement of one node's mean along the other's normal (convexity /
//   concavity: |s_i.d| < |d| sin(eps1) and |s_j.d| < |d| sin(eps1)); eps2 bounds how fast
//   normals may turn with distance (|s_i.s_j| > 1 - sin(|d| eps2)). With eps1 = 0.03 a
//   15 cm kerb between node means 4 m apart (0.0375) fails, as do walls; the looser reading
//   (eps = 0.1 on the displacement) accepts kerbs up to 0.4 m.
// * Re-seeding: the reference accepts every unreached terrain node as a new root, untested,
//   so the convexity test only trims the first component. We re-seed only from terrain nodes
//   that are plausible ground: the planes of the candidate and of its nearest reached node
//   (xy distance between means, at most reseed_max_distance) must agree within
//   reseed_max_height_diff at the midpoint between the two means (a ramp's plane meets the
//   flat plane at the foot of the ramp; a platform or roof is offset everywhere), and the
//   candidate's weight must be at least reseed_min_weight_ratio of the start node's.
//   Candidates are tried in decreasing weight (ties: lower index), repeatedly until none is
//   accepted, so the result is deterministic. Each accepted candidate roots a new B-TGS.
#include "travel/TraversableGraphSearch.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "Prefault.hpp"

namespace travel {

namespace {
// Eq. 2 with sin(eps1) computed once per frame, not once per edge. The two offset tests come
// first: they need no sin, and most failing edges (walls, kerbs) fail them.
struct EdgeTest {
    double eps2;
    float sin_eps1;
    explicit EdgeTest(const Params& params)
        : eps2(params.eps2), sin_eps1(static_cast<float>(std::sin(params.eps1))) {}
    template <class Node>  // TriNode or HotNode: reads mean and normal
    bool operator()(const Node& a, const Node& b) const {
        const Eigen::Vector3f d = b.mean - a.mean;
        const float len = d.norm();
        if (!(len > 0.f)) return true;  // coincident means: nothing separates the nodes
        const float max_offset = len * sin_eps1;
        if (!(std::fabs(a.normal.dot(d)) < max_offset && std::fabs(b.normal.dot(d)) < max_offset))
            return false;
        const float normal_turn =
            static_cast<float>(std::sin(std::min(static_cast<double>(len) * eps2, M_PI / 2)));
        return std::fabs(a.normal.dot(b.normal)) > 1.f - normal_turn;
    }
};

// Calls visit(i) for every set bit i in [lo, hi] of the bit array `bits`, in increasing i.
template <class Visit>
void forEachSetBit(const uint64_t* bits, int lo, int hi, Visit&& visit) {
    if (lo > hi) return;
    const int first = lo / 64, last = hi / 64;
    for (int w = first; w <= last; ++w) {
        uint64_t word = bits[w];
        if (w == first) word &= ~uint64_t{0} << (lo % 64);
        if (w == last && hi % 64 != 63) word &= (uint64_t{1} << (hi % 64 + 1)) - 1;
        for (; word != 0; word &= word - 1) visit(64 * w + __builtin_ctzll(word));
    }
}
}  // namespace

bool isTraversableEdge(const TriNode& a, const TriNode& b, const Params& params) {
    return EdgeTest(params)(a, b);
}

void TraversableGraphSearch::reserve(const TriGridField& field) {
    const std::size_t nodes = static_cast<std::size_t>(field.numNodes());
    detail::prefault(reached_, nodes), detail::prefault(reached_where_, nodes);
    detail::prefault(candidates_, nodes), detail::prefault(nearest_, nodes);
    detail::prefault(candidate_keys_, nodes);
    detail::prefault(node_reached_, nodes), detail::prefault(node_xy_, nodes);
    detail::prefault(terrain_slot_, nodes), detail::prefault(hot_, nodes);
    detail::prefault(terrain_, nodes);
    const int n = field.cellsPerSide();
    const std::size_t bit_words =
        static_cast<std::size_t>(n) * static_cast<std::size_t>((n + 63) / 64);
    detail::prefault(row_cells_, bit_words), detail::prefault(col_cells_, bit_words);
}

void TraversableGraphSearch::markReached(int node, int16_t component, const TriGridField& field,
                                         TerrainModel& model) {
    TriNode& reached = model.nodes[node];
    reached.reached = true;
    reached.component = component;
    node_reached_[node] = 1;
    const Eigen::Vector2f xy = hot_[terrain_slot_[node]].mean.head<2>();
    node_xy_[node] = xy;
    const int cell = node / 4, n = field.cellsPerSide();
    const int ix = cell % n, iy = cell / n;
    row_cells_[static_cast<std::size_t>(iy) * words_ + ix / 64] |= uint64_t{1} << (ix % 64);
    col_cells_[static_cast<std::size_t>(ix) * words_ + iy / 64] |= uint64_t{1} << (iy % 64);
    reached_.push_back(node);
    reached_where_.push_back({xy, ix, iy});
}

void TraversableGraphSearch::searchFrom(int root, int16_t component, const TriGridField& field,
                                        const Params& params, TerrainModel& model) {
    // reached_ is the queue of every search of the frame: this one's nodes are appended.
    std::size_t head = reached_.size();
    const EdgeTest traversable(params);
    markReached(root, component, field, model);
    for (; head < reached_.size(); ++head) {
        const int i = reached_[head];
        const HotNode& from = hot_[terrain_slot_[i]];
        const TriGridField::Neighbours& nb = field.neighbours(i);
        for (int k = 0; k < nb.count; ++k) {
            const int j = nb.ids[k];
            const int32_t slot = terrain_slot_[j];
            if (slot < 0 || node_reached_[j]) continue;  // not terrain, or reached
            if (!traversable(from, hot_[slot])) continue;
            markReached(j, component, field, model);
        }
    }
}

// The reached node whose mean is nearest (xy) to `xy` (a candidate's mean), at most
// sqrt(max_dist2) away, or -1 (nearest = that node, best_d2 = its squared distance, or
// max_dist2; cx, cy = the candidate's cell). Cells are visited in rings of growing Chebyshev
// radius around the candidate's cell, up to window_rings. Means lie inside their cells, so a node
// of ring r is at least (r - 1) r_cell away: the scan stops when that exceeds the best distance
// found (exact, not a heuristic): the result is the nearest reached node of the window, ties to
// the lower id.
void TraversableGraphSearch::nearestReached(const Eigen::Vector2f& xy, const TriGridField& field,
                                            float max_dist2, Nearest& near) const {
    const int n = field.cellsPerSide();
    const int cx = near.cx, cy = near.cy;
    int nearest = -1;
    float best = max_dist2;
    const auto visit_cell = [&](int cell) {
        for (int k = 0; k < 4; ++k) {
            const int id = 4 * cell + k;
            if (!node_reached_[id]) continue;
            const float d2 = (node_xy_[id] - xy).squaredNorm();
            if (d2 < best || (d2 == best && id < nearest)) best = d2, nearest = id;
        }
    };
    for (int ring = 0; ring <= window_rings_; ++ring) {
        const float gap = std::max(0, ring - 1) * field.resolution();
        if (gap * gap > best) break;
        // The ring's two rows (one at ring 0), then its two columns without their corners.
        const int x_lo = std::max(0, cx - ring), x_hi = std::min(n - 1, cx + ring);
        for (const int iy : {cy - ring, cy + ring}) {
            if (iy >= 0 && iy < n)
                forEachSetBit(&row_cells_[static_cast<std::size_t>(iy) * words_], x_lo, x_hi,
                              [&](int ix) { visit_cell(iy * n + ix); });
            if (ring == 0) break;
        }
        if (ring == 0) continue;
        const int y_lo = std::max(0, cy - ring + 1), y_hi = std::min(n - 1, cy + ring - 1);
        for (const int ix : {cx - ring, cx + ring}) {
            if (ix >= 0 && ix < n)
                forEachSetBit(&col_cells_[static_cast<std::size_t>(ix) * words_], y_lo, y_hi,
                              [&](int iy) { visit_cell(iy * n + ix); });
        }
    }
    near.node = nearest;
    near.d2 = best;
}

// nearestReached() of candidate c, from what it was when last asked: the reached set only
// grows, so the nearest is the nearer of the last answer and the nodes reached since (in the
// same window, same ties); a full ring scan (which visits only cells with reached nodes) when
// more than kMaxNewReached nodes were reached since. Re-seeding asks every candidate again
// after each accepted seed.
constexpr std::size_t kMaxNewReached = 64;
int TraversableGraphSearch::nearestReachedNow(std::size_t c, const TriGridField& field,
                                              float max_dist2) {
    Nearest& near = nearest_[c];
    if (near.cx < 0) return -1;  // mean outside the grid
    const Eigen::Vector2f xy = hot_[terrain_slot_[candidates_[c]]].mean.head<2>();
    const std::size_t reached = reached_.size();
    if (near.seen == 0 || reached - near.seen > kMaxNewReached) {
        nearestReached(xy, field, max_dist2, near);
    } else {
        for (std::size_t k = near.seen; k < reached; ++k) {
            const ReachedWhere& where = reached_where_[k];
            if (std::abs(where.cx - near.cx) > window_rings_ ||
                std::abs(where.cy - near.cy) > window_rings_)
                continue;
            const float d2 = (where.xy - xy).squaredNorm();
            const int id = reached_[k];
            if (d2 < near.d2 || (d2 == near.d2 && id < near.node)) near.d2 = d2, near.node = id;
        }
    }
    near.seen = reached;
    return near.node;
}

namespace {
// Key that orders floats as their values do (for non-NaN values; -0 and +0 are one key).
uint32_t orderedBits(float value) {
    value += 0.f;  // -0 -> +0
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
}
}  // namespace

void TraversableGraphSearch::run(const TriGridField& field, const Params& params,
                                 TerrainModel& model) {
    model.seed_node = -1;
    model.num_components = 0;
    // One pass over all nodes (most of them empty: OS128 has 3.4k of 14.4k nodes with points):
    // reset reached / component where a previous search set them (after embedding they are
    // already reset: no write, so no cache line of an untouched node is dirtied) and copy
    // what the searches read of the terrain nodes into hot_.
    const int num_nodes = static_cast<int>(model.nodes.size());
    terrain_slot_.resize(model.nodes.size());
    hot_.clear(), terrain_.clear();
    for (int id = 0; id < num_nodes; ++id) {
        TriNode& node = model.nodes[id];
        if (node.reached || node.component != -1) node.reached = false, node.component = -1;
        if (node.node_class != NodeClass::Terrain) {
            terrain_slot_[id] = -1;
            continue;
        }
        terrain_slot_[id] = static_cast<int32_t>(hot_.size());
        hot_.push_back({node.mean, node.normal, node.d, node.weight});
        terrain_.push_back(id);
    }
    // Compact copies of `reached` and of the reached nodes' mean xy for the nearest-node scans.
    node_reached_.assign(model.nodes.size(), 0);
    node_xy_.resize(model.nodes.size());
    const int n = field.cellsPerSide();
    words_ = (n + 63) / 64;
    row_cells_.assign(static_cast<std::size_t>(n) * words_, 0);
    col_cells_.assign(static_cast<std::size_t>(n) * words_, 0);
    // Start node (see the decisions above).
    const float radius2 = static_cast<float>(params.seed_search_radius * params.seed_search_radius);
    int seed = -1;
    float seed_weight = 0.f;
    for (std::size_t t = 0; t < terrain_.size(); ++t) {
        const HotNode& node = hot_[t];
        if (node.mean.head<2>().squaredNorm() > radius2) continue;
        if (std::fabs(node.mean.z() + params.sensor_height) > params.seed_height_tolerance)
            continue;
        if (seed < 0 || node.weight > seed_weight) seed = terrain_[t], seed_weight = node.weight;
    }
    if (seed < 0) return;
    model.seed_node = seed;
    reached_.clear(), reached_where_.clear();
    searchFrom(seed, 0, field, params, model);
    int16_t component = 1;

    // Re-seeding from plausible ground only: the unreached terrain nodes at least min_weight
    // heavy, in decreasing weight (ties: lower id first).
    const float min_weight = static_cast<float>(params.reseed_min_weight_ratio) * seed_weight;
    candidates_.clear(), candidate_keys_.clear();
    bool nan_weight = false;
    for (std::size_t t = 0; t < terrain_.size(); ++t) {
        const int id = terrain_[t];
        if (node_reached_[id] || hot_[t].weight < min_weight) continue;
        candidates_.push_back(id);
        nan_weight |= std::isnan(hot_[t].weight);
        // Decreasing weight, then increasing id (the ids are in increasing order here).
        candidate_keys_.push_back(uint64_t{~orderedBits(hot_[t].weight)} << 32 |
                                  static_cast<uint32_t>(id));
    }
    if (nan_weight) {  // no order of values: keep the comparison sort's own answer
        std::stable_sort(candidates_.begin(), candidates_.end(), [&](int a, int b) {
            return hot_[terrain_slot_[a]].weight > hot_[terrain_slot_[b]].weight;
        });
    } else {
        std::sort(candidate_keys_.begin(), candidate_keys_.end());
        for (std::size_t c = 0; c < candidates_.size(); ++c)
            candidates_[c] = static_cast<int>(candidate_keys_[c] & 0xffffffffu);
    }
    const float max_dist2 =
        static_cast<float>(params.reseed_max_distance * params.reseed_max_distance);
    window_rings_ = static_cast<int>(std::ceil(std::sqrt(max_dist2) / field.resolution())) + 1;
    nearest_.resize(candidates_.size());
    for (std::size_t c = 0; c < candidates_.size(); ++c) {
        const HotNode& cand = hot_[terrain_slot_[candidates_[c]]];
        const int node = field.nodeOf(cand.mean.x(), cand.mean.y());
        nearest_[c] = Nearest{};
        if (node >= 0) nearest_[c].cx = (node / 4) % n, nearest_[c].cy = (node / 4) / n;
    }
    bool accepted_any = true;
    while (accepted_any && component < std::numeric_limits<int16_t>::max()) {
        accepted_any = false;
        for (std::size_t c = 0; c < candidates_.size(); ++c) {
            const int id = candidates_[c];
            if (node_reached_[id]) continue;
            const HotNode& cand = hot_[terrain_slot_[id]];
            const int nearest = nearestReachedNow(c, field, max_dist2);
            if (nearest < 0) continue;
            const HotNode& ref = hot_[terrain_slot_[nearest]];
            const Eigen::Vector2f mid = 0.5f * (ref.mean + cand.mean).head<2>();
            const float gap = planeHeightAt(ref.normal, ref.d, mid.x(), mid.y()) -
                              planeHeightAt(cand.normal, cand.d, mid.x(), mid.y());
            if (std::fabs(gap) > params.reseed_max_height_diff) continue;
            if (component == std::numeric_limits<int16_t>::max()) break;  // ids are int16
            searchFrom(id, component++, field, params, model);
            accepted_any = true;
        }
    }
    model.num_components = component;
}

}  // namespace travel
