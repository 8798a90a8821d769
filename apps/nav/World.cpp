// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "nav/World.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

#include "travel/Text.hpp"
#include "travel/TextFile.hpp"

namespace travel::navsim {
namespace {

constexpr double kDeg = M_PI / 180.0;

Eigen::Vector2d dirOf(double deg) {
    return {std::cos(deg * kDeg), std::sin(deg * kDeg)};
}

/// Rectangle centred on c, `length` along yaw, `width` across, counter-clockwise.
std::vector<Eigen::Vector2d> rectangle(const Eigen::Vector2d& c, double yaw_deg, double length,
                                       double width) {
    const Eigen::Vector2d u = dirOf(yaw_deg) * (0.5 * length);
    const Eigen::Vector2d v = Eigen::Vector2d(-u.y(), u.x()).normalized() * (0.5 * width);
    return {c - u - v, c + u - v, c + u + v, c - u + v};
}

struct Line {
    const std::string& source;
    int number;
    std::string keyword;
    std::vector<double> values;

    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error(source + ":" + std::to_string(number) + ": " +
                                 travel::quotedExcerpt(keyword) + ": " + what);
    }
    void expect(std::size_t min_count, std::size_t max_count, const char* usage) const {
        if (values.size() < min_count || values.size() > max_count)
            fail("expected " + std::string(usage) + ", got " + std::to_string(values.size()) +
                 " numbers");
    }
    double positive(std::size_t i, const char* name) const {
        if (!(values[i] > 0)) fail(std::string(name) + " must be > 0");
        return values[i];
    }
};

}  // namespace

World parseWorld(const std::string& text, const std::string& source_name) {
    World w;
    w.source = source_name;
    std::istringstream in(text);
    std::string raw;
    int number = 0;
    bool have_start = false, have_goal = false;
    std::map<std::string, int> counts;
    while (std::getline(in, raw)) {
        ++number;
        if (const auto hash = raw.find('#'); hash != std::string::npos) raw.erase(hash);
        std::istringstream words(raw);
        Line line{source_name, number, {}, {}};
        if (!(words >> line.keyword)) continue;
        const std::string& k = line.keyword;
        const std::string id = k + " " + std::to_string(++counts[k]);
        // Object ids of the simulated LiDAR's ground truth: 1, 2, ... over boxes, poles, walls
        // and movers in file order.
        const auto objectId = [&] {
            return static_cast<uint32_t>(counts["box"] + counts["pole"] + counts["wall"] +
                                         counts["mover"]);
        };
        if (k == "name") {
            if (!(words >> w.name)) line.fail("expected a name");
            continue;
        }
        std::string token;
        while (words >> token) {
            try {
                std::size_t used = 0;
                const double v = std::stod(token, &used);
                if (used != token.size() || !std::isfinite(v)) throw std::invalid_argument(token);
                line.values.push_back(v);
            } catch (const std::exception&) {
                line.fail(travel::quotedExcerpt(token) + " is not a finite number");
            }
        }
        const auto& v = line.values;
        if (k == "start") {
            line.expect(3, 3, "X Y YAW_DEG");
            w.start = {v[0], v[1], v[2] * kDeg};
            have_start = true;
        } else if (k == "goal") {
            line.expect(2, 2, "X Y");
            w.goal = {v[0], v[1]};
            have_goal = true;
        } else if (k == "bounds") {
            line.expect(4, 4, "XMIN YMIN XMAX YMAX");
            if (!(v[0] < v[2] && v[1] < v[3])) line.fail("need XMIN < XMAX and YMIN < YMAX");
            w.bounds = {v[0], v[1], v[2], v[3]};
        } else if (k == "ramp") {
            line.expect(6, 7, "X Y DIR_DEG LENGTH WIDTH SLOPE_DEG [PLATEAU]");
            sim::Ramp r;
            r.start = {v[0], v[1]};
            r.direction = dirOf(v[2]);
            r.length = line.positive(3, "LENGTH");
            r.width = line.positive(4, "WIDTH");
            r.slope_deg = v[5];
            if (!(std::abs(v[5]) < 80)) line.fail("SLOPE_DEG must be within +/-80");
            if (v.size() == 7) {
                if (!(v[6] >= 0)) line.fail("PLATEAU must be >= 0");
                r.plateau_length = v[6];
            }
            w.scene.ramps.push_back(r);
        } else if (k == "step") {
            line.expect(4, 6, "X Y DIR_DEG HEIGHT [LENGTH WIDTH]");
            if (v.size() == 5) line.fail("give both LENGTH and WIDTH, or neither");
            sim::Step s;
            s.start = {v[0], v[1]};
            s.direction = dirOf(v[2]);
            s.height = v[3];
            if (v.size() == 6) {
                s.length = line.positive(4, "LENGTH");
                s.width = line.positive(5, "WIDTH");
            }
            w.scene.steps.push_back(s);
        } else if (k == "kerb") {
            line.expect(6, 6, "X Y YAW_DEG LENGTH DEPTH HEIGHT");
            const Eigen::Vector2d c(v[0], v[1]);
            const double length = line.positive(3, "LENGTH"), depth = line.positive(4, "DEPTH");
            const double height = line.positive(5, "HEIGHT");
            sim::Step s;
            s.direction = dirOf(v[2] + 90.0);  // rises across the long axis
            s.start = c - s.direction * (0.5 * depth);
            s.height = height;
            s.length = depth;
            s.width = length;
            w.kerb_steps.push_back(w.scene.steps.size());
            w.scene.steps.push_back(s);
            w.obstacles.push_back({id, rectangle(c, v[2], length, depth), 0.0, height});
        } else if (k == "bump") {
            line.expect(4, 4, "X Y AMPLITUDE SIGMA");
            w.scene.bumps.push_back({{v[0], v[1]}, v[2], line.positive(3, "SIGMA")});
        } else if (k == "roughness") {
            line.expect(2, 2, "AMPLITUDE WAVELENGTH");
            w.scene.roughness = {v[0], line.positive(1, "WAVELENGTH")};
        } else if (k == "box" || k == "mover") {
            const bool mover = k == "mover";
            if (mover)
                line.expect(8, 8, "X Y YAW_DEG LENGTH WIDTH HEIGHT VX VY");
            else
                line.expect(6, 6, "X Y YAW_DEG LENGTH WIDTH HEIGHT");
            sim::Box b;
            b.id = objectId();
            b.centre = {v[0], v[1]};
            b.yaw_deg = v[2];
            b.length = line.positive(3, "LENGTH");
            b.width = line.positive(4, "WIDTH");
            b.height = line.positive(5, "HEIGHT");
            if (mover) {
                Mover m;
                m.motion.box = b;
                m.motion.velocity = {v[6], v[7]};
                m.box = w.scene.boxes.size();
                m.obstacle = w.obstacles.size();
                w.movers.push_back(m);
            }
            w.scene.boxes.push_back(b);
            w.obstacles.push_back(
                {id, rectangle(b.centre, v[2], b.length, b.width), 0.0, b.height, mover});
        } else if (k == "pole") {
            line.expect(4, 4, "X Y RADIUS HEIGHT");
            sim::Pole p;
            p.id = objectId();
            p.centre = {v[0], v[1]};
            p.radius = line.positive(2, "RADIUS");
            p.height = line.positive(3, "HEIGHT");
            w.scene.poles.push_back(p);
            w.obstacles.push_back({id, {p.centre}, p.radius, p.height});
        } else if (k == "wall") {
            line.expect(6, 6, "X1 Y1 X2 Y2 THICKNESS HEIGHT");
            sim::Wall wl;
            wl.id = objectId();
            wl.a = {v[0], v[1]};
            wl.b = {v[2], v[3]};
            if ((wl.b - wl.a).norm() < 1e-6) line.fail("the two ends coincide");
            wl.thickness = line.positive(4, "THICKNESS");
            wl.height = line.positive(5, "HEIGHT");
            w.scene.walls.push_back(wl);
            const Eigen::Vector2d d = wl.b - wl.a;
            w.obstacles.push_back({id,
                                   rectangle(0.5 * (wl.a + wl.b), std::atan2(d.y(), d.x()) / kDeg,
                                             d.norm(), wl.thickness),
                                   0.0, wl.height});
        } else {
            line.fail(
                "unknown keyword (expected name, start, goal, bounds, ramp, step, kerb, "
                "bump, roughness, box, pole, wall or mover)");
        }
    }
    if (!have_start || !have_goal)
        throw std::runtime_error(source_name + ": a world needs a 'start' and a 'goal' line");
    try {
        w.scene.validate();
    } catch (const std::exception& e) {
        throw std::runtime_error(source_name + ": " + e.what());
    }
    return w;
}

void placeMovers(World& w, double t) {
    for (const Mover& m : w.movers) {
        sim::Box& b = w.scene.boxes[m.box];
        b = m.motion.box;
        b.centre += m.motion.velocity * t;
        w.obstacles[m.obstacle].polygon = rectangle(b.centre, b.yaw_deg, b.length, b.width);
    }
}

World loadWorld(const std::string& path) {
    return parseWorld(
        travel::readTextFile(path, "a world is text, one item a line (apps/nav/World.hpp)"), path);
}

World shiftedObstacles(const World& world, unsigned seed, double amplitude) {
    World w = world;
    if (seed == 0) return w;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-amplitude, amplitude);
    const Eigen::Vector2d kerb_shift(d(rng), d(rng));
    const Eigen::Vector2d box_shift(d(rng), d(rng));
    for (auto& o : w.obstacles) {
        const bool kerb = o.what.rfind("kerb", 0) == 0, box = o.what.rfind("box", 0) == 0;
        if (!kerb && !box) continue;
        for (auto& p : o.polygon) p += kerb ? kerb_shift : box_shift;
    }
    for (std::size_t k : w.kerb_steps) w.scene.steps[k].start += kerb_shift;
    const Eigen::Vector2d mover_shift(d(rng), d(rng));  // drawn last: older seeds unchanged
    for (auto& b : w.scene.boxes) b.centre += box_shift;
    for (auto& m : w.movers) m.motion.box.centre += mover_shift;
    placeMovers(w, 0.0);
    w.name += "_seed" + std::to_string(seed);
    return w;
}

Eigen::Vector4d worldExtent(const World& w) {
    if (w.bounds != Eigen::Vector4d::Zero()) return w.bounds;
    Eigen::Vector2d lo = w.start.head<2>().cwiseMin(w.goal),
                    hi = w.start.head<2>().cwiseMax(w.goal);
    for (const auto& o : w.obstacles)
        for (const auto& p : o.polygon) {
            lo = lo.cwiseMin(p - Eigen::Vector2d::Constant(o.radius));
            hi = hi.cwiseMax(p + Eigen::Vector2d::Constant(o.radius));
        }
    return {lo.x() - 2.0, lo.y() - 2.0, hi.x() + 2.0, hi.y() + 2.0};
}

}  // namespace travel::navsim
