// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/sim/Scenes.hpp"

#include <cmath>

namespace travel::sim {
namespace {

// A 15 m ramp rising along +x from x = start_x, centred on y = 0.
Ramp rampAlongX(double start_x, double width, double slope_deg) {
    Ramp ramp;
    ramp.start = {start_x, 0.0};
    ramp.direction = {1.0, 0.0};
    ramp.length = 15.0;
    ramp.width = width;
    ramp.slope_deg = slope_deg;
    return ramp;
}

Step halfPlane(const Eigen::Vector2d& start, const Eigen::Vector2d& towards_raised_side,
               double height) {
    Step step;
    step.start = start;
    step.direction = towards_raised_side;
    step.height = height;
    return step;
}

Box box(uint32_t id, double x, double y, double length, double width, double height,
        double yaw_deg = 0.0) {
    Box b;
    b.id = id;
    b.centre = {x, y};
    b.yaw_deg = yaw_deg;
    b.length = length;
    b.width = width;
    b.height = height;
    return b;
}

Box car(uint32_t id, double x, double y, double yaw_deg) {
    return box(id, x, y, 4.5, 1.8, 1.5, yaw_deg);
}

// A verge beside the road along x: from y = y_start it rises `rise` metres over `length` metres
// away from the road (outward +1: towards +y, -1: towards -y) to a plateau; 400 m long.
Ramp vergeBesideRoad(double y_start, double outward, double length, double rise) {
    Ramp ramp;
    ramp.start = {0.0, y_start};
    ramp.direction = {0.0, outward};
    ramp.length = length;
    ramp.width = 400.0;
    ramp.slope_deg = std::atan(rise / length) / kDegToRad;
    return ramp;
}

Pole pole(uint32_t id, double x, double y, double radius, double height) {
    Pole p;
    p.id = id;
    p.centre = {x, y};
    p.radius = radius;
    p.height = height;
    return p;
}

Wall wall(uint32_t id, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double thickness,
          double height) {
    Wall w;
    w.id = id;
    w.a = a;
    w.b = b;
    w.thickness = thickness;
    w.height = height;
    return w;
}

}  // namespace

Scene flatGround() {
    return Scene{};
}

Scene slope(double slope_deg) {
    Scene scene;
    scene.ramps.push_back(rampAlongX(6.0, 20.0, slope_deg));
    return scene;
}

Scene kerbsAndSteps() {
    Scene scene;
    constexpr double kKerbHeight = 0.15;
    // Kerbs with raised sidewalks beyond them on both sides of the road.
    scene.steps.push_back(halfPlane({0.0, 4.5}, {0.0, 1.0}, kKerbHeight));
    scene.steps.push_back(halfPlane({0.0, -5.5}, {0.0, -1.0}, kKerbHeight));
    // Stairs across the road: the raised regions add up to 1, 2, 3 steps, then a landing.
    constexpr double kTread = 0.4;
    for (int i = 0; i < 3; ++i) {
        Step step = halfPlane({8.0 + kTread * i, -0.5}, {1.0, 0.0}, 0.15);
        step.width = 10.0;  // the road, y in [-5.5, 4.5]
        scene.steps.push_back(step);
    }
    return scene;
}

Scene bumpyTerrain() {
    Scene scene;
    scene.bumps = {
        {{10.0, 5.0}, 0.3, 3.0},   {{-8.0, 12.0}, 0.5, 4.0},   {{15.0, -10.0}, 0.2, 2.0},
        {{-12.0, -9.0}, 0.4, 3.0}, {{25.0, 20.0}, 0.5, 4.0},   {{0.0, -22.0}, 0.35, 2.5},
        {{-25.0, 3.0}, 0.25, 3.5}, {{30.0, -25.0}, 0.45, 3.0},
    };
    scene.roughness.amplitude = 0.02;
    scene.roughness.wavelength = 1.5;
    return scene;
}

Scene urbanObjects() {
    Scene scene;
    scene.boxes = {car(1, 10.0, 3.0, 0.0), car(2, 10.0, 5.8, 0.0), car(3, -12.0, -6.0, 30.0)};
    scene.poles = {pole(4, 6.0, -4.0, 0.10, 3.0), pole(5, -5.0, 7.0, 0.15, 5.0),
                   pole(6, 12.0, -6.0, 0.12, 4.0)};
    scene.walls = {wall(7, {-18.0, -14.0}, {-6.0, -14.0}, 0.2, 1.0),
                   // On the line of sight through pole 6, which shadows part of it.
                   wall(8, {24.0, -16.0}, {24.0, -4.0}, 0.3, 3.0)};
    return scene;
}

Scene mixed() {
    Scene scene;
    scene.ramps.push_back(rampAlongX(12.0, 8.0, 10.0));
    scene.steps.push_back(halfPlane({0.0, 5.0}, {0.0, 1.0}, 0.15));
    scene.bumps = {{{-15.0, -12.0}, 0.4, 3.0}, {{8.0, -16.0}, 0.3, 2.5}, {{-20.0, 15.0}, 0.5, 4.0}};
    scene.boxes = {car(1, -8.0, -2.0, 10.0)};
    scene.poles = {pole(2, 5.0, -4.0, 0.12, 4.0)};
    scene.walls = {wall(3, {-10.0, 8.0}, {0.0, 8.0}, 0.2, 2.0)};
    return scene;
}

Scene fencesAndWalls() {
    Scene scene;
    // Fence along y = 6: thin posts, and mesh panels whose lower edge is 2 cm above the ground
    // (the rays through the mesh holes are not modelled: the panels are solid, 1 cm thick).
    uint32_t panel_id = 101;
    for (int k = 0; k < 25; ++k) {
        const double x = -30.0 + 2.5 * k;
        scene.poles.push_back(pole(static_cast<uint32_t>(k + 1), x, 6.0, 0.04, 1.6));
        if (k + 1 < 25) {
            Box panel = box(panel_id++, x + 1.25, 6.0, 2.0, 0.01, 1.5);  // 0.5 m gaps
            panel.clearance = 0.02;
            scene.boxes.push_back(panel);
        }
    }
    // Wall on a footing along y = -7: the footing's top is a 0.6 m wide strip 0.3 m high.
    scene.walls.push_back(wall(200, {-30.0, -7.0}, {30.0, -7.0}, 0.25, 2.5));
    scene.boxes.push_back(box(201, 0.0, -7.0, 60.0, 0.6, 0.3));
    return scene;
}

Scene meshFencesOnRoughVerges() {
    Scene scene;
    // Left: grass rising 0.3 m over 2 m from y = 4, a mesh fence on the plateau at y = 7.
    // Right: a rough bank rising 0.4 m over 3 m from y = -5 (7.6 deg), walls on it at y = -9.
    scene.ramps = {vergeBesideRoad(4.0, 1.0, 2.0, 0.3), vergeBesideRoad(-5.0, -1.0, 3.0, 0.4)};
    scene.roughness.amplitude = 0.04;
    scene.roughness.wavelength = 1.0;
    // Posts every 2.5 m (ids 1-12, x -15..12.5); between them mesh: vertical wires 8 cm wide
    // every 20 cm (the rays between them reach the grass behind), 3 cm above the ground.
    uint32_t wire_id = 101;
    for (int k = 0; k < 12; ++k) {
        const double x = -15.0 + 2.5 * k;
        scene.poles.push_back(pole(static_cast<uint32_t>(k + 1), x, 7.0, 0.04, 1.6));
        for (int w = 1; w < 12; ++w) {
            Box wire = box(wire_id, x + 0.2 * w + 0.05, 7.0, 0.08, 0.01, 1.45);
            wire.clearance = 0.03;
            wire.return_fraction = 0.7;  // thin wires: 30 % of the rays that hit them are lost
            scene.boxes.push_back(wire);
        }
        ++wire_id;  // one id per panel
    }
    // A 1.2 m garden wall straight on the rough bank (id 200), x < 0, and a 2 m wall (id 201)
    // on a 0.15 m high, 0.3 m wide footing (id 202), x > 0.
    scene.walls.push_back(wall(200, {-30.0, -9.0}, {-1.0, -9.0}, 0.2, 1.2));
    scene.walls.push_back(wall(201, {1.0, -9.0}, {30.0, -9.0}, 0.2, 2.0));
    scene.boxes.push_back(box(202, 15.5, -9.0, 29.0, 0.3, 0.15));
    return scene;
}

Scene grassVerges() {
    Scene scene;
    scene.ramps = {vergeBesideRoad(4.0, 1.0, 2.0, 0.3), vergeBesideRoad(-4.0, -1.0, 1.5, 0.5)};
    scene.roughness.amplitude = 0.03;
    scene.roughness.wavelength = 1.0;
    return scene;
}

Scene vergesWithStreetFurniture() {
    Scene scene;
    scene.ramps = {vergeBesideRoad(4.0, 1.0, 2.0, 0.3), vergeBesideRoad(14.0, 1.0, 1.0, 0.2),
                   vergeBesideRoad(-4.0, -1.0, 1.5, 0.5), vergeBesideRoad(-22.0, -1.0, 1.0, 0.3)};
    scene.roughness.amplitude = 0.03;
    scene.roughness.wavelength = 1.0;
    uint32_t id = 1;
    for (double x = -32.0; x <= 32.0; x += 4.0) {              // within 40 m of the sensor
        scene.poles.push_back(pole(id++, x, 6.5, 0.05, 1.2));  // fence posts
        scene.poles.push_back(pole(id++, x + 2.0, -24.0, 0.05, 1.2));
        if (static_cast<int>(x) % 8 != 0) continue;
        scene.poles.push_back(pole(id++, x + 4.0, -7.0, 0.15, 5.0));  // tree trunks
        scene.poles.push_back(pole(id++, x + 2.0, 16.0, 0.15, 5.0));
    }
    return scene;
}

Scene offRoadMeadow() {
    Scene scene;
    scene.bumps = {
        {{6.0, 4.0}, 0.3, 2.0},    {{-7.0, 9.0}, 0.5, 3.0},    {{12.0, -6.0}, 0.4, 2.5},
        {{-10.0, -8.0}, 0.6, 4.0}, {{18.0, 12.0}, 0.5, 3.0},   {{2.0, -14.0}, 0.35, 1.5},
        {{-18.0, 2.0}, 0.25, 2.0}, {{25.0, -18.0}, 0.45, 3.5}, {{-22.0, -20.0}, 0.3, 2.5},
        {{8.0, 20.0}, -0.3, 3.0},  {{-3.0, 4.0}, -0.2, 2.0},
    };
    scene.roughness.amplitude = 0.05;
    scene.roughness.wavelength = 1.2;
    const double bushes[8][4] = {{7, -3, 1.0, 0.8},   {-5, 6, 1.4, 1.2},   {14, 8, 1.2, 1.0},
                                 {-12, -4, 0.8, 0.6}, {20, -10, 1.6, 1.2}, {-9, 15, 1.0, 0.9},
                                 {4, 11, 0.9, 0.7},   {-16, -13, 1.2, 1.1}};
    for (int k = 0; k < 8; ++k)
        scene.boxes.push_back(box(static_cast<uint32_t>(k + 1), bushes[k][0], bushes[k][1],
                                  bushes[k][2], bushes[k][2], bushes[k][3], 20.0 * k));
    const double trunks[6][3] = {{9, 2, 0.2},    {-6, -7, 0.3}, {15, -2, 0.15},
                                 {-14, 9, 0.25}, {3, -9, 0.2},  {22, 6, 0.3}};
    for (int k = 0; k < 6; ++k)
        scene.poles.push_back(
            pole(static_cast<uint32_t>(11 + k), trunks[k][0], trunks[k][1], trunks[k][2], 4.0));
    return scene;
}

namespace {

// SemanticKITTI labels the whole of a meadow, a hillside or a ditch terrain, whatever the slope
// its roughness makes locally (5 cm on 1.2 m waves reach 15 deg, 30-40 deg on a 20 deg hill).
constexpr double kWholeTerrainIsGround = 90.0;

GroundCover grass(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double height,
                  double return_fraction) {
    GroundCover cover;
    cover.lo = lo;
    cover.hi = hi;
    cover.height = height;
    cover.return_fraction = return_fraction;
    return cover;
}

// offRoadMeadow's terrain (bumps, roughness) under grass of `height` everywhere within 80 m.
Scene grassyMeadow(double height) {
    Scene scene = offRoadMeadow();
    scene.boxes.clear(), scene.poles.clear();
    scene.covers.push_back(grass({-80.0, -80.0}, {80.0, 80.0}, height, 0.5));
    scene.max_ground_slope_deg = kWholeTerrainIsGround;
    return scene;
}

// Rocks 0.2-0.6 m (ids 31-38): boxes resting on (and sunk into) the terrain.
void addRocks(Scene& scene) {
    const double rocks[8][4] = {{5, 3, 0.5, 0.3},    {-4, -5, 0.8, 0.45}, {11, -1, 0.6, 0.2},
                                {-8, 1, 1.0, 0.6},   {2, 7, 0.4, 0.25},   {16, 10, 0.9, 0.5},
                                {-13, -9, 0.7, 0.4}, {8, -12, 0.5, 0.35}};
    for (int k = 0; k < 8; ++k)
        scene.boxes.push_back(box(static_cast<uint32_t>(31 + k), rocks[k][0], rocks[k][1],
                                  rocks[k][2], 0.8 * rocks[k][2], rocks[k][3], 35.0 * k));
}

// offRoadMeadow's bushes (ids 1-8) with foliage returning 70 % of the rays, and its trunks.
void addBushesAndTrunks(Scene& scene) {
    const Scene meadow = offRoadMeadow();
    for (Box bush : meadow.boxes) {
        bush.return_fraction = 0.7;
        scene.boxes.push_back(bush);
    }
    scene.poles.insert(scene.poles.end(), meadow.poles.begin(), meadow.poles.end());
}

// A fence of posts every 3 m from a to b, four wires between them (one id per span).
void addFarmFence(Scene& scene, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                  uint32_t first_post_id, uint32_t first_span_id) {
    const Eigen::Vector2d along = b - a;
    const int spans = static_cast<int>(std::lround(along.norm() / 3.0));
    const double yaw = std::atan2(along.y(), along.x()) / kDegToRad;
    for (int k = 0; k <= spans; ++k) {
        const Eigen::Vector2d p = a + along * (static_cast<double>(k) / spans);
        scene.poles.push_back(
            pole(first_post_id + static_cast<uint32_t>(k), p.x(), p.y(), 0.06, 1.3));
        if (k == spans) break;
        const Eigen::Vector2d mid = a + along * ((k + 0.5) / spans);
        for (double height : {0.2, 0.55, 0.9, 1.25}) {
            Box wire = box(first_span_id + static_cast<uint32_t>(k), mid.x(), mid.y(),
                           along.norm() / spans - 0.12, 0.015, 0.015, yaw);
            wire.clearance = height;
            wire.return_fraction = 0.6;
            scene.boxes.push_back(wire);
        }
    }
}

// A ditch along x on one side (outward +1: towards +y), from |y| = y_start: sides of slope_deg
// down to `depth`, a flat bottom `bottom` wide, and up again.
void addDitch(Scene& scene, double y_start, double outward, double depth, double slope_deg,
              double bottom) {
    const double side = depth / std::tan(slope_deg * kDegToRad);
    Ramp down;
    down.start = {0.0, y_start};
    down.direction = {0.0, outward};
    down.length = side;
    down.width = 400.0;
    down.slope_deg = -slope_deg;
    Ramp up = down;
    up.start = {0.0, y_start + outward * (side + bottom)};
    up.slope_deg = slope_deg;
    scene.ramps.push_back(down);
    scene.ramps.push_back(up);
}

}  // namespace

Scene offRoadTallGrassAndRocks() {
    Scene scene = grassyMeadow(0.12);
    scene.covers.push_back(grass({4.0, -10.0}, {12.0, -2.0}, 0.3, 0.6));
    scene.covers.push_back(grass({-10.0, -14.0}, {-2.0, -6.0}, 0.3, 0.6));
    scene.covers.push_back(grass({9.0, 2.0}, {15.0, 8.0}, 0.5, 0.7));
    scene.covers.push_back(grass({-13.0, 1.0}, {-7.0, 7.0}, 0.5, 0.7));
    scene.covers.push_back(grass({0.0, 11.0}, {6.0, 17.0}, 0.5, 0.7));
    addBushesAndTrunks(scene);
    const double shrubs[6][4] = {{6, 0, 0.8, 0.4},    {-3, 9, 0.6, 0.3},  {12, -8, 1.0, 0.5},
                                 {-9, -3, 0.7, 0.35}, {17, 3, 0.9, 0.45}, {-15, 6, 0.8, 0.4}};
    for (int k = 0; k < 6; ++k) {
        Box shrub = box(static_cast<uint32_t>(21 + k), shrubs[k][0], shrubs[k][1], shrubs[k][2],
                        shrubs[k][2], shrubs[k][3], 25.0 * k);
        shrub.return_fraction = 0.6;
        scene.boxes.push_back(shrub);
    }
    addRocks(scene);
    return scene;
}

Scene offRoadFenceLines() {
    Scene scene = grassyMeadow(0.15);
    addFarmFence(scene, {-24.0, 6.0}, {24.0, 6.0}, 1, 101);
    addFarmFence(scene, {14.0, -21.0}, {14.0, 21.0}, 31, 201);
    return scene;
}

Scene offRoadTrackWithDitchesRutsAndPuddles() {
    Scene scene;
    scene.roughness.amplitude = 0.03;
    scene.roughness.wavelength = 1.0;
    scene.max_ground_slope_deg = kWholeTerrainIsGround;
    for (double side : {1.0, -1.0}) {
        Step rut;
        rut.start = {0.0, 0.6 * side};
        rut.direction = {0.0, side};
        rut.height = -0.1;
        rut.length = 0.35;
        rut.width = 400.0;
        scene.steps.push_back(rut);
    }
    const double puddles[5][4] = {{6.0, 0.78, 1.0, 0.12},
                                  {12.0, -0.2, 1.8, 0.1},
                                  {-8.0, 0.0, 1.6, 0.12},
                                  {20.0, 0.78, 1.2, 0.1},
                                  {-15.0, -0.78, 1.0, 0.12}};
    for (const auto& p : puddles) {
        Puddle puddle;
        puddle.centre = {p[0], p[1]};
        puddle.radius = p[2];
        puddle.depth = p[3];
        scene.puddles.push_back(puddle);
    }
    addDitch(scene, 3.5, 1.0, 0.6, 20.0, 0.8);
    addDitch(scene, -3.5, -1.0, 0.4, 15.0, 0.6);
    scene.covers.push_back(grass({-80.0, -0.5}, {80.0, 0.5}, 0.1, 0.4));
    scene.covers.push_back(grass({-80.0, 3.2}, {80.0, 80.0}, 0.2, 0.5));
    scene.covers.push_back(grass({-80.0, -80.0}, {80.0, -3.2}, 0.2, 0.5));
    scene.poles = {pole(11, 5.0, 7.0, 0.2, 4.0), pole(12, 14.0, 7.5, 0.25, 4.0),
                   pole(13, -10.0, 7.2, 0.15, 4.0)};
    for (uint32_t k = 0; k < 3; ++k) {
        Box bush = box(k + 1, -6.0 + 9.0 * k, -7.5, 1.2, 1.0, 1.0, 30.0 * k);
        bush.return_fraction = 0.7;
        scene.boxes.push_back(bush);
    }
    return scene;
}

Scene offRoadHillside(double slope_deg) {
    Scene scene = grassyMeadow(0.15);
    Ramp hill;
    hill.start = {-40.0, 0.0};
    hill.direction = {1.0, 0.0};
    hill.length = 80.0;
    hill.width = 400.0;
    hill.slope_deg = slope_deg;
    scene.ramps.push_back(hill);
    addBushesAndTrunks(scene);
    addRocks(scene);
    return scene;
}

Scene carBesideSensor(double gap) {
    Scene scene;
    scene.boxes = {car(1, 0.0, gap + 0.9, 0.0)};
    return scene;
}

std::vector<Box> realisticCar(uint32_t id, const Eigen::Vector2d& centre, double yaw_deg,
                              double paint_return, double tyre_return,
                              const Eigen::Vector2d& velocity) {
    const double c = std::cos(yaw_deg * kDegToRad), s = std::sin(yaw_deg * kDegToRad);
    std::vector<Box> parts;
    // A part in car coordinates: u along the car (front +), v across, z from z0 to z1.
    const auto part = [&](double u, double v, double length, double width, double z0, double z1,
                          double return_fraction) {
        Box b = box(id, centre.x() + c * u - s * v, centre.y() + s * u + c * v, length, width,
                    z1 - z0, yaw_deg);
        b.clearance = z0;
        b.velocity = velocity;
        b.return_fraction = return_fraction;
        parts.push_back(b);
    };
    part(0.0, 0.0, 4.5, 1.8, 0.35, 0.95, paint_return);  // body: bonnet, doors, boot
    for (double u : {-1.35, 1.35})
        for (double v : {-0.78, 0.78}) part(u, v, 0.65, 0.22, 0.0, 0.65, tyre_return);
    // Cabin u in [-1.5, 0.7]: A, B and C pillars on both sides, windows between them.
    for (double v : {-0.75, 0.75}) {
        part(0.6, v, 0.2, 0.1, 0.95, 1.38, paint_return);
        part(-0.4, v, 0.12, 0.1, 0.95, 1.38, paint_return);
        part(-1.4, v, 0.2, 0.1, 0.95, 1.38, paint_return);
    }
    part(-0.4, 0.0, 2.2, 1.6, 1.38, 1.48, paint_return);  // roof
    part(-0.1, 0.0, 0.35, 1.4, 0.5, 1.2, 1.0);            // front seat backs
    part(-1.15, 0.0, 0.4, 1.4, 0.5, 1.15, 1.0);           // rear bench
    return parts;
}

Scene realisticCarBesideSensor(double gap) {
    Scene scene;
    scene.boxes = realisticCar(1, {0.0, gap + 0.9}, 0.0, 0.7, 0.5);
    return scene;
}

std::vector<Box> egoVehicle() {
    // Passat B6 Variant: 4.77 x 1.82 m, front 2.7 m ahead of the scanner: centre 2.7 - 4.77 / 2.
    Box body = box(kEgoVehicleId, 2.7 - 4.77 / 2, 0.0, 4.77, 1.82, 0.95 - 0.35, 0.0);
    body.clearance = 0.35;
    return {body};
}

Scene realisticCarBesideEgoVehicle(double gap) {
    Scene scene = realisticCarBesideSensor(gap);
    const std::vector<Box> ego = egoVehicle();
    scene.boxes.insert(scene.boxes.end(), ego.begin(), ego.end());
    return scene;
}

Scene parkedCarsAt20To25Metres() {
    Scene scene;
    for (const std::vector<Box>& parts :
         {realisticCar(1, {-3.0, 21.0}, 0.0), realisticCar(2, {5.0, 23.5}, 0.0, 0.7, 0.5),
          realisticCar(3, {-24.0, -4.0}, 90.0)})
        scene.boxes.insert(scene.boxes.end(), parts.begin(), parts.end());
    return scene;
}

Scene movingCarAcrossSweepStart(double distance, double yaw_deg, const Eigen::Vector2d& velocity) {
    Scene scene;
    scene.boxes = realisticCar(1, {distance, 0.0}, yaw_deg, 1.0, 1.0, velocity);
    return scene;
}

Scene personBesideCar(double distance, double gap) {
    Scene scene;
    scene.boxes = realisticCar(1, {0.0, distance}, 0.0);
    scene.boxes.push_back(box(2, 2.25 + gap + 0.25, distance, 0.5, 0.35, 1.75, 0.0));
    scene.boxes.push_back(box(3, 0.5, distance - 0.9 - gap - 0.175, 0.5, 0.35, 1.75, 0.0));
    return scene;
}

Scene parkedCarRow(double distance, double gap) {
    Scene scene;
    for (uint32_t k = 0; k < 4; ++k) {
        const std::vector<Box> parts =
            realisticCar(k + 1, {-9.75 + k * (4.5 + gap), distance}, 0.0);
        scene.boxes.insert(scene.boxes.end(), parts.begin(), parts.end());
    }
    return scene;
}

Scene carBeforeHedge(double distance, double gap, double height) {
    Scene scene;
    scene.boxes = realisticCar(1, {0.0, distance}, 0.0);
    Wall hedge;
    hedge.id = 2;
    hedge.a = {-10.0, distance + 0.9 + gap + 0.5};
    hedge.b = {10.0, distance + 0.9 + gap + 0.5};
    hedge.thickness = 1.0;
    hedge.height = height;
    scene.walls.push_back(hedge);
    return scene;
}

Scene objectBehindParkedCar(double distance, double gap, bool behind_is_car) {
    Scene scene;
    scene.boxes = realisticCar(1, {0.0, distance}, 0.0);
    if (behind_is_car) {
        const std::vector<Box> parts = realisticCar(2, {0.3, distance + 1.8 + gap}, 0.0);
        scene.boxes.insert(scene.boxes.end(), parts.begin(), parts.end());
    } else {
        scene.boxes.push_back(box(2, -0.9, distance + 0.9 + gap + 0.175, 0.5, 0.35, 1.2, 0.0));
    }
    return scene;
}

Eigen::Isometry3d sensorPoseAt(const Scene& scene, double x, double y, double height,
                               double roll_deg, double pitch_deg, double yaw_deg) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(x, y, scene.terrainHeight(x, y) + height);
    pose.linear() = (Eigen::AngleAxisd(yaw_deg * kDegToRad, Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(pitch_deg * kDegToRad, Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(roll_deg * kDegToRad, Eigen::Vector3d::UnitX()))
                        .toRotationMatrix();
    return pose;
}

}  // namespace travel::sim
