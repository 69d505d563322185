// OpenSubdiv's evaluators as the conformance tests configure them (see osd_references.h).

#include "osd_references.h"

#include "far_points.h"

#include <opensubdiv/far/patchTableFactory.h>

using namespace OpenSubdiv;

namespace profsubd_test {

namespace {

BfrFactories::Factory::Options factory_options(bool caching) {
    BfrFactories::Factory::Options o;
    o.SetApproxLevelSmooth(10).SetApproxLevelSharp(10);
    o.EnableCaching(caching);
    return o;
}

}  // namespace

BfrFactories::BfrFactories(const Far::TopologyRefiner &refiner)
    : cached(refiner, factory_options(true)), uncached(refiner, factory_options(false)) {}

PatchTableEvaluator::PatchTableEvaluator(const OsdShape &shape, const Sdc::Options &options, int isolation,
                                         bool double_local_points) {
    refiner_ = build_refiner(shape, options);
    Far::PatchTableFactory::Options po(isolation);
    po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    if (double_local_points) po.SetPatchPrecision<double>();
    po.useInfSharpPatch = true;
    refiner_->RefineAdaptive(po.GetRefineAdaptiveOptions());
    table_.reset(Far::PatchTableFactory::Create(*refiner_, po));
    map_.reset(new Far::PatchMap(*table_));
    int nref = refiner_->GetNumVerticesTotal(), nloc = table_->GetNumLocalPoints();
    std::vector<FarPoint> points = refine_points(*refiner_, shape.positions, nloc);
    if (nloc > 0 && double_local_points)
        table_->GetLocalPointStencilTable<double>()->UpdateValues(points.data(), points.data() + nref);
    else if (nloc > 0)
        table_->ComputeLocalPointValues(points.data(), points.data() + nref);
    points_.resize(3 * points.size());
    for (size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < 3; ++k) points_[3 * i + k] = points[i].p[k];
}

bool PatchTableEvaluator::evaluate(int face, double u, double v, double p[3], double du[3], double dv[3],
                                   int *depth) const {
    const Far::PatchTable::PatchHandle *h = map_->FindPatch(face, u, v);
    if (!h) return false;
    if (depth) *depth = table_->GetPatchParam(*h).GetDepth();
    double wp[20], wu[20], wv[20];
    table_->EvaluateBasis(*h, u, v, wp, wu, wv);
    auto cvs = table_->GetPatchVertices(*h);
    for (int k = 0; k < 3; ++k) {
        p[k] = 0;
        if (du) du[k] = 0;
        if (dv) dv[k] = 0;
        for (int i = 0; i < cvs.size(); ++i) {
            double x = points_[3 * cvs[i] + k];
            p[k] += wp[i] * x;
            if (du) du[k] += wu[i] * x;
            if (dv) dv[k] += wv[i] * x;
        }
    }
    return true;
}

}  // namespace profsubd_test
