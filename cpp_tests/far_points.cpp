// Positions refined by OpenSubdiv's Far.

#include "far_points.h"

#include <opensubdiv/far/primvarRefiner.h>

namespace profsubd_test {

using namespace OpenSubdiv;

std::vector<FarPoint> refine_points(const Far::TopologyRefiner &refiner, const std::vector<double> &positions,
                                    int extra) {
    std::vector<FarPoint> out(refiner.GetNumVerticesTotal() + extra);
    const int base = refiner.GetLevel(0).GetNumVertices();
    for (int v = 0; v < base; ++v)
        for (int k = 0; k < 3; ++k) out[v].p[k] = positions[3 * v + k];
    Far::PrimvarRefinerReal<double> primvar(refiner);
    FarPoint *src = out.data();
    for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
        FarPoint *dst = src + refiner.GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        src = dst;
    }
    return out;
}

}  // namespace profsubd_test
