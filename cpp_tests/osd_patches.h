// OpenSubdiv's Osd evaluation path, as viewers and DCC applications use it: a Far stencil
// table of the refined and local points applied by Osd::CpuEvaluator::EvalStencils into an
// Osd::CpuVertexBuffer, and Osd::CpuEvaluator::EvalPatches over an Osd::CpuPatchTable built
// from the Far::PatchTable of a PatchTableEvaluator (osd_references.h: the same adaptive
// refiner, patches and PatchMap). OpenSubdiv 3.5's Osd is single precision (float buffers,
// float stencil weights, float patch coordinates).
#pragma once

#include "osd_references.h"

#include <memory>
#include <vector>

namespace profsubd_test {

class OsdPatches {
public:
    // `far` (which must outlive this; float local points, the default) gives the refiner,
    // patches and map; `positions`: 3 doubles per control vertex.
    OsdPatches(const PatchTableEvaluator &far, const std::vector<double> &positions);
    ~OsdPatches();
    OsdPatches(const OsdPatches &) = delete;
    OsdPatches &operator=(const OsdPatches &) = delete;

    // Position and first derivatives at Ptex face `face`, (u, v), through the PatchTable's
    // map, as doubles (from Osd's floats). False where the PatchMap has no patch (holes).
    bool evaluate(int face, double u, double v, double p[3], double du[3], double dv[3]) const;

private:
    const OpenSubdiv::Far::PatchMap &map_;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace profsubd_test
