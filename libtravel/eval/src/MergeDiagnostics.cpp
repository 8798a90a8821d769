// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/MergeDiagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "travel/Pipeline.hpp"
#include "travel/RangeImage.hpp"
#include "travel/RunClustering.hpp"
#include "travel/eval/ObjectMetrics.hpp"

namespace travel::eval {

const char* toString(LinkRule rule) {
    switch (rule) {
        case LinkRule::Horizontal:
            return "horizontal";
        case LinkRule::Vertical:
            return "vertical";
        case LinkRule::RangeScaledVertical:
            return "range-scaled vertical";
        case LinkRule::Occlusion:
            return "occlusion";
        case LinkRule::Seam:
            return "seam";
        case LinkRule::Indirect:
            return "indirect";
    }
    return "?";
}

std::string semanticName(uint32_t semantic) {
    struct Name {
        uint32_t id;
        const char* name;
    };
    static const Name kNames[] = {{0, "unlabeled"},
                                  {1, "outlier"},
                                  {10, "car"},
                                  {11, "bicycle"},
                                  {13, "bus"},
                                  {15, "motorcycle"},
                                  {16, "on-rails"},
                                  {18, "truck"},
                                  {20, "other-vehicle"},
                                  {30, "person"},
                                  {31, "bicyclist"},
                                  {32, "motorcyclist"},
                                  {40, "road"},
                                  {44, "parking"},
                                  {48, "sidewalk"},
                                  {49, "other-ground"},
                                  {50, "building"},
                                  {51, "fence"},
                                  {52, "other-structure"},
                                  {60, "lane-marking"},
                                  {70, "vegetation"},
                                  {71, "trunk"},
                                  {72, "terrain"},
                                  {80, "pole"},
                                  {81, "traffic-sign"},
                                  {99, "other-object"},
                                  {252, "moving-car"},
                                  {253, "moving-bicyclist"},
                                  {254, "moving-person"},
                                  {255, "moving-motorcyclist"},
                                  {256, "moving-on-rails"},
                                  {257, "moving-bus"},
                                  {258, "moving-truck"},
                                  {259, "moving-other-vehicle"}};
    for (const Name& n : kNames)
        if (n.id == semantic) return n.name;
    return "class-" + std::to_string(semantic);
}

namespace {

// Closest pairs between a part and the rest of its cluster, by the rule they satisfy.
struct LinkSearch {
    float same_row = std::numeric_limits<float>::infinity();      // min d2, same ring
    float cross_row = std::numeric_limits<float>::infinity();     // min d2, rings 1..span apart
    float cross_excess = std::numeric_limits<float>::infinity();  // min d2 - (R dtheta)^2
    float any = std::numeric_limits<float>::infinity();
    float occlusion = std::numeric_limits<float>::infinity();  // same ring, ranges within T_horz
    float seam = std::numeric_limits<float>::infinity();       // same ring, at the sweep start
    std::size_t same_pair[2] = {0, 0}, cross_pair[2] = {0, 0}, excess_pair[2] = {0, 0},
                any_pair[2] = {0, 0}, occlusion_pair[2] = {0, 0}, seam_pair[2] = {0, 0};
};

}  // namespace

std::vector<MergedPart> mergedParts(const std::vector<uint32_t>& cluster_id,
                                    const std::vector<uint32_t>& gt_labels, const PointCloud& cloud,
                                    const Pipeline& pipeline, std::size_t min_part_points) {
    const std::size_t n = cloud.size();
    std::vector<MergedPart> parts;
    if (cluster_id.size() != n || gt_labels.size() != n) return parts;
    // What the object stage linked on: its rows and columns, its coordinates, its rows'
    // elevations and the parameters in use (`auto` values resolved).
    const RangeImage& image = pipeline.rangeImage();
    const RunClustering& clustering = pipeline.clustering();
    const AlignedCloud& aligned = pipeline.aligned();
    const Params& params = pipeline.params();
    if (!params.cluster_objects)
        throw std::invalid_argument(
            "travel::eval::mergedParts: the pipeline's object stage is off (cluster_objects): "
            "there is no linkage to diagnose");
    if (aligned.x.size() != n || image.row().size() != n ||
        clustering.rowElevations().size() != static_cast<std::size_t>(image.rows()))
        throw std::invalid_argument(
            "travel::eval::mergedParts: the pipeline's last frame is not this cloud of " +
            std::to_string(n) + " points clustered (cluster_objects)");
    const std::vector<uint32_t> object = groundTruthObjects(gt_labels, cloud.x, cloud.y, cloud.z);
    const std::vector<float>&x = aligned.x, &y = aligned.y, &z = aligned.z;
    std::vector<float> range(n, 0.f);
    for (std::size_t i = 0; i < n; ++i)
        if (aligned.valid[i]) range[i] = std::sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
    const std::vector<int16_t>& row = image.row();
    const int rows = image.rows();

    // Group key: the GT object, else the semantic class (high bit set).
    auto groupOf = [&](std::size_t i) -> uint32_t {
        return object[i] != 0 ? object[i] : (0x80000000u | (gt_labels[i] & 0xFFFFu));
    };
    std::vector<uint32_t> order;
    for (std::size_t i = 0; i < n; ++i)
        if (cluster_id[i] != 0 && row[i] >= 0) order.push_back(static_cast<uint32_t>(i));
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return cluster_id[a] != cluster_id[b] ? cluster_id[a] < cluster_id[b]
                                              : groupOf(a) < groupOf(b);
    });
    const float t_h2 = float(params.horizontal_merge_dist * params.horizontal_merge_dist);
    const float t_v2 = float(params.vertical_merge_dist * params.vertical_merge_dist);
    const float occ2 = float(params.occlusion_max_gap * params.occlusion_max_gap);
    const float seam2 = float(params.seam_max_shift * params.seam_max_shift);
    const int span = params.vertical_ring_span;
    const float t_h = float(params.horizontal_merge_dist);
    // RunClustering's seam linkage: runs touching the sweep start column.
    const int seam_col = image.sweepStartColumn(), cols = image.cols();
    const std::vector<int32_t>& col = image.col();
    auto nearSeam = [&](std::size_t i) {
        if (seam_col < 0) return false;
        const int d = std::abs(col[i] - seam_col) % cols;
        return std::min(d, cols - d) <= RunClustering::kSeamColumns;
    };
    std::vector<std::vector<uint32_t>> by_row(rows);
    for (std::size_t a = 0; a < order.size();) {
        std::size_t b = a;
        while (b < order.size() && cluster_id[order[b]] == cluster_id[order[a]]) ++b;
        // Groups of the cluster [a, b): [start, end) ranges of `order`.
        std::vector<std::pair<std::size_t, std::size_t>> groups;
        for (std::size_t g = a; g < b;) {
            std::size_t e = g;
            while (e < b && groupOf(order[e]) == groupOf(order[g])) ++e;
            groups.emplace_back(g, e);
            g = e;
        }
        if (groups.size() < 2) {
            a = b;
            continue;
        }
        std::size_t owner = 0;
        for (std::size_t g = 1; g < groups.size(); ++g)
            if (groups[g].second - groups[g].first > groups[owner].second - groups[owner].first)
                owner = g;
        for (auto& v : by_row) v.clear();
        for (std::size_t k = a; k < b; ++k) by_row[row[order[k]]].push_back(order[k]);
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const std::size_t gb = groups[g].first, ge = groups[g].second;
            if (g == owner || ge - gb < min_part_points) continue;
            const uint32_t group = groupOf(order[gb]);
            LinkSearch s;
            for (std::size_t k = gb; k < ge; ++k) {
                const uint32_t p = order[k];
                const int rp = row[p];
                for (int rq = std::max(0, rp - span); rq <= std::min(rows - 1, rp + span); ++rq) {
                    const float elev_step = clustering.ringSpacing(rp, rq);
                    for (const uint32_t q : by_row[rq]) {
                        if (groupOf(q) == group) continue;
                        const float dx = x[p] - x[q], dy = y[p] - y[q], dz = z[p] - z[q];
                        const float d2 = dx * dx + dy * dy + dz * dz;
                        if (d2 < s.any) s.any = d2, s.any_pair[0] = p, s.any_pair[1] = q;
                        if (rq == rp) {
                            if (d2 < s.same_row)
                                s.same_row = d2, s.same_pair[0] = p, s.same_pair[1] = q;
                            if (d2 < s.occlusion && std::fabs(range[p] - range[q]) < t_h)
                                s.occlusion = d2, s.occlusion_pair[0] = p, s.occlusion_pair[1] = q;
                            if (d2 < s.seam && nearSeam(p) && nearSeam(q))
                                s.seam = d2, s.seam_pair[0] = p, s.seam_pair[1] = q;
                            continue;
                        }
                        // The vertical update compares points at most T_ext columns apart,
                        // not across the 0/360-degree seam (RunClustering::runsTouch()).
                        if (std::abs(col[p] - col[q]) > params.vertical_column_extension) continue;
                        if (d2 < s.cross_row)
                            s.cross_row = d2, s.cross_pair[0] = p, s.cross_pair[1] = q;
                        const float gap = range[rq > rp ? q : p] * elev_step;  // upper point
                        const float excess = d2 - gap * gap;
                        if (excess < s.cross_excess)
                            s.cross_excess = excess, s.excess_pair[0] = p, s.excess_pair[1] = q;
                    }
                }
            }
            MergedPart part;
            part.cluster = cluster_id[order[gb]];
            part.owner_semantic = gt_labels[order[groups[owner].first]] & 0xFFFFu;
            part.part_semantic = gt_labels[order[gb]] & 0xFFFFu;
            part.cluster_points = b - a;
            part.owner_points = groups[owner].second - groups[owner].first;
            part.part_points = ge - gb;
            part.part_is_object = (group & 0x80000000u) == 0;
            part.same_label = gt_labels[order[gb]] == gt_labels[order[groups[owner].first]];
            std::vector<float> ranges;
            for (std::size_t k = gb; k < ge; ++k) ranges.push_back(range[order[k]]);
            std::nth_element(ranges.begin(), ranges.begin() + ranges.size() / 2, ranges.end());
            part.range = ranges[ranges.size() / 2];
            const std::size_t* pair = s.any_pair;
            if (s.same_row < t_h2)
                part.rule = LinkRule::Horizontal, pair = s.same_pair;
            else if (s.cross_row < t_v2)
                part.rule = LinkRule::Vertical, pair = s.cross_pair;
            else if (s.cross_excess < t_v2)
                part.rule = LinkRule::RangeScaledVertical, pair = s.excess_pair;
            else if (s.occlusion < occ2)
                part.rule = LinkRule::Occlusion, pair = s.occlusion_pair;
            else if (s.seam < seam2)
                part.rule = LinkRule::Seam, pair = s.seam_pair;
            const std::size_t p = pair[0], q = pair[1];
            if (std::isfinite(s.any)) {
                const float dx = x[p] - x[q], dy = y[p] - y[q], dz = z[p] - z[q];
                part.link_distance = std::sqrt(dx * dx + dy * dy + dz * dz);
                part.depth_jump = std::fabs(range[p] - range[q]);
                part.row_gap = std::abs(row[p] - row[q]);
                part.part_point = static_cast<uint32_t>(p);
                part.rest_point = static_cast<uint32_t>(q);
                part.part_row = row[p], part.rest_row = row[q];
                part.ring_spacing = clustering.ringSpacing(row[p], row[q]);
            }
            parts.push_back(part);
        }
        a = b;
    }
    return parts;
}

void writeMergedPartsCsv(std::ostream& csv, const std::string& frame,
                         const std::vector<MergedPart>& parts, bool header) {
    if (header)
        csv << "frame,cluster,cluster_points,owner,owner_points,part,part_points,part_is_object,"
               "same_label,range,rule,link_distance,depth_jump,row_gap\n";
    for (const MergedPart& p : parts)
        csv << frame << ',' << p.cluster << ',' << p.cluster_points << ','
            << semanticName(p.owner_semantic) << ',' << p.owner_points << ','
            << semanticName(p.part_semantic) << ',' << p.part_points << ',' << p.part_is_object
            << ',' << p.same_label << ',' << p.range << ',' << toString(p.rule) << ','
            << p.link_distance << ',' << p.depth_jump << ',' << p.row_gap << '\n';
}

namespace {
const char* rangeBand(float r) {
    return r < 10.f ? "0-10" : r < 20.f ? "10-20" : r < 30.f ? "20-30" : r < 40.f ? "30-40" : "40+";
}
}  // namespace

void MergeTable::addTo(std::vector<Row>& rows, const std::string& key, const MergedPart& part) {
    auto it = std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.key == key; });
    if (it == rows.end()) {
        rows.push_back(Row{key});
        it = rows.end() - 1;
    }
    ++it->parts;
    it->points += part.part_points;
    it->depth_jump += part.depth_jump;
}

void MergeTable::add(const std::vector<MergedPart>& parts) {
    uint32_t last = 0;
    for (const MergedPart& p : parts) {
        if (p.cluster != last) ++clusters_, last = p.cluster;
        const std::string pair =
            semanticName(p.owner_semantic) + " + " + semanticName(p.part_semantic) +
            (p.part_is_object ? "" : " (rest)") + (p.same_label ? " (same label)" : "");
        addTo(by_rule_, toString(p.rule), p);
        addTo(by_pair_, pair, p);
        addTo(by_all_, pair + " | " + rangeBand(p.range) + " m | " + toString(p.rule), p);
    }
}

std::string MergeTable::markdown(std::size_t top) const {
    std::ostringstream md;
    auto table = [&](const char* title, std::vector<Row> rows, std::size_t limit) {
        std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
            return a.points != b.points ? a.points > b.points : a.key < b.key;
        });
        // The delimiter row has one cell per column: the title's own columns (" | "
        // separated) and the three counts, or Markdown does not render it as a table.
        const std::string header =
            std::string("| ") + title + " | parts | part points | mean depth jump [m] |";
        md << "\n" << header << "\n|";
        for (std::size_t c = 1; c < std::size_t(std::count(header.begin(), header.end(), '|')); ++c)
            md << "---|";
        md << "\n";
        for (std::size_t k = 0; k < rows.size() && k < limit; ++k) {
            char line[96];
            std::snprintf(line, sizeof line, " | %zu | %zu | %.2f |\n", rows[k].parts,
                          rows[k].points,
                          rows[k].depth_jump / std::max<std::size_t>(rows[k].parts, 1));
            md << "| " << rows[k].key << line;
        }
    };
    md << "Clusters holding more than one ground-truth group: " << clusters_ << "\n";
    table("linkage rule", by_rule_, by_rule_.size());
    table("owner + part class", by_pair_, top);
    table("owner + part | range | rule", by_all_, top);
    return md.str();
}

}  // namespace travel::eval
