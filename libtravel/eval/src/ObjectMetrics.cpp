// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/ObjectMetrics.hpp"

#include "travel/eval/Metrics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace travel {

namespace {

// Everything that is neither ground nor without truth (0 unlabeled, 1 outlier).
bool isObjectClass(uint32_t semantic) {
    return semantic != 0 && semantic != 1 && !isSemanticKittiGround(semantic);
}

bool isThingClass(uint32_t semantic) {
    return (semantic >= 10 && semantic <= 32) || (semantic >= 252 && semantic <= 259);
}

void checkInputs(std::size_t n, const std::vector<uint32_t>* cluster_id,
                 const std::vector<PointClass>* pred, const std::vector<float>& x,
                 const std::vector<float>& y, const std::vector<float>& z,
                 const ObjectEvalOptions& options, const char* who) {
    const bool sizes_ok = (!cluster_id || cluster_id->size() == n) &&
                          (!pred || pred->size() == n) && x.size() == n && y.size() == n &&
                          z.size() == n;
    if (!sizes_ok) {
        throw std::invalid_argument(
            std::string(who) + ": sizes differ (" + std::to_string(n) + " labels, " +
            (cluster_id ? std::to_string(cluster_id->size()) + " cluster ids, " : "") +
            (pred ? std::to_string(pred->size()) + " classes, " : "") + std::to_string(x.size()) +
            " x, " + std::to_string(y.size()) + " y, " + std::to_string(z.size()) + " z)");
    }
    const double d = options.gt_cluster_distance;
    if (!(d > 0) || !std::isfinite(d)) {
        throw std::invalid_argument(std::string(who) + ": gt_cluster_distance must be > 0, got " +
                                    std::to_string(d));
    }
}

// Voxel cell coordinates, clamped to 21 bits each so that three pack into one uint64. Clamping
// only merges far cells (more candidates, same distance test), so the result stays exact.
constexpr int32_t kCellLimit = 1 << 20;

int32_t cellCoord(float v, double inv_cell) {
    const double c = std::floor(static_cast<double>(v) * inv_cell);
    return static_cast<int32_t>(std::clamp(c, -double(kCellLimit), double(kCellLimit - 1)));
}

uint64_t packCell(int32_t cx, int32_t cy, int32_t cz) {
    return (static_cast<uint64_t>(cx + kCellLimit) << 42) |
           (static_cast<uint64_t>(cy + kCellLimit) << 21) | static_cast<uint64_t>(cz + kCellLimit);
}

struct CellKey {
    uint32_t label;  // the full GT label: cells never mix (semantic, instance) groups
    uint64_t cell;
    bool operator==(const CellKey& o) const { return label == o.label && cell == o.cell; }
};

struct CellKeyHash {
    std::size_t operator()(const CellKey& k) const {
        uint64_t h = k.cell * 0x9E3779B97F4A7C15ull ^ (uint64_t(k.label) * 0xC2B2AE3D27D4EB4Full);
        h ^= h >> 31;
        return static_cast<std::size_t>(h);
    }
};

// GT object id per point, see groundTruthObjects().
std::vector<uint32_t> labelObjects(const std::vector<uint32_t>& gt, const std::vector<float>& x,
                                   const std::vector<float>& y, const std::vector<float>& z,
                                   const ObjectEvalOptions& options) {
    const std::size_t n = gt.size();
    std::vector<uint32_t> object_of_point(n, 0);

    std::vector<uint32_t> pts;  // object points, ascending index
    for (std::size_t i = 0; i < n; ++i) {
        if (isObjectClass(gt[i] & 0xFFFFu) && std::isfinite(x[i]) && std::isfinite(y[i]) &&
            std::isfinite(z[i]))
            pts.push_back(static_cast<uint32_t>(i));
    }
    const std::size_t m = pts.size();
    if (m == 0) return object_of_point;

    const double d = options.gt_cluster_distance, d2 = d * d, inv_cell = 1.0 / d;
    std::vector<int32_t> cx(m), cy(m), cz(m);
    std::vector<uint64_t> cell(m);
    for (std::size_t k = 0; k < m; ++k) {
        const uint32_t i = pts[k];
        cx[k] = cellCoord(x[i], inv_cell), cy[k] = cellCoord(y[i], inv_cell);
        cz[k] = cellCoord(z[i], inv_cell);
        cell[k] = packCell(cx[k], cy[k], cz[k]);
    }
    // Points sorted by (label, cell): each occupied cell of a group is one contiguous run of
    // slots. The BFS works on slots, with the coordinates copied in slot order.
    std::vector<uint32_t> order(m);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        const uint32_t la = gt[pts[a]], lb = gt[pts[b]];
        if (la != lb) return la < lb;
        if (cell[a] != cell[b]) return cell[a] < cell[b];
        return a < b;
    });
    std::vector<float> sx(m), sy(m), sz(m);
    std::vector<uint32_t> slot_of(m), run_of(m), run_begin;
    std::unordered_map<CellKey, uint32_t, CellKeyHash> run_index;
    run_index.reserve(m);
    for (uint32_t s = 0; s < m; ++s) {
        const uint32_t k = order[s], i = pts[k];
        sx[s] = x[i], sy[s] = y[i], sz[s] = z[i];
        slot_of[k] = s;
        if (s == 0 || gt[i] != gt[pts[order[s - 1]]] || cell[k] != cell[order[s - 1]]) {
            run_index.emplace(CellKey{gt[i], cell[k]}, static_cast<uint32_t>(run_begin.size()));
            run_begin.push_back(s);
        }
        run_of[s] = static_cast<uint32_t>(run_begin.size() - 1);
    }
    const uint32_t num_runs = static_cast<uint32_t>(run_begin.size());
    run_begin.push_back(static_cast<uint32_t>(m));

    // Neighbouring runs (same label, the 27 surrounding cells), looked up once per cell rather
    // than once per point: CSR lists.
    std::vector<uint32_t> nbr_begin(num_runs + 1, 0), nbrs;
    nbrs.reserve(std::size_t(num_runs) * 8);
    for (uint32_t r = 0; r < num_runs; ++r) {
        nbr_begin[r] = static_cast<uint32_t>(nbrs.size());
        const uint32_t k = order[run_begin[r]], label = gt[pts[k]];
        for (int dx = -1; dx <= 1; ++dx) {
            const int32_t nx = cx[k] + dx;
            if (nx < -kCellLimit || nx >= kCellLimit) continue;
            for (int dy = -1; dy <= 1; ++dy) {
                const int32_t ny = cy[k] + dy;
                if (ny < -kCellLimit || ny >= kCellLimit) continue;
                for (int dz = -1; dz <= 1; ++dz) {
                    const int32_t nz = cz[k] + dz;
                    if (nz < -kCellLimit || nz >= kCellLimit) continue;
                    const auto it = run_index.find(CellKey{label, packCell(nx, ny, nz)});
                    if (it != run_index.end()) nbrs.push_back(it->second);
                }
            }
        }
    }
    nbr_begin[num_runs] = static_cast<uint32_t>(nbrs.size());

    // BFS from every unassigned point in input order: object ids follow the smallest index of
    // each object, whatever the hash map's layout (deterministic).
    std::vector<uint32_t> object(m, 0), queue;  // object per slot
    queue.reserve(m);
    uint32_t num_objects = 0;
    for (uint32_t k = 0; k < m; ++k) {
        const uint32_t seed = slot_of[k];
        if (object[seed] != 0) continue;
        object[seed] = ++num_objects;
        queue.clear();
        queue.push_back(seed);
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const uint32_t q = queue[head], r = run_of[q];
            const double qx = sx[q], qy = sy[q], qz = sz[q];
            for (uint32_t nb = nbr_begin[r]; nb < nbr_begin[r + 1]; ++nb) {
                const uint32_t nr = nbrs[nb];
                for (uint32_t f = run_begin[nr]; f < run_begin[nr + 1]; ++f) {
                    if (object[f] != 0) continue;
                    const double ex = sx[f] - qx, ey = sy[f] - qy, ez = sz[f] - qz;
                    if (ex * ex + ey * ey + ez * ez <= d2) {
                        object[f] = num_objects;
                        queue.push_back(f);
                    }
                }
            }
        }
    }

    // Drop small objects, renumber the others in the same order.
    std::vector<uint32_t> size(num_objects + 1, 0), kept_id(num_objects + 1, 0);
    for (uint32_t s = 0; s < m; ++s) ++size[object[s]];
    uint32_t kept = 0;
    for (uint32_t o = 1; o <= num_objects; ++o) {
        if (size[o] >= options.min_gt_object_points) kept_id[o] = ++kept;
    }
    for (uint32_t s = 0; s < m; ++s) object_of_point[pts[order[s]]] = kept_id[object[s]];
    return object_of_point;
}

// (N_i / N) ln(N / N_i): written this way every term is >= 0 and a whole share gives +0.
double entropyTerm(std::size_t part, std::size_t whole) {
    const double p = static_cast<double>(part) / static_cast<double>(whole);
    return p * std::log(static_cast<double>(whole) / static_cast<double>(part));
}

struct LabelPair {
    uint32_t first, second;
    bool operator<(const LabelPair& o) const {
        return first != o.first ? first < o.first : second < o.second;
    }
};

// Sum and count of the entropies of the `first` labels over their `second` labels; pairs must be
// sorted. With `zero_is_singletons`, second = 0 stands for that many singleton labels.
void sumEntropies(const std::vector<LabelPair>& pairs, bool zero_is_singletons, double& sum,
                  std::size_t& count) {
    sum = 0, count = 0;
    for (std::size_t s = 0; s < pairs.size();) {
        std::size_t e = s;
        while (e < pairs.size() && pairs[e].first == pairs[s].first) ++e;
        const std::size_t whole = e - s;
        double h = 0;
        for (std::size_t a = s; a < e;) {
            std::size_t b = a;
            while (b < e && pairs[b].second == pairs[a].second) ++b;
            if (zero_is_singletons && pairs[a].second == 0) {
                h += static_cast<double>(b - a) * entropyTerm(1, whole);
            } else {
                h += entropyTerm(b - a, whole);
            }
            a = b;
        }
        sum += h;
        ++count;
        s = e;
    }
}

}  // namespace

std::vector<uint32_t> groundTruthObjects(const std::vector<uint32_t>& gt_labels,
                                         const std::vector<float>& x, const std::vector<float>& y,
                                         const std::vector<float>& z,
                                         const ObjectEvalOptions& options) {
    checkInputs(gt_labels.size(), nullptr, nullptr, x, y, z, options, "groundTruthObjects");
    return labelObjects(gt_labels, x, y, z, options);
}

ObjectScores evaluateObjects(const std::vector<uint32_t>& cluster_id,
                             const std::vector<PointClass>& pred,
                             const std::vector<uint32_t>& gt_labels, const std::vector<float>& x,
                             const std::vector<float>& y, const std::vector<float>& z,
                             const ObjectEvalOptions& options) {
    const std::size_t n = gt_labels.size();
    checkInputs(n, &cluster_id, &pred, x, y, z, options, "evaluateObjects");
    ObjectScores out;

    // --- OSE / USE over the scored points of the kept GT objects.
    const std::vector<uint32_t> object = labelObjects(gt_labels, x, y, z, options);
    std::vector<LabelPair> pairs;  // (object, cluster)
    for (std::size_t i = 0; i < n; ++i) {
        if (object[i] == 0) continue;
        if (options.entropy_on_predicted_nonground && pred[i] != PointClass::NonGround) continue;
        pairs.push_back({object[i], cluster_id[i]});
    }
    SegmentationEntropy& h = out.entropy;
    h.num_points = pairs.size();
    std::sort(pairs.begin(), pairs.end());
    sumEntropies(pairs, true, h.ose_sum, h.num_gt_objects);
    // (cluster, object) without the unclustered points: singleton clusters have USE 0.
    std::size_t kept = 0;
    for (const LabelPair& p : pairs) {
        if (p.second != 0) pairs[kept++] = {p.second, p.first};
    }
    pairs.resize(kept);
    std::sort(pairs.begin(), pairs.end());
    sumEntropies(pairs, false, h.use_sum, h.num_clusters);
    h.ose_mean = h.num_gt_objects ? h.ose_sum / static_cast<double>(h.num_gt_objects) : 0.0;
    h.use_mean = h.num_clusters ? h.use_sum / static_cast<double>(h.num_clusters) : 0.0;

    // --- Instance coverage / purity.
    struct InstancePoint {
        uint32_t semantic, instance, cluster;
        bool operator<(const InstancePoint& o) const {
            if (semantic != o.semantic) return semantic < o.semantic;
            if (instance != o.instance) return instance < o.instance;
            return cluster < o.cluster;
        }
    };
    std::vector<InstancePoint> inst;
    std::unordered_map<uint32_t, std::size_t> cluster_size;
    for (std::size_t i = 0; i < n; ++i) {
        if (cluster_id[i] != 0) ++cluster_size[cluster_id[i]];
        const uint32_t semantic = gt_labels[i] & 0xFFFFu, instance = gt_labels[i] >> 16;
        if (isThingClass(semantic) && instance != 0)
            inst.push_back({semantic, instance, cluster_id[i]});
    }
    std::sort(inst.begin(), inst.end());
    double coverage_sum = 0, purity_sum = 0;
    for (std::size_t s = 0; s < inst.size();) {
        std::size_t e = s;
        while (e < inst.size() && inst[e].semantic == inst[s].semantic &&
               inst[e].instance == inst[s].instance)
            ++e;
        InstanceScore score;
        score.semantic = inst[s].semantic, score.instance = inst[s].instance;
        score.points = e - s;
        if (score.points >= options.min_instance_points) {
            const GroupInClusters group =
                locateGroup(e - s, [&](std::size_t k) { return inst[s + k].cluster; });
            score.best_cluster = group.best_cluster;
            if (score.best_cluster != 0) {
                const std::size_t best_size = cluster_size[score.best_cluster];
                score.coverage = static_cast<double>(group.best_count) / static_cast<double>(e - s);
                score.purity =
                    static_cast<double>(group.best_count) / static_cast<double>(best_size);
                ++out.clustered;
                purity_sum += score.purity;
                if (group.mergedInto(best_size)) ++out.merged;
            }
            coverage_sum += score.coverage;
            if (group.split()) ++out.split;
            out.instances.push_back(score);
        }
        s = e;
    }
    if (!out.instances.empty())
        out.mean_coverage = coverage_sum / static_cast<double>(out.instances.size());
    if (out.clustered > 0) out.mean_purity = purity_sum / static_cast<double>(out.clustered);
    return out;
}

void ObjectScoreAccumulator::add(const ObjectScores& frame) {
    ++frames_;
    ose_ += frame.entropy.ose_sum, use_ += frame.entropy.use_sum;
    gt_objects_ += frame.entropy.num_gt_objects, clusters_ += frame.entropy.num_clusters;
    for (const InstanceScore& s : frame.instances) {
        ++instances_;
        coverage_ += s.coverage;
        if (s.best_cluster != 0) ++clustered_, purity_ += s.purity;
    }
    split_ += frame.split, merged_ += frame.merged;
}

ObjectSummary ObjectScoreAccumulator::summary() const {
    const auto mean = [](double sum, std::size_t n) {
        return n ? sum / static_cast<double>(n) : 0.0;
    };
    ObjectSummary s;
    s.frames = frames_;
    s.ose_per_frame = mean(ose_, frames_), s.use_per_frame = mean(use_, frames_);
    s.ose_per_object = mean(ose_, gt_objects_), s.use_per_cluster = mean(use_, clusters_);
    s.gt_objects = gt_objects_, s.clusters = clusters_;
    s.instances = instances_, s.clustered = clustered_, s.split = split_, s.merged = merged_;
    s.mean_coverage = mean(coverage_, instances_), s.mean_purity = mean(purity_, clustered_);
    return s;
}

}  // namespace travel
