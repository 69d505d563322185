#include "osd_patches.h"

#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/cpuEvaluator.h>
#include <opensubdiv/osd/cpuPatchTable.h>
#include <opensubdiv/osd/cpuVertexBuffer.h>
#include <opensubdiv/osd/types.h>

using namespace OpenSubdiv;

namespace profsubd_test {

namespace {

// The patch-coordinate buffer EvalPatches binds (Osd has no CPU one of its own in 3.5).
struct PatchCoordBuffer {
    std::vector<Osd::PatchCoord> coords;
    Osd::PatchCoord *BindCpuBuffer() { return coords.data(); }
};

struct VertexBufferDeleter {
    void operator()(Osd::CpuVertexBuffer *b) const { delete b; }
};
using VertexBufferPtr = std::unique_ptr<Osd::CpuVertexBuffer, VertexBufferDeleter>;

}  // namespace

struct OsdPatches::Impl {
    std::unique_ptr<Osd::CpuPatchTable> table;
    VertexBufferPtr points;  // control, refined and local points
    VertexBufferPtr p, du, dv;  // one evaluated point
};

OsdPatches::OsdPatches(const PatchTableEvaluator &far, const std::vector<double> &positions)
    : map_(far.map()), impl_(new Impl) {
    const Far::TopologyRefiner &refiner = far.refiner();
    const Far::PatchTable &table = far.table();
    // The refined points level by level (a factorized table, every point from the control
    // points, takes minutes to build around catmark_pole360's valence-360 vertex; Osd takes
    // either), then the local points (end caps) from the refined ones with the PatchTable's
    // own stencils, as StencilTableFactory::AppendLocalPointStencilTable would splice them.
    Far::StencilTableFactory::Options so;
    so.generateOffsets = true;
    so.generateIntermediateLevels = true;  // the patches index every level's points
    so.factorizeIntermediateLevels = false;
    std::unique_ptr<const Far::StencilTable> refined(Far::StencilTableFactory::Create(refiner, so));
    const Far::StencilTable *local = table.GetLocalPointStencilTable();
    const int ncoarse = refiner.GetLevel(0).GetNumVertices();
    const int nrefined = refined->GetNumStencils(), nlocal = local ? local->GetNumStencils() : 0;
    impl_->points.reset(Osd::CpuVertexBuffer::Create(3, ncoarse + nrefined + nlocal));
    std::vector<float> coarse(positions.begin(), positions.end());
    impl_->points->UpdateData(coarse.data(), 0, ncoarse);
    Osd::BufferDescriptor all(0, 3, 3);
    // Level k's stencils index level k-1's points from 0.
    float *buffer = impl_->points->BindCpuBuffer();
    for (int k = 1, first = 0, src = 0, dst = ncoarse; k <= refiner.GetMaxLevel(); ++k) {
        const int n = refiner.GetLevel(k).GetNumVertices();
        Osd::BufferDescriptor from(3 * src, 3, 3), to(3 * dst, 3, 3);
        Osd::CpuEvaluator::EvalStencils(buffer, from, buffer, to, &refined->GetSizes()[0], &refined->GetOffsets()[0],
                                        &refined->GetControlIndices()[0], &refined->GetWeights()[0], first, first + n);
        first += n;
        src = dst;
        dst += n;
    }
    if (nlocal > 0) {
        Osd::BufferDescriptor dst(3 * (ncoarse + nrefined), 3, 3);
        Osd::CpuEvaluator::EvalStencils(impl_->points.get(), all, impl_->points.get(), dst, local);
    }
    impl_->table.reset(Osd::CpuPatchTable::Create(&table));
    impl_->p.reset(Osd::CpuVertexBuffer::Create(3, 1));
    impl_->du.reset(Osd::CpuVertexBuffer::Create(3, 1));
    impl_->dv.reset(Osd::CpuVertexBuffer::Create(3, 1));
}

OsdPatches::~OsdPatches() = default;

bool OsdPatches::evaluate(int face, double u, double v, double p[3], double du[3], double dv[3]) const {
    const Far::PatchTable::PatchHandle *h = map_.FindPatch(face, u, v);
    if (!h) return false;
    PatchCoordBuffer coords;
    coords.coords.emplace_back(*h, (float)u, (float)v);
    Osd::BufferDescriptor src(0, 3, 3), dst(0, 3, 3);
    Osd::CpuEvaluator::EvalPatches(impl_->points.get(), src, impl_->p.get(), dst, impl_->du.get(), dst,
                                   impl_->dv.get(), dst, 1, &coords, impl_->table.get());
    const float *fp = impl_->p->BindCpuBuffer(), *fu = impl_->du->BindCpuBuffer(), *fv = impl_->dv->BindCpuBuffer();
    for (int k = 0; k < 3; ++k) {
        p[k] = fp[k];
        du[k] = fu[k];
        dv[k] = fv[k];
    }
    return true;
}

}  // namespace profsubd_test
