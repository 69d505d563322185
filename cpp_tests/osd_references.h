// OpenSubdiv's own (face, u, v) evaluators as the conformance tests configure them: Bfr at
// approximation level 10 (with and without its topology cache) and Far's PatchTable +
// PatchMap (adaptive, isolation 10, Gregory end caps, infinitely sharp patches).
#pragma once

#include "osd_shape.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>

#include <memory>

namespace profsubd_test {

// Bfr factories over `refiner` (which must outlive them), approximation level 10. The
// uncached one is for faces where 3.5's cache mixes up faces (interior valence-2 corners).
struct BfrFactories {
    using Factory = OpenSubdiv::Bfr::RefinerSurfaceFactory<>;
    explicit BfrFactories(const OpenSubdiv::Far::TopologyRefiner &refiner);
    Factory cached, uncached;
};

// Far's PatchTable + PatchMap of `shape` under `options`, with the refined and local points.
// `isolation`: adaptive isolation level (10 in the conformance tests; dart_isolation varies
// it); `double_local_points`: end-cap local points from Far's double stencils (float ones
// otherwise, which Osd also applies; only near irregular corners do they differ).
class PatchTableEvaluator {
public:
    PatchTableEvaluator(const OsdShape &shape, const OpenSubdiv::Sdc::Options &options, int isolation = 10,
                        bool double_local_points = false);
    // Position and derivatives at (u, v) of Ptex face `face`; null patch (false) where there is
    // no surface. `depth`: the patch's refinement level (its derivatives scale by 2^depth).
    bool evaluate(int face, double u, double v, double p[3], double du[3] = nullptr, double dv[3] = nullptr,
                  int *depth = nullptr) const;

    // The adaptively refined topology, the table and its map (for Osd over the same patches).
    const OpenSubdiv::Far::TopologyRefiner &refiner() const { return *refiner_; }
    const OpenSubdiv::Far::PatchTable &table() const { return *table_; }
    const OpenSubdiv::Far::PatchMap &map() const { return *map_; }

private:
    std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner_;
    std::unique_ptr<OpenSubdiv::Far::PatchTable> table_;
    std::unique_ptr<OpenSubdiv::Far::PatchMap> map_;
    std::vector<double> points_;  // 3 per point: refined vertices, then local points
};

}  // namespace profsubd_test
