// Benchmark: profsubd vs OpenSubdiv 3.5, single thread, double precision, same process.
//
// Mesh: OpenSubdiv's catmark_car and catmark_bishop refined once by Far and put side by side
// (10,040 quads: extraordinary vertices, semi-sharp creases, boundaries), or the OBJs given as
// arguments (each refined once, then merged). Built by cmake, not run by ctest:
// `cmake --build build --target bench_eval && build/cpp_tests/bench_eval [--p2] [--build-only] [--memory] [mesh.obj...]`
// (`--p2`: the refinement benchmark only; `--threads N`: profsubd's threads in P2, 0 for all
// cores, the default; `--build-only`: one build and one position update on
// each side, untimed, for callgrind; `--eval-only [--reps K]`: each side built once, then the
// random points evaluated K times (1 by default: for callgrind), profsubd and Far alternated,
// also with --scale; `--cpu-time`: time in the thread's processor time instead of wall-clock; `--memory`: the heap a built evaluator holds on each side), or `bench_eval --scale [--scale-min D] [--scale-max E]
// [--scale-only FAMILY-PREFIX] [--scale-skip PARTS]`: build, position
// update, evaluation and refinement at 10^D..10^E faces (3 and 6 by default) on random and
// shape-derived meshes (scripts/plot_scale.py plots its rows), each side in its own child processes
// with its peak resident memory per stage (at 10^6 faces run it under `prlimit --as=BYTES`, so
// that an overrun fails a child instead of waking the out-of-memory killer).
//
// P1: 10^6 random (face, u, v) -> position + du + dv.
//     profsubd_evaluator_evaluate (one batch call) vs Bfr::Surface<double> with its cache
//     (points in random order, and grouped by face), vs Far::PatchTable + PatchMap.
//     Build times (evaluator, factory, adaptive refinement + patch table) reported apart.
//     Position update for the same topology: profsubd_evaluator_update_positions vs Far's
//     refinement + local-point stencils in one double-precision table
//     (StencilTableReal<double>::UpdateValues, the loop Osd::CpuEvaluator::EvalStencils runs;
//     Osd's evaluators take floats in 3.5), each ending with every patch point computed.
// Threads: the evaluator build, 10^6 points, a position update and the limit stencils at 1, 2
//     and all cores, beside Osd::OmpEvaluator (OpenMP) running EvalStencils (refinement +
//     local points) and EvalPatches (the same 10^6 points) at the same thread counts. Osd's
//     evaluators take float buffers and weights in 3.5: that side is single precision.
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
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/cpuPatchTable.h>
#include <opensubdiv/osd/ompEvaluator.h>
#include <opensubdiv/osd/types.h>

#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <thread>

using namespace OpenSubdiv;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

// The calling thread's processor time, seconds.
double thread_cpu() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// The process's processor time, all threads, seconds.
double process_cpu() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// --scale times single-threaded work in the thread's processor time, which a loaded shared
// machine disturbs far less than wall-clock time (waiting for a core is not counted).
bool use_thread_cpu = false;

// Best of `reps` runs of f (seconds).
double best(int reps, const std::function<void()> &f) {
    double b = 1e300;
    for (int r = 0; r < reps; ++r) {
        if (use_thread_cpu) {
            double t = thread_cpu();
            f();
            b = std::min(b, thread_cpu() - t);
            continue;
        }
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

// The shape refined once by Far, as a new OsdShape (creases and corners at level 1; with
// `keep_sharpness`, a crease keeps its parent's sharpness instead of the decayed one, so that
// the share of deeply refined faces does not fall with each refinement).
profsubd_test::OsdShape refine_once(const profsubd_test::OsdShape &s, bool keep_sharpness = false) {
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
            out.crease_sharpness.push_back(keep_sharpness ? sh + 1.0f : sh);
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

// --scale prints the resident memory after each step of Far's builds, so that a build that runs
// out of memory shows the step it reached.
bool print_far_steps = false;

void far_step(const char *what) {
    if (print_far_steps) {
        std::printf("  Far: %-40s RSS %9.1f MiB\n", what, rss_kb() / 1024.0);
        std::fflush(stdout);
    }
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
    far_step("build: adaptive refinement");
    table.reset(Far::PatchTableFactory::Create(*adaptive, po));
    far_step("build: PatchTable");
    pmap.reset(new Far::PatchMap(*table));
    int nref = adaptive->GetNumVerticesTotal();
    pp = profsubd_test::refine_points(*adaptive, shape.positions, table->GetNumLocalPoints());
    if (table->GetNumLocalPoints() > 0) table->ComputeLocalPointValues(pp.data(), pp.data() + nref);
    far_step("build: PatchMap, refined and local points");
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

// Far's counterpart of the batch evaluation: PatchMap lookup, basis, patch points.
void far_evaluate(const Far::PatchTable &table, const Far::PatchMap &pmap,
                  const std::vector<profsubd_test::FarPoint> &pp, const profsubd_test::FacePoints &pts, double *P,
                  double *DU, double *DV) {
    double wp[20], wu[20], wv[20];
    const size_t n = pts.faces.size();
    for (size_t i = 0; i < n; ++i) {
        const Far::PatchTable::PatchHandle *h = pmap.FindPatch(pts.faces[i], pts.us[i], pts.vs[i]);
        if (!h) continue;  // a hole
        table.EvaluateBasis(*h, pts.us[i], pts.vs[i], wp, wu, wv);
        auto cvs = table.GetPatchVertices(*h);
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
}

// Far's counterpart of profsubd_refine_uniform: TopologyRefiner + RefineUniform +
// PrimvarRefiner; returns the last refined point's x (a checksum) and the level's counts.
double far_refine(const profsubd_test::OsdShape &shape, int level, int counts[2]) {
    auto r = profsubd_test::build_refiner(shape);
    r->RefineUniform(Far::TopologyRefiner::UniformOptions(level));
    std::vector<profsubd_test::FarPoint> pts = profsubd_test::refine_points(*r, shape.positions);
    counts[0] = r->GetLevel(level).GetNumVertices();
    counts[1] = r->GetLevel(level).GetNumFaces();
    return pts.back().p[0];
}

// OpenSubdiv's multi-core path: Osd::OmpEvaluator over float buffers (Osd 3.5 evaluates in
// float only). One stencil table takes the control points to every refined and local point
// (Far's factorized refinement stencils with the PatchTable's local points appended), and
// EvalPatches evaluates patch coordinates found once through the PatchMap.
struct OsdOmp {
    std::unique_ptr<Far::TopologyRefiner> refiner;
    std::unique_ptr<Far::PatchTable> table;
    std::unique_ptr<Far::PatchMap> map;
    std::unique_ptr<const Far::StencilTable> stencils;
    std::unique_ptr<Osd::CpuPatchTable> cpu_table;
    std::vector<float> points;  // control points, then the stencils' points, 3 floats each
    std::vector<Osd::PatchCoord> coords;
    std::vector<float> p, du, dv;
    int ncoarse = 0;

    OsdOmp(const profsubd_test::OsdShape &shape, const profsubd_test::FacePoints &pts) {
        std::vector<profsubd_test::FarPoint> unused;  // Far's double points: Osd makes its own
        far_build(shape, refiner, table, map, unused);
        Far::StencilTableFactory::Options so;
        so.generateIntermediateLevels = true;
        std::unique_ptr<const Far::StencilTable> refined(Far::StencilTableFactory::Create(*refiner, so));
        const Far::StencilTable *local = table->GetLocalPointStencilTable();
        if (local && local->GetNumStencils() > 0)
            stencils.reset(Far::StencilTableFactory::AppendLocalPointStencilTable(*refiner, refined.get(), local));
        else
            stencils = std::move(refined);
        cpu_table.reset(Osd::CpuPatchTable::Create(table.get()));
        ncoarse = refiner->GetLevel(0).GetNumVertices();
        points.assign(3 * (ncoarse + stencils->GetNumStencils()), 0.0f);
        for (size_t i = 0; i < pts.faces.size(); ++i) {
            const Far::PatchTable::PatchHandle *h = map->FindPatch(pts.faces[i], pts.us[i], pts.vs[i]);
            if (h) coords.emplace_back(*h, (float)pts.us[i], (float)pts.vs[i]);
        }
        p.resize(3 * coords.size());
        du.resize(3 * coords.size());
        dv.resize(3 * coords.size());
    }

    // New control points (doubles, converted as Osd's users do) through every stencil.
    void update(const std::vector<double> &positions) {
        for (int i = 0; i < 3 * ncoarse; ++i) points[i] = (float)positions[i];
        Osd::BufferDescriptor src(0, 3, 3), dst(3 * ncoarse, 3, 3);
        Osd::OmpEvaluator::EvalStencils(points.data(), src, points.data(), dst, &stencils->GetSizes()[0],
                                        &stencils->GetOffsets()[0], &stencils->GetControlIndices()[0],
                                        &stencils->GetWeights()[0], 0, stencils->GetNumStencils());
    }

    void evaluate() {
        Osd::BufferDescriptor src(0, 3, 3), d(0, 3, 3);
        Osd::OmpEvaluator::EvalPatches(points.data(), src, p.data(), d, du.data(), d, dv.data(), d, (int)coords.size(),
                                       coords.data(), cpu_table->GetPatchArrayBuffer(),
                                       cpu_table->GetPatchIndexBuffer(), cpu_table->GetPatchParamBuffer());
    }
};

// A profsubd stencil table's rows as flat arrays (offsets, indices, weights' bits).
std::vector<uint64_t> table_words(const profsubd_stencil_table *t) {
    size_t rows = 0, nnz = 0, needed = 0;
    profsubd_stencil_table_num_rows(t, &rows);
    profsubd_stencil_table_num_entries(t, &nnz);
    std::vector<uint32_t> offsets(rows + 1), indices(nnz);
    std::vector<double> weights(nnz);
    profsubd_stencil_table_get_offsets(t, offsets.data(), offsets.size(), &needed);
    profsubd_stencil_table_get_indices(t, indices.data(), indices.size(), &needed);
    profsubd_stencil_table_get_weights(t, weights.data(), weights.size(), &needed);
    std::vector<uint64_t> out(offsets.begin(), offsets.end());
    out.insert(out.end(), indices.begin(), indices.end());
    for (double w : weights) {
        uint64_t b;
        std::memcpy(&b, &w, sizeof b);
        out.push_back(b);
    }
    return out;
}

// Heap bytes the process holds (glibc's mallinfo2 over all arenas: chunks in use plus
// mmapped blocks).
size_t heap_in_use() {
    struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

// Memory of a built evaluator on each side: heap held after the build less before it (one
// thread; profsubd_evaluator_new with its positions, Far's adaptive TopologyRefiner +
// PatchTable + PatchMap with the refined and local points' positions, as far_build).
void memory(const profsubd_test::OsdShape &shape, const profsubd_mesh *mesh, profsubd_options *opts) {
    profsubd_options_set_threads(opts, 1);
    size_t before = heap_in_use();
    profsubd_evaluator *ev = nullptr;
    if (profsubd_evaluator_new(mesh, opts, &ev) != PROFSUBD_OK)
        std::fprintf(stderr, "build: %s\n", profsubd_last_error_message());
    double ps = (double)(heap_in_use() - before);
    profsubd_evaluator_free(ev);
    before = heap_in_use();
    std::unique_ptr<Far::TopologyRefiner> adaptive;
    std::unique_ptr<Far::PatchTable> table;
    std::unique_ptr<Far::PatchMap> pmap;
    std::vector<profsubd_test::FarPoint> pp;
    far_build(shape, adaptive, table, pmap, pp);
    double far = (double)(heap_in_use() - before);
    adaptive.reset();
    double far_no_refiner = (double)(heap_in_use() - before);
    const double mib = 1.0 / (1024.0 * 1024.0);
    std::printf("\nMemory of a built evaluator (heap held after the build, mallinfo2, one thread)\n");
    std::printf("  profsubd evaluator:                                 %8.1f MiB\n", ps * mib);
    std::printf("  Far TopologyRefiner + PatchTable + PatchMap + points: %8.1f MiB (%.1f MiB without the refiner)\n",
                far * mib, far_no_refiner * mib);
    std::printf("  ratio profsubd/Far memory: %.3f (without the refiner: %.3f)   (target <= 1.0)\n", ps / far, ps / far_no_refiner);
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

// --eval-only: each side built once (untimed), then `reps` evaluations of the same `n` random
// points (seed 7, as the full run), profsubd and Far's PatchTable + PatchMap alternated so that
// a change in the machine's load hits both alike; prints every run and the best of each side.
// With reps = 1 it is the run to profile (`valgrind --tool=callgrind --cache-sim=yes
// --toggle-collect=profsubd_evaluator_evaluate` or `--toggle-collect='*far_evaluate*'`).
void eval_only(const profsubd_test::OsdShape &shape, const profsubd_mesh *mesh, profsubd_options *opts, int n,
               int reps) {
    profsubd_options_set_threads(opts, 1);
    profsubd_evaluator *ev = nullptr;
    if (profsubd_evaluator_new(mesh, opts, &ev) != PROFSUBD_OK) {
        std::fprintf(stderr, "build: %s\n", profsubd_last_error_message());
        return;
    }
    profsubd_evaluator_set_threads(ev, 1);
    std::unique_ptr<Far::TopologyRefiner> adaptive;
    std::unique_ptr<Far::PatchTable> table;
    std::unique_ptr<Far::PatchMap> pmap;
    std::vector<profsubd_test::FarPoint> pp;
    far_build(shape, adaptive, table, pmap, pp);
    profsubd_test::FacePoints pts = profsubd_test::random_face_points(n, shape.num_faces(), 7);
    std::vector<double> P(3 * n), DU(3 * n), DV(3 * n), Pfar(3 * n);
    double t_ps = 1e300, t_far = 1e300;
    for (int r = 0; r < reps; ++r) {
        double a = best(1, [&] {
            if (profsubd_evaluator_evaluate(ev, pts.faces.data(), pts.us.data(), pts.vs.data(), n, P.data(),
                                            DU.data(), DV.data()) != PROFSUBD_OK)
                std::fprintf(stderr, "evaluate: %s\n", profsubd_last_error_message());
        });
        double b = best(1, [&] { far_evaluate(*table, *pmap, pp, pts, Pfar.data(), DU.data(), DV.data()); });
        t_ps = std::min(t_ps, a);
        t_far = std::min(t_far, b);
        std::printf("eval-only run %d: profsubd %8.2f ms, Far %8.2f ms, ratio %.3f\n", r + 1, 1e3 * a, 1e3 * b, a / b);
    }
    double maxdiff = 0;
    for (int i = 0; i < 3 * n; ++i) maxdiff = std::max(maxdiff, std::fabs(P[i] - Pfar[i]));
    uint64_t hash = 1469598103934665603ull;  // FNV-1a over profsubd's result bits
    for (const std::vector<double> *a : {&P, &DU, &DV})
        for (double x : *a) {
            uint64_t b;
            std::memcpy(&b, &x, sizeof b);
            hash = (hash ^ b) * 1099511628211ull;
        }
    std::printf("eval-only: profsubd result bits hash %016llx\n", (unsigned long long)hash);
    std::printf("eval-only: %d faces, %d points, best profsubd %.2f ms (%.1f ns/point), Far %.2f ms (%.1f ns/point), "
                "ratio profsubd/Far PatchTable evaluate %.3f (target <= 0.67); max |profsubd - Far| %.3g (%s)\n",
                shape.num_faces(), n, 1e3 * t_ps, 1e9 * t_ps / n, 1e3 * t_far, 1e9 * t_far / n, t_ps / t_far, maxdiff,
                use_thread_cpu ? "thread processor time" : "wall-clock");
    profsubd_evaluator_free(ev);
}

// Uniform in [0, 1) from the top 53 bits of a 64-bit Mersenne twister (the engine's output is
// fixed by the standard; std::uniform_real_distribution's is not).
double uniform(std::mt19937_64 &rng) { return (rng() >> 11) * 0x1.0p-53; }

// A random quad-dominant closed manifold of about `target` faces: a torus of a x b quads
// (R = 3, r = 1) with every vertex moved by up to 0.3 of a cell in each direction, 2 % of the
// quads split into two triangles along a random diagonal (valence 5-6 extraordinary vertices
// at the diagonals' ends, and non-quads); with `creases`, 5 % of the rings around the tube
// and 3 % of the rings along it made semi-sharp creases of random sharpness in [0.5, 4) and
// 0.2 % of the other edges semi-sharp (sharpness 2: darts at their ends). Deterministic
// (std::mt19937_64 seeded with `seed`).
profsubd_test::OsdShape random_torus(int target, bool creases, uint64_t seed) {
    std::mt19937_64 rng(seed);
    const int a = std::max(8, (int)std::lround(std::sqrt(2.0 * target))), b = std::max(4, target / a);
    const double R = 3, r = 1, cell = 2 * M_PI / std::max(a, b);
    profsubd_test::OsdShape out;
    out.options = profsubd_test::profsubd_default_options();
    auto id = [&](int i, int j) { return ((i + a) % a) * b + (j + b) % b; };
    for (int i = 0; i < a; ++i)
        for (int j = 0; j < b; ++j) {
            double u = 2 * M_PI * i / a + 0.3 * cell * (2 * uniform(rng) - 1);
            double v = 2 * M_PI * j / b + 0.3 * cell * (2 * uniform(rng) - 1);
            double rr = r * (1 + 0.3 * cell * (2 * uniform(rng) - 1));
            out.positions.push_back((R + rr * std::cos(v)) * std::cos(u));
            out.positions.push_back((R + rr * std::cos(v)) * std::sin(u));
            out.positions.push_back(rr * std::sin(v));
        }
    for (int i = 0; i < a; ++i)
        for (int j = 0; j < b; ++j) {
            int q[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
            if (uniform(rng) < 0.02) {
                int k = uniform(rng) < 0.5 ? 0 : 1;  // diagonal q[k]-q[k+2]
                int t1[3] = {q[k], q[k + 1], q[k + 2]}, t2[3] = {q[k], q[k + 2], q[(k + 3) % 4]};
                for (int *t : {t1, t2}) {
                    out.face_sizes.push_back(3);
                    out.face_indices.insert(out.face_indices.end(), t, t + 3);
                }
            } else {
                out.face_sizes.push_back(4);
                out.face_indices.insert(out.face_indices.end(), q, q + 4);
            }
        }
    if (creases) {
        auto crease = [&](int v0, int v1, float sh) {
            out.crease_vertices.push_back(v0);
            out.crease_vertices.push_back(v1);
            out.crease_sharpness.push_back(sh);
        };
        std::vector<bool> ring_i(a), ring_j(b);
        for (int i = 0; i < a; ++i) ring_i[i] = uniform(rng) < 0.05;
        for (int j = 0; j < b; ++j) ring_j[j] = uniform(rng) < 0.03;
        for (int i = 0; i < a; ++i)
            if (ring_i[i]) {
                float sh = (float)(0.5 + 3.5 * uniform(rng));
                for (int j = 0; j < b; ++j) crease(id(i, j), id(i, j + 1), sh);
            }
        for (int j = 0; j < b; ++j)
            if (ring_j[j]) {
                float sh = (float)(0.5 + 3.5 * uniform(rng));
                for (int i = 0; i < a; ++i) crease(id(i, j), id(i + 1, j), sh);
            }
        for (int i = 0; i < a; ++i)
            for (int j = 0; j < b; ++j) {
                if (!ring_i[i] && uniform(rng) < 0.002) crease(id(i, j), id(i, j + 1), 2.0f);
                if (!ring_j[j] && uniform(rng) < 0.002) crease(id(i, j), id(i + 1, j), 2.0f);
            }
    }
    return out;
}

// Peak resident memory since the last reset_peak_rss() (VmHWM of /proc/self/status), MiB.
double peak_rss_mib() {
    FILE *f = std::fopen("/proc/self/status", "r");
    long kb = -1;
    char line[256];
    while (f && std::fgets(line, sizeof line, f))
        if (std::sscanf(line, "VmHWM: %ld kB", &kb) == 1) break;
    if (f) std::fclose(f);
    return kb / 1024.0;
}

// Starts a new peak (writing 5 to clear_refs resets VmHWM to the current resident size), after
// handing freed heap back to the system so that a stage's peak does not include the last one's.
void reset_peak_rss() {
    malloc_trim(0);
    FILE *f = std::fopen("/proc/self/clear_refs", "w");
    if (f) {
        std::fputs("5", f);
        std::fclose(f);
    }
}

// One side's --scale results: processor times (seconds) and the peak resident memory of each
// stage (MiB, whole process); NaN where the stage did not run or its process failed.
struct SideResult {
    double build = NAN, update = NAN, eval = NAN, refine = NAN;
    double mem_build = NAN, mem_update = NAN, mem_eval = NAN, mem_refine = NAN;
    double checksum = 0;

    // The stages `part` measured, taken over.
    void take(const SideResult &part) {
        double *to[] = {&build, &update, &eval, &refine, &mem_build, &mem_update, &mem_eval, &mem_refine};
        const double *from[] = {&part.build,     &part.update,     &part.eval,     &part.refine,
                                &part.mem_build, &part.mem_update, &part.mem_eval, &part.mem_refine};
        for (int i = 0; i < 8; ++i)
            if (!std::isnan(*from[i])) *to[i] = *from[i];
        checksum += part.checksum;
    }
};

// The peak of a stage, printed as it ends (a `mem` line: if a later stage runs out of memory,
// the last line says how far it got) and reset for the next one.
double stage_peak(const char *family, int faces, const char *side, const char *stage) {
    double peak = peak_rss_mib();
    std::printf("mem %-14s %9d %-8s %-8s peak RSS %9.1f MiB\n", family, faces, side, stage, peak);
    std::fflush(stdout);
    reset_peak_rss();
    return peak;
}

// The --scale parts not to run (--scale-skip: any of profsubd-evaluator, profsubd-refine,
// far-evaluator, far-update, far-refine, comma-separated), e.g. a side known not to fit in memory.
std::string scale_skip;

// Runs f in a child process and adds what it measured to `out`; false if the child failed
// (killed, or out of memory under `prlimit --as`). Each part of a --scale row runs in its own
// process, so that its peak memory is its own, all of it is returned before the next part
// starts, and a part that runs out of memory loses only its own figures.
bool in_child(const char *what, const std::function<SideResult()> &f, SideResult *out) {
    std::string name(what);
    if (scale_skip.find(name) != std::string::npos) {
        std::printf("skipped %s (--scale-skip)\n", what);
        return false;
    }
    std::fflush(stdout);
    int fd[2];
    if (pipe(fd) != 0) return false;
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        reset_peak_rss();
        SideResult r = f();
        bool ok = write(fd[1], &r, sizeof r) == (ssize_t)sizeof r;
        std::fflush(stdout);
        _exit(ok ? 0 : 1);
    }
    close(fd[1]);
    SideResult r;
    bool ok = pid > 0 && read(fd[0], &r, sizeof r) == (ssize_t)sizeof r;
    close(fd[0]);
    int status = 0;
    struct rusage ru = {};
    if (pid > 0) wait4(pid, &status, 0, &ru);
    ok = ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (ok)
        out->take(r);
    else if (pid > 0 && WIFSIGNALED(status))
        std::printf("failed %s: killed by signal %d at peak RSS %.1f MiB (the last mem line is the last stage it "
                    "finished)\n",
                    what, WTERMSIG(status), ru.ru_maxrss / 1024.0);
    else
        std::printf("failed %s (the last mem line is the last stage it finished)\n", what);
    return ok;
}

// Far's counterpart of a position update, level by level, as Osd's users apply it (and as
// osd_patches.cpp does): each adaptive level's stencils from the level before, then the
// PatchTable's local points from the refined ones, in double. The table factorized to the
// control points that the benchmark mesh uses (far_update_stencils) holds more weights: on the
// 101,647-face random creased torus this stage peaked at 3,004 MiB with it, 2,390 MiB without.
struct FarLevelUpdate {
    std::unique_ptr<Far::PatchTable> table;  // owns the local-point stencils
    std::unique_ptr<Far::StencilTableReal<double> const> refined;
    const Far::StencilTableReal<double> *local = nullptr;
    std::vector<int> level_sizes;  // refined vertices of levels 1, 2, ...
    int ncoarse = 0;
    std::vector<profsubd_test::FarPoint> points;  // control, each level's, local points

    explicit FarLevelUpdate(const profsubd_test::OsdShape &shape) {
        Far::PatchTableFactory::Options po;
        po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
        po.SetPatchPrecision<double>();
        auto r = profsubd_test::build_refiner(shape);
        r->RefineAdaptive(po.GetRefineAdaptiveOptions());
        far_step("update: adaptive refinement");
        table.reset(Far::PatchTableFactory::Create(*r, po));
        far_step("update: PatchTable (double)");
        Far::StencilTableFactoryReal<double>::Options so;
        so.generateOffsets = true;
        so.generateIntermediateLevels = true;
        so.factorizeIntermediateLevels = false;
        refined.reset(Far::StencilTableFactoryReal<double>::Create(*r, so));
        far_step("update: refinement stencils");
        local = table->GetLocalPointStencilTable<double>();
        ncoarse = r->GetLevel(0).GetNumVertices();
        for (int k = 1; k <= r->GetMaxLevel(); ++k) level_sizes.push_back(r->GetLevel(k).GetNumVertices());
        points.resize(ncoarse + refined->GetNumStencils() + (local ? local->GetNumStencils() : 0));
    }

    void update(const std::vector<double> &x) {
        for (int v = 0; v < ncoarse; ++v)
            for (int d = 0; d < 3; ++d) points[v].p[d] = x[3 * v + d];
        profsubd_test::FarPoint *out = points.data() + ncoarse;  // stencil i writes out[i]
        int first = 0, src = 0;
        for (int n : level_sizes) {
            refined->UpdateValues(points.data() + src, out, first, first + n);  // level k-1 from 0
            src = ncoarse + first;
            first += n;
        }
        if (local && local->GetNumStencils() > 0) local->UpdateValues(points.data(), out + first);
    }
};

// What one --scale row measures, shared by the parts that run in child processes.
struct ScaleCase {
    const char *family;
    const profsubd_test::OsdShape &shape;
    const profsubd_mesh *mesh;
    const profsubd_options *opts;  // one thread
    const profsubd_test::FacePoints &pts;
    const std::vector<double> &moved;  // the positions of the update
    int level, reps;
};

// profsubd's evaluator: build, update, evaluation.
SideResult profsubd_evaluator_part(const ScaleCase &c) {
    SideResult r;
    const int nf = c.shape.num_faces(), n = (int)c.pts.faces.size();
    std::vector<double> P(3 * n), DU(3 * n), DV(3 * n);
    profsubd_evaluator *ev = nullptr;
    r.build = best(c.reps, [&] {
        if (ev) profsubd_evaluator_free(ev);
        ev = nullptr;
        if (profsubd_evaluator_new(c.mesh, c.opts, &ev) != PROFSUBD_OK)
            std::fprintf(stderr, "build: %s\n", profsubd_last_error_message());
    });
    r.mem_build = stage_peak(c.family, nf, "profsubd", "build");
    if (!ev) std::exit(1);
    profsubd_evaluator_set_threads(ev, 1);
    r.update = best(c.reps, [&] { profsubd_evaluator_update_positions(ev, c.moved.data(), c.shape.num_vertices()); });
    r.mem_update = stage_peak(c.family, nf, "profsubd", "update");
    r.eval = best(c.reps, [&] {
        if (profsubd_evaluator_evaluate(ev, c.pts.faces.data(), c.pts.us.data(), c.pts.vs.data(), n, P.data(),
                                        DU.data(), DV.data()) != PROFSUBD_OK)
            std::fprintf(stderr, "evaluate: %s\n", profsubd_last_error_message());
    });
    r.mem_eval = stage_peak(c.family, nf, "profsubd", "evaluate");
    r.checksum = P[0];
    profsubd_evaluator_free(ev);
    return r;
}

// profsubd's uniform refinement.
SideResult profsubd_refine_part(const ScaleCase &c) {
    SideResult r;
    r.refine = best(c.reps, [&] {
        profsubd_mesh *out = nullptr;
        if (profsubd_refine_uniform(c.mesh, c.opts, c.level, &out) != PROFSUBD_OK)
            std::fprintf(stderr, "refine: %s\n", profsubd_last_error_message());
        profsubd_mesh_free(out);
    });
    r.mem_refine = stage_peak(c.family, c.shape.num_faces(), "profsubd", "refine");
    return r;
}

// Far's adaptive refinement + PatchTable + PatchMap with points, and evaluation through them.
SideResult far_evaluator_part(const ScaleCase &c) {
    SideResult r;
    const int nf = c.shape.num_faces(), n = (int)c.pts.faces.size();
    std::vector<double> P(3 * n), DU(3 * n), DV(3 * n);
    std::unique_ptr<Far::TopologyRefiner> adaptive;
    std::unique_ptr<Far::PatchTable> table;
    std::unique_ptr<Far::PatchMap> pmap;
    std::vector<profsubd_test::FarPoint> pp;
    r.build = best(c.reps, [&] { far_build(c.shape, adaptive, table, pmap, pp); });
    std::printf("far %-14s %9d adaptive refinement: %d levels, %d vertices; %d local points\n", c.family, nf,
                adaptive->GetMaxLevel() + 1, adaptive->GetNumVerticesTotal(), table->GetNumLocalPoints());
    r.mem_build = stage_peak(c.family, nf, "Far", "build");
    r.eval = best(c.reps, [&] { far_evaluate(*table, *pmap, pp, c.pts, P.data(), DU.data(), DV.data()); });
    r.mem_eval = stage_peak(c.family, nf, "Far", "evaluate");
    r.checksum = P[0];
    return r;
}

// Far's position update (its own adaptive refinement, PatchTable and level-by-level stencils).
SideResult far_update_part(const ScaleCase &c) {
    SideResult r;
    FarLevelUpdate far(c.shape);
    r.update = best(c.reps, [&] { far.update(c.moved); });
    r.mem_update = stage_peak(c.family, c.shape.num_faces(), "Far", "update");
    r.checksum = far.points.back().p[0];
    return r;
}

// Far's uniform refinement.
SideResult far_refine_part(const ScaleCase &c) {
    SideResult r;
    int counts[2];
    r.refine = best(c.reps, [&] { r.checksum += far_refine(c.shape, c.level, counts); });
    r.mem_refine = stage_peak(c.family, c.shape.num_faces(), "Far", "refine");
    return r;
}

// --scale: build, position update, evaluation of 2 x 10^5 random points and uniform refinement
// to level 1 on both sides, one thread each, at about 10^3 .. 10^max_exp faces, for four
// families: random tori with and without semi-sharp creases, and catmark_car refined by Far
// with its semi-sharp creases (kept at sharpness 5 at every level) and without them. Each
// side's evaluator, update (Far) and refinement run in child processes, with the peak memory
// of every stage (`mem` lines). One `row` line per mesh (scripts/plot_scale.py reads them),
// `nan` where a part failed. With `eval_reps` > 0 only the evaluation (`--eval-only`).
void scale(int min_exp, int max_exp, const std::string &only, int eval_reps) {
    use_thread_cpu = true;
    print_far_steps = true;
    profsubd_test::OsdShape car;
    std::string err;
    if (!profsubd_test::read_osd_shape(profsubd_test::osd_shapes_dir() + "/catmark_car.obj", &car, &err)) {
        std::fprintf(stderr, "bench_eval: %s\n", err.c_str());
        return;
    }
    auto runs = [&](const std::string &family) { return family.compare(0, only.size(), only) == 0; };
    // The car refined k times with its creases kept, for k = 0, 1, 3, 5 (1,575, 6,300,
    // 100,800, 1,612,800 quads): the sizes nearest the powers of ten (only if a car family runs).
    std::vector<profsubd_test::OsdShape> cars;
    for (int k = 0; (runs("car_creased") || runs("car_smooth")) && (int)cars.size() + 3 <= max_exp; ++k) {
        if (k == 0 || k == 1 || k == 3 || k == 5) cars.push_back(car);
        if (k == 5) break;
        car = refine_once(car, true);
    }
    const int N = 200000, level = 1;
    std::printf("scale: one thread each side, thread processor time; best of 3 below 10^4 faces, else one run; %d random points; "
                "refinement to level %d\n",
                N, level);
    std::printf("%-16s %9s | %9s %9s %6s | %8s %8s %6s | %8s %8s %6s | %8s %8s %6s | %7s %7s\n", "row family", "faces",
                "build ms", "Far ms", "ratio", "upd ms", "Far ms", "ratio", "eval ms", "Far ms", "ratio", "ref ms",
                "Far ms", "ratio", "us/f ps", "us/f Far");
    struct Case {
        std::string family;
        profsubd_test::OsdShape shape;
    };
    for (int e = std::max(3, min_exp); e <= max_exp; ++e) {
        std::vector<Case> cases;
        const int target = (int)std::lround(std::pow(10.0, e));
        cases.push_back({"random_creased", random_torus(target, true, 1000 + e)});
        cases.push_back({"random_smooth", random_torus(target, false, 1000 + e)});
        if (e - 3 < (int)cars.size()) {
            cases.push_back({"car_creased", cars[e - 3]});
            profsubd_test::OsdShape smooth = cars[e - 3];
            smooth.crease_vertices.clear();
            smooth.crease_sharpness.clear();
            cases.push_back({"car_smooth", smooth});
        }
        for (Case &k : cases) {
            if (!runs(k.family)) continue;
            const profsubd_test::OsdShape &shape = k.shape;
            const char *family = k.family.c_str();
            const int nf = shape.num_faces();
            profsubd_test::MeshPtr mesh = profsubd_test::new_mesh_capi(shape, &err);
            if (!mesh) {
                std::fprintf(stderr, "bench_eval: %s: %s\n", family, err.c_str());
                continue;
            }
            profsubd_options *opts = profsubd_test::capi_options(shape.options).release();
            profsubd_options_set_threads(opts, 1);
            if (eval_reps > 0) {
                std::printf("%s:\n", family);
                eval_only(shape, mesh.get(), opts, N, eval_reps);
                profsubd_options_free(opts);
                continue;
            }
            profsubd_test::FacePoints pts = profsubd_test::random_face_points(N, nf, 7);
            std::vector<double> moved(shape.positions.size());
            for (size_t i = 0; i < moved.size(); ++i) moved[i] = 1.01 * shape.positions[i] + 0.001 * (i % 7);
            const ScaleCase c{family, shape, mesh.get(), opts, pts, moved, level, nf >= 10000 ? 1 : 3};
            std::printf("mem %-14s %9d %-8s %-8s RSS %9.1f MiB (the mesh and points, before the children)\n", family,
                        nf, "both", "start", rss_kb() / 1024.0);
            SideResult ps, far;
            in_child("profsubd-evaluator", [&] { return profsubd_evaluator_part(c); }, &ps);
            in_child("profsubd-refine", [&] { return profsubd_refine_part(c); }, &ps);
            in_child("far-evaluator", [&] { return far_evaluator_part(c); }, &far);
            in_child("far-update", [&] { return far_update_part(c); }, &far);
            in_child("far-refine", [&] { return far_refine_part(c); }, &far);
            profsubd_options_free(opts);
            std::printf("row %-12s %9d | %9.1f %9.1f %6.2f | %8.2f %8.2f %6.2f | %8.1f %8.1f %6.2f | %8.1f %8.1f %6.2f | "
                        "%7.2f %7.2f\n",
                        family, nf, 1e3 * ps.build, 1e3 * far.build, ps.build / far.build, 1e3 * ps.update,
                        1e3 * far.update, ps.update / far.update, 1e3 * ps.eval, 1e3 * far.eval, ps.eval / far.eval,
                        1e3 * ps.refine, 1e3 * far.refine, ps.refine / far.refine, 1e6 * ps.build / nf,
                        1e6 * far.build / nf);
            std::printf("peak %-11s %9d | build %8.1f %8.1f | update %8.1f %8.1f | evaluate %8.1f %8.1f | refine %8.1f "
                        "%8.1f MiB (profsubd, Far)\n",
                        family, nf, ps.mem_build, far.mem_build, ps.mem_update, far.mem_update, ps.mem_eval,
                        far.mem_eval, ps.mem_refine, far.mem_refine);
            std::fflush(stdout);
            if (ps.checksum + far.checksum == 12345.678) std::printf("(checksum)\n");
        }
    }
    std::printf("columns: build = evaluator build vs Far adaptive refinement + PatchTable + PatchMap (with points);\n"
                "upd = position update vs Far refinement + local-point stencils applied level by level (double,\n"
                "UpdateValues; target <= 1.0); eval = %d random points vs PatchTable + PatchMap; ref = uniform\n"
                "refinement to level %d vs TopologyRefiner + PrimvarRefiner; us/f = build microseconds per face;\n"
                "peak = the stage's peak resident memory (VmHWM) of its child process, which starts as a copy of\n"
                "this one (the `start` RSS); nan = the part failed (its `failed` line)\n",
                N, level);
}

}  // namespace

int main(int argc, char **argv) {
    bool p2_only = false, build_only_mode = false, memory_only = false;
    int eval_reps = 0;
    size_t p2_threads = 0;
    int scale_max = 0, scale_min = 3;
    std::string scale_only;
    std::vector<std::string> paths;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--p2")
            p2_only = true;
        else if (std::string(argv[i]) == "--threads" && i + 1 < argc)
            p2_threads = std::strtoul(argv[++i], nullptr, 10);
        else if (std::string(argv[i]) == "--build-only")
            build_only_mode = true;
        else if (std::string(argv[i]) == "--memory")
            memory_only = true;
        else if (std::string(argv[i]) == "--cpu-time")
            use_thread_cpu = true;
        else if (std::string(argv[i]) == "--eval-only")
            eval_reps = std::max(eval_reps, 1);
        else if (std::string(argv[i]) == "--reps" && i + 1 < argc)
            eval_reps = std::max(1, std::atoi(argv[++i]));
        else if (std::string(argv[i]) == "--scale")
            scale_max = std::max(scale_max, 6);
        else if (std::string(argv[i]) == "--scale-max" && i + 1 < argc)
            scale_max = std::atoi(argv[++i]);
        else if (std::string(argv[i]) == "--scale-min" && i + 1 < argc)
            scale_min = std::atoi(argv[++i]);
        else if (std::string(argv[i]) == "--scale-only" && i + 1 < argc)
            scale_only = argv[++i];
        else if (std::string(argv[i]) == "--scale-skip" && i + 1 < argc)
            scale_skip = argv[++i];
        else
            paths.push_back(argv[i]);
    }
    if (scale_max > 0) {
        scale(scale_min, scale_max, scale_only, eval_reps);
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
    if (memory_only) {
        memory(shape, mesh.get(), opts);
        profsubd_options_free(opts);
        return 0;
    }
    if (eval_reps > 0) {
        eval_only(shape, mesh.get(), opts, 1000000, eval_reps);
        profsubd_options_free(opts);
        return 0;
    }
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
    // Alternated runs, so that a change in the machine's load hits both sides alike; the
    // process's processor time of profsubd's runs beside their wall time (all its threads).
    profsubd_options_set_threads(opts, p2_threads);
    double t_ref_ps = 1e300, t_ref_far = 1e300, cpu_ref_ps = 1e300;
    for (int rep = 0; rep < 7; ++rep) {
        double cpu = process_cpu();
        t_ref_ps = std::min(t_ref_ps, best(1, run_ps));
        cpu_ref_ps = std::min(cpu_ref_ps, process_cpu() - cpu);
        t_ref_far = std::min(t_ref_far, best(1, run_far));
    }
    double m_ps = peak_mib(run_ps);
    profsubd_options_set_threads(opts, 0);
    double m_far = peak_mib(run_far);
    std::printf("\nP2: uniform refinement to level %d, topology + positions (best of 7, alternated)\n", level);
    std::printf("  profsubd_refine_uniform:               %8.1f ms   peak +%.1f MiB   (threads %zu, "
                "0: all %u cores; processor %.1f ms)\n",
                1e3 * t_ref_ps, m_ps, p2_threads, std::thread::hardware_concurrency(), 1e3 * cpu_ref_ps);
    std::printf("  Far TopologyRefiner + PrimvarRefiner:  %8.1f ms   peak +%.1f MiB\n", 1e3 * t_ref_far, m_far);
    std::printf("  level %d: profsubd %zu vertices, %zu faces; Far %d vertices, %d faces\n", level, ps_counts[0],
                ps_counts[1], far_counts[0], far_counts[1]);
    std::printf("  ratio profsubd/Far: time %.3f   peak memory %.3f   (target: time <= 1.0)\n", t_ref_ps / t_ref_far, m_ps / m_far);
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
    double t_eval_far = best(3, [&] { far_evaluate(*table, *pmap, pp, points, P.data(), DU.data(), DV.data()); });
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
    std::printf("  ratio profsubd/Bfr (random order):   evaluate %.3f   build+evaluate %.3f   (target <= 0.67)\n", t_eval_ps / t_eval_bfr,
                (t_build_ps + t_eval_ps) / (t_build_bfr + t_eval_bfr));
    std::printf("  ratio profsubd/Bfr (grouped by face): evaluate %.3f\n", t_eval_ps / t_eval_bfr_grouped);
    std::printf("  ratio profsubd/Far PatchTable:       evaluate %.3f   build+evaluate %.3f   (target: evaluate <= 0.67)\n",
                t_eval_ps / t_eval_far, (t_build_ps + t_eval_ps) / (t_build_far + t_eval_far));
    std::printf("  ratio profsubd/Far build (one thread): %.3f   (target <= 1.0)\n", t_build_ps / t_build_far);
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
    std::printf("  ratio profsubd/OpenSubdiv position update: %.3f   (target <= 1.0)\n", t_update_ps / t_update_far);
    memory(shape, mesh.get(), opts);


    // --- Threads: profsubd at 1, 2 and all cores beside Osd::OmpEvaluator (float).
    std::vector<int> counts = {1, 2};
    const int hw = (int)std::thread::hardware_concurrency();
    if (hw > 2) counts.push_back(hw);
    OsdOmp omp(shape, points);
    std::printf("\nThreads (%d cores): profsubd (double) beside Osd::OmpEvaluator (OpenMP; Osd 3.5 evaluates in float "
                "only);\nbest of 3, speed-up over one thread in brackets, profsubd's results compared with one thread's\n",
                hw);
    std::printf("  %7s | %17s %17s %17s %17s | %17s %17s | %s\n", "threads", "build ms", "evaluate ms", "update ms",
                "limit stencils ms", "Osd EvalStencils", "Osd EvalPatches", "profsubd results");
    double base[6] = {0, 0, 0, 0, 0, 0};
    std::vector<double> P1, U1;
    std::vector<uint64_t> L1;
    const size_t probe = std::min<size_t>(N, 100000);  // points compared after an update
    for (int t : counts) {
        profsubd_options_set_threads(opts, t);
        double tb = best(3, build_ps);
        profsubd_evaluator_set_threads(ev, t);
        double te = best(3, eval_ps);
        std::vector<double> Pt(P.begin(), P.end());
        double tu = best(3, [&] { profsubd_evaluator_update_positions(ev, moved.data(), nv); });
        profsubd_evaluator_evaluate(ev, faces.data(), us.data(), vs.data(), probe, P.data(), DU.data(), DV.data());
        std::vector<double> Ut(P.begin(), P.begin() + 3 * probe);
        profsubd_stencil_table *lt = nullptr;
        double tl = best(3, [&] {
            profsubd_stencil_table_free(lt);
            lt = nullptr;
            if (profsubd_limit_stencils_new(mesh.get(), opts, PROFSUBD_LIMIT_POSITION, &lt) != PROFSUBD_OK)
                std::fprintf(stderr, "limit stencils: %s\n", profsubd_last_error_message());
        });
        std::vector<uint64_t> Lt = table_words(lt);
        profsubd_stencil_table_free(lt);
        Osd::OmpEvaluator::SetNumThreads(t);
        double to_s = best(3, [&] { omp.update(moved); });
        double to_p = best(3, [&] { omp.evaluate(); });
        bool same = true;
        if (t == 1) {
            P1 = Pt;
            U1 = Ut;
            L1 = Lt;
            double v[6] = {tb, te, tu, tl, to_s, to_p};
            std::copy(v, v + 6, base);
        } else {
            same = std::memcmp(P1.data(), Pt.data(), P1.size() * sizeof(double)) == 0 &&
                   std::memcmp(U1.data(), Ut.data(), U1.size() * sizeof(double)) == 0 && L1 == Lt;
        }
        std::printf("  %7d | %8.1f (%5.2fx) %8.1f (%5.2fx) %8.2f (%5.2fx) %8.2f (%5.2fx) | %8.2f (%5.2fx) %8.1f (%5.2fx) | "
                    "%s\n",
                    t, 1e3 * tb, base[0] / tb, 1e3 * te, base[1] / te, 1e3 * tu, base[2] / tu, 1e3 * tl, base[3] / tl,
                    1e3 * to_s, base[4] / to_s, 1e3 * to_p, base[5] / to_p,
                    t == 1 ? "(reference)" : same ? "bit-identical" : "DIFFERENT");
        std::fflush(stdout);
    }
    std::printf("  (%zu Osd patch coordinates; %d Osd stencils; profsubd update checked on %zu points)\n",
                omp.coords.size(), omp.stencils->GetNumStencils(), probe);
    checksum += omp.p[0];
    std::printf("(checksum %g)\n", checksum);

    profsubd_evaluator_free(ev);
    profsubd_options_free(opts);
    return 0;
}
