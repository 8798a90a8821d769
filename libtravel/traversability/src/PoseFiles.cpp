// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/PoseFiles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "travel/Text.hpp"
#include "travel/TextFile.hpp"

namespace travel {
namespace {

struct Line {
    int number = 0;
    std::vector<double> values;
};

std::runtime_error error(const std::string& path, int line, const std::string& what) {
    return std::runtime_error(path + ":" + std::to_string(line) + ": " + what);
}

/// Data lines of a whitespace-separated numeric file ('#' comments, blank lines skipped).
/// `prefix` (e.g. "Tr:") selects lines starting with it and drops it.
std::vector<Line> readNumericLines(const std::string& path, const std::string& prefix = "") {
    std::istringstream in(readTextFile(path, "expected lines of numbers"));
    std::vector<Line> lines;
    std::string text;
    int number = 0;
    while (std::getline(in, text)) {
        ++number;
        const auto hash = text.find('#');
        if (hash != std::string::npos) text.erase(hash);
        std::istringstream words(text);
        std::string word;
        if (!prefix.empty()) {
            if (!(words >> word) || word != prefix) continue;
        }
        Line line;
        line.number = number;
        int column = 0;
        while (words >> word) {
            ++column;
            char* end = nullptr;
            const double v = std::strtod(word.c_str(), &end);
            if (end != word.c_str() + word.size() || !std::isfinite(v))
                throw error(path, number,
                            "column " + std::to_string(column) + ": " + quotedExcerpt(word) +
                                " is not a finite number");
            line.values.push_back(v);
        }
        if (!line.values.empty()) lines.push_back(std::move(line));
    }
    return lines;
}

void requireColumns(const std::string& path, const Line& line, std::size_t n, const char* layout) {
    if (line.values.size() != n)
        throw error(path, line.number,
                    "expected " + std::to_string(n) + " numbers (" + layout + "), got " +
                        std::to_string(line.values.size()));
}

Eigen::Isometry3d fromRowMajor3x4(const std::vector<double>& v) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) T.matrix()(r, c) = v[std::size_t(4 * r + c)];
    return T;
}

constexpr const char* kTumLayout = "timestamp x y z qx qy qz qw";
constexpr const char* kKittiLayout = "row-major 3x4 pose matrix";

PoseTrajectory parseTum(const std::string& path, const std::vector<Line>& lines) {
    PoseTrajectory out;
    for (const Line& line : lines) {
        requireColumns(path, line, 8, kTumLayout);
        const auto& v = line.values;
        if (!out.times.empty() && !(v[0] > out.times.back()))
            throw error(path, line.number,
                        "timestamp " + std::to_string(v[0]) + " is not after the previous one (" +
                            std::to_string(out.times.back()) + "): timestamps must increase");
        Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
        if (!(std::abs(q.norm() - 1.0) < 1e-2))
            throw error(path, line.number, "the quaternion (qx qy qz qw) is not of unit length");
        q.normalize();
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.linear() = q.toRotationMatrix();
        T.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
        out.times.push_back(v[0]);
        out.poses.push_back(T);
    }
    if (out.poses.empty()) throw std::runtime_error(path + ": no poses in the file");
    return out;
}

PoseTrajectory parseKitti(const std::string& path, const std::vector<Line>& lines) {
    PoseTrajectory out;
    for (const Line& line : lines) {
        requireColumns(path, line, 12, kKittiLayout);
        out.poses.push_back(fromRowMajor3x4(line.values));
    }
    if (out.poses.empty()) throw std::runtime_error(path + ": no poses in the file");
    return out;
}

}  // namespace

PoseTrajectory readTumPoses(const std::string& path) {
    return parseTum(path, readNumericLines(path));
}

PoseTrajectory readKittiPoses(const std::string& path) {
    return parseKitti(path, readNumericLines(path));
}

PoseTrajectory readPoseFile(const std::string& path) {
    const std::vector<Line> lines = readNumericLines(path);
    if (lines.empty()) throw std::runtime_error(path + ": no poses in the file");
    const std::size_t n = lines.front().values.size();
    if (n == 8) return parseTum(path, lines);
    if (n == 12) return parseKitti(path, lines);
    throw error(path, lines.front().number,
                "expected 8 numbers (TUM: " + std::string(kTumLayout) +
                    ") or 12 (KITTI: " + kKittiLayout + "), got " + std::to_string(n));
}

Eigen::Isometry3d readKittiCalibTr(const std::string& path) {
    const std::vector<Line> lines = readNumericLines(path, "Tr:");
    if (lines.empty())
        throw std::runtime_error(path + ": no 'Tr:' line (velodyne to cam0 transform)");
    requireColumns(path, lines.front(), 12, "Tr: row-major 3x4 matrix");
    return fromRowMajor3x4(lines.front().values);
}

void kittiCameraToLidar(PoseTrajectory& trajectory, const Eigen::Isometry3d& tr) {
    const Eigen::Isometry3d tr_inv = tr.inverse();
    for (auto& pose : trajectory.poses) pose = tr_inv * pose * tr;
}

std::optional<PoseTrajectory> readSequenceLidarPoses(const std::string& sequence_dir) {
    if (sequence_dir.empty()) return std::nullopt;
    const std::string poses = sequence_dir + "/poses.txt", calib = sequence_dir + "/calib.txt";
    if (!std::ifstream(poses)) return std::nullopt;
    PoseTrajectory trajectory = readKittiPoses(poses);
    if (std::ifstream(calib)) kittiCameraToLidar(trajectory, readKittiCalibTr(calib));
    return trajectory;
}

std::string kittiPoseLine(const Eigen::Isometry3d& pose) {
    const Eigen::Matrix<double, 3, 4> M = pose.matrix().topRows<3>();
    std::string line;
    char number[32];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) {
            std::snprintf(number, sizeof(number), "%.9e%s", M(r, c),
                          (r == 2 && c == 3) ? "\n" : " ");
            line += number;
        }
    return line;
}

std::optional<Eigen::Isometry3d> poseAt(const PoseTrajectory& trajectory, double t,
                                        double tolerance, double max_gap) {
    const auto& times = trajectory.times;
    if (times.empty() || !std::isfinite(t)) return std::nullopt;
    if (t < times.front() - tolerance || t > times.back() + tolerance) return std::nullopt;
    if (t <= times.front()) return trajectory.poses.front();
    if (t >= times.back()) return trajectory.poses.back();
    const std::size_t hi =
        std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    const std::size_t lo = hi - 1;
    const double gap = times[hi] - times[lo];
    if (gap > max_gap) return std::nullopt;
    const double a = (t - times[lo]) / gap;
    const Eigen::Isometry3d& A = trajectory.poses[lo];
    const Eigen::Isometry3d& B = trajectory.poses[hi];
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() =
        Eigen::Quaterniond(A.linear()).slerp(a, Eigen::Quaterniond(B.linear())).toRotationMatrix();
    T.translation() = (1 - a) * A.translation() + a * B.translation();
    return T;
}

}  // namespace travel
