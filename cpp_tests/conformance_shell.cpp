// Hollow solids (profsubd_shell) against OpenSubdiv: the limit position of every control
// vertex of the solid, computed by Bfr::Surface<double> at a corner of one of its faces
// (approximation levels 10), read from the OBJ file profsubd writes, must equal the data
// point the vertex interpolates (profsubd_fitted_get_targets: the outer wall's limit and the
// offset at the vertex) to 1e-10 x the targets' bounding-box diagonal. Models: the open
// vase and the closed bottle of examples/profiles, at crust levels 0 and 1. Also: bad input
// to profsubd_shell and profsubd_offset_evaluate fails with a status and writes nothing.
#include "capi_mesh.h"
#include "osd_shape.h"
#include "test_support.h"
#include "vertex_targets.h"

#include <opensubdiv/far/topologyRefiner.h>

#include <cmath>
#include <cstdio>
#include <memory>

using namespace profsubd_test;
using namespace OpenSubdiv;

#ifndef PROFSUBD_PROFILE_EXAMPLES
#error "PROFSUBD_PROFILE_EXAMPLES must name examples/profiles"
#endif

namespace {

std::string sci(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2e", x);
    return buf;
}

struct FittedDeleter {
    void operator()(profsubd_fitted *f) const { profsubd_fitted_free(f); }
};
using FittedPtr = std::unique_ptr<profsubd_fitted, FittedDeleter>;

// One solid: Bfr at every control vertex vs its target.
void check_solid(Checker &ck, const std::string &name, const profsubd_mesh *input, double thickness,
                 uint32_t level) {
    ck.set_context(name + ", level " + std::to_string(level));
    profsubd_fitted *raw = nullptr;
    profsubd_status st = profsubd_shell(input, thickness, level, 0.0, 0, nullptr, &raw);
    FittedPtr solid(raw);
    if (!ck.check(st == PROFSUBD_OK, "profsubd_shell: " + describe_status(st))) {
        return;
    }
    profsubd_mesh *mesh_raw = nullptr;
    if (!ck.check(profsubd_fitted_get_mesh(solid.get(), &mesh_raw) == PROFSUBD_OK, "get mesh")) {
        return;
    }
    MeshPtr mesh(mesh_raw);
    size_t needed = 0;
    profsubd_fitted_get_targets(solid.get(), nullptr, 0, &needed);
    std::vector<double> targets(needed);
    ck.equal(profsubd_fitted_get_targets(solid.get(), targets.data(), needed, &needed), PROFSUBD_OK,
             "targets");
    static TempDir dir;
    OsdShape shape;
    std::string err = shape_via_obj(mesh.get(), dir.file("solid.obj"), &shape);
    if (!ck.check(err.empty(), "OBJ round trip: " + err)) {
        return;
    }
    std::unique_ptr<Far::TopologyRefiner> refiner = build_refiner(shape);
    if (!ck.check(refiner != nullptr, "Far accepts the solid")) {
        return;
    }
    const Far::TopologyLevel &base = refiner->GetLevel(0);
    ck.equal(count_boundary_edges(base), 0, "no boundary edges");
    ck.equal(targets.size(), shape.positions.size(), "one target per vertex");
    std::vector<double> bfr = bfr_vertex_limits(*refiner, shape.positions);
    double worst = 0;
    for (size_t v = 0; 3 * v + 2 < targets.size(); ++v) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (bfr[3 * v + k] - targets[3 * v + k]) * (bfr[3 * v + k] - targets[3 * v + k]);
        worst = !(std::sqrt(d2) <= worst) ? std::sqrt(d2) : worst;
    }
    double diag = bbox_diagonal(targets);
    ck.check(worst <= 1e-10 * diag, "Bfr limit at every vertex = target: worst " + sci(worst / diag) +
                                        " x diagonal");
    ck.note(name + " level " + std::to_string(level) + ": " + std::to_string(targets.size() / 3) +
            " vertices, " + std::to_string(base.GetNumFaces()) + " faces, Bfr vs targets worst " +
            sci(worst / diag) + " x diagonal");
}

}  // namespace

int main() {
    Checker ck("conformance_shell");
    for (const char *name : {"vase", "bottle"}) {
        std::string err;
        std::string path = std::string(PROFSUBD_PROFILE_EXAMPLES) + "/" + name + ".obj";
        ck.set_context(name);
        MeshPtr mesh = load_obj_capi(path, &err);
        if (!ck.check(mesh != nullptr, "read " + path + ": " + err)) {
            continue;
        }
        // 0.5 % of the bottle's diagonal of 5.6, 1 % of the vase's 5.8.
        double c = std::string(name) == "vase" ? 0.058 : 0.028;
        for (uint32_t level : {0u, 1u}) {
            check_solid(ck, name, mesh.get(), c, level);
        }
        // Bad input: a status, nothing written.
        ck.set_context(std::string(name) + ", bad input");
        profsubd_fitted *untouched = reinterpret_cast<profsubd_fitted *>(0x1);
        for (double bad : {0.0, -1.0, std::nan("")}) {
            ck.equal(profsubd_shell(mesh.get(), bad, 0, 0.0, 0, nullptr, &untouched),
                     PROFSUBD_ERROR_INVALID_ARGUMENT, "thickness " + std::to_string(bad));
        }
        ck.equal(profsubd_shell(mesh.get(), c, 0, 0.0, 4, nullptr, &untouched), PROFSUBD_ERROR_INVALID_ARGUMENT,
                 "unknown flag");
        ck.check(untouched == reinterpret_cast<profsubd_fitted *>(0x1), "out untouched");
        uint32_t face = 0;
        double u = 0.5, v = 0.5, pos[3] = {7, 7, 7};
        ck.equal(profsubd_offset_evaluate(mesh.get(), nullptr, -c, 0, 0.0, 0, 0, &face, &u, &v, 1, pos, nullptr,
                                          nullptr, nullptr),
                 PROFSUBD_ERROR_INVALID_ARGUMENT, "offset: negative thickness");
        ck.check(pos[0] == 7 && pos[1] == 7 && pos[2] == 7, "offset: positions untouched");
        ck.equal(profsubd_offset_evaluate(mesh.get(), nullptr, c, 0, 0.0, 0, 0, &face, &u, &v, 1, pos, nullptr,
                                          nullptr, nullptr),
                 PROFSUBD_OK, "offset: one point");
        ck.check(std::isfinite(pos[0]) && pos[0] != 7, "offset: position written");
    }
    return ck.finish();
}
