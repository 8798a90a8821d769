// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "MapTestScene.hpp"

#include <mrpt/maps/CPointsMapXYZI.h>

#include <algorithm>
#include <cmath>

#include "travel/sim/SyntheticLidar.hpp"

namespace travel_map_test {

using travel::sim::Scene;

namespace {
constexpr double kSensorHeight = 1.8;
constexpr int kPoses = 17;
}  // namespace

Scene mapScene() {
    Scene s;
    travel::sim::Ramp ramp;
    ramp.start = {-4.0, 6.0};
    ramp.direction = {1.0, 0.0};
    ramp.length = 6.0;
    ramp.width = 4.0;
    ramp.slope_deg = 10.0;
    ramp.plateau_length = 3.0;
    s.ramps.push_back(ramp);
    travel::sim::Step kerb;
    kerb.start = {0.0, -7.1};  // inside a cell row, not on a cell edge
    kerb.direction = {0.0, -1.0};
    kerb.height = 0.15;
    s.steps.push_back(kerb);
    travel::sim::Box box;
    box.id = 1;
    box.centre = {3.0, -9.0};
    box.length = 2.0;
    box.width = 1.5;
    box.height = 1.2;
    s.boxes.push_back(box);
    travel::sim::Pole pole;
    pole.id = 2;
    pole.centre = {-5.0, 3.0};
    pole.radius = 0.15;
    pole.height = 3.0;
    s.poles.push_back(pole);
    s.validate();
    return s;
}

std::vector<mrpt::poses::CPose3D> robotPoses() {
    std::vector<mrpt::poses::CPose3D> poses;
    for (int k = 0; k < kPoses; ++k) poses.emplace_back(-12.0 + 1.5 * k, 0.0, 0.0, 0.0, 0.0, 0.0);
    return poses;
}

mrpt::obs::CObservationPointCloud::Ptr sweep(const Scene& scene, std::size_t k) {
    const mrpt::poses::CPose3D robot = robotPoses().at(k);
    const mrpt::poses::CPose3D mount(0.0, 0.0, kSensorHeight, 0.0, 0.0, 0.0);
    const mrpt::poses::CPose3D sensor = robot + mount;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = sensor.getRotationMatrix().asEigen();
    T.translation() = Eigen::Vector3d(sensor.x(), sensor.y(), sensor.z());
    travel::sim::LidarModel model = travel::sim::LidarModel::vlp16(900);
    model.range_noise_sigma = 0.01;
    model.seed = 11 + uint32_t(k);
    const travel::sim::Scan scan = travel::sim::scan(scene, model, T);

    auto obs = mrpt::obs::CObservationPointCloud::Create();
    auto points = mrpt::maps::CPointsMapXYZI::Create();
    points->reserve(scan.cloud.size());
    for (std::size_t i = 0; i < scan.cloud.size(); ++i)
        points->insertPointFast(scan.cloud.x[i], scan.cloud.y[i], scan.cloud.z[i]);
    points->mark_as_modified();
    obs->pointcloud = points;
    obs->sensorPose = mount;
    obs->sensorLabel = "VLP16";
    obs->timestamp = mrpt::Clock::fromDouble(1.0e9 + 0.1 * double(k));
    return obs;
}

std::vector<CellTruth> cellTruth(const Scene& scene, double min_x, double min_y, int nx, int ny,
                                 double resolution, double max_step, double max_slope_deg) {
    constexpr int kSamples = 6;  // per side, both cell edges included
    const double spacing = resolution / (kSamples - 1);
    const double allowed_rise = spacing * std::tan(max_slope_deg * M_PI / 180.0);
    std::vector<CellTruth> cells(std::size_t(nx) * std::size_t(ny));
    double h[kSamples][kSamples];
    for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix) {
            CellTruth& c = cells[std::size_t(iy) * nx + ix];
            const double x0 = min_x + ix * resolution, y0 = min_y + iy * resolution;
            bool steep = false;
            for (int sy = 0; sy < kSamples; ++sy)
                for (int sx = 0; sx < kSamples; ++sx) {
                    const double x = x0 + sx * spacing, y = y0 + sy * spacing;
                    h[sy][sx] = scene.terrainHeight(x, y);
                    steep = steep || scene.terrainSlopeDeg(x, y) > max_slope_deg;
                    for (const auto& box : scene.boxes) {
                        const double yaw = box.yaw_deg * M_PI / 180.0;
                        const double dx = x - box.centre.x(), dy = y - box.centre.y();
                        const double along = dx * std::cos(yaw) + dy * std::sin(yaw);
                        const double across = -dx * std::sin(yaw) + dy * std::cos(yaw);
                        if (std::abs(along) <= box.length / 2 && std::abs(across) <= box.width / 2)
                            c.box = true;
                    }
                }
            for (const auto& pole : scene.poles) {  // circle vs rectangle
                const double qx = std::clamp(pole.centre.x(), x0, x0 + resolution);
                const double qy = std::clamp(pole.centre.y(), y0, y0 + resolution);
                if (std::hypot(qx - pole.centre.x(), qy - pole.centre.y()) <= pole.radius)
                    c.pole = true;
            }
            double step = 0;
            for (int sy = 0; sy < kSamples; ++sy)
                for (int sx = 0; sx < kSamples; ++sx) {
                    if (sx + 1 < kSamples)
                        step = std::max(step, std::abs(h[sy][sx + 1] - h[sy][sx]));
                    if (sy + 1 < kSamples)
                        step = std::max(step, std::abs(h[sy + 1][sx] - h[sy][sx]));
                }
            const bool has_step = step - allowed_rise > max_step;
            c.truth = (c.box || c.pole || steep || has_step) ? Truth::Obstacle : Truth::Traversable;
        }
    for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix) {
            CellTruth& c = cells[std::size_t(iy) * nx + ix];
            for (int oy = -1; oy <= 1; ++oy)
                for (int ox = -1; ox <= 1; ++ox) {
                    const int jx = ix + ox, jy = iy + oy;
                    if (jx < 0 || jy < 0 || jx >= nx || jy >= ny) continue;
                    if (cells[std::size_t(jy) * nx + jx].truth != c.truth) c.border = true;
                }
        }
    return cells;
}

std::string mapIni(const std::string& section) {
    return "[" + section +
           "]\n"
           "traversabilityMap_count=1\n"
           "[" +
           section +
           "_traversabilityMap_00_creationOpts]\n"
           "min_x=-14\nmax_x=14\nmin_y=-12\nmax_y=10\nresolution=0.25\noctomap_resolution=0.2\n"
           "[" +
           section +
           "_traversabilityMap_00_insertOpts]\n"
           // The map's thresholds were set with the preset's former 2 m cells; with the 4 m
           // cells of the preset now, the box's footprint drops from 43/48 to 35/48 obstacle
           // cells (issue 14 report: open item).
           "preset=vlp16\ntgf_resolution=2\nsensor_height=1.8\nmax_step_height=0.1\n"
           "max_neighbour_step=0.1\n"
           "max_traversable_slope_deg=20\n";
}

}  // namespace travel_map_test
