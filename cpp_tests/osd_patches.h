// OpenSubdiv's Osd evaluation path, as viewers and DCC applications use it: a Far stencil
// table of the refined and local points applied by Osd::CpuEvaluator::EvalStencils into an
// Osd::CpuVertexBuffer, and Osd::CpuEvaluator::EvalPatches over an Osd::CpuPatchTable built
// from a Far::PatchTable. OpenSubdiv 3.5's Osd is single precision (float buffers, float
// stencil weights, float patch coordinates).
#pragma once

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <memory>
#include <vector>

namespace profsubd_test {

class OsdPatches {
public:
    // `refiner`: adaptively refined as for `table`; `positions`: 3 doubles per control vertex.
    OsdPatches(const OpenSubdiv::Far::TopologyRefiner &refiner, const OpenSubdiv::Far::PatchTable &table,
               const std::vector<double> &positions);
    ~OsdPatches();
    OsdPatches(const OsdPatches &) = delete;
    OsdPatches &operator=(const OsdPatches &) = delete;

    // Position and first derivatives at Ptex face `face`, (u, v), through `map`, as doubles
    // (from Osd's floats). False where the PatchMap has no patch (holes).
    bool evaluate(const OpenSubdiv::Far::PatchMap &map, int face, double u, double v, double p[3], double du[3],
                  double dv[3]) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace profsubd_test
