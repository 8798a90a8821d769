// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/EuclideanClustering.hpp"

#include <nanoflann.hpp>
#include <utility>

#include "travel/eval/Segmenter.hpp"

namespace travel::eval {

// nanoflann dataset adaptor over the non-ground points (structure of arrays), and the tree.
struct EuclideanClustering::Tree {
    struct Points {
        std::vector<float> x, y, z;
        std::vector<uint32_t> index;  // input index of each point
        std::size_t kdtree_get_point_count() const { return x.size(); }
        float kdtree_get_pt(std::size_t i, std::size_t dim) const {
            return dim == 0 ? x[i] : dim == 1 ? y[i] : z[i];
        }
        template <class BBox>
        bool kdtree_get_bbox(BBox&) const {
            return false;
        }
    };
    using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Points>,
                                                      Points, 3, uint32_t>;

    Points points;
    Index index{3, points, nanoflann::KDTreeSingleIndexAdaptorParams(10)};
    std::vector<std::pair<uint32_t, float>> neighbours;  // reused by every radius query
    std::vector<uint32_t> component;                     // per point, 0 = not visited
};

EuclideanClustering::EuclideanClustering(const EuclideanOptions& options)
    : options_(options), tree_(std::make_unique<Tree>()) {}
EuclideanClustering::~EuclideanClustering() = default;
EuclideanClustering::EuclideanClustering(EuclideanClustering&&) noexcept = default;
EuclideanClustering& EuclideanClustering::operator=(EuclideanClustering&&) noexcept = default;

void EuclideanClustering::cluster(const AlignedCloud& aligned,
                                  const std::vector<PointClass>& labels, const Params& params,
                                  std::vector<uint32_t>& cluster_id) {
    const std::size_t n = labels.size();
    cluster_id.assign(n, 0u);
    Tree& t = *tree_;
    Tree::Points& pts = t.points;
    pts.x.clear(), pts.y.clear(), pts.z.clear(), pts.index.clear();
    for (std::size_t i = 0; i < n; ++i) {
        if (labels[i] != PointClass::NonGround) continue;
        pts.x.push_back(aligned.x[i]), pts.y.push_back(aligned.y[i]);
        pts.z.push_back(aligned.z[i]), pts.index.push_back(static_cast<uint32_t>(i));
    }
    const std::size_t m = pts.x.size();
    if (m == 0) return;
    t.index.buildIndex();

    // Breadth-first search from each unvisited point in input order. Components do not depend
    // on the order neighbours are returned in, so no sorting is needed.
    const float radius2 = static_cast<float>(options_.tolerance * options_.tolerance);
    const nanoflann::SearchParams unsorted(32, 0.f, false);
    t.component.assign(m, 0u);
    uint32_t next_component = 0;
    for (std::size_t seed = 0; seed < m; ++seed) {
        if (t.component[seed]) continue;
        t.component[seed] = ++next_component;
        queue_.clear();
        queue_.push_back(static_cast<uint32_t>(seed));
        for (std::size_t head = 0; head < queue_.size(); ++head) {
            const uint32_t p = queue_[head];
            const float query[3] = {pts.x[p], pts.y[p], pts.z[p]};
            nanoflann::RadiusResultSet<float, uint32_t> result(radius2, t.neighbours);
            t.index.findNeighbors(result, query, unsorted);
            for (const auto& [q, d2] : t.neighbours) {
                (void)d2;
                if (t.component[q]) continue;
                t.component[q] = next_component;
                queue_.push_back(q);
            }
        }
    }
    for (std::size_t k = 0; k < m; ++k) cluster_id[pts.index[k]] = t.component[k];
    renumberClusters(cluster_id, next_component, params.min_cluster_size, params.max_cluster_size,
                     count_, new_id_);
}

}  // namespace travel::eval
