// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// Build: g++ -O2 -std=c++17 scripts/compare_octomaps.cpp -o compare_octomaps -loctomap -loctomath
// Use:   compare_octomaps before.bt after.bt
// Compares the leaves of two OctoMap .bt files: occupied / free voxel sets and their overlap.
#include <octomap/OcTree.h>
#include <cstdio>
#include <set>
#include <tuple>
using Key = std::tuple<int, int, int>;
static void leaves(const char* path, std::set<Key>& occ, std::set<Key>& fre) {
    octomap::OcTree tree(0.1);
    tree.readBinary(path);
    for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
        const int size = 1 << (tree.getTreeDepth() - it.getDepth());  // pruned leaves: all cells
        const auto k = it.getKey();
        for (int dx = 0; dx < size; ++dx)
            for (int dy = 0; dy < size; ++dy)
                for (int dz = 0; dz < size; ++dz)
                    (tree.isNodeOccupied(*it) ? occ : fre)
                        .insert({k[0] + dx, k[1] + dy, k[2] + dz});
    }
}
int main(int argc, char** argv) {
    if (argc != 3) return 2;
    std::set<Key> oa, fa, ob, fb;
    leaves(argv[1], oa, fa), leaves(argv[2], ob, fb);
    auto common = [](const std::set<Key>& a, const std::set<Key>& b) {
        std::size_t n = 0;
        for (auto& k : a) n += b.count(k);
        return n;
    };
    std::printf(
        "occupied: %zu -> %zu, both %zu; free: %zu -> %zu, both %zu; occupied now free %zu, free "
        "now occupied %zu\n",
        oa.size(), ob.size(), common(oa, ob), fa.size(), fb.size(), common(fa, fb), common(oa, fb),
        common(fa, ob));
}
