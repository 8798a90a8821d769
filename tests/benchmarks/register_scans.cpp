// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// Build: cmake --build build --target register_scans (beside bench_travel)
// Use:   build/tests/benchmarks/register_scans DIR/*.pcd > poses.txt  (KITTI format, LiDAR poses,
// frame 0 = identity) Frame-to-frame point-to-plane ICP over PCD scans -> KITTI pose file (LiDAR
// poses).
#include <Eigen/Dense>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nanoflann.hpp>
#include <string>

#include <unordered_map>
#include <vector>
#include "travel/io/ScanIO.hpp"
using V = Eigen::Vector3d;
// Points of a scan in any format the apps read (travel::readScan), 3-50 m from the sensor.
static std::vector<V> load(const std::string& p) {
    travel::PointCloud cloud;
    travel::readScan(p, cloud);
    std::vector<V> out;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const V q(cloud.x[i], cloud.y[i], cloud.z[i]);
        const double r = q.head<2>().norm();
        if (r > 3 && r < 50) out.push_back(q);
    }
    return out;
}
static std::vector<V> voxel(const std::vector<V>& in, double s) {
    std::unordered_map<long long, std::pair<V, int>> m;
    for (auto& p : in) {
        long long k = ((long long)std::floor(p.x() / s) + 100000) * 1000003LL * 1000003LL +
                      ((long long)std::floor(p.y() / s) + 100000) * 1000003LL +
                      ((long long)std::floor(p.z() / s) + 100000);
        auto& e = m[k];
        e.first += p;
        e.second++;
    }
    std::vector<V> out;
    for (auto& [k, e] : m) out.push_back(e.first / e.second);
    return out;
}
struct Cloud {
    std::vector<V> pts;
    size_t kdtree_get_point_count() const { return pts.size(); }
    double kdtree_get_pt(size_t i, size_t d) const { return pts[i][d]; }
    template <class B>
    bool kdtree_get_bbox(B&) const {
        return false;
    }
};
using Tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3>;
int main(int argc, char** argv) {
    std::vector<Eigen::Isometry3d> poses{Eigen::Isometry3d::Identity()};
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    std::vector<V> prev;
    for (int a = 1; a < argc; ++a) {
        auto raw = load(argv[a]);
        if (a == 1) {
            prev = raw;
            continue;
        }
        Cloud tgt{voxel(prev, 0.2)};
        Tree tree(3, tgt, {10});
        // normals of the target
        std::vector<V> nrm(tgt.pts.size());
        std::vector<bool> ok(tgt.pts.size());
        for (size_t i = 0; i < tgt.pts.size(); ++i) {
            unsigned idx[10];
            double d2[10];
            size_t k = tree.knnSearch(tgt.pts[i].data(), 10, idx, d2);
            if (k < 6 || d2[k - 1] > 1.0) continue;
            V c = V::Zero();
            for (size_t j = 0; j < k; ++j) c += tgt.pts[idx[j]];
            c /= k;
            Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
            for (size_t j = 0; j < k; ++j) {
                V d = tgt.pts[idx[j]] - c;
                C += d * d.transpose();
            }
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
            nrm[i] = es.eigenvectors().col(0);
            ok[i] = true;
        }
        auto src = voxel(raw, 0.4);
        Eigen::Isometry3d T = motion;  // maps current -> previous
        for (int it = 0; it < 40; ++it) {
            Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
            Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
            double maxd = it < 10 ? 1.0 : 0.5;
            int used = 0;
            for (auto& p0 : src) {
                V p = T * p0;
                unsigned i;
                double d2;
                tree.knnSearch(p.data(), 1, &i, &d2);
                if (!ok[i] || d2 > maxd * maxd) continue;
                double r = nrm[i].dot(p - tgt.pts[i]);
                Eigen::Matrix<double, 6, 1> J;
                J << p.cross(nrm[i]), nrm[i];
                H += J * J.transpose();
                g += J * r;
                ++used;
            }
            Eigen::Matrix<double, 6, 1> dx = -H.ldlt().solve(g);
            Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
            double ang = dx.head<3>().norm();
            if (ang > 0) D.linear() = Eigen::AngleAxisd(ang, dx.head<3>() / ang).toRotationMatrix();
            D.translation() = dx.tail<3>();
            T = D * T;
            if (dx.norm() < 1e-6) break;
            if (it == 39) std::cerr << "frame " << a - 1 << " used " << used << "\n";
        }
        motion = T;
        poses.push_back(poses.back() * T);
        prev = raw;
        std::cerr << a - 1 << " step " << T.translation().transpose() << "\n";
    }
    for (auto& P : poses) {
        Eigen::Matrix<double, 3, 4> M = P.matrix().topRows<3>();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c)
                std::printf("%.9e%s", M(r, c), (r == 2 && c == 3) ? "\n" : " ");
    }
}
