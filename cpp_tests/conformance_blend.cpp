// Conformance of the GBS pipe blends (examples/blends/*.obj with *.targets.txt, written by
// `profsubd blend`) with OpenSubdiv 3.5: Bfr::Surface<double>'s limit at every control vertex
// equals the vertex's target (the GBS limit at that vertex of GBS level gbs_level) to
// 1e-10 x the targets' bounding-box diagonal, and so does profsubd's exact evaluator.
#include "capi_mesh.h"
#include "test_support.h"
#include "vertex_targets.h"

#include <cmath>
#include <sstream>

using namespace profsubd_test;
using namespace OpenSubdiv;

#ifndef PROFSUBD_BLEND_EXAMPLES
#error "PROFSUBD_BLEND_EXAMPLES must name examples/blends"
#endif

namespace {

// Largest distance between points of 3 doubles (NaN counts as a failure).
double worst_distance(const std::vector<double> &a, const std::vector<double> &b) {
    double worst = 0;
    for (size_t v = 0; 3 * v + 2 < b.size(); ++v) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (a[3 * v + k] - b[3 * v + k]) * (a[3 * v + k] - b[3 * v + k]);
        worst = !(std::sqrt(d2) <= worst) ? std::sqrt(d2) : worst;
    }
    return worst;
}

}  // namespace

int main() {
    Checker ck("conformance_blend");
    // Even orders; three_way_n6 of six columns; the Fig. 3-4 six-pipe examples (k = 3: the quad
    // split of the dual level).
    for (const char *name : {"three_way", "four_way", "six_way", "tee", "three_way_n6", "six_way_k4_v2",
                             "six_way_k8_v07", "six_way_k3_v1", "six_way_k3_cos", "six_way_k3_cosh"}) {
        std::string base = std::string(PROFSUBD_BLEND_EXAMPLES) + "/" + name;
        ck.set_context(name);
        OsdShape shape;
        std::vector<double> targets;
        std::string err;
        if (!ck.check(read_osd_shape(base + ".obj", &shape, &err), "read " + base + ".obj: " + err) ||
            !ck.check(read_targets(base + ".targets.txt", &targets), "read targets")) {
            continue;
        }
        MeshPtr mesh = load_obj_capi(base + ".obj", &err);
        if (!ck.check(mesh != nullptr, "C API reads it: " + err)) continue;
        std::unique_ptr<Far::TopologyRefiner> refiner = build_refiner(shape);
        if (!ck.check(refiner != nullptr, "Far accepts the mesh")) continue;
        ck.equal(targets.size(), shape.positions.size(), "one target per vertex");
        double diag = bbox_diagonal(targets);
        double bfr = worst_distance(bfr_vertex_limits(*refiner, shape.positions), targets);
        std::vector<double> exact;
        double mine = std::nan("");
        if (ck.check(profsubd_vertex_limits(mesh.get(), &exact), "profsubd evaluator")) {
            mine = worst_distance(exact, targets);
        }
        std::ostringstream s;
        s << name << ": " << targets.size() / 3 << " vertices, Bfr limit vs target max " << bfr / diag
          << " x diagonal, profsubd exact vs target " << mine / diag;
        ck.note(s.str());
        ck.check(bfr <= 1e-10 * diag, "Bfr's limit at every control vertex equals its target");
        ck.check(mine <= 1e-10 * diag, "profsubd's exact limit equals every target");
    }
    return ck.finish();
}
