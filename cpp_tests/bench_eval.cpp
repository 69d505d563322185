// Benchmark: profsubd vs OpenSubdiv 3.5, single thread, double precision, same process.
//
// Mesh: OpenSubdiv's catmark_car and catmark_bishop refined once by Far and put side by side
// (10,040 quads: extraordinary vertices, semi-sharp creases, boundaries), or the OBJs given as
// arguments (each refined once, then merged). Built by cmake, not run by ctest:
// `cmake --build build --target bench_eval && build/cpp_tests/bench_eval [--p2] [--build-only] [mesh.obj...]`
// (`--p2`: the refinement benchmark only; `--build-only`: one build and one position update on
// each side, untimed, for callgrind), or `bench_eval --scale [--scale-max 6]`: build and update
// at 10^3..10^5 (10^6) faces.
//
// P1: 10^6 random (face, u, v) -> position + du + dv.
//     profsubd_evaluator_evaluate (one batch call) vs Bfr::Surface<double> with its cache
//     (points in random order, and grouped by face), vs Far::PatchTable + PatchMap.
//     Build times (evaluator, factory, adaptive refinement + patch table) reported apart.
//     Position update for the same topology: profsubd_evaluator_update_positions vs Far's
//     refinement + local-point stencils in one double-precision table
//     (StencilTableReal<double>::UpdateValues, the loop Osd::CpuEvaluator::EvalStencils runs;
//     Osd's evaluators take floats in 3.5), each ending with every patch point computed.
// P2: uniform refinement to level 3, topology + positions: profsubd_refine_uniform vs
//     Far::TopologyRefiner::RefineUniform + PrimvarRefinerReal<double>::Interpolate
//     (TopologyRefiner construction included on both sides), time and peak memory (each run
//     in a forked child; peak resident memory above the child's start).

#include "capi_mesh.h"
#include "far_points.h"
#include "osd_shape.h"
#include "random_points.h"
#include "test_support.h"

#include <profsubd.h>

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <thread>

using namespace OpenSubdiv;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

// Best of `reps` runs of f (seconds).
double best(int reps, const std::function<void()> &f) {
    double b = 1e300;
    for (int r = 0; r < reps; ++r) {
        auto t = Clock::now();
        f();
        b = std::min(b, seconds(t));
    }
    return b;
}

long rss_kb() {
    FILE *f = std::fopen("/proc/self/statm", "r");
    long pages = 0, resident = 0;
    if (f) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

// Runs f in a child process; returns its peak resident memory above its start, in MiB.
double peak_mib(const std::function<void()> &f) {
    int fd[2];
    if (pipe(fd) != 0) return -1;
    pid_t pid = fork();
    if (pid == 0) {
        long start = rss_kb();
        f();
        ssize_t w = write(fd[1], &start, sizeof start);
        (void)w;
        _exit(0);
    }
    long start = 0;
    ssize_t r = read(fd[0], &start, sizeof start);
    (void)r;
    int status = 0;
    struct rusage ru;
    wait4(pid, &status, 0, &ru);
    close(fd[0]);
    close(fd[1]);
    return (ru.ru_maxrss - start) / 1024.0;
}

// The shape refined once by Far, as a new OsdShape (creases and corners at level 1).
profsubd_test::OsdShape refine_once(const profsubd_test::OsdShape &s) {
    auto refiner = profsubd_test::build_refiner(s);
    Far::TopologyRefiner::UniformOptions uo(1);
    uo.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uo);
    std::vector<profsubd_test::FarPoint> pts = profsubd_test::refine_points(*refiner, s.positions);
    const Far::TopologyLevel &l = refiner->GetLevel(1);
    profsubd_test::OsdShape out;
    out.options = s.options;
    for (int v = 0; v < l.GetNumVertices(); ++v)
        for (int k = 0; k < 3; ++k) out.positions.push_back(pts[s.num_vertices() + v].p[k]);
    for (int f = 0; f < l.GetNumFaces(); ++f) {
        auto fv = l.GetFaceVertices(f);
        out.face_sizes.push_back(fv.size());
        for (int k = 0; k < fv.size(); ++k) out.face_indices.push_back(fv[k]);
    }
    for (int e = 0; e < l.GetNumEdges(); ++e) {
        float sh = l.GetEdgeSharpness(e);
        if (sh > 0 && !l.IsEdgeBoundary(e)) {
            auto ev = l.GetEdgeVertices(e);
            out.crease_vertices.push_back(ev[0]);
            out.crease_vertices.push_back(ev[1]);
            out.crease_sharpness.push_back(sh);
        }
    }
    for (int v = 0; v < l.GetNumVertices(); ++v) {
        float sh = l.GetVertexSharpness(v);
        if (sh > 0 && !(l.IsVertexBoundary(v) && l.GetVertexFaces(v).size() == 1)) {
            out.corner_vertices.push_back(v);
            out.corner_sharpness.push_back(sh);
        }
    }
    return out;
}

// `b` appended to `a` as a separate component (a's options are kept).
void append_shape(profsubd_test::OsdShape &a, const profsubd_test::OsdShape &b) {
    const int offset = a.num_vertices();
    if (a.face_sizes.empty()) a.options = b.options;
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    a.face_sizes.insert(a.face_sizes.end(), b.face_sizes.begin(), b.face_sizes.end());
    for (int v : b.face_indices) a.face_indices.push_back(v + offset);
    for (int v : b.crease_vertices) a.crease_vertices.push_back(v + offset);
    a.crease_sharpness.insert(a.crease_sharpness.end(), b.crease_sharpness.begin(), b.crease_sharpness.end());
    for (int v : b.corner_vertices) a.corner_vertices.push_back(v + offset);
    a.corner_sharpness.insert(a.corner_sharpness.end(), b.corner_sharpness.begin(), b.corner_sharpness.end());
}

// Far's counterpart of the evaluator build: adaptive refinement + PatchTable + PatchMap, with
// the refined and local points' positions.
void far_build(const profsubd_test::OsdShape &shape, std::unique_ptr<Far::TopologyRefiner> &adaptive,
               std::unique_ptr<Far::PatchTable> &table, std::unique_ptr<Far::PatchMap> &pmap,
               std::vector<profsubd_test::FarPoint> &pp) {
    adaptive = profsubd_test::build_refiner(shape);
    Far::PatchTableFactory::Options po;
    po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    adaptive->RefineAdaptive(po.GetRefineAdaptiveOptions());
    table.reset(Far::PatchTableFactory::Create(*adaptive, po));
    pmap.reset(new Far::PatchMap(*table));
    int nref = adaptive->GetNumVerticesTotal();
    pp = profsubd_test::refine_points(*adaptive, shape.positions, table->GetNumLocalPoints());
    if (table->GetNumLocalPoints() > 0) table->ComputeLocalPointValues(pp.data(), pp.data() + nref);
}

// Far's counterpart of a position update: refinement + local-point stencils in one table.
std::unique_ptr<Far::StencilTableReal<double> const> far_update_stencils(const profsubd_test::OsdShape &shape) {
    Far::PatchTableFactory::Options po;
    po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    po.SetPatchPrecision<double>();
    auto r = profsubd_test::build_refiner(shape);
    r->RefineAdaptive(po.GetRefineAdaptiveOptions());
    std::unique_ptr<Far::PatchTable> t(Far::PatchTableFactory::Create(*r, po));
    Far::StencilTableFactoryReal<double>::Options so;
    so.generateIntermediateLevels = true;
    std::unique_ptr<Far::StencilTableReal<double> const> refinement(
        Far::StencilTableFactoryReal<double>::Create(*r, so));
    return std::unique_ptr<Far::StencilTableReal<double> const>(
        Far::StencilTableFactoryReal<double>::AppendLocalPointStencilTable(*r, refinement.get(),
                                                                          t->GetLocalPointStencilTable<double>()));
}

// --build-only: each side's build and one position update, once, untimed: the run to profile
// with `valgrind --tool=callgrind` (instruction counts, repeatable on a loaded machine).
void build_only(const profsubd_test::OsdShape &shape, const profsubd_mesh *mesh, const profsubd_options *opts) {
    profsubd_evaluator *ev = nullptr;
    if (profsubd_evaluator_new(mesh, opts, &ev) != PROFSUBD_OK)
        std::fprintf(stderr, "build: %s\n", profsubd_last_error_message());
    std::unique_ptr<Far::TopologyRefiner> adaptive;
    std::unique_ptr<Far::PatchTable> table;
    std::unique_ptr<Far::PatchMap> pmap;
    std::vector<profsubd_test::FarPoint> pp;
    far_build(shape, adaptive, table, pmap, pp);
    if (ev && profsubd_evaluator_update_positions(ev, shape.positions.data(), shape.num_vertices()) != PROFSUBD_OK)
        std::fprintf(stderr, "update: %s\n", profsubd_last_error_message());
    auto stencils = far_update_stencils(shape);
    std::vector<profsubd_test::FarPoint> src(shape.num_vertices()), dst(stencils->GetNumStencils());
    for (int v = 0; v < shape.num_vertices(); ++v)
        for (int d = 0; d < 3; ++d) src[v].p[d] = shape.positions[3 * v + d];
    stencils->UpdateValues(src.data(), dst.data());
    std::printf("build-only: %zu patch points (Far), %d stencils\n", pp.size(), stencils->GetNumStencils());
    profsubd_evaluator_free(ev);
}

// --scale: build and position update on both sides for meshes of 10^3 to 10^5 faces (10^6
// with --scale-max 6): catmark_car refined 0..k times by Far, creases and all.
void scale(int max_exp) {
    profsubd_test::OsdShape shape;
    std::string err;
    if (!profsubd_test::read_osd_shape(profsubd_test::osd_shapes_dir() + "/catmark_car.obj", &shape, &err)) {
        std::fprintf(stderr, "bench_eval: %s\n", err.c_str());
        return;
    }
    std::printf("scale: catmark_car refined k times by Far (semi-sharp creases), one thread; best of 3 (1 above 10^5 faces)\n");
    std::printf("%9s %11s %11s %7s %11s %11s %7s %9s\n", "faces", "build ms", "Far ms", "ratio", "update ms",
                "Far ms", "ratio", "ns/face");
    while (true) {
        const int nf = shape.num_faces();
        if (nf > std::pow(10.0, max_exp) * 1.1) break;
        profsubd_test::MeshPtr mesh = profsubd_test::new_mesh_capi(shape, &err);
        profsubd_options *opts = profsubd_test::capi_options(shape.options).release();
        profsubd_options_set_threads(opts, 1);
        const int reps = nf > 200000 ? 1 : 3;
        profsubd_evaluator *ev = nullptr;
        double t_ps = best(reps, [&] {
            if (ev) profsubd_evaluator_free(ev);
            profsubd_evaluator_new(mesh.get(), opts, &ev);
        });
        std::unique_ptr<Far::TopologyRefiner> adaptive;
        std::unique_ptr<Far::PatchTable> table;
        std::unique_ptr<Far::PatchMap> pmap;
        std::vector<profsubd_test::FarPoint> pp;
        double t_far = best(reps, [&] { far_build(shape, adaptive, table, pmap, pp); });
        double t_up = best(reps, [&] {
            profsubd_evaluator_update_positions(ev, shape.positions.data(), shape.num_vertices());
        });
        auto stencils = far_update_stencils(shape);
        std::vector<profsubd_test::FarPoint> src(shape.num_vertices()), dst(stencils->GetNumStencils());
        double t_up_far = best(reps, [&] {
            for (int v = 0; v < shape.num_vertices(); ++v)
                for (int d = 0; d < 3; ++d) src[v].p[d] = shape.positions[3 * v + d];
            stencils->UpdateValues(src.data(), dst.data());
        });
        std::printf("%9d %11.1f %11.1f %7.2f %11.2f %11.2f %7.2f %9.0f\n", nf, 1e3 * t_ps, 1e3 * t_far, t_ps / t_far,
                    1e3 * t_up, 1e3 * t_up_far, t_up / t_up_far, 1e9 * t_ps / nf);
        std::fflush(stdout);
        profsubd_evaluator_free(ev);
        profsubd_options_free(opts);
        shape = refine_once(shape);
    }
}

}  // namespace

int main(int argc, char **argv) {
    bool p2_only = false, build_only_mode = false;
    int scale_max = 0;
    std::vector<std::string> paths;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--p2")
            p2_only = true;
        else if (std::string(argv[i]) == "--build-only")
            build_only_mode = true;
        else if (std::string(argv[i]) == "--scale")
            scale_max = std::max(scale_max, 5);
        else if (std::string(argv[i]) == "--scale-max" && i + 1 < argc)
            scale_max = std::atoi(argv[++i]);
        else
            paths.push_back(argv[i]);
    }
    if (scale_max > 0) {
        scale(scale_max);
        return 0;
    }
    if (paths.empty())
        for (const char *name : {"catmark_car", "catmark_bishop"})
            paths.push_back(profsubd_test::osd_shapes_dir() + "/" + name + ".obj");
    profsubd_test::OsdShape shape;
    std::string err;
    for (const std::string &path : paths) {
        profsubd_test::OsdShape base;
        if (!profsubd_test::read_osd_shape(path, &base, &err)) {
            std::fprintf(stderr, "bench_eval: %s: %s\n", path.c_str(), err.c_str());
            return 1;
        }
        append_shape(shape, refine_once(base));
        std::printf("mesh: %s refined once\n", path.c_str());
    }
    std::printf("mesh: %d vertices, %d faces, %zu creases, %zu corners\n", shape.num_vertices(),
                shape.num_faces(), shape.crease_sharpness.size(), shape.corner_sharpness.size());

    profsubd_test::MeshPtr mesh = profsubd_test::new_mesh_capi(shape, &err);
    if (!mesh) {
        std::fprintf(stderr, "bench_eval: %s\n", err.c_str());
        return 1;
    }
    profsubd_options *opts = profsubd_test::capi_options(shape.options).release();
    if (build_only_mode) {
        build_only(shape, mesh.get(), opts);
        profsubd_options_free(opts);
        return 0;
    }
    double checksum = 0;

    // --- P2: uniform refinement to level 3.
    const int level = 3;
    size_t ps_counts[2] = {0, 0};
    int far_counts[2] = {0, 0};
    auto run_ps = [&] {
        profsubd_mesh *out = nullptr;
        if (profsubd_refine_uniform(mesh.get(), opts, level, &out) != PROFSUBD_OK)
            std::fprintf(stderr, "refine: %s\n", profsubd_last_error_message());
        profsubd_mesh_num_vertices(out, &ps_counts[0]);
        profsubd_mesh_num_faces(out, &ps_counts[1]);
        profsubd_mesh_free(out);
    };
    auto run_far = [&] {
        auto r = profsubd_test::build_refiner(shape);
        r->RefineUniform(Far::TopologyRefiner::UniformOptions(level));
        std::vector<profsubd_test::FarPoint> pts = profsubd_test::refine_points(*r, shape.positions);
        checksum += pts.back().p[0];
        far_counts[0] = r->GetLevel(level).GetNumVertices();
        far_counts[1] = r->GetLevel(level).GetNumFaces();
    };
    // Alternated runs, so that a change in the machine's load hits both sides alike.
    double t_ref_ps = 1e300, t_ref_far = 1e300;
    for (int rep = 0; rep < 7; ++rep) {
        t_ref_ps = std::min(t_ref_ps, best(1, run_ps));
        t_ref_far = std::min(t_ref_far, best(1, run_far));
    }
    double m_ps = peak_mib(run_ps);
    double m_far = peak_mib(run_far);
    std::printf("\nP2: uniform refinement to level %d, topology + positions (best of 7, alternated)\n", level);
    std::printf("  profsubd_refine_uniform:               %8.1f ms   peak +%.1f MiB\n", 1e3 * t_ref_ps, m_ps);
    std::printf("  Far TopologyRefiner + PrimvarRefiner:  %8.1f ms   peak +%.1f MiB\n", 1e3 * t_ref_far, m_far);
    std::printf("  level %d: profsubd %zu vertices, %zu faces; Far %d vertices, %d faces\n", level, ps_counts[0],
                ps_counts[1], far_counts[0], far_counts[1]);
    std::printf("  ratio profsubd/Far: time %.3f   peak memory %.3f\n", t_ref_ps / t_ref_far, m_ps / m_far);
    if (p2_only) {
        std::printf("(checksum %g)\n", checksum);
        profsubd_options_free(opts);
        return 0;
    }

    const int N = 1000000;
    const int nf = shape.num_faces();
    profsubd_test::FacePoints points = profsubd_test::random_face_points(N, nf, 7);
    const std::vector<uint32_t> &faces = points.faces;
    const std::vector<double> &us = points.us, &vs = points.vs;
    std::vector<double> P(3 * N), DU(3 * N), DV(3 * N);

    // --- P1: profsubd.
    profsubd_evaluator *ev = nullptr;
    auto build_ps = [&] {
        if (ev) profsubd_evaluator_free(ev);
        profsubd_evaluator_new(mesh.get(), opts, &ev);
    };
    profsubd_options_set_threads(opts, 0);
    double t_build_ps_all = best(3, build_ps);
    profsubd_options_set_threads(opts, 1);
    double t_build_ps = best(3, build_ps);
    auto eval_ps = [&] {
        profsubd_status st = profsubd_evaluator_evaluate(ev, faces.data(), us.data(), vs.data(), N, P.data(),
                                                         DU.data(), DV.data());
        if (st != PROFSUBD_OK) std::fprintf(stderr, "evaluate: %s\n", profsubd_last_error_message());
    };
    profsubd_evaluator_set_threads(ev, 0);
    double t_eval_ps_all = best(3, eval_ps);
    std::vector<double> Pall = P;
    profsubd_evaluator_set_threads(ev, 1);
    double t_eval_ps = best(3, eval_ps);
    std::vector<double> Pps = P;
    bool same_all = std::equal(Pall.begin(), Pall.end(), Pps.begin());
    checksum += P[0];

    // --- P1: Bfr with its cache.
    auto refiner = profsubd_test::build_refiner(shape);
    using Factory = Bfr::RefinerSurfaceFactory<>;
    Factory::Options fo;
    std::unique_ptr<Factory> factory;
    double t_build_bfr = best(3, [&] { factory.reset(new Factory(*refiner, fo)); });
    Bfr::Surface<double> surface;
    std::vector<double> patch;
    auto bfr_point = [&](int i) {
        double uv[2] = {us[i], vs[i]};
        surface.Evaluate(uv, patch.data(), 3, &P[3 * i], &DU[3 * i], &DV[3 * i]);
    };
    // Random order: a fresh surface per point, as a caller with random queries would do.
    double t_eval_bfr = best(3, [&] {
        factory.reset(new Factory(*refiner, fo));  // cold cache each run, like profsubd's build
        for (int i = 0; i < N; ++i) {
            factory->InitVertexSurface(faces[i], &surface);
            patch.resize(3 * surface.GetNumPatchPoints());
            surface.PreparePatchPoints(shape.positions.data(), 3, patch.data(), 3);
            bfr_point(i);
        }
    });
    double maxdiff = 0;
    for (int i = 0; i < 3 * N; ++i) maxdiff = std::max(maxdiff, std::fabs(P[i] - Pps[i]));
    std::vector<int> order(N);
    for (int i = 0; i < N; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return faces[a] < faces[b]; });
    double t_eval_bfr_grouped = best(3, [&] {
        int current = -1;
        for (int i : order) {
            if ((int)faces[i] != current) {
                current = faces[i];
                factory->InitVertexSurface(current, &surface);
                patch.resize(3 * surface.GetNumPatchPoints());
                surface.PreparePatchPoints(shape.positions.data(), 3, patch.data(), 3);
            }
            bfr_point(i);
        }
    });
    checksum += P[3];

    // --- P1: Far PatchTable + PatchMap.
    std::unique_ptr<Far::TopologyRefiner> adaptive;
    std::unique_ptr<Far::PatchTable> table;
    std::unique_ptr<Far::PatchMap> pmap;
    std::vector<profsubd_test::FarPoint> pp;
    double t_build_far = best(3, [&] { far_build(shape, adaptive, table, pmap, pp); });
    double t_eval_far = best(3, [&] {
        double wp[20], wu[20], wv[20];
        for (int i = 0; i < N; ++i) {
            const Far::PatchTable::PatchHandle *h = pmap->FindPatch(faces[i], us[i], vs[i]);
            table->EvaluateBasis(*h, us[i], vs[i], wp, wu, wv);
            auto cvs = table->GetPatchVertices(*h);
            double p[3] = {0, 0, 0}, du[3] = {0, 0, 0}, dv[3] = {0, 0, 0};
            for (int k = 0; k < cvs.size(); ++k) {
                const double *c = pp[cvs[k]].p;
                for (int d = 0; d < 3; ++d) {
                    p[d] += wp[k] * c[d];
                    du[d] += wu[k] * c[d];
                    dv[d] += wv[k] * c[d];
                }
            }
            for (int d = 0; d < 3; ++d) {
                P[3 * i + d] = p[d];
                DU[3 * i + d] = du[d];
                DV[3 * i + d] = dv[d];
            }
        }
    });
    checksum += P[6];

    // --- Position update: new control points through the same topology.
    std::vector<double> moved(shape.positions.size());
    for (size_t i = 0; i < moved.size(); ++i) moved[i] = 1.01 * shape.positions[i] + 0.001 * (i % 7);
    const size_t nv = shape.num_vertices();
    double t_update_ps = 1e300;
    for (int rep = 0; rep < 5; ++rep) {
        const std::vector<double> &x = rep % 2 ? shape.positions : moved;
        t_update_ps = std::min(t_update_ps, best(1, [&] {
            if (profsubd_evaluator_update_positions(ev, x.data(), nv) != PROFSUBD_OK)
                std::fprintf(stderr, "update: %s\n", profsubd_last_error_message());
        }));
    }
    std::unique_ptr<Far::StencilTableReal<double> const> stencils = far_update_stencils(shape);
    std::vector<profsubd_test::FarPoint> src(nv), dst(stencils->GetNumStencils());
    double t_update_far = 1e300;
    for (int rep = 0; rep < 5; ++rep) {
        const std::vector<double> &x = rep % 2 ? shape.positions : moved;
        t_update_far = std::min(t_update_far, best(1, [&] {
            for (size_t v = 0; v < nv; ++v)
                for (int d = 0; d < 3; ++d) src[v].p[d] = x[3 * v + d];
            stencils->UpdateValues(src.data(), dst.data());
        }));
    }
    checksum += dst.back().p[0];

    std::printf("\nP1: %d random (face,u,v), position + du + dv (best of 3 runs, single thread)\n", N);
    std::printf("  profsubd evaluator:      build %8.1f ms   evaluate %8.1f ms  (%6.1f ns/point)\n", 1e3 * t_build_ps,
                1e3 * t_eval_ps, 1e9 * t_eval_ps / N);
    std::printf("  Bfr::Surface, cache:     build %8.1f ms   evaluate %8.1f ms  (%6.1f ns/point, random order)\n",
                1e3 * t_build_bfr, 1e3 * t_eval_bfr, 1e9 * t_eval_bfr / N);
    std::printf("                                               evaluate %8.1f ms  (%6.1f ns/point, grouped by face)\n",
                1e3 * t_eval_bfr_grouped, 1e9 * t_eval_bfr_grouped / N);
    std::printf("  Far PatchTable+PatchMap: build %8.1f ms   evaluate %8.1f ms  (%6.1f ns/point)\n", 1e3 * t_build_far,
                1e3 * t_eval_far, 1e9 * t_eval_far / N);
    std::printf("  ratio profsubd/Bfr (random order):   evaluate %.3f   build+evaluate %.3f\n", t_eval_ps / t_eval_bfr,
                (t_build_ps + t_eval_ps) / (t_build_bfr + t_eval_bfr));
    std::printf("  ratio profsubd/Bfr (grouped by face): evaluate %.3f\n", t_eval_ps / t_eval_bfr_grouped);
    std::printf("  ratio profsubd/Far PatchTable:       evaluate %.3f   build+evaluate %.3f\n", t_eval_ps / t_eval_far,
                (t_build_ps + t_eval_ps) / (t_build_far + t_eval_far));
    std::printf("  max |profsubd - Bfr| over all coordinates: %.3g\n", maxdiff);
    std::printf("\nAll cores (%u): profsubd evaluate %8.1f ms, speed-up %.2f over one thread, results %s\n",
                std::thread::hardware_concurrency(), 1e3 * t_eval_ps_all, t_eval_ps / t_eval_ps_all,
                same_all ? "bit-identical" : "DIFFERENT");
    std::printf("All cores (%u): profsubd build %8.1f ms, speed-up %.2f over one thread; ratio to Far (one thread) %.3f\n",
                std::thread::hardware_concurrency(), 1e3 * t_build_ps_all, t_build_ps / t_build_ps_all,
                t_build_ps_all / t_build_far);
    std::printf("\nPosition update, same topology (best of 5, alternating two position sets)\n");
    std::printf("  profsubd_evaluator_update_positions:       %8.2f ms\n", 1e3 * t_update_ps);
    std::printf("  Far refinement + local-point stencils:     %8.2f ms  (%d stencils, double)\n", 1e3 * t_update_far,
                stencils->GetNumStencils());
    std::printf("  ratio profsubd/OpenSubdiv position update: %.3f\n", t_update_ps / t_update_far);

    std::printf("(checksum %g)\n", checksum);

    profsubd_evaluator_free(ev);
    profsubd_options_free(opts);
    return 0;
}
