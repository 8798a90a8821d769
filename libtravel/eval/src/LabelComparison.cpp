// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/LabelComparison.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdarg>
#include <cstdio>
#include <numeric>
#include <tuple>

#include "travel/eval/Metrics.hpp"
#include "travel/eval/ObjectMetrics.hpp"

namespace travel {

namespace {

double percent(std::size_t part, std::size_t whole) {
    return whole ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 100.0;
}

double totalMs(const StageTimings& t) {
    return t.ground_total + t.objects_total;
}

bool sameGeometry(const TerrainSummary& a, const TerrainSummary& b) {
    return a.resolution == b.resolution && a.cells_per_side == b.cells_per_side &&
           a.origin_xy == b.origin_xy;
}

/// Nodes traversable in exactly one of the two models (both lists ascend by index).
std::size_t changedTraversable(const TerrainSummary& golden, const TerrainSummary& run) {
    if (!sameGeometry(golden, run)) return golden.numTraversable() + run.numTraversable();
    std::size_t changed = 0, g = 0, r = 0;
    const auto& a = golden.nodes;
    const auto& b = run.nodes;
    while (g < a.size() || r < b.size()) {
        if (r == b.size() || (g < a.size() && a[g].index < b[r].index)) {
            changed += a[g++].traversable;
        } else if (g == a.size() || b[r].index < a[g].index) {
            changed += b[r++].traversable;
        } else {
            changed += a[g++].traversable != b[r++].traversable;
        }
    }
    return changed;
}

struct IdPair {
    uint32_t golden, run;
    bool operator<(const IdPair& o) const {
        return golden != o.golden ? golden < o.golden : run < o.run;
    }
    bool operator==(const IdPair& o) const { return golden == o.golden && run == o.run; }
};

/// Clusters of the two runs: overlaps, one-to-one matching, split and merged golden clusters.
void compareClusters(const LabelledFrame& golden, const LabelledFrame& run, FrameComparison& c) {
    const std::size_t n = golden.size();
    const bool have_ids = golden.clusterId.size() == n && run.clusterId.size() == n;
    if (!have_ids) return;
    std::vector<IdPair> pairs;  // points in a cluster in either run
    std::vector<std::size_t> run_size;
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t g = golden.clusterId[i], r = run.clusterId[i];
        if (r != 0) {
            if (r >= run_size.size()) run_size.resize(r + 1, 0);
            ++run_size[r];
        }
        if (g != 0 || r != 0) pairs.push_back({g, r});
    }
    c.clustered_points = pairs.size();
    std::sort(pairs.begin(), pairs.end());

    // Overlap of each (golden, run) pair of clusters.
    struct Overlap {
        uint32_t golden, run;
        std::size_t points;
    };
    std::vector<Overlap> overlaps;
    for (std::size_t a = 0; a < pairs.size();) {
        std::size_t b = a;
        while (b < pairs.size() && pairs[b] == pairs[a]) ++b;
        if (pairs[a].golden != 0 && pairs[a].run != 0)
            overlaps.push_back({pairs[a].golden, pairs[a].run, b - a});
        a = b;
    }
    // Greedy one-to-one matching by decreasing overlap (deterministic ties).
    std::sort(overlaps.begin(), overlaps.end(), [](const Overlap& x, const Overlap& y) {
        return std::tie(y.points, x.golden, x.run) < std::tie(x.points, y.golden, y.run);
    });
    std::vector<char> golden_used, run_used(run_size.size(), 0);
    for (const Overlap& o : overlaps) {
        if (o.golden >= golden_used.size()) golden_used.resize(o.golden + 1, 0);
        if (golden_used[o.golden] || run_used[o.run]) continue;
        golden_used[o.golden] = run_used[o.run] = 1;
        ++c.matched_clusters;
        c.matched_points += o.points;
    }
    c.cluster_agreement = percent(c.matched_points, c.clustered_points);

    // Split / merged golden clusters: the pairs of one golden id are contiguous, run ids
    // ascending.
    for (std::size_t s = 0; s < pairs.size();) {
        std::size_t e = s;
        while (e < pairs.size() && pairs[e].golden == pairs[s].golden) ++e;
        if (pairs[s].golden != 0) {
            ++c.golden_clusters;
            const GroupInClusters group =
                locateGroup(e - s, [&](std::size_t k) { return pairs[s + k].run; });
            c.split += group.split();
            c.merged += group.best_cluster != 0 && group.mergedInto(run_size[group.best_cluster]);
        }
        s = e;
    }
    for (std::size_t r = 1; r < run_size.size(); ++r) c.run_clusters += run_size[r] != 0;
}

void addInto(FrameComparison& sum, const FrameComparison& f) {
    sum.golden_points += f.golden_points, sum.run_points += f.run_points;
    sum.size_mismatch = sum.size_mismatch || f.size_mismatch;
    for (int g = 0; g < 4; ++g)
        for (int r = 0; r < 4; ++r) sum.confusion[g][r] += f.confusion[g][r];
    sum.class_changed += f.class_changed;
    sum.golden_clusters += f.golden_clusters, sum.run_clusters += f.run_clusters;
    sum.matched_clusters += f.matched_clusters;
    sum.split += f.split, sum.merged += f.merged;
    sum.clustered_points += f.clustered_points, sum.matched_points += f.matched_points;
    sum.golden_traversable += f.golden_traversable, sum.run_traversable += f.run_traversable;
    sum.changed_nodes += f.changed_nodes;
    sum.golden_ms += f.golden_ms, sum.run_ms += f.run_ms;
}

const char* className(int c) {
    return toString(static_cast<PointClass>(c));
}

std::string fmt(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string fmt(const char* format, ...) {
    char text[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof text, format, args);
    va_end(args);
    return text;
}

/// "ground -> nonground 120, nonground -> ground 4" (the changed classes, most points first).
std::string classChangesText(const FrameComparison& c, std::size_t max_items) {
    std::vector<std::tuple<uint64_t, int, int>> changes;
    for (int g = 0; g < 4; ++g)
        for (int r = 0; r < 4; ++r)
            if (g != r && c.confusion[g][r]) changes.emplace_back(c.confusion[g][r], g, r);
    std::sort(changes.begin(), changes.end(), [](const auto& a, const auto& b) {
        return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) > std::get<0>(b) : a < b;
    });
    std::string text;
    for (std::size_t k = 0; k < changes.size() && k < max_items; ++k) {
        const auto& [n, g, r] = changes[k];
        text += (text.empty() ? "" : ", ") +
                fmt("%s -> %s %" PRIu64, className(g), className(r), static_cast<uint64_t>(n));
    }
    return text.empty() ? "none" : text;
}

}  // namespace

double FrameComparison::badness() const {
    if (size_mismatch) return 1e18;
    return static_cast<double>(class_changed) +
           static_cast<double>(clustered_points - matched_points) + 10.0 * changed_nodes;
}

FrameComparison compareFrames(const LabelledFrame& golden, const LabelledFrame& run) {
    FrameComparison c;
    c.golden_points = golden.size(), c.run_points = run.size();
    c.golden_ms = totalMs(golden.timings), c.run_ms = totalMs(run.timings);
    c.golden_traversable = golden.terrain.numTraversable();
    c.run_traversable = run.terrain.numTraversable();
    c.changed_nodes = changedTraversable(golden.terrain, run.terrain);
    if (golden.size() != run.size()) {
        c.size_mismatch = true;
        c.class_agreement = c.cluster_agreement = 0;
        c.class_changed = std::max(golden.size(), run.size());
        return c;
    }
    for (std::size_t i = 0; i < golden.size(); ++i)
        ++c.confusion[golden.labels[i] & 3u][run.labels[i] & 3u];
    for (int g = 0; g < 4; ++g)
        for (int r = 0; r < 4; ++r)
            if (g != r) c.class_changed += c.confusion[g][r];
    c.class_agreement = percent(golden.size() - c.class_changed, golden.size());
    compareClusters(golden, run, c);
    return c;
}

std::vector<uint8_t> classChanges(const LabelledFrame& golden, const LabelledFrame& run) {
    std::vector<uint8_t> changed;
    if (golden.size() != run.size()) return changed;
    changed.resize(golden.size());
    for (std::size_t i = 0; i < golden.size(); ++i) changed[i] = golden.labels[i] != run.labels[i];
    return changed;
}

FrameComparison RegressionReport::total() const {
    FrameComparison sum;
    for (const Frame& f : compared_) addInto(sum, f.comparison);
    const std::size_t points = std::max(sum.golden_points, sum.run_points);
    sum.class_agreement = percent(points - std::min(points, sum.class_changed), points);
    sum.cluster_agreement = percent(sum.matched_points, sum.clustered_points);
    return sum;
}

double RegressionReport::timeRatio() const {
    std::vector<double> ratios;
    for (const Frame& f : compared_)
        if (f.comparison.golden_ms > 0)
            ratios.push_back(f.comparison.run_ms / f.comparison.golden_ms);
    return median(ratios);
}

std::vector<std::size_t> RegressionReport::worstFrames(std::size_t n) const {
    std::vector<std::size_t> order;
    for (std::size_t k = 0; k < compared_.size(); ++k)
        if (compared_[k].comparison.badness() > 0) order.push_back(k);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return compared_[a].comparison.badness() > compared_[b].comparison.badness();
    });
    if (order.size() > n) order.resize(n);
    return order;
}

RegressionVerdict RegressionReport::verdict(const RegressSection& tol) const {
    RegressionVerdict v;
    const FrameComparison sum = total();
    double worst_class = 100;
    std::size_t worst_frame = 0;
    for (std::size_t k = 0; k < compared_.size(); ++k)
        if (compared_[k].comparison.class_agreement < worst_class)
            worst_class = compared_[k].comparison.class_agreement, worst_frame = k;
    const auto fail = [&](const std::string& why) { v.failures.push_back(why); };
    if (compared_.empty()) fail("no frame compared");
    if (worst_class < tol.min_class_agreement)
        fail(fmt("class agreement %.3f %% in frame %zu < min_class_agreement %g %%", worst_class,
                 worst_frame, tol.min_class_agreement));
    if (sum.cluster_agreement < tol.min_cluster_agreement)
        fail(fmt("cluster agreement %.3f %% < min_cluster_agreement %g %%", sum.cluster_agreement,
                 tol.min_cluster_agreement));
    if (sum.split > static_cast<std::size_t>(tol.max_split_clusters))
        fail(fmt("%zu split clusters > max_split_clusters %d", sum.split, tol.max_split_clusters));
    if (sum.merged > static_cast<std::size_t>(tol.max_merged_clusters))
        fail(fmt("%zu merged clusters > max_merged_clusters %d", sum.merged,
                 tol.max_merged_clusters));
    if (sum.changed_nodes > static_cast<std::size_t>(tol.max_changed_nodes))
        fail(fmt("%zu traversable nodes changed > max_changed_nodes %d", sum.changed_nodes,
                 tol.max_changed_nodes));
    if (missing_.size() > static_cast<std::size_t>(tol.max_missing_frames))
        fail(fmt("%zu golden frames missing > max_missing_frames %d", missing_.size(),
                 tol.max_missing_frames));
    if (extra_.size() > static_cast<std::size_t>(tol.max_extra_frames))
        fail(fmt("%zu extra frames > max_extra_frames %d", extra_.size(), tol.max_extra_frames));
    const double ratio = timeRatio();
    if (tol.max_time_ratio > 0 && ratio > tol.max_time_ratio)
        fail(fmt("time ratio %.2f > max_time_ratio %g", ratio, tol.max_time_ratio));
    v.passed = v.failures.empty();

    std::size_t changed_frames = 0;
    for (const Frame& f : compared_) changed_frames += f.comparison.badness() > 0;
    v.line =
        fmt("%s: %zu frames compared (%zu differ), %zu missing, %zu extra; class agreement "
            "%.3f %%, cluster agreement %.3f %%, split %zu, merged %zu, traversable nodes "
            "changed %zu, time x%.2f",
            v.passed ? "PASS" : "FAIL", compared_.size(), changed_frames, missing_.size(),
            extra_.size(), sum.class_agreement, sum.cluster_agreement, sum.split, sum.merged,
            sum.changed_nodes, ratio);
    if (!v.passed) {
        v.line += " (";
        for (std::size_t k = 0; k < v.failures.size(); ++k)
            v.line += (k ? "; " : "") + v.failures[k];
        v.line += ")";
    }
    return v;
}

void RegressionReport::writeCsv(std::ostream& out) const {
    out << "frame,status,timestamp,sensor_label,golden_points,run_points,class_changed,"
           "class_agreement";
    for (int g = 0; g < 4; ++g)
        for (int r = 0; r < 4; ++r)
            if (g != r) out << ',' << className(g) << "_to_" << className(r);
    out << ",golden_clusters,run_clusters,matched_clusters,split,merged,cluster_agreement,"
           "golden_traversable,run_traversable,changed_nodes,golden_ms,run_ms\n";
    for (std::size_t k = 0; k < compared_.size(); ++k) {
        const Frame& f = compared_[k];
        const FrameComparison& c = f.comparison;
        out << fmt("%zu,%s,%.6f,%s,%zu,%zu,%zu,%.4f", k,
                   c.size_mismatch ? "size_mismatch" : "compared", f.key.seconds,
                   f.key.label.c_str(), c.golden_points, c.run_points, c.class_changed,
                   c.class_agreement);
        for (int g = 0; g < 4; ++g)
            for (int r = 0; r < 4; ++r)
                if (g != r) out << ',' << c.confusion[g][r];
        out << fmt(",%zu,%zu,%zu,%zu,%zu,%.4f,%zu,%zu,%zu,%.3f,%.3f\n", c.golden_clusters,
                   c.run_clusters, c.matched_clusters, c.split, c.merged, c.cluster_agreement,
                   c.golden_traversable, c.run_traversable, c.changed_nodes, c.golden_ms, c.run_ms);
    }
    const auto absent = [&](const FrameKey& key, const char* status) {
        out << fmt(",%s,%.6f,%s", status, key.seconds, key.label.c_str());
        for (int k = 0; k < 27; ++k) out << ',';  // the comparison columns, empty
        out << '\n';
    };
    for (const FrameKey& key : missing_) absent(key, "missing");
    for (const FrameKey& key : extra_) absent(key, "extra");
}

void RegressionReport::writeMarkdown(
    std::ostream& out, const std::string& title, const RegressSection& tol,
    const std::vector<std::pair<std::size_t, std::string>>& pictures) const {
    const RegressionVerdict v = verdict(tol);
    const FrameComparison sum = total();
    out << "# " << title << "\n\n**" << v.line << "**\n\n";
    if (!v.failures.empty()) {
        out << "Outside the tolerances:\n\n";
        for (const std::string& why : v.failures) out << "- " << why << "\n";
        out << "\n";
    }
    out << "## Totals\n\n| | golden | run |\n|---|---:|---:|\n";
    out << fmt("| points | %zu | %zu |\n", sum.golden_points, sum.run_points);
    out << fmt("| clusters | %zu | %zu |\n", sum.golden_clusters, sum.run_clusters);
    out << fmt("| traversable nodes | %zu | %zu |\n", sum.golden_traversable, sum.run_traversable);
    out << fmt("| TRAVEL ms (sum) | %.1f | %.1f |\n\n", sum.golden_ms, sum.run_ms);

    out << "## Classes (rows: golden, columns: run)\n\n| golden \\ run |";
    for (int r = 0; r < 4; ++r) out << ' ' << className(r) << " |";
    out << "\n|---|---:|---:|---:|---:|\n";
    for (int g = 0; g < 4; ++g) {
        out << "| " << className(g) << " |";
        for (int r = 0; r < 4; ++r) out << ' ' << sum.confusion[g][r] << " |";
        out << "\n";
    }
    // Ground as the positive class, the golden run as the truth.
    ConfusionCounts ground;
    const int G = static_cast<int>(PointClass::Ground);
    for (int g = 0; g < 4; ++g)
        for (int r = 0; r < 4; ++r) {
            const uint64_t n = sum.confusion[g][r];
            if (g == G && r == G)
                ground.tp += n;
            else if (g == G)
                ground.fn += n;
            else if (r == G)
                ground.fp += n;
            else
                ground.tn += n;
        }
    const GroundScores scores = scoresFrom(ground);
    out << fmt(
        "\nClass agreement %.3f %% (%zu points changed). Ground against the golden ground: "
        "precision %.3f %%, recall %.3f %%.\n\n",
        sum.class_agreement, sum.class_changed, scores.precision, scores.recall);
    out << fmt(
        "## Clusters\n\nCluster agreement %.3f %% (%zu of %zu clustered points in "
        "one-to-one matched clusters, %zu of %zu golden clusters matched); split %zu, "
        "merged %zu.\n\n",
        sum.cluster_agreement, sum.matched_points, sum.clustered_points, sum.matched_clusters,
        sum.golden_clusters, sum.split, sum.merged);

    out << "## Frames that differ\n\n";
    const std::vector<std::size_t> worst = worstFrames(compared_.size());
    if (worst.empty())
        out << "None.\n\n";
    else {
        out << "| frame | time [s] | sensor | changed points | classes changed | cluster "
               "agreement | split | merged | nodes changed |\n"
               "|---:|---:|---|---:|---|---:|---:|---:|---:|\n";
        for (std::size_t k : worst) {
            const Frame& f = compared_[k];
            const FrameComparison& c = f.comparison;
            out << fmt("| %zu | %.6f | %s | %zu | %s | %.3f %% | %zu | %zu | %zu |\n", k,
                       f.key.seconds, f.key.label.c_str(), c.class_changed,
                       c.size_mismatch ? "point counts differ" : classChangesText(c, 4).c_str(),
                       c.cluster_agreement, c.split, c.merged, c.changed_nodes);
        }
        out << "\n";
    }
    const auto listKeys = [&](const std::vector<FrameKey>& keys, const char* what) {
        out << "## " << what << "\n\n";
        if (keys.empty()) out << "None.\n\n";
        for (const FrameKey& key : keys)
            out << fmt("- %.6f s, %s\n", key.seconds, key.label.c_str());
        if (!keys.empty()) out << "\n";
    };
    listKeys(missing_, "Golden frames missing from the run");
    listKeys(extra_, "Frames of the run without a golden frame");
    out << fmt("## Timing\n\nMedian run / golden TRAVEL time per frame: x%.2f%s.\n\n", timeRatio(),
               tol.max_time_ratio > 0 ? "" : " (not checked: max_time_ratio = 0)");
    if (!pictures.empty()) {
        out << "## Differences, bird's-eye (changed points in black over the golden classes)\n\n";
        for (const auto& [k, file] : pictures)
            out << "Frame " << k << ":\n\n![frame " << k << "](" << file << ")\n\n";
    }
}

}  // namespace travel
