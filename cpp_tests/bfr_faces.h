// Every base face of an OBJ shape that has a limit surface, as OpenSubdiv's Bfr sees it: the
// one place the harness's Bfr-side checks (conformance_folds, bending_energy) set up Far's
// refiner and Bfr's factory, so both evaluate the same surfaces the same way.
#pragma once

#include "osd_shape.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyLevel.h>

#include <memory>
#include <vector>

namespace profsubd_test {

// Calls `visit(level, face, surface, patch_points)` for each face of `shape`'s base level with
// a limit surface (Bfr approximation level 10, smooth and sharp; holes and faces Bfr declines
// are skipped), its patch points prepared from the shape's positions (xyz). `visit` returns
// false to stop. Returns false when Far rejects the mesh.
template <class Visit>
bool for_each_bfr_surface(const OsdShape &shape, Visit visit) {
    using namespace OpenSubdiv;
    std::unique_ptr<Far::TopologyRefiner> refiner = build_refiner(shape);
    if (!refiner) return false;
    const Far::TopologyLevel &level = refiner->GetLevel(0);
    using Factory = Bfr::RefinerSurfaceFactory<>;
    Factory::Options options;
    options.SetApproxLevelSmooth(10).SetApproxLevelSharp(10);
    Factory factory(*refiner, options);
    Bfr::Surface<double> surface;
    std::vector<double> points;
    for (int f = 0; f < level.GetNumFaces(); ++f) {
        if (!factory.InitVertexSurface(f, &surface)) continue;  // holes, no limit surface
        points.resize(3 * surface.GetNumPatchPoints());
        surface.PreparePatchPoints(shape.positions.data(), 3, points.data(), 3);
        if (!visit(level, f, surface, points.data())) break;
    }
    return true;
}

}  // namespace profsubd_test
