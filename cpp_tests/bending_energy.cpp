// The bending energy of a limit surface on OpenSubdiv's side, the independent reference for
// profsubd's undulation measure (src/construct/design.rs): E = ∫ (κ₁² + κ₂²) dA of the limit
// surface of an OBJ file (tags as written by profsubd), by Gauss-Legendre quadrature on each
// face from Bfr::Surface<double>'s first and second derivatives (approximation level 10):
// with the first and second fundamental forms I = [E F; F G] and II = [L M; M N] (the second
// derivatives against the unit normal), κ₁² + κ₂² = tr((I⁻¹ II)²) and dA = √det I du dv.
// Each face is cut into 4 x 4 squares (the library's lattice cells) with 4 x 4 Gauss points
// each, and again into 8 x 8: the difference is printed as the quadrature's own uncertainty
// (the integrand is not smooth at an extraordinary vertex's corner).
//
// Runs:
//   bending_energy FILE.obj...             the energy of each file (and, with --faces K,
//                                          its K most bending faces and where they are);
//   bending_energy --compare TABLE         TABLE: lines "FILE.obj<TAB>energy<TAB>tolerance"
//                                          (profsubd's limit energy,
//                                          SurfaceReport::limit_bending_energy, written by
//                                          scripts/bending_energy.sh); fails unless every Bfr
//                                          energy is within the relative tolerance of it.
// No profsubd code computes anything here: the OBJ is read by the harness's own parser and
// evaluated by Bfr.
#include "bfr_faces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace profsubd_test;
using namespace OpenSubdiv;

namespace {

struct V3 {
    double x = 0, y = 0, z = 0;
};
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 v3(const double *p) { return {p[0], p[1], p[2]}; }

// Gauss-Legendre nodes and weights on [0, 1], 4 points.
constexpr double kNode[4] = {0.5 - 0.43056815579702629, 0.5 - 0.16999052179242813, 0.5 + 0.16999052179242813,
                             0.5 + 0.43056815579702629};
constexpr double kWeight[4] = {0.17392742256872693, 0.32607257743127307, 0.32607257743127307, 0.17392742256872693};

// (κ₁² + κ₂²) √det I at one point from its derivatives; 0 where the Jacobian vanishes.
double integrand(V3 du, V3 dv, V3 duu, V3 duv, V3 dvv) {
    const double e = dot(du, du), f = dot(du, dv), g = dot(dv, dv);
    const double det = e * g - f * f;
    if (!(det > 0)) return 0;
    const V3 c = cross(du, dv);
    const double len = std::sqrt(dot(c, c));
    const V3 n = (1.0 / len) * c;
    const double l = dot(duu, n), m = dot(duv, n), nn = dot(dvv, n);
    // S = I⁻¹ II.
    const double s11 = (g * l - f * m) / det, s12 = (g * m - f * nn) / det;
    const double s21 = (e * m - f * l) / det, s22 = (e * nn - f * m) / det;
    const double trace_s2 = s11 * s11 + 2 * s12 * s21 + s22 * s22;
    return trace_s2 * std::sqrt(det);
}

struct FaceEnergy {
    int face = 0;
    double energy = 0;
    V3 centre;
};

struct Energy {
    bool ok = false;
    std::string error;
    double coarse = 0;  // 4 x 4 squares per face
    double fine = 0;    // 8 x 8 squares per face
    std::vector<FaceEnergy> faces;
};

// Energy of one face cut into `cuts` x `cuts` squares of 4 x 4 Gauss points.
double face_energy(const Bfr::Surface<double> &surface, const double *points, int cuts) {
    double total = 0;
    double p[3], du[3], dv[3], duu[3], duv[3], dvv[3];
    const double h = 1.0 / cuts;
    for (int j = 0; j < cuts; ++j) {
        for (int i = 0; i < cuts; ++i) {
            for (int b = 0; b < 4; ++b) {
                for (int a = 0; a < 4; ++a) {
                    const double uv[2] = {(i + kNode[a]) * h, (j + kNode[b]) * h};
                    surface.Evaluate(uv, points, 3, p, du, dv, duu, duv, dvv);
                    total += kWeight[a] * kWeight[b] * h * h *
                             integrand(v3(du), v3(dv), v3(duu), v3(duv), v3(dvv));
                }
            }
        }
    }
    return total;
}

Energy bending_energy(const std::string &path) {
    Energy out;
    OsdShape shape;
    if (!read_osd_shape(path, &shape, &out.error)) return out;
    bool quads = true;
    const bool built = for_each_bfr_surface(shape, [&](const Far::TopologyLevel &level, int f,
                                                       const Bfr::Surface<double> &surface,
                                                       const double *points) {
        if (level.GetFaceVertices(f).size() != 4) {
            out.error = "face " + std::to_string(f) + " is not a quad";
            return quads = false;
        }
        const double coarse = face_energy(surface, points, 4);
        out.coarse += coarse;
        out.fine += face_energy(surface, points, 8);
        double p[3], du[3], dv[3];
        const double mid[2] = {0.5, 0.5};
        surface.Evaluate(mid, points, 3, p, du, dv);
        out.faces.push_back({f, coarse, v3(p)});
        return true;
    });
    if (!built) {
        out.error = "Far rejects the mesh";
        return out;
    }
    if (!quads) return out;
    out.ok = true;
    return out;
}

int usage() {
    std::fprintf(stderr, "usage: bending_energy [--faces K] FILE.obj...\n"
                         "       bending_energy --compare TABLE\n");
    return 2;
}

}  // namespace

int main(int argc, char **argv) {
    if (argc < 2) return usage();
    const std::string first = argv[1];
    if (first == "--compare") {
        if (argc != 3) return usage();
        std::ifstream table(argv[2]);
        if (!table) {
            std::fprintf(stderr, "cannot read %s\n", argv[2]);
            return 2;
        }
        int failed = 0, checked = 0;
        double worst = 0;
        std::string line;
        while (std::getline(table, line)) {
            std::istringstream fields(line);
            std::string path;
            double library = 0, tol = 0;
            if (!std::getline(fields, path, '\t') || !(fields >> library >> tol)) continue;
            Energy e = bending_energy(path);
            if (!e.ok) {
                std::printf("FAIL %s: %s\n", path.c_str(), e.error.c_str());
                ++failed;
                continue;
            }
            const double rel = e.fine / library - 1;
            const bool ok = std::fabs(rel) <= tol;
            worst = std::max(worst, std::fabs(rel));
            std::printf("%s %s: Bfr %.6g (4x4 squares %.6g), profsubd %.6g, relative %+.2e (tolerance %.2g)\n",
                        ok ? "ok  " : "FAIL", path.c_str(), e.fine, e.coarse, library, rel, tol);
            failed += ok ? 0 : 1;
            ++checked;
        }
        std::printf("%d files, %d outside their tolerance, largest relative difference %.2e\n", checked, failed,
                    worst);
        return failed == 0 && checked > 0 ? 0 : 1;
    }
    int top = 0, k = 1;
    if (first == "--faces") {
        if (argc < 4) return usage();
        top = std::atoi(argv[2]);
        k = 3;
    }
    int status = 0;
    for (; k < argc; ++k) {
        Energy e = bending_energy(argv[k]);
        if (!e.ok) {
            std::printf("%s: %s\n", argv[k], e.error.c_str());
            status = 1;
            continue;
        }
        std::printf("%s: bending energy %.8g (4x4 squares per face %.8g, difference %.1e)\n", argv[k], e.fine,
                    e.coarse, std::fabs(e.fine - e.coarse) / std::max(e.fine, 1e-300));
        std::sort(e.faces.begin(), e.faces.end(),
                  [](const FaceEnergy &a, const FaceEnergy &b) { return a.energy > b.energy; });
        for (int i = 0; i < top && i < static_cast<int>(e.faces.size()); ++i) {
            const FaceEnergy &f = e.faces[i];
            std::printf("  face %d: %.6g at (%.4f, %.4f, %.4f)\n", f.face, f.energy, f.centre.x, f.centre.y,
                        f.centre.z);
        }
    }
    return status;
}
