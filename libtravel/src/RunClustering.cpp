// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Above-ground object segmentation (paper Sec. IV). Decisions (travel-algorithm.md Sec. 3):
// * Every non-ground point is clustered: several points may share a range-image cell (none is
//   dropped, unlike the reference which keeps the first point of a cell).
// * Distances are 3-D Euclidean everywhere (the reference uses xy distance only, which merges
//   objects stacked above one another, e.g. a canopy over a car).
// * Skipped linkage at point level: a point continues the most recent of the last T_skip + 1
//   open runs of its ring whose end is within T_horz. This is the paper's "run i merges with
//   runs up to T_skip ahead when their facing end points are close", applied as the ring is
//   swept, and it keeps a run's points together when a nearer object interleaves with it (two
//   points in one column).
// * Occlusions: a distance test alone cannot bridge the shadow of an occluder, which grows
//   with the distance ratio (a 0.24 m pole at 13 m hides 0.47 m of a wall at 26 m). A point
//   also continues an open run when the gap is at most occlusion_max_gap, the two ends' ranges
//   differ by less than T_horz, and every point seen in between is nearer than both ends by
//   more than T_horz (it is in front: an occluder, not a gap in the object).
// * Circular linkage: the runs still open at the end of a ring (up to T_skip + 1) are compared
//   with its first runs across the 0/360-degree seam; this also covers rings with one or two
//   runs. (Runs are not linked vertically across the seam: an object seen on one side of it
//   in one ring and only on the other side in the next stays split; rare, not handled.)
// * Vertical merges scale with range (extends the vertical update, Sec. IV-C): points of rows
//   k apart are at least R * (angle between the rows) apart even on one vertical surface: 0.15 m
//   per HDL-64E ring at 25 m, 0.66 m across T_ring = 3 lower-block rings, 0.5 m (T_vert
//   itself) per ring at 57 m. So T_vert is the separation beyond that forced one: two runs
//   merge when their points are closer than sqrt(T_vert^2 + (R * dtheta)^2), R the upper
//   point's range (points at R1, R2 on rays dtheta apart are at least max(R1, R2) dtheta
//   apart; the run's farthest range would lend an oblique wall's far end to its near points),
//   dtheta one ring's spacing (the rows' mean elevations apart / rows apart). A vertical surface
//   with missing rings (dark paint, windows) stays one object at 25-80 m; at 10 m the bound grows
//   by at most 2 cm per ring.
// * Seam linkage (extends the circular linkage): a spinning sensor sees the two sides of the
//   column where its sweep started 0.1 s apart, so an object moving relative to it (oncoming
//   traffic, or anything while the ego vehicle drives) is cut there and its halves are shifted
//   by v * 0.1 s (1.5 m at 15 m/s), beyond T_horz. Runs of a ring ending and starting within
//   kSeamColumns of RangeImage::sweepStartColumn() merge when their facing ends are closer than
//   seam_max_shift. Only runs touching that one column qualify, so the looser distance cannot
//   chain objects elsewhere.
// * See-through linkage (windows; extends the horizontal update): rays through a car's glass
//   return from its seats or far side, 1-2.5 m behind the body around the window, beyond
//   T_horz and T_vert: on KITTI a car at 28 m kept its windows' returns as two clusters (a
//   tenth of its points). A run is seen through a gap when the nearest points before and after
//   it on its ring (within kEnclosureWalk points) are in front of all its points by more than
//   T_horz, belong to one cluster, are at most occlusion_max_gap apart, and its farthest point
//   is at most see_through_depth behind them (a run seen through a gap but farther behind it
//   is an object beyond the enclosing one, e.g. a car parked behind a car, and keeps its
//   cluster apart). Nor does a cluster with a run lying more than see_through_width behind the
//   near face of a car-high enclosing cluster (z extent <= 2 m), measured in xy across the face
//   (the line through that cluster's nearest points on either side of the run, within
//   occlusion_max_gap): a car's far side is at most its width behind the near window frame
//   whatever the viewing angle, while the depth along the ray grows to 2.5 m at 45 degrees; a
//   child or a car 0.2-0.6 m behind a car's far side is deeper. Taller clusters (vans, trucks
//   and buses up to 2.55 m wide; trees) keep the depth bound only. A cluster joins the
//   enclosing one when all its
//   runs seen through gaps are seen through that one cluster's, it lies inside that cluster's
//   range-image box, behind its nearest point, is smaller, and at least one of its runs has
//   the enclosing cluster's points in front of it within two rows above or below (a window is
//   a hole, closed by roof and door; the gap between fence panels is a slot, open above and
//   below: a car behind a fence, seen only through the slots, stays apart).
// * Set-back linkage (issue 14; extends the vertical update): seen end on at 20-25 m, a sedan's
//   rings pass over its rear face (or bonnet) onto the cabin 0.6-1.2 m (1.5-2.2 m) behind it; the
//   boot lid or bonnet between, seen at a grazing angle of 2 degrees, spreads adjacent rings
//   metres apart and is hit by one ring or none, so the depth jump between the face's top row
//   and the cabin's lowest is beyond T_vert and the car fell in two. A cluster standing on a
//   nearer one (every run of its lowest row has that cluster's points in front of it, by more
//   than T_horz, in the row below) joins it when it lies within that cluster's columns, spans
//   at least half of them (a cabin spans 0.8-0.9 of its body, a person behind a car a third
//   or less), and its nearest point is at most set_back_depth behind that cluster's (a bonnet
//   reaches 1.6 m; a car parked behind a car seen side on is 1.8 m or more behind it).
// * Merges through union-find with path halving; the root of a set is its smallest run index.
#include "travel/RunClustering.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#ifdef __SSE2__
#include <emmintrin.h>
#endif
#include <array>

#include "CpuDispatch.hpp"
#include "Prefault.hpp"
#include "travel/TerrainModel.hpp"
#include "travel/TriGridField.hpp"

namespace travel {

inline float RunClustering::dist2(uint32_t a, uint32_t b) const {
    const SortedPoint &p = pts_[a], &q = pts_[b];
    const float dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
    return dx * dx + dy * dy + dz * dz;
}

namespace {

// out[k] = std::sqrt(x^2 + y^2 + z^2) of p[k], the same floats, 4 at a time: std::sqrt keeps
// a branch for errno that stops GCC from vectorising, and Eigen's fast-math sqrt is approximate.
template <class Point>
void computeRanges(const Point* p, float* out, uint32_t n) {
    static_assert(sizeof(Point) == 4 * sizeof(float));
    uint32_t k = 0;
#ifdef __SSE2__
    for (; k + 4 <= n; k += 4) {
        // Four points (x, y, z, column bits) transposed into x, y, z lanes.
        __m128 vx = _mm_loadu_ps(&p[k].x), vy = _mm_loadu_ps(&p[k + 1].x);
        __m128 vz = _mm_loadu_ps(&p[k + 2].x), vw = _mm_loadu_ps(&p[k + 3].x);
        _MM_TRANSPOSE4_PS(vx, vy, vz, vw);
        const __m128 sum =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(vx, vx), _mm_mul_ps(vy, vy)), _mm_mul_ps(vz, vz));
        _mm_storeu_ps(out + k, _mm_sqrt_ps(sum));
    }
#endif
    for (; k < n; ++k) out[k] = std::sqrt(p[k].x * p[k].x + p[k].y * p[k].y + p[k].z * p[k].z);
}

// c[k] += c[k - 1] for k = 1..n-1 (the same integers as the scalar loop), 4 at a time: the
// counting sort's offsets over every range-image cell, most of them empty on sparse scans, and
// the vertical update's per-column tables.
void inclusivePrefixSum(uint32_t* c, std::size_t n) {
    std::size_t k = 0;
#ifdef __SSE2__
    __m128i carry = _mm_setzero_si128();  // the last sum, in every lane
    for (; k + 4 <= n; k += 4) {
        __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + k));
        x = _mm_add_epi32(x, _mm_slli_si128(x, 4));
        x = _mm_add_epi32(x, _mm_slli_si128(x, 8));
        x = _mm_add_epi32(x, carry);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(c + k), x);
        carry = _mm_shuffle_epi32(x, 0xff);
    }
#endif
    for (k = std::max<std::size_t>(k, 1); k < n; ++k) c[k] += c[k - 1];
}

// The non-ground points with a row, in input order: their input indices and keys
// row * cols + col, in input[0, total) and key[0, total); returns total. Branch-free (ground and
// non-ground points alternate unpredictably); input and key hold n values.
uint32_t compactScalar(const int16_t* row, const int32_t* col, const PointClass* labels,
                       std::size_t begin, std::size_t n, int cols, uint32_t total, uint32_t* input,
                       uint32_t* key) {
    for (std::size_t i = begin; i < n; ++i) {
        input[total] = static_cast<uint32_t>(i);
        key[total] = static_cast<uint32_t>(row[i] * cols + col[i]);
        total += labels[i] == PointClass::NonGround && row[i] >= 0;
    }
    return total;
}

#ifdef TRAVEL_AVX2_INTRINSICS
// For each 8-bit mask, the lanes whose bit is set, in order (the rest: 0).
constexpr std::array<std::array<int32_t, 8>, 256> kLeftPack = [] {
    std::array<std::array<int32_t, 8>, 256> table{};
    for (int mask = 0; mask < 256; ++mask) {
        int k = 0;
        for (int lane = 0; lane < 8; ++lane)
            if (mask & (1 << lane)) table[mask][k++] = lane;
    }
    return table;
}();

// compactScalar() 8 points at a time: the selected lanes' indices and keys moved to the front
// (vpermd with kLeftPack) and stored at `total`; the same values.
__attribute__((target("avx2,popcnt"))) uint32_t compactAvx2(const int16_t* row, const int32_t* col,
                                                            const PointClass* labels, std::size_t n,
                                                            int cols, uint32_t* input,
                                                            uint32_t* key) {
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i columns = _mm256_set1_epi32(cols);
    const __m256i non_ground = _mm256_set1_epi32(static_cast<int>(PointClass::NonGround));
    const __m256i minus_one = _mm256_set1_epi32(-1);
    uint32_t total = 0;
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i r =
            _mm256_cvtepi16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(row + i)));
        const __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(col + i));
        const __m256i k = _mm256_add_epi32(_mm256_mullo_epi32(r, columns), c);
        const __m256i label =
            _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(labels + i)));
        const __m256i selected = _mm256_and_si256(_mm256_cmpeq_epi32(label, non_ground),
                                                  _mm256_cmpgt_epi32(r, minus_one));
        const int mask = _mm256_movemask_ps(_mm256_castsi256_ps(selected));
        const __m256i pack =
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kLeftPack[mask].data()));
        const __m256i index = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(i)), lanes);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(input + total),
                            _mm256_permutevar8x32_epi32(index, pack));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(key + total),
                            _mm256_permutevar8x32_epi32(k, pack));
        total += static_cast<uint32_t>(__builtin_popcount(static_cast<unsigned>(mask)));
    }
    return compactScalar(row, col, labels, i, n, cols, total, input, key);
}
#endif

uint32_t compact(const int16_t* row, const int32_t* col, const PointClass* labels, std::size_t n,
                 int cols, uint32_t* input, uint32_t* key) {
#ifdef TRAVEL_AVX2_INTRINSICS
    if (detail::cpuHasAvx2()) return compactAvx2(row, col, labels, n, cols, input, key);
#endif
    return compactScalar(row, col, labels, 0, n, cols, 0, input, key);
}

// A run's bounding box while the horizontal sweep grows it: the same floats as per-axis
// std::min / std::max of x, y, z; stored into a RunBox with its fourth lane 0.
struct GrowBox {
#ifdef __SSE2__
    __m128 lo = _mm_setzero_ps(), hi = _mm_setzero_ps();  // 4th lane: column bits, ignored
    template <class Point>
    void start(const Point& p) {
        lo = hi = _mm_loadu_ps(&p.x);
    }
    template <class Point>
    void add(const Point& p) {
        // min(p, lo) is (p < lo ? p : lo), as std::min(lo, p); max likewise.
        const __m128 v = _mm_loadu_ps(&p.x);
        lo = _mm_min_ps(v, lo), hi = _mm_max_ps(v, hi);
    }
    template <class Box>
    void load(const Box& box) {
        lo = _mm_loadu_ps(box.lo.data()), hi = _mm_loadu_ps(box.hi.data());
    }
    template <class Box>
    void store(Box& box) const {
        const __m128 xyz = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
        _mm_storeu_ps(box.lo.data(), _mm_and_ps(lo, xyz));
        _mm_storeu_ps(box.hi.data(), _mm_and_ps(hi, xyz));
    }
#else
    float lo[3] = {}, hi[3] = {};
    template <class Point>
    void start(const Point& p) {
        lo[0] = hi[0] = p.x, lo[1] = hi[1] = p.y, lo[2] = hi[2] = p.z;
    }
    template <class Point>
    void add(const Point& p) {
        const float v[3] = {p.x, p.y, p.z};
        for (int axis = 0; axis < 3; ++axis)
            lo[axis] = std::min(lo[axis], v[axis]), hi[axis] = std::max(hi[axis], v[axis]);
    }
    template <class Box>
    void load(const Box& box) {
        for (int axis = 0; axis < 3; ++axis) lo[axis] = box.lo[axis], hi[axis] = box.hi[axis];
    }
    template <class Box>
    void store(Box& box) const {
        for (int axis = 0; axis < 3; ++axis) box.lo[axis] = lo[axis], box.hi[axis] = hi[axis];
        box.lo[3] = box.hi[3] = 0.f;
    }
#endif
};

}  // namespace

inline int RunClustering::find(int run) {
    while (parent_[run] != run) {
        parent_[run] = parent_[parent_[run]];  // path halving
        run = parent_[run];
    }
    return run;
}

void RunClustering::unite(int a, int b) {
    a = find(a), b = find(b);
    if (a == b) return;
    if (a < b)
        parent_[b] = a;
    else
        parent_[a] = b;
}

void RunClustering::reserve(std::size_t points, std::size_t cells) {
    using detail::prefault;
    prefault(key_count_, cells + 1);
    prefault(sorted_, points), prefault(pts_, points), prefault(point_run_, points);
    prefault(range_, points);
    prefault(next_in_run_, points), prefault(point_id_, points);
    prefault(input_, points), prefault(key_, points);
    // Runs: a few points each on real scans; more grow the buffers once.
    const std::size_t runs = points / 4 + 1;
    prefault(run_first_, runs), prefault(run_last_, runs);
    prefault(run_far_range_, runs), prefault(run_near_range_, runs);
    prefault(run_col_begin_, runs), prefault(run_col_end_, runs), prefault(run_row_, runs);
    prefault(parent_, runs), prefault(merge_dist2_, runs + 4), prefault(near_, runs);
    prefault(blocks_, 4 * 4096);
    prefault(run_size_, runs), prefault(run_first_input_, runs);
    prefault(run_box_, runs), prefault(box_arrays_, 6 * (runs + 4));
    prefault(run_root_, runs), prefault(run_id_, runs), prefault(root_size_, runs);
    prefault(root_first_, runs), prefault(root_id_, runs), prefault(root_order_, runs);
    prefault(root_box_, runs), prefault(involved_, runs);
    // vertical()'s per-column tables: T_ring + 1 rows of columns + 1 entries (the default T_ring
    // = 3 with up to 4096 columns; more grow once).
    prefault(first_run_, std::min<std::size_t>(cells + 1, 4 * 4097));
}

void RunClustering::horizontal(const AlignedCloud& cloud, const RangeImage& image,
                               const std::vector<PointClass>& labels, const Params& params) {
    const int rows = image.rows(), cols = image.cols();
    cols_ = cols;
    const std::vector<int16_t>& row = image.row();
    const std::vector<int32_t>& col = image.col();
    const std::size_t n = labels.size();

    // Counting sort of the non-ground points by (row, column); stable, so points sharing a
    // cell stay in input order (deterministic). The points to sort and their keys are first
    // gathered without branches (ground and non-ground points alternate unpredictably).
    const std::size_t num_keys = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    key_count_.assign(num_keys + 1, 0);
    input_.resize(n), key_.resize(n);
    const uint32_t total =
        compact(row.data(), col.data(), labels.data(), n, cols, input_.data(), key_.data());
    for (uint32_t m = 0; m < total; ++m) ++key_count_[key_[m] + 1];
    inclusivePrefixSum(key_count_.data(), num_keys + 1);
    row_begin_.resize(rows + 1);
    for (int r = 0; r <= rows; ++r) row_begin_[r] = key_count_[static_cast<std::size_t>(r) * cols];
    sorted_.resize(total), pts_.resize(total), range_.resize(total);
    for (uint32_t m = 0; m < total; ++m) {
        const uint32_t i = input_[m];
        const uint32_t slot = key_count_[key_[m]]++;
        sorted_[slot] = i;
        // Contiguous copies in sorted order: every later access is by sorted position.
        pts_[slot] = {cloud.x[i], cloud.y[i], cloud.z[i], col[i]};
    }
    computeRanges(pts_.data(), range_.data(), total);
    row_elevation_.assign(static_cast<std::size_t>(rows), 0.f);

    // Runs, ring by ring.
    run_first_.clear(), run_last_.clear(), run_col_begin_.clear(), run_col_end_.clear();
    run_row_.clear(), parent_.clear(), run_far_range_.clear(), run_near_range_.clear();
    run_size_.clear(), run_first_input_.clear(), run_box_.clear();
    point_run_.resize(total), next_in_run_.assign(total, kEndOfRun);
    row_runs_begin_.assign(rows + 1, 0);
    const float t_horz = static_cast<float>(params.horizontal_merge_dist);
    const float merge2 = t_horz * t_horz;
    const float occlusion2 =
        static_cast<float>(params.occlusion_max_gap * params.occlusion_max_gap);
    const std::size_t max_open = static_cast<std::size_t>(params.horizontal_skip_runs) + 1;
    const int seam_col = image.sweepStartColumn();
    const float seam2 = static_cast<float>(params.seam_max_shift * params.seam_max_shift);
    const SortedPoint* pts = pts_.data();
    const float* ranges = range_.data();
    const uint32_t* sorted = sorted_.data();
    uint32_t* next_in_run = next_in_run_.data();
    int32_t* point_run = point_run_.data();
    open_runs_.resize(max_open);
    int32_t* const open_runs = open_runs_.data();
    for (int r = 0; r < rows; ++r) {
        row_runs_begin_[r] = static_cast<uint32_t>(run_first_.size());
        std::size_t open = 0;  // open_runs[0, open), most recent last
        // Puts `run` in the most recent slot, open_runs[slot] leaving and the later ones moving
        // one slot down (a rotation through swaps: GCC makes the plain copy loop a memmove call).
        auto pushOpen = [&](std::size_t slot, int32_t run) {
            for (std::size_t s = open; s-- > slot;) std::swap(run, open_runs[s]);
        };
        // The most recent open run, whose points mostly follow one another: its box, ranges,
        // size and first input point are kept here (registers) and written back when another
        // run takes a point (one store per point instead of a dozen read-modify-writes). The
        // box is two 4-lane registers (x, y, z and the column's bits, ignored): fewer
        // registers than six floats, so the sweep's state does not spill to the stack.
        int current = -1;
        GrowBox box;
        float far = 0, near = 0;
        uint32_t size = 0, first_input = 0;
        auto store = [&] {
            box.store(run_box_[current]);
            run_far_range_[current] = far, run_near_range_[current] = near;
            run_size_[current] = size, run_first_input_[current] = first_input;
            run_col_end_[current] = pts[run_last_[current]].col;
        };
        auto load = [&](int run) {
            box.load(run_box_[run]);
            far = run_far_range_[run], near = run_near_range_[run];
            size = run_size_[run], first_input = run_first_input_[run];
            current = run;
        };
        auto extend = [&](uint32_t k, float range) {  // current takes sorted point k
            box.add(pts[k]);
            far = std::max(far, range), near = std::min(near, range);
            ++size;
            first_input = std::min(first_input, sorted[k]);
        };
        // Each row's elevation: the range-weighted mean sine of its points' elevations.
        float sum_z = 0.f, sum_range = 0.f;
        const uint32_t row_end = row_begin_[r + 1];
        for (uint32_t k = row_begin_[r]; k < row_end; ++k) {
            const float range = ranges[k];
            sum_z += pts[k].z, sum_range += range;
            // The most recent open run is `current`, whose last point is k - 1 (every point
            // joins or opens the run that becomes current): the usual case, tested first on
            // consecutive points, without looking up the open runs. Its last point and box
            // stay in registers.
            if (current >= 0 && dist2(k, k - 1) < merge2) {
                next_in_run[k - 1] = k;
                point_run[k] = current;
                extend(k, range);
                continue;
            }
            if (current >= 0) run_last_[current] = k - 1;
            // The most recent other open run that p continues. `current`, the most recent one
            // (open_runs[open - 1]), cannot take it: its end k - 1 failed the test above, and
            // no point lies between them to occlude.
            int joined = -1;
            std::size_t joined_slot = 0;
            for (std::size_t s = open - (open > 0); s-- > 0;) {
                const int o = open_runs[s];
                const uint32_t last = run_last_[o];
                const float d2 = dist2(k, last);
                const float last_range = ranges[last];
                // One branch for both links (the occlusion candidates are rare).
                const bool close = d2 < merge2;
                if (!(close | ((d2 < occlusion2) & (std::fabs(range - last_range) < t_horz))))
                    continue;
                bool link = close;
                if (!close) {
                    // Across an occlusion only if every point swept since the run's end is in
                    // front of both ends (rare: computed only here).
                    const float in_front = std::min(range, last_range) - t_horz;
                    link = last + 1 < k;
                    for (uint32_t j = last + 1; j < k && link; ++j) link = ranges[j] < in_front;
                }
                if (link) {
                    joined = o, joined_slot = s;
                    break;
                }
            }
            if (joined >= 0) {
                next_in_run[run_last_[joined]] = k;
                run_last_[joined] = k;
                point_run[k] = joined;
                if (joined != current) store(), load(joined);
                extend(k, range);
                // Keep the extended run open longest: move it to the most recent slot.
                pushOpen(joined_slot, joined);
                continue;
            }
            if (current >= 0) store();
            const int run = static_cast<int>(run_first_.size());
            run_first_.push_back(k), run_last_.push_back(k);
            run_col_begin_.push_back(pts[k].col), run_col_end_.push_back(pts[k].col);
            run_row_.push_back(static_cast<int16_t>(r));
            parent_.push_back(run);
            // Written by store().
            run_far_range_.emplace_back(), run_near_range_.emplace_back();
            run_size_.emplace_back(), run_first_input_.emplace_back(), run_box_.emplace_back();
            current = run;
            box.start(pts[k]);
            far = near = range, size = 1, first_input = sorted[k];
            point_run[k] = run;
            if (open == max_open)
                pushOpen(0, run);  // the oldest closes
            else
                open_runs[open++] = run;
        }
        if (current >= 0) run_last_[current] = row_end - 1, store();
        if (sum_range > 0.f)
            row_elevation_[r] = std::asin(std::clamp(sum_z / sum_range, -1.f, 1.f));
        if (seam_col >= 0 && seam2 > 0.f)
            linkAcrossSeam(static_cast<int>(row_runs_begin_[r]),
                           static_cast<int>(run_first_.size()), seam_col, cols, seam2);
        // Circular linkage across the seam: the runs still open at the end of the ring (the
        // ones that reach it, whenever they started) against the ring's first runs.
        const int begin = static_cast<int>(row_runs_begin_[r]);
        const int end = static_cast<int>(run_first_.size());
        const int first_runs = static_cast<int>(std::min<std::size_t>(max_open, end - begin));
        for (std::size_t s = 0; s < open; ++s) {
            const int late = open_runs[s];
            for (int early = begin; early < begin + first_runs; ++early)
                if (late != early && dist2(run_last_[late], run_first_[early]) < merge2)
                    unite(late, early);
        }
    }
    row_runs_begin_[rows] = static_cast<uint32_t>(run_first_.size());
}

// Runs [begin, end) of one ring: those whose last column is within kSeamColumns of the seam
// against those whose first column is, the second starting after the first ends (cyclically).
void RunClustering::linkAcrossSeam(int begin, int end, int seam_col, int cols, float max_dist2) {
    // KITTI's rings start up to 0.5 deg (3 columns of 2048) after the cut.
    const auto cyclic = [cols](int a, int b) {  // b - a, wrapped into [-cols / 2, cols / 2)
        int d = (b - a) % cols;
        d += d < -cols / 2 ? cols : 0;
        d -= d >= cols / 2 ? cols : 0;
        return d;
    };
    seam_before_.clear(), seam_after_.clear();
    for (int run = begin; run < end; ++run) {
        if (std::abs(cyclic(seam_col, run_col_end_[run])) <= kSeamColumns)
            seam_before_.push_back(run);
        if (std::abs(cyclic(seam_col, run_col_begin_[run])) <= kSeamColumns)
            seam_after_.push_back(run);
    }
    for (const int a : seam_before_)
        for (const int b : seam_after_) {
            const int gap = cyclic(run_col_end_[a], run_col_begin_[b]);
            if (a != b && gap > 0 && gap <= 2 * kSeamColumns &&
                dist2(run_last_[a], run_first_[b]) < max_dist2)
                unite(a, b);
        }
}

bool RunClustering::runsTouch(int a, int b, int column_window, float t_vert2,
                              float ring_step2) const {
    // Both runs' points are in column order: sweep them together, comparing points whose
    // columns differ by at most column_window. The ring spacing is taken at the range of a's
    // point (see the file comment), so a run reaching far (an oblique wall, a ragged bush) does
    // not lend its far end's spacing to its near points.
    uint32_t jb = run_first_[b];
    const int last_col = run_col_end_[b] + column_window;  // a's points beyond: none near
    for (uint32_t ka = run_first_[a]; ka != kEndOfRun; ka = next_in_run_[ka]) {
        const int ca = pts_[ka].col;
        if (ca > last_col) return false;
        const float max_dist2 = t_vert2 + ring_step2 * range_[ka] * range_[ka];
        while (jb != kEndOfRun && pts_[jb].col < ca - column_window) jb = next_in_run_[jb];
        for (uint32_t kb = jb; kb != kEndOfRun; kb = next_in_run_[kb]) {
            if (pts_[kb].col > ca + column_window) break;
            if (dist2(ka, kb) < max_dist2) return true;
        }
    }
    return false;
}

namespace {

// The vertical update's box test, kBoxLanes runs at a time.
constexpr uint32_t kBoxLanes = 4;

// Run boxes as arrays (lo x, y, z, hi x, y, z): the lanes of the box test are consecutive runs
// of one row.
struct BoxArrays {
    const float* coord[6];
};

// Bit l set when run first + l (first + l < end) and run `fixed` have boxes nearer than
// limit[l] (limit[0] for every lane when broadcast_limit): the squared gap per axis max(0, gap),
// added as x^2 + y^2 + z^2 in that order (the same floats as one pair at a time).
inline unsigned nearLanes(const BoxArrays& box, uint32_t fixed, uint32_t first, uint32_t end,
                          const float* limit, bool broadcast_limit) {
    const uint32_t lanes = end > first ? std::min(end - first, kBoxLanes) : 0;
#ifdef __SSE2__
    const unsigned in_range = (1u << lanes) - 1;
    __m128 gap2[3];
    for (int axis = 0; axis < 3; ++axis) {
        const float* lo = box.coord[axis];
        const float* hi = box.coord[axis + 3];
        const __m128 d1 = _mm_sub_ps(_mm_set1_ps(lo[fixed]), _mm_loadu_ps(hi + first));
        const __m128 d2 = _mm_sub_ps(_mm_loadu_ps(lo + first), _mm_set1_ps(hi[fixed]));
        const __m128 gap = _mm_max_ps(_mm_max_ps(d1, d2), _mm_setzero_ps());
        gap2[axis] = _mm_mul_ps(gap, gap);
    }
    const __m128 sum = _mm_add_ps(_mm_add_ps(gap2[0], gap2[1]), gap2[2]);
    const __m128 lim = broadcast_limit ? _mm_set1_ps(*limit) : _mm_loadu_ps(limit);
    return in_range & static_cast<unsigned>(_mm_movemask_ps(_mm_cmplt_ps(sum, lim)));
#else
    unsigned near = 0;
    for (uint32_t l = 0; l < lanes; ++l) {
        const uint32_t run = first + l;
        float gap2[3];
        for (int axis = 0; axis < 3; ++axis) {
            const float* lo = box.coord[axis];
            const float* hi = box.coord[axis + 3];
            const float gap = std::max(std::max(lo[fixed] - hi[run], lo[run] - hi[fixed]), 0.f);
            gap2[axis] = gap * gap;
        }
        near |= unsigned(gap2[0] + gap2[1] + gap2[2] < limit[broadcast_limit ? 0 : l]) << l;
    }
    return near;
#endif
}

// For each mask of kBoxLanes bits: the lanes set, in order (then 0), and their number.
struct LaneList {
    alignas(16) uint32_t lane[1u << kBoxLanes][kBoxLanes];
    uint8_t count[1u << kBoxLanes];
};
constexpr LaneList kLaneList = [] {
    LaneList list{};
    for (unsigned mask = 0; mask < (1u << kBoxLanes); ++mask)
        for (uint32_t l = 0; l < kBoxLanes; ++l)
            if (mask >> l & 1u) list.lane[mask][list.count[mask]++] = l;
    return list;
}();

// Writes the pairs {fixed, first + l} (fixed_first) or {first + l, fixed} of the lanes l set in
// mask, in lane order, at out[0..]; kBoxLanes pairs are written whatever their number. Returns
// their number.
template <class Pair>
inline uint32_t listPairs(Pair* out, uint32_t fixed, uint32_t first, unsigned mask,
                          bool fixed_first) {
    static_assert(sizeof(Pair) == 2 * sizeof(uint32_t));
#ifdef __SSE2__
    const __m128i lanes =
        _mm_add_epi32(_mm_set1_epi32(static_cast<int>(first)),
                      _mm_load_si128(reinterpret_cast<const __m128i*>(kLaneList.lane[mask])));
    const __m128i same = _mm_set1_epi32(static_cast<int>(fixed));
    const __m128i lo =
        fixed_first ? _mm_unpacklo_epi32(same, lanes) : _mm_unpacklo_epi32(lanes, same);
    const __m128i hi =
        fixed_first ? _mm_unpackhi_epi32(same, lanes) : _mm_unpackhi_epi32(lanes, same);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), lo);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 2), hi);
#else
    for (uint32_t j = 0; j < kBoxLanes; ++j) {
        const uint32_t other = first + kLaneList.lane[mask][j];
        out[j] = fixed_first ? Pair{fixed, other} : Pair{other, fixed};
    }
#endif
    return kLaneList.count[mask];
}

// Bit i set when range[begin + i] < nearer_than, i < n <= 12 (the same compares as one at a
// time).
inline unsigned nearerBits(const std::vector<float>& range, uint32_t begin, uint32_t n,
                           float nearer_than) {
    unsigned bits = 0;
#ifdef __SSE2__
    if (begin + 12 <= range.size()) {
        const float* r = range.data() + begin;
        const __m128 limit = _mm_set1_ps(nearer_than);
        for (int block = 0; block < 3; ++block)
            bits |= static_cast<unsigned>(
                        _mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(r + 4 * block), limit)))
                    << (4 * block);
        return bits & ((1u << n) - 1);
    }
#endif
    for (uint32_t i = 0; i < n; ++i) bits |= unsigned(range[begin + i] < nearer_than) << i;
    return bits;
}

}  // namespace

void RunClustering::vertical(const Params& params) {
    const int rows = static_cast<int>(row_runs_begin_.size()) - 1;
    const int ext = params.vertical_column_extension;
    const float t_vert2 =
        static_cast<float>(params.vertical_merge_dist * params.vertical_merge_dist);
    const int span = params.vertical_ring_span;
    const int32_t *col_begin = run_col_begin_.data(), *col_end = run_col_end_.data();
    // Run a of the upper row and run b of a lower row are compared when b's columns overlap
    // a's widened by T_ext, [lo, hi]; they merge when two of their points are nearer than
    // sqrt(T_vert^2 + (R dtheta)^2), R the upper point's range (see the file comment), which
    // is at most merge_dist2_[a] (R = a's farthest range); most pairs' boxes are already farther
    // apart (a wall behind a bush), so the box test comes first. The merges give the same clusters
    // in any order, so each pair of rows is swept once, both rows' runs in first-column order: the
    // pairs where b starts within [lo, hi] (for each a), then those where b starts before lo and
    // reaches it (for each b, the a whose lo lies in b's columns). No pair is visited twice, and
    // none that does not overlap. Each such list of runs is a range of one row's runs, found from
    // a per-column table of the row (no search: a search loop's exit is a mispredicted branch).
    const uint32_t num_runs = static_cast<uint32_t>(run_first_.size());
    const std::size_t stride = num_runs + kBoxLanes;
    box_arrays_.resize(6 * stride);
    BoxArrays arrays;
    {
        float* coord[6];
        for (int axis = 0; axis < 6; ++axis) {
            coord[axis] = box_arrays_.data() + axis * stride;
            arrays.coord[axis] = coord[axis];
        }
        for (uint32_t run = 0; run < num_runs; ++run) {
            const RunBox& box = run_box_[run];
            coord[0][run] = box.lo[0], coord[1][run] = box.lo[1], coord[2][run] = box.lo[2];
            coord[3][run] = box.hi[0], coord[4][run] = box.hi[1], coord[5][run] = box.hi[2];
        }
    }
    // Per row and column c in [0, cols]: the row's first run starting at c or after (the row's
    // end if none). Rows r - span .. r only, in a ring of span + 1 tables.
    const int cols = rows > 0 ? static_cast<int>((key_count_.size() - 1) / rows) : 0;
    const std::size_t table_size = static_cast<std::size_t>(cols) + 1;
    const int num_tables = std::min(span, rows) + 1;
    first_run_.resize(static_cast<std::size_t>(num_tables) * table_size);
    auto table = [&](int q) {
        return first_run_.data() + std::size_t(q % num_tables) * table_size;
    };
    auto fillTable = [&](int q) {  // runs starting in each column, then their prefix sums
        uint32_t* first = table(q);
        std::fill(first, first + table_size, 0u);
        for (uint32_t run = row_runs_begin_[q]; run < row_runs_begin_[q + 1]; ++run)
            ++first[col_begin[run] + 1];
        first[0] = row_runs_begin_[q];
        inclusivePrefixSum(first, table_size);
    };
    float ring_step2 = 0.f;  // (one ring's spacing of the pair of rows being swept [rad])^2
    auto merge = [&](uint32_t a, uint32_t b) {
        const int root_a = find(static_cast<int>(a)), root_b = find(static_cast<int>(b));
        if (root_a == root_b ||
            !runsTouch(static_cast<int>(a), static_cast<int>(b), ext, t_vert2, ring_step2))
            return;
        parent_[std::max(root_a, root_b)] = std::min(root_a, root_b);
    };
    // The pairs whose boxes are near are listed without a branch (one in five is, at random),
    // then merged, once per pair of rows. Each run's candidates are first cut into blocks of
    // kBoxLanes, kListedBlocks of them written whatever their number (most runs have fewer; the
    // count advances by the number needed), so that the box test is one loop over the blocks
    // of all runs: a loop per run would end on a mispredicted branch per run.
    constexpr uint32_t kListedBlocks = 4;
    uint32_t num_blocks = 0;
    auto blockRoom = [&](std::size_t more) {
        if (blocks_.size() < num_blocks + more) blocks_.resize(2 * (num_blocks + more));
    };
    auto listBlocks = [&](uint32_t fixed, uint32_t first, uint32_t last, std::size_t runs_left) {
        const uint32_t count = (last - first + kBoxLanes - 1) / kBoxLanes;
        if (count > kListedBlocks) blockRoom(count + kListedBlocks * runs_left);  // rare
        CandidateBlock* out = blocks_.data() + num_blocks;
        for (uint32_t j = 0; j < kListedBlocks; ++j) out[j] = {fixed, first + j * kBoxLanes, last};
        for (uint32_t j = kListedBlocks; j < count; ++j)
            out[j] = {fixed, first + j * kBoxLanes, last};
        num_blocks += count;
    };
    uint32_t num_near = 0;
    auto room = [&](uint32_t more) {
        if (near_.size() < num_near + more) near_.resize(2 * (num_near + more));
        return near_.data();
    };
    merge_dist2_.resize(stride);
    if (rows > 0) fillTable(0);
    for (int r = 1; r < rows; ++r) {
        const uint32_t a_begin = row_runs_begin_[r], a_end = row_runs_begin_[r + 1];
        fillTable(r);
        const uint32_t* above = table(r);
        // The nearest rows first: their merges make the farther rows' pairs mostly one cluster
        // already, and those skip the point-by-point test.
        for (int rr = r - 1; rr >= std::max(0, r - span); --rr) {
            const uint32_t b_begin = row_runs_begin_[rr], b_end = row_runs_begin_[rr + 1];
            if (a_begin == a_end || b_begin == b_end) continue;
            const uint32_t* below = table(rr);
            const float ring_step = ringSpacing(r, rr);
            ring_step2 = ring_step * ring_step;
            // The box pre-filter with a's farthest range: no pair of a's points needs more
            // (runsTouch takes the spacing at each point's own range).
            for (uint32_t a = a_begin; a < a_end; ++a) {
                const float beam_gap = run_far_range_[a] * ring_step;
                merge_dist2_[a] = t_vert2 + beam_gap * beam_gap;
            }
            num_near = 0;
            // b starts within [lo, hi].
            num_blocks = 0;
            blockRoom(kListedBlocks * (a_end - a_begin + 1));
            for (uint32_t a = a_begin; a < a_end; ++a) {
                const int lo = col_begin[a] - ext, hi = col_end[a] + ext;
                listBlocks(a, below[std::max(lo, 0)], below[std::min(hi + 1, cols)], a_end - a);
            }
            NearPair* near = room(kBoxLanes * (num_blocks + 1));
            for (uint32_t i = 0; i < num_blocks; ++i) {
                const CandidateBlock block = blocks_[i];
                const uint32_t a = block.fixed, b = block.first;
                const unsigned lanes = nearLanes(arrays, a, b, block.end, &merge_dist2_[a], true);
                num_near += listPairs(near + num_near, a, b, lanes, true);
            }
            // b starts before lo and reaches it: col_begin[b] < lo <= col_end[b], i.e.
            // col_begin[b] + ext < col_begin[a] <= col_end[b] + ext.
            num_blocks = 0;
            blockRoom(kListedBlocks * (b_end - b_begin + 1));
            for (uint32_t b = b_begin; b < b_end; ++b)
                listBlocks(b, above[std::min(col_begin[b] + ext + 1, cols)],
                           above[std::min(col_end[b] + ext + 1, cols)], b_end - b);
            near = room(kBoxLanes * (num_blocks + 1));
            for (uint32_t i = 0; i < num_blocks; ++i) {
                const CandidateBlock block = blocks_[i];
                const uint32_t b = block.fixed, a = block.first;
                const unsigned lanes = nearLanes(arrays, b, a, block.end, &merge_dist2_[a], false);
                num_near += listPairs(near + num_near, b, a, lanes, false);
            }
            for (uint32_t k = 0; k < num_near; ++k) merge(near_[k].a, near_[k].b);
        }
    }
    linkSeenThrough(params);
    linkSetBackTops(params);
}

int RunClustering::enclosingRoot(uint32_t first, uint32_t last, uint32_t row_lo, uint32_t row_hi,
                                 float nearer_than, int own_root) {
    // The points in front of the run before and after it on its ring, nearest first, skipping
    // background seen through the far window as well and occluders in front of the object.
    // Roots from run_root_ (no merge happens while runs are looked at).
    constexpr uint32_t kEnclosureWalk = 10;
    uint32_t before[kEnclosureWalk];
    int32_t before_root[kEnclosureWalk];
    // Which points are in front, as bits (k = begin + bit), before any root is looked up: none
    // on one side needs no root (one branch for both sides).
    const uint32_t num_walk_before = std::min(first - row_lo, kEnclosureWalk);
    const unsigned in_front_before =
        nearerBits(range_, first - num_walk_before, num_walk_before, nearer_than);
    const unsigned in_front_after =
        nearerBits(range_, last + 1, std::min(row_hi - (last + 1), kEnclosureWalk), nearer_than);
    if ((in_front_before == 0) | (in_front_after == 0)) return -1;
    uint32_t num_before = 0;  // nearest to the run first
    for (unsigned bits = in_front_before; bits != 0; bits &= ~(1u << (31 - __builtin_clz(bits))))
        before[num_before++] = first - num_walk_before + (31 - __builtin_clz(bits));
    uint32_t after[kEnclosureWalk];
    uint32_t num_after = 0;
    for (unsigned bits = in_front_after; bits != 0; bits &= bits - 1)
        after[num_after++] = last + 1 + __builtin_ctz(bits);
    for (uint32_t i = 0; i < num_before; ++i) before_root[i] = run_root_[point_run_[before[i]]];
    for (uint32_t j = 0; j < num_after; ++j) {
        const uint32_t k = after[j];
        const int root = run_root_[point_run_[k]];
        if (root == own_root) continue;  // its own part in front (the far side before a child)
        for (uint32_t i = 0; i < num_before; ++i)
            if (before_root[i] == root) {
                enclosure_left_ = before[i], enclosure_right_ = k;
                return root;
            }
    }
    return -1;
}

float RunClustering::depthBehindFrame(uint32_t run, int enclosing, float max_lateral) const {
    // The frame: on each side of the run on its ring, the nearest point of the enclosing cluster
    // within max_lateral of the run's end, across its ray (the adjacent points may be seats or
    // the far side, already joined to it).
    const int row = run_row_[run];
    const uint32_t row_lo = row_begin_[row], row_hi = row_begin_[row + 1];
    constexpr uint32_t kMaxWalk = 256;
    const auto nearestOfEnclosing = [&](uint32_t end, int step) {
        const SortedPoint& e = pts_[end];
        const float inv = 1.f / std::max(std::hypot(e.x, e.y), 1e-3f);
        const float ux = e.x * inv, uy = e.y * inv;
        uint32_t best = kEndOfRun;
        float best_range = std::numeric_limits<float>::infinity();
        uint32_t k = end;
        for (uint32_t walked = 0; walked < kMaxWalk; ++walked) {
            if (step < 0 ? k == row_lo : k + 1 >= row_hi) break;
            k += step;
            if (std::fabs(ux * pts_[k].y - uy * pts_[k].x) > max_lateral) break;
            if (range_[k] < best_range && run_root_[point_run_[k]] == enclosing)
                best = k, best_range = range_[k];
        }
        return best;
    };
    const uint32_t left = nearestOfEnclosing(run_first_[run], -1);
    const uint32_t right = nearestOfEnclosing(run_last_[run], +1);
    if (left == kEndOfRun || right == kEndOfRun) return 0.f;
    // The frame's line in xy through those two points; its normal n points away from the sensor
    // (at the origin).
    const SortedPoint &l = pts_[left], &r = pts_[right];
    float nx = l.y - r.y, ny = r.x - l.x;
    const float length = std::sqrt(nx * nx + ny * ny);
    if (!(length > 1e-3f)) return 0.f;  // one point: no line (cannot happen: two columns)
    nx /= length, ny /= length;
    if (nx * l.x + ny * l.y < 0.f) nx = -nx, ny = -ny;
    float deepest = 0.f;
    for (uint32_t k = run_first_[run]; k != kEndOfRun; k = next_in_run_[k])
        deepest = std::max(deepest, nx * (pts_[k].x - l.x) + ny * (pts_[k].y - l.y));
    return deepest;
}

bool RunClustering::closedAboveOrBelow(int r, int rows, uint32_t b, int root, float nearer_than) {
    // A window is a hole in a surface, closed by the roof above and the door below (one of
    // them may be hidden by an occluder); a gap between fence panels is a slot, open above
    // and below: what is seen through it shows there too, or nothing does.
    constexpr int kRowsLooked = 2;
    for (int dr = -kRowsLooked; dr <= kRowsLooked; ++dr) {
        const int rr = r + dr;
        if (dr == 0 || rr < 0 || rr >= rows) continue;
        const SortedPoint* pts = pts_.data();
        uint32_t k = firstPointFrom(rr, run_col_begin_[b]);
        for (; k < row_begin_[rr + 1] && pts[k].col <= run_col_end_[b]; ++k)
            if (range_[k] < nearer_than && run_root_[point_run_[k]] == root) return true;
    }
    return false;
}

void RunClustering::boxInvolvedRoots(bool closed_only) {
    // Only these roots' boxes are reset and filled (a reset of every run's box would write
    // 28 bytes a run).
    const std::size_t num_runs = run_first_.size();
    involved_.assign(num_runs, 0);
    root_box_.resize(num_runs);
    auto involve = [&](int32_t root) {
        if (!involved_[root]) involved_[root] = 1, root_box_[root] = RootBox{};
    };
    for (std::size_t run = 0; run < num_runs; ++run)
        if (enclosure_[run] >= 0 && (!closed_only || closed_[run]))
            involve(static_cast<int32_t>(run)), involve(enclosure_[run]);
    for (std::size_t run = 0; run < num_runs; ++run) {
        const int32_t root = run_root_[run];
        if (involved_[root])
            root_box_[root].add(run_row_[run], run_col_begin_[run], run_col_end_[run],
                                run_near_range_[run], run_size_[run]);
    }
}

void RunClustering::linkSeenThrough(const Params& params) {
    const float depth = static_cast<float>(params.see_through_depth);
    if (depth <= 0.f) return;
    const float width = static_cast<float>(params.see_through_width);
    const float t_horz = static_cast<float>(params.horizontal_merge_dist);
    const float max_gap = static_cast<float>(params.occlusion_max_gap),
                max_gap2 = max_gap * max_gap;
    const int num_runs = static_cast<int>(run_first_.size());
    const int rows = static_cast<int>(row_runs_begin_.size()) - 1;
    // Per root: the cluster its runs are seen through (kNone: none; kConflict: more than one)
    // and whether one of those runs is closed above or below by it.
    constexpr int32_t kNone = -1, kConflict = -2;
    enclosure_.assign(static_cast<std::size_t>(num_runs), kNone);
    closed_.assign(static_cast<std::size_t>(num_runs), 0);
    run_root_.resize(static_cast<std::size_t>(num_runs));
    for (int run = 0; run < num_runs; ++run) run_root_[run] = find(run);
    if (width > 0.f) unionRootBoxes();  // each cluster's height
    bool any = false;
    for (int r = 0; r < rows; ++r) {
        const uint32_t row_lo = row_begin_[r], row_hi = row_begin_[r + 1];
        for (uint32_t b = row_runs_begin_[r]; b < row_runs_begin_[r + 1]; ++b) {
            const int root = run_root_[b];
            int32_t& state = enclosure_[root];
            if (state == kConflict) continue;
            const float nearer_than = run_near_range_[b] - t_horz;
            const int enclosing =
                enclosingRoot(run_first_[b], run_last_[b], row_lo, row_hi, nearer_than, root);
            if (enclosing < 0 || enclosing == root) continue;
            const uint32_t left = enclosure_left_, right = enclosure_right_;
            if (dist2(left, right) > max_gap2) continue;
            // Deeper behind a car-high enclosing cluster's near face than a car is wide (in xy,
            // across the face): beyond its far side (a child or a car right behind a car).
            // Taller clusters (vans, trucks, buses up to 2.55 m wide; trees) keep the depth
            // bound only.
            if (width > 0.f &&
                root_box3_[enclosing].hi[2] - root_box3_[enclosing].lo[2] <= kCarMaxHeight &&
                depthBehindFrame(b, enclosing, max_gap) > width) {
                state = kConflict;
                continue;
            }
            // Seen through the gap but deeper behind it than any vehicle is wide: the cluster
            // is beyond the nearer one (a car parked behind a car), not its far side.
            if (run_far_range_[b] > std::max(range_[left], range_[right]) + depth) {
                state = kConflict;
                continue;
            }
            if (state == kNone) state = enclosing, any = true;
            if (state != enclosing) {
                state = kConflict;
                continue;
            }
            if (!closed_[root])
                closed_[root] = closedAboveOrBelow(r, rows, b, enclosing, nearer_than);
        }
    }
    if (!any) return;
    boxInvolvedRoots(true);
    // A cluster joins the one it is seen through when it lies inside that one's range-image
    // box, behind it, and is smaller: the seats and far side of a car seen through its windows.
    for (int run = 0; run < num_runs; ++run) {
        if (enclosure_[run] < 0 || !closed_[run]) continue;
        const RootBox &f = root_box_[run], &e = root_box_[enclosure_[run]];
        if (f.row_lo >= e.row_lo && f.row_hi <= e.row_hi && f.col_lo >= e.col_lo &&
            f.col_hi <= e.col_hi && f.nearest > e.nearest && f.points < e.points)
            unite(run, enclosure_[run]);
    }
}

uint32_t RunClustering::firstPointFrom(int row, int col) const {
    // After the counting sort's scatter in horizontal(), key_count_[key] is the end of cell
    // `key`'s slots, so key_count_[key - 1] is its start: the first point of key or after.
    const std::size_t key =
        static_cast<std::size_t>(row) * cols_ + static_cast<std::size_t>(std::clamp(col, 0, cols_));
    return key == 0 ? 0u : key_count_[key - 1];
}

int RunClustering::rootInFrontBelow(uint32_t run, float t_horz, float depth) const {
    // The row below the run, swept with it in column order: in each of the run's columns (+-1,
    // the rings' azimuths differ) its nearest point there.
    const int r = run_row_[run];
    const uint32_t below_hi = row_begin_[r];
    const SortedPoint* pts = pts_.data();
    uint32_t j = firstPointFrom(r - 1, run_col_begin_[run] - 1);
    int found = kNoRoot;
    float least_depth = std::numeric_limits<float>::infinity();
    for (uint32_t k = run_first_[run]; k != kEndOfRun; k = next_in_run_[k]) {
        const int c = pts[k].col;
        while (j < below_hi && pts[j].col < c - 1) ++j;
        float nearest = std::numeric_limits<float>::infinity();
        uint32_t jn = 0;
        for (uint32_t m = j; m < below_hi && pts[m].col <= c + 1; ++m)
            if (range_[m] < nearest) nearest = range_[m], jn = m;
        if (!(nearest < range_[k] - t_horz)) continue;  // nothing below, or not in front
        const int root = run_root_[point_run_[jn]];
        if (found != kNoRoot && found != root) return kConflictRoot;
        found = root;
        least_depth = std::min(least_depth, range_[k] - nearest);
    }
    // Starting deeper behind it than any vehicle reaches: an object beyond the one in front.
    return least_depth <= depth ? found : found == kNoRoot ? kNoRoot : kConflictRoot;
}

void RunClustering::linkSetBackTops(const Params& params) {
    const float depth = static_cast<float>(params.set_back_depth);
    if (depth <= 0.f) return;
    const float t_horz = static_cast<float>(params.horizontal_merge_dist);
    const int num_runs = static_cast<int>(run_first_.size());
    run_root_.resize(static_cast<std::size_t>(num_runs));
    for (int run = 0; run < num_runs; ++run) run_root_[run] = find(run);
    // Per root: the cluster in front of it right below its lowest row (kNoRoot: none;
    // kConflictRoot: some of those runs are not over one such cluster). Runs are in row order,
    // so a root's first run lies in its lowest row.
    enclosure_.assign(static_cast<std::size_t>(num_runs), kNoRoot);
    root_low_row_.assign(static_cast<std::size_t>(num_runs), -1);
    bool any = false;
    for (int run = 0; run < num_runs; ++run) {
        const int root = run_root_[run];
        if (root_low_row_[root] < 0) root_low_row_[root] = run_row_[run];
        if (run_row_[run] != root_low_row_[root]) continue;
        int32_t& state = enclosure_[root];
        if (state == kConflictRoot) continue;
        const int below = run_row_[run] > 0 ? rootInFrontBelow(run, t_horz, depth) : kNoRoot;
        if (below == kNoRoot || below == root || (state != kNoRoot && state != below)) {
            state = kConflictRoot;
            continue;
        }
        state = below, any = true;
    }
    if (!any) return;
    boxInvolvedRoots(false);
    // The top joins the cluster it stands on when it lies within that one's columns, spans at
    // least half of them, and its nearest point is at most set_back_depth behind that one's.
    for (int run = 0; run < num_runs; ++run) {
        if (enclosure_[run] < 0) continue;
        const RootBox &f = root_box_[run], &e = root_box_[enclosure_[run]];
        if (f.col_lo >= e.col_lo && f.col_hi <= e.col_hi &&
            2 * (f.col_hi - f.col_lo + 1) >= e.col_hi - e.col_lo + 1 && f.row_lo > e.row_lo &&
            f.nearest > e.nearest && f.nearest <= e.nearest + depth)
            unite(run, enclosure_[run]);
    }
}

void RunClustering::attachFeet(const AlignedCloud& cloud, const RangeImage& image,
                               const std::vector<uint32_t>& feet,
                               const std::vector<uint32_t>& faces) {
    const std::vector<int16_t>& row = image.row();
    const std::vector<int32_t>& col = image.col();
    const std::size_t cols = static_cast<std::size_t>(image.cols());
    for (std::size_t f = 0; f < feet.size(); ++f) {
        // The face point's sorted position: after the counting sort in horizontal(),
        // key_count_[key] is the end of cell `key`'s slots and key_count_[key - 1] its start.
        const uint32_t face = faces[f];
        const std::size_t key = static_cast<std::size_t>(row[face]) * cols + col[face];
        uint32_t slot = key == 0 ? 0 : key_count_[key - 1];
        const uint32_t end = key_count_[key];
        while (slot < end && sorted_[slot] != face) ++slot;
        if (slot == end) continue;  // not clustered (cannot happen for a non-ground face)
        // Appended after the sorted points (row_begin_ does not cover them): only the id
        // assignment and the summaries read them.
        const uint32_t foot = feet[f];
        const int32_t run = point_run_[slot];
        sorted_.push_back(foot);
        pts_.push_back({cloud.x[foot], cloud.y[foot], cloud.z[foot], col[foot]});
        const SortedPoint& p = pts_.back();
        range_.push_back(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
        point_run_.push_back(run), next_in_run_.push_back(kEndOfRun);
        ++run_size_[run];
        run_first_input_[run] = std::min(run_first_input_[run], foot);
    }
}

void RunClustering::unionRootBoxes() {
    const std::size_t num_runs = run_first_.size();
    const float inf = std::numeric_limits<float>::infinity();
    root_box3_.assign(num_runs,
                      RunBox{Eigen::Array4f::Constant(inf), Eigen::Array4f::Constant(-inf)});
    for (std::size_t run = 0; run < num_runs; ++run) {
        RunBox& box = root_box3_[run_root_[run]];
        box.lo = box.lo.min(run_box_[run].lo), box.hi = box.hi.max(run_box_[run].hi);
    }
}

void RunClustering::wallBottoms(const Params& params, int cols, std::vector<int16_t>& bottom_row,
                                std::vector<float>& bottom_range) {
    bottom_row.assign(static_cast<std::size_t>(cols), -1);
    bottom_range.resize(static_cast<std::size_t>(cols));
    const float min_length = static_cast<float>(params.vertical_face_min_length);
    const int num_runs = static_cast<int>(run_first_.size());
    if (num_runs == 0 || !(min_length > 0.f)) return;
    // Each cluster's box, then whether it is wall-like.
    run_root_.resize(static_cast<std::size_t>(num_runs));
    for (int run = 0; run < num_runs; ++run) run_root_[run] = find(run);
    unionRootBoxes();
    wall_root_.assign(static_cast<std::size_t>(num_runs), 0);
    for (int run = 0; run < num_runs; ++run) {
        if (run_root_[run] != run) continue;
        const Eigen::Array4f side = root_box3_[run].hi - root_box3_[run].lo;
        wall_root_[run] = std::max(side[0], side[1]) >= min_length;
    }
    // Rows bottom up: the first point met in a column is its lowest.
    const SortedPoint* pts = pts_.data();
    const uint32_t num_sorted = row_begin_.back();
    int unclaimed = cols;
    for (uint32_t k = 0; k < num_sorted && unclaimed > 0; ++k) {
        int16_t& bottom = bottom_row[pts[k].col];
        if (bottom != -1) continue;
        const int run = point_run_[k];
        bottom = wall_root_[run_root_[run]] ? run_row_[run] : -2;
        bottom_range[pts[k].col] = std::sqrt(pts[k].x * pts[k].x + pts[k].y * pts[k].y);
        --unclaimed;
    }
    for (int16_t& bottom : bottom_row) bottom = std::max<int16_t>(bottom, -1);
}

void RunClustering::assignIds(const Params& params, std::vector<uint32_t>& cluster_id) {
    const std::size_t num_runs = run_first_.size();
    // Root of every run once (not a find() per point), then sizes and first points per root
    // from the runs' (counted as the runs were built).
    run_root_.resize(num_runs);
    for (std::size_t run = 0; run < num_runs; ++run) run_root_[run] = find(static_cast<int>(run));
    root_size_.assign(num_runs, 0);
    root_first_.assign(num_runs, std::numeric_limits<uint32_t>::max());
    for (std::size_t run = 0; run < num_runs; ++run) {
        const int root = run_root_[run];
        root_size_[root] += run_size_[run];
        root_first_[root] = std::min(root_first_[root], run_first_input_[run]);
    }
    root_order_.clear();
    for (std::size_t run = 0; run < num_runs; ++run) {
        if (root_size_[run] == 0) continue;  // not a root
        if (root_size_[run] < static_cast<uint32_t>(params.min_cluster_size) ||
            root_size_[run] > static_cast<uint32_t>(params.max_cluster_size))
            continue;
        root_order_.push_back(static_cast<int32_t>(run));
    }
    std::sort(root_order_.begin(), root_order_.end(),
              [&](int32_t a, int32_t b) { return root_first_[a] < root_first_[b]; });
    root_id_.assign(num_runs, 0);
    for (std::size_t k = 0; k < root_order_.size(); ++k)
        root_id_[root_order_[k]] = static_cast<uint32_t>(k + 1);
    // Id of every run once, then one lookup per point.
    run_id_.resize(num_runs);
    for (std::size_t run = 0; run < num_runs; ++run) run_id_[run] = root_id_[run_root_[run]];
    const uint32_t num_points = static_cast<uint32_t>(sorted_.size());
    const int32_t* point_run = point_run_.data();
    const uint32_t* input = sorted_.data();
    point_id_.resize(num_points);
    uint32_t* point_id = point_id_.data();
    const uint32_t* run_id = run_id_.data();
    uint32_t* id_of_input = cluster_id.data();
    for (uint32_t k = 0; k < num_points; ++k) {
        point_id[k] = run_id[point_run[k]];
        id_of_input[input[k]] = point_id[k];
    }
}

// With AVX2 (CpuDispatch.hpp) a point's three coordinates are one vector in both passes.
TRAVEL_AVX2_CLONES
void RunClustering::summarize(const TriGridField& field, const TerrainModel& terrain,
                              std::vector<ClusterSummary>& clusters) {
    const uint32_t num = static_cast<uint32_t>(root_order_.size());
    clusters.assign(num, ClusterSummary{});
    sums_.assign(num, Sums{});
    const float inf = std::numeric_limits<float>::infinity();
    for (uint32_t k = 0; k < num; ++k) {
        clusters[k].id = k + 1;
        clusters[k].first_point = root_first_[root_order_[k]];
        clusters[k].aabb_min.setConstant(inf);
        clusters[k].aabb_max.setConstant(-inf);
        clusters[k].num_points = 0;
    }
    // Pass 1 over the clustered points (sorted order, contiguous): counts, boxes, moments.
    // Consecutive points mostly share a cluster: accumulate each stretch of one id in registers
    // and add it to the cluster once, instead of chaining every += through the cluster's
    // memory. A point is one vector (x, y, z, 0): its box as lane-wise selects (the same as
    // std::min / std::max one coordinate at a time), its sums and products as double lanes
    // (each lane the same adds in the same order as one scalar per sum: the same bits).
    typedef float Float4 __attribute__((vector_size(16)));
    typedef int32_t Int4 __attribute__((vector_size(16)));
    typedef double Double4 __attribute__((vector_size(32)));
    const Int4 xyz_only = {-1, -1, -1, 0};  // the column's lane -> +0
    const SortedPoint* pts = pts_.data();
    const uint32_t* ids = point_id_.data();
    const uint32_t num_points = static_cast<uint32_t>(point_id_.size());
    const auto load = [&](uint32_t k) {
        Int4 bits;
        std::memcpy(&bits, &pts[k], sizeof bits);
        bits &= xyz_only;
        Float4 p;
        std::memcpy(&p, &bits, sizeof p);
        return p;
    };
    for (uint32_t k = 0; k < num_points;) {
        const uint32_t id = ids[k];
        if (id == 0) {
            ++k;
            continue;
        }
        const uint32_t begin = k;
        Float4 lo = Float4{} + inf, hi = Float4{} - inf;
        Double4 sum = {0, 0, 0, 0}, products = {0, 0, 0, 0};  // x, y, z; xx, xy, yy
        for (; k < num_points && ids[k] == id; ++k) {
            const Float4 p = load(k);
            lo = p < lo ? p : lo, hi = hi < p ? p : hi;
            const Double4 v = __builtin_convertvector(p, Double4);
            sum += v;
            products += Double4{v[0], v[0], v[1], 0} * Double4{v[0], v[1], v[1], 0};
        }
        ClusterSummary& c = clusters[id - 1];
        Sums& s = sums_[id - 1];
        c.num_points += k - begin;
        c.aabb_min = c.aabb_min.cwiseMin(Eigen::Vector3f(lo[0], lo[1], lo[2]));
        c.aabb_max = c.aabb_max.cwiseMax(Eigen::Vector3f(hi[0], hi[1], hi[2]));
        s.sx += sum[0], s.sy += sum[1], s.sz += sum[2];
        s.sxx += products[0], s.sxy += products[1], s.syy += products[2];
    }
    // Oriented box axes from the 2-D covariance of xy.
    for (uint32_t k = 0; k < num; ++k) {
        ClusterSummary& c = clusters[k];
        Sums& s = sums_[k];
        const double inv = 1.0 / std::max<uint32_t>(c.num_points, 1);
        const double mx = s.sx * inv, my = s.sy * inv;
        c.centroid = Eigen::Vector3f(float(mx), float(my), float(s.sz * inv));
        const double cxx = s.sxx * inv - mx * mx, cyy = s.syy * inv - my * my;
        const double cxy = s.sxy * inv - mx * my;
        c.obb_yaw = static_cast<float>(0.5 * std::atan2(2 * cxy, cxx - cyy));
        s.cos_yaw = std::cos(c.obb_yaw), s.sin_yaw = std::sin(c.obb_yaw);
        s.extent = Eigen::Vector4f(inf, -inf, inf, -inf);  // umin, umax, vmin, vmax
    }
    // Pass 2: extents along the box axes (same stretch accumulation), (u, v) as two lanes:
    // u = cos x + sin y, v = -sin x + cos y, each product and sum as in scalar code.
    for (uint32_t k = 0; k < num_points;) {
        const uint32_t id = ids[k];
        if (id == 0) {
            ++k;
            continue;
        }
        Sums& sum = sums_[id - 1];
        const Float4 along_x = {sum.cos_yaw, -sum.sin_yaw, 0.f, 0.f};
        const Float4 along_y = {sum.sin_yaw, sum.cos_yaw, 0.f, 0.f};
        Float4 lo = Float4{} + inf, hi = Float4{} - inf;
        for (; k < num_points && ids[k] == id; ++k) {
            const Float4 p = load(k);
            const Float4 uv =
                along_x * Float4{p[0], p[0], 0.f, 0.f} + along_y * Float4{p[1], p[1], 0.f, 0.f};
            lo = uv < lo ? uv : lo, hi = hi < uv ? uv : hi;
        }
        Eigen::Vector4f& e = sum.extent;
        e[0] = std::min(e[0], lo[0]), e[1] = std::max(e[1], hi[0]);
        e[2] = std::min(e[2], lo[1]), e[3] = std::max(e[3], hi[1]);
    }
    for (uint32_t k = 0; k < num; ++k) {
        ClusterSummary& c = clusters[k];
        const Eigen::Vector4f& e = sums_[k].extent;
        float length = e[1] - e[0], width = e[3] - e[2];
        const float um = 0.5f * (e[0] + e[1]), vm = 0.5f * (e[2] + e[3]);
        const float cy = sums_[k].cos_yaw, sy = sums_[k].sin_yaw;
        c.obb_center = Eigen::Vector3f(cy * um - sy * vm, sy * um + cy * vm,
                                       0.5f * (c.aabb_min.z() + c.aabb_max.z()));
        if (width > length) {  // length is the longer side; yaw follows it
            std::swap(length, width);
            c.obb_yaw += static_cast<float>(c.obb_yaw > 0 ? -M_PI / 2 : M_PI / 2);
        }
        c.obb_extent = Eigen::Vector3f(length, width, c.aabb_max.z() - c.aabb_min.z());
        // Ground under the centroid: the refitted plane of its node, if the model has one.
        c.ground_z = std::numeric_limits<float>::quiet_NaN();
        const int node = field.nodeOf(c.centroid.x(), c.centroid.y());
        if (node >= 0 && terrain.nodes[node].refitted) {
            const TriNode& t = terrain.nodes[node];
            c.ground_z = planeHeightAt(t.refit_normal, t.refit_d, c.centroid.x(), c.centroid.y());
        }
        c.height_above_ground = c.aabb_max.z() - c.ground_z;
    }
}

}  // namespace travel
