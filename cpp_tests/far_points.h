// Positions refined by OpenSubdiv's Far (PrimvarRefinerReal<double>), shared by the
// conformance tests and the benchmark.
#pragma once

#include <opensubdiv/far/topologyRefiner.h>

#include <vector>

namespace profsubd_test {

// Far's primvar type for a position of 3 doubles.
struct FarPoint {
    double p[3];
    void Clear() { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(FarPoint const &s, double w) {
        p[0] += w * s.p[0];
        p[1] += w * s.p[1];
        p[2] += w * s.p[2];
    }
};

// The position of every vertex of every level of `refiner` (already refined, uniformly or
// adaptively), level after level as Far numbers them when stacked, from `positions` (3
// doubles per level-0 vertex); then `extra` zero points (room for a PatchTable's local points).
std::vector<FarPoint> refine_points(const OpenSubdiv::Far::TopologyRefiner &refiner,
                                    const std::vector<double> &positions, int extra = 0);

}  // namespace profsubd_test
