// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/sim/SyntheticLidar.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace travel::sim {
namespace {

constexpr float kTerrainIntensity = 0.5f;
constexpr float kObjectIntensity = 0.8f;
// Bisection stops when the crossing is bracketed this tightly [m]: 18 halvings of a 0.25 m step.
// The iteration cap only guards against ranges so large that doubles cannot resolve that.
constexpr double kBisectionTolerance = 1e-6;
constexpr int kMaxBisections = 40;
// Rays closer than this to parallel with a face are treated as parallel.
constexpr double kParallelEpsilon = 1e-12;

// A Box or a Wall, ready for the slab test.
struct PlacedBox {
    uint32_t id;
    Eigen::Vector2d centre;
    double cos_yaw, sin_yaw;
    double half_length, half_width;
    ZRange z;
    Eigen::Vector2d velocity{0.0, 0.0};
    double return_fraction = 1.0;
};

struct PlacedPole {
    uint32_t id;
    Eigen::Vector2d centre;
    double radius;
    ZRange z;
};

struct ObjectHit {
    double t = kInfinity;
    uint32_t id = 0;
    double return_fraction = 1.0;
};

// Salts of rayHash for the ground covers and the puddles (object ids stay below them).
constexpr uint32_t kCoverSalt = 0xC0000000u;
constexpr uint32_t kPuddleSalt = 0xD0000000u;
// At most this many ground covers are read per ray (the per-ray canopy heights live on the
// stack).
constexpr std::size_t kMaxCovers = 64;

// A fixed pseudo-random number in [0, 1) for a ray and an object (splitmix64 finaliser).
double rayHash(int ring, int column, uint32_t id) {
    uint64_t z = (uint64_t(uint32_t(ring)) << 40) ^ (uint64_t(uint32_t(column)) << 16) ^ id;
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return double(z >> 11) * (1.0 / 9007199254740992.0);
}

// The range [t_near, t_far] of the ray inside the slab lo <= origin + t dir <= hi.
bool clipToSlab(double origin, double dir, double lo, double hi, double& t_near, double& t_far) {
    if (std::abs(dir) < kParallelEpsilon) return origin >= lo && origin <= hi;
    double t0 = (lo - origin) / dir, t1 = (hi - origin) / dir;
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
    return t_near <= t_far;
}

// The first t > 0 where the ray enters the box (or leaves it, from a sensor inside), the box
// being where it is at `time` into the sweep.
double intersect(const PlacedBox& box, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                 double time) {
    const Eigen::Vector2d centre = box.centre + time * box.velocity;
    const double px = origin.x() - centre.x(), py = origin.y() - centre.y();
    const double local_x = box.cos_yaw * px + box.sin_yaw * py;
    const double local_y = -box.sin_yaw * px + box.cos_yaw * py;
    const double dir_x = box.cos_yaw * dir.x() + box.sin_yaw * dir.y();
    const double dir_y = -box.sin_yaw * dir.x() + box.cos_yaw * dir.y();
    double t_near = -kInfinity, t_far = kInfinity;
    if (!clipToSlab(local_x, dir_x, -box.half_length, box.half_length, t_near, t_far) ||
        !clipToSlab(local_y, dir_y, -box.half_width, box.half_width, t_near, t_far) ||
        !clipToSlab(origin.z(), dir.z(), box.z.bottom, box.z.top, t_near, t_far)) {
        return kInfinity;
    }
    if (t_near > 0.0) return t_near;
    return t_far > 0.0 ? t_far : kInfinity;
}

// Vertical cylinder with its two caps.
double intersect(const PlacedPole& pole, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& dir) {
    const double px = origin.x() - pole.centre.x(), py = origin.y() - pole.centre.y();
    const double radius_sq = pole.radius * pole.radius;
    double best = kInfinity;
    const double a = dir.x() * dir.x() + dir.y() * dir.y();
    if (a > kParallelEpsilon) {
        const double half_b = px * dir.x() + py * dir.y();
        const double c = px * px + py * py - radius_sq;
        const double discriminant = half_b * half_b - a * c;
        if (discriminant >= 0.0) {
            const double root = std::sqrt(discriminant);
            for (double t : {(-half_b - root) / a, (-half_b + root) / a}) {
                const double z = origin.z() + t * dir.z();
                if (t > 0.0 && z >= pole.z.bottom && z <= pole.z.top) {
                    best = std::min(best, t);
                    break;  // the roots are ascending
                }
            }
        }
    }
    if (std::abs(dir.z()) > kParallelEpsilon) {
        for (double cap_z : {pole.z.top, pole.z.bottom}) {
            const double t = (cap_z - origin.z()) / dir.z();
            const double x = px + t * dir.x(), y = py + t * dir.y();
            if (t > 0.0 && t < best && x * x + y * y <= radius_sq) best = t;
        }
    }
    return best;
}

// Upper bounds of the terrain height on square grids around the sensor. Each cell holds the
// bound over its 3 x 3 neighbourhood, so it bounds any segment that starts in the cell and is no
// longer than a cell. Lets the march cross empty air in long strides without evaluating h(x, y):
// a coarse level for the open sky, a fine one for close to the ground.
class TerrainBounds {
  public:
    struct Level {
        double cell_size = 1.0;
        double inv_cell_size = 1.0;
        int cells_per_side = 0;
        Eigen::Vector2d corner{0.0, 0.0};
        std::vector<double> dilated;  // row-major, y rows, x columns

        /// Upper bound of h over any segment of length <= cell_size starting at (x, y).
        double boundNear(double x, double y, double global_bound) const {
            const double col = std::floor((x - corner.x()) * inv_cell_size);
            const double row = std::floor((y - corner.y()) * inv_cell_size);
            // Outside the grid; the outer ring also lacks neighbours for its dilation.
            if (col < 1 || row < 1 || col >= cells_per_side - 1 || row >= cells_per_side - 1) {
                return global_bound;
            }
            return dilated[static_cast<std::size_t>(row) * cells_per_side +
                           static_cast<std::size_t>(col)];
        }
    };

    /// Covers every point within `reach` of `centre` (in xy) with at least two fine cells of
    /// margin.
    void build(const Scene& scene, const Eigen::Vector2d& centre, double reach) {
        constexpr int kMaxFineCellsPerSide = 1024;
        constexpr int kCoarseFactor = 8;
        global_bound_ = scene.terrainUpperBound();

        Level& fine = levels_[1];
        fine.cell_size = std::max(1.0, 2.0 * reach / kMaxFineCellsPerSide);
        const int fine_cells = static_cast<int>(std::ceil(2.0 * reach / fine.cell_size)) + 4;
        const int coarse_cells = (fine_cells + kCoarseFactor - 1) / kCoarseFactor;
        fine.cells_per_side = coarse_cells * kCoarseFactor;
        fine.corner =
            centre - Eigen::Vector2d::Constant(0.5 * fine.cells_per_side * fine.cell_size);
        fine.inv_cell_size = 1.0 / fine.cell_size;

        Level& coarse = levels_[0];
        coarse.cell_size = kCoarseFactor * fine.cell_size;
        coarse.inv_cell_size = 1.0 / coarse.cell_size;
        coarse.cells_per_side = coarse_cells;
        coarse.corner = fine.corner;

        std::vector<double> fine_bound(static_cast<std::size_t>(fine.cells_per_side) *
                                       fine.cells_per_side);
        std::vector<double> coarse_bound(static_cast<std::size_t>(coarse_cells) * coarse_cells,
                                         -kInfinity);
        for (int row = 0; row < fine.cells_per_side; ++row) {
            for (int col = 0; col < fine.cells_per_side; ++col) {
                const Eigen::Vector2d lo = fine.corner + fine.cell_size * Eigen::Vector2d(col, row);
                const Eigen::Vector2d hi = lo + Eigen::Vector2d::Constant(fine.cell_size);
                const double bound = scene.terrainUpperBound(lo, hi);
                fine_bound[static_cast<std::size_t>(row) * fine.cells_per_side + col] = bound;
                double& coarse_cell =
                    coarse_bound[static_cast<std::size_t>(row / kCoarseFactor) * coarse_cells +
                                 col / kCoarseFactor];
                coarse_cell = std::max(coarse_cell, bound);
            }
        }
        dilate(fine_bound, fine);
        dilate(coarse_bound, coarse);
    }

    double globalBound() const { return global_bound_; }
    /// Coarse first, then fine.
    const std::array<Level, 2>& levels() const { return levels_; }
    double fineCellSize() const { return levels_[1].cell_size; }

  private:
    static void dilate(const std::vector<double>& bound, Level& level) {
        const int n = level.cells_per_side;
        const auto at = [&](int row, int col) {
            return bound[static_cast<std::size_t>(row) * n + col];
        };
        level.dilated.assign(bound.size(), -kInfinity);
        for (int row = 0; row < n; ++row) {
            for (int col = 0; col < n; ++col) {
                double neighbourhood = -kInfinity;
                for (int r = std::max(row - 1, 0); r <= std::min(row + 1, n - 1); ++r) {
                    for (int c = std::max(col - 1, 0); c <= std::min(col + 1, n - 1); ++c) {
                        neighbourhood = std::max(neighbourhood, at(r, c));
                    }
                }
                level.dilated[static_cast<std::size_t>(row) * n + col] = neighbourhood;
            }
        }
    }

    double global_bound_ = 0.0;
    std::array<Level, 2> levels_;
};

// Everything the rays share, derived once per scan.
struct PreparedScene {
    const Scene& scene;
    std::vector<PlacedBox> boxes;
    std::vector<PlacedPole> poles;
    std::vector<double> water_levels;
    TerrainBounds bounds;

    PreparedScene(const Scene& world, const Eigen::Vector3d& sensor_position, double max_range)
        : scene(world) {
        boxes.reserve(world.boxes.size() + world.walls.size());
        for (const Box& box : world.boxes) {
            const double yaw = box.yaw_deg * kDegToRad;
            boxes.push_back({box.id, box.centre, std::cos(yaw), std::sin(yaw), 0.5 * box.length,
                             0.5 * box.width, world.placement(box), box.velocity,
                             box.return_fraction});
        }
        for (const Wall& wall : world.walls) {
            const Eigen::Vector2d along = wall.b - wall.a;
            const double yaw = std::atan2(along.y(), along.x());
            boxes.push_back({wall.id, 0.5 * (wall.a + wall.b), std::cos(yaw), std::sin(yaw),
                             0.5 * along.norm(), 0.5 * wall.thickness, world.placement(wall)});
        }
        poles.reserve(world.poles.size());
        for (const Pole& pole : world.poles) {
            poles.push_back({pole.id, pole.centre, pole.radius, world.placement(pole)});
        }
        for (std::size_t k = 0; k < world.puddles.size(); ++k)
            water_levels.push_back(world.waterLevel(k));
        bounds.build(world, sensor_position.head<2>(), max_range);
    }

    ObjectHit nearestObject(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                            double time) const {
        ObjectHit hit;
        for (const PlacedBox& box : boxes) {
            const double t = intersect(box, origin, dir, time);
            if (t < hit.t) hit = {t, box.id, box.return_fraction};
        }
        for (const PlacedPole& pole : poles) {
            const double t = intersect(pole, origin, dir);
            if (t < hit.t) hit = {t, pole.id, 1.0};
        }
        return hit;
    }

    // Ray height above the surface it returns from at t: > 0 above, <= 0 at or below. The
    // surface is the terrain, raised inside each ground cover k by this ray's canopy[k] (the
    // height of the blade it returns from there; 0 when it reaches the soil).
    double clearance(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t,
                     const double* canopy) const {
        const double x = origin.x() + t * dir.x(), y = origin.y() + t * dir.y();
        double raised = 0.0;
        for (std::size_t k = 0; k < scene.covers.size(); ++k) {
            const GroundCover& cover = scene.covers[k];
            if (canopy[k] > raised && x >= cover.lo.x() && x <= cover.hi.x() && y >= cover.lo.y() &&
                y <= cover.hi.y())
                raised = canopy[k];
        }
        return origin.z() + t * dir.z() - scene.terrainHeight(x, y) - raised;
    }

    // The first puddle's water the ray reaches before t_end: its index and t, or -1.
    int firstWater(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_end,
                   double& t_water) const {
        int first = -1;
        if (!(dir.z() < 0.0)) return first;
        for (std::size_t k = 0; k < scene.puddles.size(); ++k) {
            const double t = (water_levels[k] - origin.z()) / dir.z();
            if (!(t > 0.0) || t >= t_end) continue;
            const Eigen::Vector2d xy = (origin + t * dir).head<2>();
            const Puddle& puddle = scene.puddles[k];
            if ((xy - puddle.centre).squaredNorm() > puddle.radius * puddle.radius) continue;
            t_end = t_water = t;
            first = static_cast<int>(k);
        }
        return first;
    }

    // First terrain crossing in [0, t_end]. The returned t is on the near (above) side of the
    // crossing, so a hit on a vertical face reports the xy of its lower side.
    bool marchTerrain(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_end,
                      const double* canopy, double& t_hit) const {
        const double global_bound = bounds.globalBound();
        double t = 0.0;
        if (origin.z() > global_bound) {
            // Nothing to hit until the ray drops below the highest terrain, if ever.
            if (dir.z() >= 0.0) return false;
            t = (origin.z() - global_bound) / -dir.z();
        } else if (dir.z() > 0.0) {
            t_end = std::min(t_end, (global_bound - origin.z()) / dir.z());
        }
        if (t > t_end) return false;
        if (clearance(origin, dir, t, canopy) <= 0.0) {  // sensor at or under the surface
            t_hit = t;
            return true;
        }
        while (t < t_end) {
            const Eigen::Vector3d p = origin + t * dir;
            bool above_bound = false;
            for (const TerrainBounds::Level& level : bounds.levels()) {
                const double t_skip = std::min(t + level.cell_size, t_end);
                const double lowest_z = std::min(p.z(), origin.z() + t_skip * dir.z());
                if (lowest_z > level.boundNear(p.x(), p.y(), global_bound)) {
                    t = t_skip;
                    above_bound = true;
                    break;
                }
            }
            if (above_bound) continue;
            // Finer steps near the sensor, where the geometry subtends larger angles.
            const double step = std::clamp(0.01 * t, 0.02, 0.25);
            const double t_next = std::min(t + step, t_end);
            if (clearance(origin, dir, t_next, canopy) <= 0.0) {
                double above = t, below = t_next;
                for (int i = 0; i < kMaxBisections && below - above > kBisectionTolerance; ++i) {
                    const double mid = 0.5 * (above + below);
                    if (clearance(origin, dir, mid, canopy) > 0.0) {
                        above = mid;
                    } else {
                        below = mid;
                    }
                }
                t_hit = above;
                return true;
            }
            t = t_next;
        }
        return false;
    }
};

// Appends n beams evenly spaced from lo_deg to hi_deg (a single beam sits at lo_deg).
void appendUniformBeams(std::vector<double>& elevations_deg, int n, double lo_deg, double hi_deg) {
    for (int i = 0; i < n; ++i)
        elevations_deg.push_back(n == 1 ? lo_deg : lo_deg + (hi_deg - lo_deg) * i / (n - 1));
}

LidarModel withMaxRange(LidarModel model, double max_range) {
    model.max_range = max_range;
    return model;
}

}  // namespace

std::vector<double> LidarModel::elevationsByRing() const {
    std::vector<double> sorted = elevations_deg;
    std::stable_sort(sorted.begin(), sorted.end());
    return sorted;
}

void LidarModel::validate() const {
    const auto require = [](bool condition, const char* what) {
        if (!condition)
            throw std::invalid_argument(std::string("travel::sim::LidarModel: ") + what);
    };
    require(!elevations_deg.empty(), "no beams");
    require(elevations_deg.size() <= std::numeric_limits<uint16_t>::max() + std::size_t{1},
            "more beams than a uint16 ring can number");
    for (double elevation : elevations_deg) {
        require(elevation > -90.0 && elevation < 90.0, "beam elevations must be in (-90, 90)");
    }
    require(columns >= 1, "columns must be >= 1");
    require(min_range >= 0.0 && max_range > min_range && std::isfinite(max_range),
            "need 0 <= min_range < max_range < inf");
    require(range_noise_sigma >= 0.0 && std::isfinite(range_noise_sigma),
            "range_noise_sigma must be >= 0");
    require(sweep_period > 0.0 && std::isfinite(sweep_period), "sweep_period must be > 0");
}

LidarModel LidarModel::hdl64(int columns) {
    // The real unit has an upper and a lower block of 32 lasers with different spacing.
    LidarModel model;
    constexpr int kBlockBeams = 32;
    appendUniformBeams(model.elevations_deg, kBlockBeams, 2.0, -8.33);
    appendUniformBeams(model.elevations_deg, kBlockBeams, -8.83, -24.33);
    model.columns = columns;
    model.max_range = 120.0;
    return model;
}

LidarModel LidarModel::hdl32(int columns) {
    return withMaxRange(uniform(32, -30.67, 10.67, columns), 100.0);
}

LidarModel LidarModel::vlp16(int columns) {
    return withMaxRange(uniform(16, -15.0, 15.0, columns), 100.0);
}

LidarModel LidarModel::os128(int columns) {
    return withMaxRange(uniform(128, -22.5, 22.5, columns), 120.0);
}

LidarModel LidarModel::uniform(int n_beams, double lo_deg, double hi_deg, int columns) {
    if (n_beams < 1) throw std::invalid_argument("travel::sim::LidarModel::uniform: n_beams < 1");
    LidarModel model;
    appendUniformBeams(model.elevations_deg, n_beams, lo_deg, hi_deg);
    model.columns = columns;
    return model;
}

Scan scan(const Scene& scene, const LidarModel& model,
          const Eigen::Isometry3d& sensor_pose_in_world) {
    Scan out;
    scan(scene, model, sensor_pose_in_world, out);
    return out;
}

namespace {

// The ray caster behind scan() and scanMoving(): column_poses is null for a static sensor
// (every column fired from sensor_pose_in_world), else one pose per column.
void scanColumns(const Scene& scene, const LidarModel& model,
                 const Eigen::Isometry3d& sensor_pose_in_world,
                 const std::vector<Eigen::Isometry3d>* column_poses, Scan& out) {
    model.validate();
    scene.validate();
    if (scene.covers.size() > kMaxCovers)
        throw std::invalid_argument("travel::sim::scan: more than " + std::to_string(kMaxCovers) +
                                    " ground covers");

    Eigen::Vector3d origin = sensor_pose_in_world.translation();
    Eigen::Matrix3d rotation = sensor_pose_in_world.linear();
    // The terrain bounds must cover every ray of the sweep, from wherever it is fired.
    double reach = model.max_range;
    if (column_poses) {
        double farthest = 0.0;
        for (const Eigen::Isometry3d& pose : *column_poses)
            farthest = std::max(farthest, (pose.translation() - origin).head<2>().norm());
        reach += farthest;
    }
    const PreparedScene world(scene, origin, reach);

    const std::vector<double> elevations = model.elevationsByRing();
    const int beams = static_cast<int>(elevations.size());
    std::vector<double> cos_elevation(beams), sin_elevation(beams);
    for (int ring = 0; ring < beams; ++ring) {
        cos_elevation[ring] = std::cos(elevations[ring] * kDegToRad);
        sin_elevation[ring] = std::sin(elevations[ring] * kDegToRad);
    }
    std::vector<double> cos_azimuth(model.columns), sin_azimuth(model.columns);
    for (int column = 0; column < model.columns; ++column) {
        const double azimuth = (model.clockwise ? -2.0 : 2.0) * kPi * column / model.columns;
        cos_azimuth[column] = std::cos(azimuth);
        sin_azimuth[column] = std::sin(azimuth);
    }

    travel::PointCloud& cloud = out.cloud;
    GroundTruth& gt = out.gt;
    cloud.clear();
    gt.clear();
    const std::size_t rays = static_cast<std::size_t>(beams) * model.columns;
    cloud.reserve(rays);
    cloud.ring.reserve(rays);
    cloud.time.reserve(rays);
    gt.cls.reserve(rays);
    gt.instance.reserve(rays);
    gt.height_above_ground.reserve(rays);

    std::mt19937 rng(model.seed);
    std::normal_distribution<double> range_noise(0.0, 1.0);

    const auto castRay = [&](int ring, int column) {
        const Eigen::Vector3d dir_sensor(cos_elevation[ring] * cos_azimuth[column],
                                         cos_elevation[ring] * sin_azimuth[column],
                                         sin_elevation[ring]);
        const Eigen::Vector3d dir = rotation * dir_sensor;

        const double time_in_sweep =
            model.sweep_period * column / static_cast<double>(model.columns);
        const ObjectHit object = world.nearestObject(origin, dir, time_in_sweep);
        // The blade of each ground cover this ray returns from (0: it reaches the soil).
        std::array<double, kMaxCovers> canopy{};
        for (std::size_t k = 0; k < scene.covers.size(); ++k) {
            const GroundCover& cover = scene.covers[k];
            const double q = rayHash(ring, column, kCoverSalt + static_cast<uint32_t>(k));
            if (q < cover.return_fraction)
                canopy[k] = cover.height * (1.0 - q / cover.return_fraction);
        }
        double t_hit = kInfinity, t_water = kInfinity;
        const int puddle =
            world.firstWater(origin, dir, std::min(object.t, model.max_range), t_water);
        uint8_t cls = NoReturn;
        uint32_t instance = 0;
        float intensity = 0.f;
        if (world.marchTerrain(origin, dir, std::min({object.t, model.max_range, t_water}),
                               canopy.data(), t_hit)) {
            const Eigen::Vector3d hit = origin + t_hit * dir;
            const bool traversable =
                scene.terrainSlopeDeg(hit.x(), hit.y()) <= scene.max_ground_slope_deg;
            cls = traversable ? Ground : NonGround;
            intensity = kTerrainIntensity;
        } else if (puddle >= 0) {
            // Specular water: the ray returns only when mirrored onto something within range;
            // the sensor places that return along the original ray, at the path's length.
            const Puddle& water = scene.puddles[static_cast<std::size_t>(puddle)];
            const double q = rayHash(ring, column, kPuddleSalt + static_cast<uint32_t>(puddle));
            if (q < water.mirror_fraction) {
                const Eigen::Vector3d surface = origin + t_water * dir;
                const Eigen::Vector3d mirrored(dir.x(), dir.y(), -dir.z());
                const double reach = model.max_range - t_water;
                const ObjectHit seen = world.nearestObject(surface, mirrored, time_in_sweep);
                double t_seen = kInfinity;
                if (!world.marchTerrain(surface, mirrored, std::min(seen.t, reach), canopy.data(),
                                        t_seen) &&
                    seen.t <= reach && rayHash(ring, column, seen.id) < seen.return_fraction)
                    t_seen = seen.t;
                if (t_seen < kInfinity) {
                    t_hit = t_water + t_seen;
                    cls = Reflection;
                    intensity = kTerrainIntensity;
                }
            }
        } else if (object.t <= model.max_range) {
            t_hit = object.t;
            cls = NonGround;
            instance = object.id;
            intensity = kObjectIntensity;
            // A dark surface absorbs the ray: no return (nothing behind it is seen either).
            if (object.return_fraction < 1.0 &&
                rayHash(ring, column, object.id) >= object.return_fraction)
                cls = NoReturn, instance = 0;
        }
        if (cls != NoReturn && t_hit < model.min_range) cls = NoReturn, instance = 0;

        const float time = static_cast<float>(time_in_sweep);
        if (cls == NoReturn) {
            if (!model.emit_no_returns) return;
            cloud.push_back(0.f, 0.f, 0.f, 0.f);
            cloud.ring.push_back(static_cast<uint16_t>(ring));
            cloud.time.push_back(time);
            gt.cls.push_back(NoReturn);
            gt.instance.push_back(0);
            gt.height_above_ground.push_back(std::numeric_limits<float>::quiet_NaN());
            return;
        }
        const Eigen::Vector3d hit = origin + t_hit * dir;
        double range = t_hit;
        if (model.range_noise_sigma > 0.0) range += model.range_noise_sigma * range_noise(rng);
        // In the sensor frame the ray starts at 0: no need to invert the pose.
        const Eigen::Vector3d point = range * dir_sensor;
        cloud.push_back(static_cast<float>(point.x()), static_cast<float>(point.y()),
                        static_cast<float>(point.z()), intensity);
        cloud.ring.push_back(static_cast<uint16_t>(ring));
        cloud.time.push_back(time);
        gt.cls.push_back(cls);
        gt.instance.push_back(instance);
        gt.height_above_ground.push_back(
            static_cast<float>(hit.z() - scene.terrainHeight(hit.x(), hit.y())));
    };

    const auto moveTo = [&](int column) {
        if (!column_poses) return;
        const Eigen::Isometry3d& pose = (*column_poses)[static_cast<std::size_t>(column)];
        origin = pose.translation();
        rotation = pose.linear();
    };
    if (model.order == PointOrder::RingMajor) {
        for (int ring = 0; ring < beams; ++ring) {
            for (int column = 0; column < model.columns; ++column) {
                moveTo(column);
                castRay(ring, column);
            }
        }
    } else {
        for (int column = 0; column < model.columns; ++column) {
            moveTo(column);
            for (int ring = 0; ring < beams; ++ring) castRay(ring, column);
        }
    }
}

}  // namespace

void scan(const Scene& scene, const LidarModel& model,
          const Eigen::Isometry3d& sensor_pose_in_world, Scan& out) {
    scanColumns(scene, model, sensor_pose_in_world, nullptr, out);
}

void scanMoving(const Scene& scene, const LidarModel& model,
                const std::vector<Eigen::Isometry3d>& column_poses, Scan& out) {
    model.validate();
    if (column_poses.size() != static_cast<std::size_t>(model.columns))
        throw std::invalid_argument("travel::sim::scanMoving: need one pose per column (" +
                                    std::to_string(model.columns) + "), got " +
                                    std::to_string(column_poses.size()));
    scanColumns(scene, model, column_poses.front(), &column_poses, out);
}

}  // namespace travel::sim
