// Revolutions and sweeps against OpenSubdiv: the limit position of every control vertex,
// computed by OpenSubdiv's Bfr::Surface<double> at a corner of one of its faces (approximation
// levels 10), must equal the data point the vertex interpolates, to 1e-10 x the bounding-box
// diagonal of the data points; so must profsubd's own exact limit through the C API
// (profsubd_evaluator_limit_vertices).
//
// Models: the checked-in examples (examples/sweeps/*.obj with *.targets.txt: wine glass,
// torus knot tube, handrail, capped 270-degree cutaways of a wine glass and a vase), the
// sketch-curve patches (examples/curves: bonnet, three_sided, open_corners, bonnet_fair) and
// models built here through the C API (sphere, cylinder, cone, partial and capped
// revolutions, torus, a square tube along a closed curve, an L-shaped square rail), each read
// back through the C API and then from the OBJ file it writes, so OpenSubdiv is configured from the
// file's option tags. Models under other subdivision options and semi-sharp creases
// (crease_sharpness): a three-quarter revolution and an open ribbon, whose one-face corner
// vertices make boundary edge-only and edge-and-corner differ (Bfr under the other rule must
// miss their targets), Chaikin creasing (every crease has one sharpness, so Bfr 3.5's Chaikin
// defect does not arise and it is held to 1e-10), and boundary none on a closed tube.
#include "capi_mesh.h"
#include "osd_shape.h"
#include "test_support.h"
#include "vertex_targets.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyLevel.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

using namespace profsubd_test;
using namespace OpenSubdiv;

#ifndef PROFSUBD_SWEEP_EXAMPLES
#error "PROFSUBD_SWEEP_EXAMPLES must name examples/sweeps"
#endif
#ifndef PROFSUBD_CURVES_EXAMPLES
#error "PROFSUBD_CURVES_EXAMPLES must name examples/curves"
#endif

namespace {

struct Model {
    std::string name;
    OsdShape shape;
    std::vector<double> targets;  // 3 per vertex
    MeshPtr mesh;                 // the same mesh through the C API
};

// Largest |a_i - b_i| over points of 3 doubles, and the diagonal of b's bounding box.
void compare(const std::vector<double> &a, const std::vector<double> &b, double *worst,
             double *diag) {
    *worst = 0;
    for (size_t v = 0; 3 * v + 2 < b.size(); ++v) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (a[3 * v + k] - b[3 * v + k]) * (a[3 * v + k] - b[3 * v + k]);
        // NaN (no surface found) must fail, so compare with !(<=).
        *worst = !(std::sqrt(d2) <= *worst) ? std::sqrt(d2) : *worst;
    }
    *diag = bbox_diagonal(b);
}

void check_model(Checker &ck, const Model &m) {
    ck.set_context(m.name);
    std::unique_ptr<Far::TopologyRefiner> refiner = build_refiner(m.shape);
    if (!ck.check(refiner != nullptr, "Far accepts the mesh")) {
        return;
    }
    ck.equal(m.targets.size(), m.shape.positions.size(), "one target per vertex");
    double worst = 0, diag = 0;
    compare(bfr_vertex_limits(*refiner, m.shape.positions), m.targets, &worst, &diag);
    std::vector<double> exact;
    double worst_exact = std::nan("");
    if (ck.check(profsubd_vertex_limits(m.mesh.get(), &exact), "profsubd evaluator")) {
        compare(exact, m.targets, &worst_exact, &diag);
    }
    std::ostringstream s;
    s << m.name << ": " << m.targets.size() / 3 << " vertices, Bfr limit vs target max "
      << worst / diag << " x diagonal, profsubd exact vs target " << worst_exact / diag;
    ck.note(s.str());
    ck.check(worst <= 1e-10 * diag, "Bfr's limit at every control vertex equals its target");
    ck.check(worst_exact <= 1e-10 * diag, "profsubd's exact limit equals every target");
}

// A plane n . x = d (unit n) that flat caps of a model lie in.
struct Plane {
    double n[3];
    double d;
};

// The flat caps are flat in OpenSubdiv's limit too: for each plane, the faces whose four
// targets lie in it (the cap's faces) are evaluated by Bfr::Surface<double> on a 9 x 9 (u, v)
// grid; every sample must lie in the plane to 1e-12 x diagonal.
void check_flat_caps(Checker &ck, const Model &m, const std::vector<Plane> &planes) {
    ck.set_context(m.name + ", flat caps");
    std::unique_ptr<Far::TopologyRefiner> refiner = build_refiner(m.shape);
    if (!ck.check(refiner != nullptr, "Far accepts the mesh")) {
        return;
    }
    double worst = 0, diag = 0;
    compare(m.targets, m.targets, &worst, &diag);
    Bfr::RefinerSurfaceFactory<>::Options options;
    options.SetApproxLevelSmooth(10).SetApproxLevelSharp(10);
    Bfr::RefinerSurfaceFactory<> factory(*refiner, options);
    const Far::TopologyLevel &level = refiner->GetLevel(0);
    Bfr::Surface<double> surface;
    Bfr::Surface<double>::PointDescriptor desc(3);
    std::vector<double> patch;
    for (const Plane &pl : planes) {
        auto distance = [&](const double *x) {
            return std::fabs(pl.n[0] * x[0] + pl.n[1] * x[1] + pl.n[2] * x[2] - pl.d);
        };
        int faces = 0;
        double far = 0;
        for (int f = 0; f < level.GetNumFaces(); ++f) {
            Far::ConstIndexArray fv = level.GetFaceVertices(f);
            bool on = true;
            for (int i = 0; i < fv.size(); ++i) {
                on = on && distance(&m.targets[3 * static_cast<size_t>(fv[i])]) < 1e-12 * diag;
            }
            if (!on || !factory.InitVertexSurface<double>(f, &surface)) {
                continue;
            }
            ++faces;
            patch.resize(static_cast<size_t>(surface.GetNumPatchPoints()) * 3);
            surface.PreparePatchPoints(m.shape.positions.data(), desc, patch.data(), desc);
            for (int a = 0; a <= 8; ++a) {
                for (int b = 0; b <= 8; ++b) {
                    double uv[2] = {a / 8.0, b / 8.0}, x[3];
                    surface.Evaluate(uv, patch.data(), desc, x);
                    far = !(distance(x) <= far) ? distance(x) : far;
                }
            }
        }
        std::ostringstream s;
        s << m.name << ": cap plane (" << pl.n[0] << ", " << pl.n[1] << ", " << pl.n[2] << ") . x = "
          << pl.d << ": " << faces << " faces, Bfr samples off the plane max " << far / diag
          << " x diagonal";
        ck.note(s.str());
        ck.check(faces > 0, "the cap has faces");
        ck.check(far <= 1e-12 * diag, "Bfr's limit surface of the cap lies in its plane");
    }
}

struct SweptDeleter {
    void operator()(profsubd_fitted *s) const { profsubd_fitted_free(s); }
};

// Read a C API result back as a model (mesh through the C API, then the targets).
bool take_result(Checker &ck, const std::string &name, profsubd_status st, profsubd_fitted *raw,
                 Model *out) {
    std::unique_ptr<profsubd_fitted, SweptDeleter> swept(raw);
    ck.set_context(name);
    if (!ck.check(st == PROFSUBD_OK, "build: " + describe_status(st))) {
        return false;
    }
    profsubd_mesh *mesh_raw = nullptr;
    if (!ck.check(profsubd_fitted_get_mesh(swept.get(), &mesh_raw) == PROFSUBD_OK, "get mesh")) {
        return false;
    }
    MeshPtr mesh(mesh_raw);
    size_t needed = 0;
    ck.equal(profsubd_fitted_get_targets(swept.get(), nullptr, 0, &needed),
             PROFSUBD_ERROR_BUFFER_TOO_SMALL, "targets size query");
    out->targets.assign(needed, 0.0);
    ck.equal(profsubd_fitted_get_targets(swept.get(), out->targets.data(), needed, &needed),
             PROFSUBD_OK, "targets copy-out");
    CapiMesh capi;
    std::string err = read_capi_mesh(mesh.get(), &capi);
    if (!ck.check(err.empty(), "read back: " + err)) {
        return false;
    }
    ck.check(capi.report.is_manifold && capi.report.is_consistently_oriented,
             "manifold, consistently oriented");
    out->name = name;
    static TempDir dir;
    err = shape_via_obj(mesh.get(), dir.file("model.obj"), &out->shape);
    out->mesh = std::move(mesh);
    return ck.check(err.empty(), "OBJ round trip: " + err) &&
           ck.check(out->shape.positions == capi.positions, "OBJ positions are exact");
}

// One model built under explicit subdivision options; checks that its OBJ records them.
bool with_options(Checker &ck, const std::string &name, Sdc::Options::VtxBoundaryInterpolation boundary,
                  Sdc::Options::CreasingMethod crease, profsubd_status st, profsubd_fitted *raw,
                  Model *out) {
    if (!take_result(ck, name, st, raw, out)) {
        return false;
    }
    return ck.equal(static_cast<int>(out->shape.options.GetVtxBoundaryInterpolation()),
                    static_cast<int>(boundary), "OBJ records the boundary rule") &&
           ck.equal(static_cast<int>(out->shape.options.GetCreasingMethod()), static_cast<int>(crease),
                    "OBJ records the crease method");
}

// Bfr under the other of edge-only / edge-and-corner misses the targets at the corners.
void check_rule_matters(Checker &ck, const Model &m) {
    ck.set_context(m.name + ", evaluated under the other boundary rule");
    Sdc::Options other = m.shape.options;
    other.SetVtxBoundaryInterpolation(other.GetVtxBoundaryInterpolation() == Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                          ? Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
                                          : Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    std::unique_ptr<Far::TopologyRefiner> refiner = build_refiner(m.shape, other);
    double worst = 0, diag = 0;
    compare(bfr_vertex_limits(*refiner, m.shape.positions), m.targets, &worst, &diag);
    std::ostringstream s;
    s << m.name << " under the other boundary rule: Bfr vs target max " << worst / diag << " x diagonal";
    ck.note(s.str());
    ck.check(worst > 1e-3 * diag, "the boundary rule changes the limit at the corners");
}

std::vector<double> circle(int n, double r, int dims) {
    std::vector<double> c;
    for (int i = 0; i < n; ++i) {
        double t = 2 * M_PI * i / n;
        c.push_back(r * std::cos(t));
        c.push_back(r * std::sin(t));
        if (dims == 3) {
            c.push_back(0.2 * std::sin(2 * t));
        }
    }
    return c;
}

}  // namespace

int main() {
    Checker ck("conformance_sweep");
    std::vector<Model> models;
    // The sweep examples, then the sketch-curve patches of examples/curves (open all-quad
    // meshes with tagged corners, fitted the same way).
    const std::string sweep_dir = PROFSUBD_SWEEP_EXAMPLES, curves_dir = PROFSUBD_CURVES_EXAMPLES;
    const std::pair<const std::string *, const char *> examples[] = {
        {&sweep_dir, "wine_glass"}, {&sweep_dir, "torus_knot_tube"}, {&sweep_dir, "handrail"},
        {&sweep_dir, "wine_glass_cutaway"}, {&sweep_dir, "vase_cutaway"}, {&curves_dir, "bonnet"},
        {&curves_dir, "three_sided"}, {&curves_dir, "open_corners"}, {&curves_dir, "bonnet_fair"}};
    for (const auto &[dir, name] : examples) {
        Model m;
        m.name = name;
        std::string base = *dir + "/" + name;
        std::string err;
        ck.set_context(name);
        if (ck.check(read_osd_shape(base + ".obj", &m.shape, &err), "read " + base + ".obj: " + err) &&
            ck.check(read_targets(base + ".targets.txt", &m.targets), "read targets") &&
            ck.check((m.mesh = load_obj_capi(base + ".obj", &err)) != nullptr, "C API reads it: " + err)) {
            models.push_back(std::move(m));
        }
    }
    profsubd_options *raw_options = nullptr;
    profsubd_options_new(&raw_options);
    OptionsPtr options(raw_options);
    // Revolutions at 16 x 32 samples: sphere (two smooth poles), cylinder, cone (tip).
    std::vector<double> semicircle;
    for (int i = 0; i <= 48; ++i) {
        double t = -M_PI / 2 + M_PI * i / 48;
        semicircle.push_back(i == 0 || i == 48 ? 0.0 : 1.5 * std::cos(t));
        semicircle.push_back(1.5 * std::sin(t));
    }
    const std::vector<double> cylinder = {1, 0, 1, 2}, cone = {1, 0, 0, 2};
    profsubd_options_set_samples(raw_options, 16, 32);
    struct Rev {
        const char *name;
        const std::vector<double> *profile;
    } revs[] = {{"sphere 16x32", &semicircle}, {"cylinder 16x32", &cylinder}, {"cone 16x32", &cone}};
    for (const Rev &r : revs) {
        profsubd_fitted *s = nullptr;
        profsubd_status st = profsubd_revolve(r.profile->data(), r.profile->size() / 2, raw_options, &s);
        Model m;
        if (take_result(ck, r.name, st, s, &m)) {
            models.push_back(std::move(m));
        }
    }
    // A sketch-curve patch through the C API: four boundary strokes on z = x^2 - y^2 and one
    // interior stroke, projected along z, 10 x 10 quads, tau = 1; at tau = 2 its limit surface
    // folds (6 faces) and, like two boundary curves, is refused with INVALID_ARGUMENT, leaving
    // the output untouched.
    {
        std::vector<double> pts;
        std::vector<size_t> sizes;
        auto stroke = [&](double x0, double y0, double x1, double y1, double lift) {
            for (int i = 0; i <= 6; ++i) {
                double x = x0 + (x1 - x0) * i / 6, y = y0 + (y1 - y0) * i / 6;
                pts.insert(pts.end(), {x, y, x * x - y * y + lift});
            }
            sizes.push_back(7);
        };
        stroke(-1, -1, 1, -1, 0);
        stroke(1, -1, 1, 1, 0);
        stroke(1, 1, -1, 1, 0);
        stroke(-1, 1, -1, -1, 0);
        stroke(-0.6, -0.5, 0.5, 0.4, 0.02);
        profsubd_options_set_samples(raw_options, 10, 10);
        const double up[3] = {0, 0, 1};
        profsubd_fitted *s = nullptr;
        profsubd_status st = profsubd_curves(pts.data(), sizes.data(), 4, 1, 1.0, up, raw_options, &s);
        Model m;
        if (take_result(ck, "sketch curves 10x10", st, s, &m)) {
            models.push_back(std::move(m));
        }
        profsubd_fitted *untouched = nullptr;
        ck.set_context("sketch curves, two boundary curves");
        ck.check(profsubd_curves(pts.data(), sizes.data(), 2, 0, 2.0, nullptr, raw_options, &untouched) ==
                         PROFSUBD_ERROR_INVALID_ARGUMENT &&
                     untouched == nullptr,
                 "two boundary curves are refused");
        ck.set_context("sketch curves 10x10, tau = 2");
        ck.check(profsubd_curves(pts.data(), sizes.data(), 4, 1, 2.0, up, raw_options, &untouched) ==
                         PROFSUBD_ERROR_INVALID_ARGUMENT &&
                     untouched == nullptr,
                 "a folded limit surface is refused");
        // The same strokes by the fair method: fold-free, its targets checked like the others.
        profsubd_fitted *fair = nullptr;
        st = profsubd_curves_fair(pts.data(), sizes.data(), 4, 1, up, raw_options, &fair);
        Model f;
        if (take_result(ck, "sketch curves 10x10, fair", st, fair, &f)) {
            models.push_back(std::move(f));
        }
    }
    // Partial revolutions: poles on the boundary meridians (sectors with a corner apex), and
    // flat caps (sectors, meridian planes) closing the solid.
    struct Wedge {
        const char *name;
        const std::vector<double> *profile;
        double angle;
        int caps;
        uint32_t samples_around;
    } wedges[] = {
        {"open sphere wedge 90 deg", &semicircle, 90, PROFSUBD_CAPS_OPEN, 8},
        {"capped sphere wedge 270 deg", &semicircle, 270, PROFSUBD_CAPS_FLAT, 24},
        {"capped half cone", &cone, 180, PROFSUBD_CAPS_FLAT, 16},
        {"capped cylinder (full turn, flat discs)", &cylinder, 360, PROFSUBD_CAPS_FLAT, 32},
    };
    for (const Wedge &w : wedges) {
        profsubd_options_set_samples(raw_options, 16, w.samples_around);
        profsubd_options_set_revolve_angle(raw_options, w.angle);
        profsubd_options_set_caps(raw_options, w.caps);
        profsubd_fitted *s = nullptr;
        profsubd_status st = profsubd_revolve(w.profile->data(), w.profile->size() / 2, raw_options, &s);
        Model m;
        if (take_result(ck, w.name, st, s, &m)) {
            models.push_back(std::move(m));
        }
    }
    // A thin-walled cup: its meridian caps bend around the column's ends.
    const std::vector<double> cup = {0, 0, 1, 0, 1, 2, 0.9, 2, 0.9, 0.2, 0, 0.2};
    profsubd_options_set_interpolation(raw_options, 1);
    profsubd_options_set_samples(raw_options, 24, 8);
    profsubd_options_set_revolve_angle(raw_options, 180.0);
    profsubd_fitted *cup_result = nullptr;
    profsubd_status cup_status =
        profsubd_revolve(cup.data(), cup.size() / 2, raw_options, &cup_result);
    Model cup_model;
    if (take_result(ck, "capped cup (polyline)", cup_status, cup_result, &cup_model)) {
        models.push_back(std::move(cup_model));
    }
    profsubd_options_set_interpolation(raw_options, 0);
    // A capped 270-degree vase with a semi-sharp crease ring (2.0) ending at corner-tagged
    // vertices on the infinitely sharp cap creases, under edge-only and uniform or Chaikin.
    const std::vector<double> vase = {1.0, 0.0, 1.4, 0.8, 1.3, 2.0, 0.9, 3.0, 0.9, 3.6};
    const uint32_t vase_corner = 2;
    profsubd_options_set_samples(raw_options, 8, 16);
    profsubd_options_set_revolve_angle(raw_options, 270.0);
    profsubd_options_set_sharp_angle(raw_options, 60.0);
    profsubd_options_set_sweep_corners(raw_options, &vase_corner, 1, nullptr, 0);
    profsubd_options_set_crease_sharpness(raw_options, 2.0f);
    profsubd_options_set_boundary(raw_options, PROFSUBD_BOUNDARY_EDGE_ONLY);
    for (int chaikin = 0; chaikin < 2; ++chaikin) {
        profsubd_options_set_crease_method(raw_options,
                                           chaikin ? PROFSUBD_CREASE_CHAIKIN : PROFSUBD_CREASE_UNIFORM);
        profsubd_fitted *vase_result = nullptr;
        profsubd_status vase_status =
            profsubd_revolve(vase.data(), vase.size() / 2, raw_options, &vase_result);
        Model vase_model;
        std::string name = std::string("capped vase, semi-sharp 2, edge-only, ") +
                           (chaikin ? "chaikin" : "uniform");
        if (with_options(ck, name, Sdc::Options::VTX_BOUNDARY_EDGE_ONLY,
                         chaikin ? Sdc::Options::CREASE_CHAIKIN : Sdc::Options::CREASE_UNIFORM,
                         vase_status, vase_result, &vase_model)) {
            models.push_back(std::move(vase_model));
        }
    }
    profsubd_options_set_sharp_angle(raw_options, 30.0);
    profsubd_options_set_sweep_corners(raw_options, nullptr, 0, nullptr, 0);
    profsubd_options_set_crease_sharpness(raw_options, 10.0f);
    profsubd_options_set_boundary(raw_options, PROFSUBD_BOUNDARY_EDGE_AND_CORNER);
    profsubd_options_set_crease_method(raw_options, PROFSUBD_CREASE_UNIFORM);
    profsubd_options_set_caps(raw_options, PROFSUBD_CAPS_OPEN);
    profsubd_options_set_revolve_angle(raw_options, 360.0);
    // Sweeps: a torus (circle along a circle), a square tube along a closed wavy curve (four
    // crease loops), an L-shaped square rail (a crease ring at the corner).
    const std::vector<double> small = circle(32, 0.5, 2), square = {-0.2, -0.2, 0.2, -0.2, 0.2, 0.2, -0.2, 0.2};
    std::vector<double> ring = circle(48, 2.0, 2), wavy = circle(48, 2.0, 3), ring3;
    for (size_t i = 0; i < ring.size(); i += 2) {
        ring3.insert(ring3.end(), {ring[i], ring[i + 1], 0.0});
    }
    const std::vector<double> ell = {0, 0, 0, 2, 0, 0, 2, 2, 0};
    struct Sw {
        const char *name;
        const std::vector<double> *profile, *trajectory;
        int closed_trajectory;
        uint32_t samples_profile, samples_trajectory;
    } sweeps[] = {
        {"torus 16x32", &small, &ring3, 1, 16, 32},
        {"square tube on a closed curve", &square, &wavy, 1, 8, 48},
        {"L-shaped square rail", &square, &ell, 0, 8, 16},
    };
    for (const Sw &w : sweeps) {
        profsubd_options_set_samples(raw_options, w.samples_profile, w.samples_trajectory);
        profsubd_options_set_sweep_closed(raw_options, 1, w.closed_trajectory);
        profsubd_fitted *s = nullptr;
        profsubd_status st = profsubd_sweep(w.profile->data(), w.profile->size() / 2,
                                            w.trajectory->data(), w.trajectory->size() / 3,
                                            raw_options, &s);
        Model m;
        if (take_result(ck, w.name, st, s, &m)) {
            models.push_back(std::move(m));
        }
    }
    // Subdivision options: boundary edge-only / edge-and-corner on open models with one-face
    // corners, Chaikin creasing, semi-sharp creases, boundary none on a closed model.
    using O = Sdc::Options;
    const std::vector<double> bowl = {1.0, 0.0, 1.3, 0.6, 1.0, 1.2, 0.6, 1.5};
    const std::vector<double> arc = {-0.3, 0.0, 0.0, 0.1, 0.3, 0.0};
    const std::vector<double> bend = {0, 0, 0, 1, 0, 0, 1.5, 1, 0, 1.5, 2, 0.5};
    const uint32_t bowl_corner = 2, arc_corner = 1, bend_corner = 1;
    profsubd_options_set_sweep_corners(raw_options, &bowl_corner, 1, nullptr, 0);
    profsubd_options_set_revolve_angle(raw_options, 270.0);
    profsubd_options_set_samples(raw_options, 8, 12);
    profsubd_options_set_crease_sharpness(raw_options, 2.0f);
    std::vector<Model> corner_models;
    for (int k = 0; k < 2; ++k) {
        bool edge_only = k == 0;
        profsubd_options_set_boundary(raw_options, edge_only ? PROFSUBD_BOUNDARY_EDGE_ONLY
                                                             : PROFSUBD_BOUNDARY_EDGE_AND_CORNER);
        profsubd_options_set_crease_method(raw_options, edge_only ? PROFSUBD_CREASE_UNIFORM
                                                                  : PROFSUBD_CREASE_CHAIKIN);
        O::VtxBoundaryInterpolation rule = edge_only ? O::VTX_BOUNDARY_EDGE_ONLY : O::VTX_BOUNDARY_EDGE_AND_CORNER;
        O::CreasingMethod method = edge_only ? O::CREASE_UNIFORM : O::CREASE_CHAIKIN;
        std::string suffix = edge_only ? ", edge-only, semi-sharp" : ", edge-and-corner, chaikin, semi-sharp";
        profsubd_fitted *s = nullptr;
        profsubd_options_set_sweep_corners(raw_options, &bowl_corner, 1, nullptr, 0);
        profsubd_status st = profsubd_revolve(bowl.data(), bowl.size() / 2, raw_options, &s);
        Model m;
        if (with_options(ck, "270-degree revolution" + suffix, rule, method, st, s, &m)) {
            corner_models.push_back(std::move(m));
        }
        profsubd_options_set_sweep_closed(raw_options, 0, 0);
        profsubd_options_set_sweep_corners(raw_options, &arc_corner, 1, &bend_corner, 1);
        st = profsubd_sweep(arc.data(), arc.size() / 2, bend.data(), bend.size() / 3, raw_options, &s);
        Model r;
        if (with_options(ck, "open ribbon" + suffix, rule, method, st, s, &r)) {
            corner_models.push_back(std::move(r));
        }
    }
    profsubd_options_set_sweep_corners(raw_options, nullptr, 0, nullptr, 0);
    profsubd_options_set_sweep_closed(raw_options, 1, 1);
    profsubd_options_set_samples(raw_options, 8, 48);
    profsubd_options_set_crease_sharpness(raw_options, 1.5f);
    profsubd_options_set_boundary(raw_options, PROFSUBD_BOUNDARY_NONE);
    profsubd_fitted *tube = nullptr;
    profsubd_status st = profsubd_sweep(square.data(), square.size() / 2, wavy.data(), wavy.size() / 3,
                                        raw_options, &tube);
    Model m;
    if (with_options(ck, "square tube, semi-sharp 1.5, boundary none, chaikin", O::VTX_BOUNDARY_NONE,
                     O::CREASE_CHAIKIN, st, tube, &m)) {
        models.push_back(std::move(m));
    }
    ck.set_context("boundary none on an open ribbon");
    profsubd_options_set_sweep_closed(raw_options, 0, 0);
    profsubd_fitted *refused = nullptr;
    ck.equal(profsubd_sweep(arc.data(), arc.size() / 2, bend.data(), bend.size() / 3, raw_options, &refused),
             PROFSUBD_ERROR_INVALID_ARGUMENT, "refused");
    ck.check(refused == nullptr, "no result");
    for (Model &c : corner_models) {
        check_rule_matters(ck, c);
        models.push_back(std::move(c));
    }
    for (const Model &m : models) {
        check_model(ck, m);
    }
    // Cap planes: the meridian planes at 0 and 270 degrees (y = 0, x = 0), 180 degrees (y = 0),
    // and the flat ends' planes.
    const Plane y0 = {{0, 1, 0}, 0}, x0 = {{1, 0, 0}, 0};
    const std::vector<std::pair<std::string, std::vector<Plane>>> caps = {
        {"wine_glass_cutaway", {y0, x0}},
        {"vase_cutaway", {y0, x0, {{0, 0, 1}, 0}, {{0, 0, 1}, 5.5}}},
        {"capped sphere wedge 270 deg", {y0, x0}},
        {"capped half cone", {y0, {{0, 0, 1}, 0}}},
        {"capped cylinder (full turn, flat discs)", {{{0, 0, 1}, 0}, {{0, 0, 1}, 2}}},
        {"capped cup (polyline)", {y0}},
    };
    for (const auto &c : caps) {
        auto m = std::find_if(models.begin(), models.end(),
                              [&](const Model &x) { return x.name == c.first; });
        ck.set_context(c.first);
        if (ck.check(m != models.end(), "model present")) {
            check_flat_caps(ck, *m, c.second);
        }
    }
    ck.set_context("");
    ck.equal(models.size(), size_t(29), "every model built");
    return ck.finish();
}
