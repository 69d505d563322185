// Benchmark: the whole profile pipeline (curves -> data points -> cage -> exact limit
// stencils -> sparse LU fit) at 128 x 64 samples through the C API, against OpenSubdiv
// building the limit stencil table of the same mesh (Far::TopologyRefiner from the mesh,
// RefineAdaptive, LimitStencilTableFactoryReal<double> at every control vertex), in the same
// run. Prints both times (best of 3) and their ratio, the pipeline on one thread and on all
// cores (and checks that both fit the same control points, bit for bit), and checks that
// OpenSubdiv's stencils applied to the fitted control points reproduce the targets.
//
//   ctest -R bench_profile -V        (or run the bench_profile executable)
//
// `bench_profile --once`: one pipeline on one thread and one table per isolation level, for
// instruction counts (docs/perf/pipeline.md):
//   taskset -c 0 valgrind --tool=callgrind --toggle-collect=profsubd_profile_build
//     --toggle-collect='*osd_limit_table*' build/cpp_tests/bench_profile --once
#include "capi_mesh.h"
#include "osd_shape.h"
#include "test_support.h"

#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyLevel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <sstream>
#include <thread>

using namespace profsubd_test;
using namespace OpenSubdiv;
using Clock = std::chrono::steady_clock;
using LimitTable = Far::LimitStencilTableReal<double>;
using LimitFactory = Far::LimitStencilTableFactoryReal<double>;

namespace {

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The calling thread's processor time, seconds: on a loaded shared machine it leaves out the
// time spent waiting for a core, so single-threaded work compares far more repeatably.
double thread_cpu() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// OpenSubdiv's limit stencil table at every control vertex (corner of its first face),
// including building the refiner and its adaptive refinement. Not inlined, and one function
// per isolation level, so that callgrind counts each alone
// (`--toggle-collect='*osd_limit_table*'`, then callgrind_annotate's inclusive counts).
template <int isolation>
__attribute__((noinline)) std::unique_ptr<const LimitTable> osd_limit_table(const OsdShape &shape) {
    static const double corner_s[4] = {0, 1, 1, 0}, corner_t[4] = {0, 0, 1, 1};
    std::unique_ptr<Far::TopologyRefiner> refiner = build_refiner(shape);
    Far::TopologyRefiner::AdaptiveOptions adaptive(isolation);
    adaptive.useInfSharpPatch = true;  // exact infinitely sharp crease patches
    refiner->RefineAdaptive(adaptive);
    const Far::TopologyLevel &level = refiner->GetLevel(0);
    LimitFactory::LocationArrayVec locations;
    for (int v = 0; v < level.GetNumVertices(); ++v) {
        int f = level.GetVertexFaces(v)[0];
        Far::ConstIndexArray fv = level.GetFaceVertices(f);
        int c = static_cast<int>(std::find(fv.begin(), fv.end(), v) - fv.begin());
        LimitFactory::LocationArray a;
        a.ptexIdx = f;  // all quads: the ptex face is the face
        a.numLocations = 1;
        a.s = &corner_s[c];
        a.t = &corner_t[c];
        locations.push_back(a);
    }
    return std::unique_ptr<const LimitTable>(LimitFactory::Create(*refiner, locations));
}

}  // namespace

int main(int argc, char **argv) {
    Checker ck("bench_profile");
    const bool once = argc > 1 && std::strcmp(argv[1], "--once") == 0;
    const int reps = once ? 1 : 3;
    // The bundled bottle's silhouettes (examples/profiles/bottle.json) at 128 x 64.
    static const double c1[] = {0, 0, 1.2, 0, 1.25, 1.5, 1.2, 3.0, 0.45, 3.6, 0.4, 4.4, 0.45, 4.6, 0, 4.6};
    static const double c2[] = {0, 0, 0.8, 0, 0.85, 1.5, 0.8, 3.0, 0.45, 3.6, 0.4, 4.4, 0.45, 4.6, 0, 4.6};
    profsubd_profile_curves curves{};
    curves.struct_size = sizeof curves;
    curves.c1 = c1;
    curves.c1_points = sizeof c1 / sizeof c1[0] / 2;
    curves.c2 = c2;
    curves.c2_points = sizeof c2 / sizeof c2[0] / 2;
    profsubd_options *raw = nullptr;
    profsubd_options_new(&raw);
    OptionsPtr options(raw);
    profsubd_options_set_samples(raw, 64, 128);

    // Best of 3 on `threads` threads (0: all cores); the last model is kept in `model`.
    profsubd_fitted *model = nullptr;
    double cpu_one = 1e300;  // processor time of the one-thread pipeline
    auto pipeline = [&](size_t threads) {
        profsubd_options_set_threads(raw, threads);
        double t = 1e300;
        for (int rep = 0; rep < reps; ++rep) {
            profsubd_fitted_free(model);
            model = nullptr;
            Clock::time_point t0 = Clock::now();
            const double c0 = thread_cpu();
            profsubd_status st = profsubd_profile_build(&curves, raw, &model);
            t = std::min(t, seconds_since(t0));
            if (threads == 1) cpu_one = std::min(cpu_one, thread_cpu() - c0);
            if (!ck.check(st == PROFSUBD_OK, "profsubd_profile_build: " + describe_status(st))) {
                return -1.0;
            }
        }
        return t;
    };
    const double t_one = pipeline(1);
    std::vector<double> one_thread;
    if (model) {
        profsubd_mesh *m1 = nullptr;
        profsubd_fitted_get_mesh(model, &m1);
        MeshPtr owned1(m1);
        size_t nv = 0;
        profsubd_mesh_num_vertices(m1, &nv);
        one_thread.resize(3 * nv);
        size_t needed = 0;
        profsubd_mesh_get_positions(m1, one_thread.data(), one_thread.size(), &needed);
    }
    const double t_profsubd = once ? t_one : pipeline(0);
    if (!model) {
        return ck.finish();
    }
    profsubd_mesh *mesh = nullptr;
    profsubd_fitted_get_mesh(model, &mesh);
    MeshPtr owned(mesh);
    size_t needed = 0;
    profsubd_fitted_get_targets(model, nullptr, 0, &needed);
    std::vector<double> targets(needed);
    profsubd_fitted_get_targets(model, targets.data(), needed, &needed);
    profsubd_fitted_free(model);
    CapiMesh capi;
    std::string err = read_capi_mesh(mesh, &capi);
    if (!ck.check(err.empty(), "read back: " + err)) {
        return ck.finish();
    }
    OsdShape shape = to_osd_shape(capi, profsubd_default_options());
    // (With --once both are the one-thread fit: nothing to compare.)
    ck.check(once || (one_thread.size() == capi.positions.size() &&
                      std::memcmp(one_thread.data(), capi.positions.data(),
                                  one_thread.size() * sizeof(double)) == 0),
             "the fit on all cores is the fit on one thread, bit for bit");
    {
        std::ostringstream s;
        s << "profsubd whole pipeline on one thread " << t_one * 1e3 << " ms, on all cores (" 
          << std::thread::hardware_concurrency() << ") " << t_profsubd * 1e3 << " ms: speed-up "
          << t_one / t_profsubd;
        ck.note(s.str());
    }

    for (int isolation : {4, 10}) {
        double t_osd = 1e300, cpu_osd = 1e300;
        std::unique_ptr<const LimitTable> table;
        for (int rep = 0; rep < reps; ++rep) {
            Clock::time_point t0 = Clock::now();
            const double c0 = thread_cpu();
            table = isolation == 4 ? osd_limit_table<4>(shape) : osd_limit_table<10>(shape);
            t_osd = std::min(t_osd, seconds_since(t0));
            cpu_osd = std::min(cpu_osd, thread_cpu() - c0);
        }
        // OpenSubdiv's stencils on the fitted points reproduce the targets (darts aside,
        // where its limit mask is approximate: allow 1e-6 there, report the worst).
        double worst = 0;
        for (int v = 0; v < table->GetNumStencils(); ++v) {
            auto s = table->GetLimitStencil(v);
            double p[3] = {0, 0, 0};
            for (int k = 0; k < s.GetSize(); ++k) {
                for (int d = 0; d < 3; ++d) {
                    p[d] += s.GetWeights()[k] * capi.positions[3 * s.GetVertexIndices()[k] + d];
                }
            }
            double e = 0;
            for (int d = 0; d < 3; ++d) {
                e = std::max(e, std::fabs(p[d] - targets[3 * v + d]));
            }
            worst = std::max(worst, e);
        }
        std::ostringstream s;
        s << "128x64 bottle (" << capi.num_vertices << " vertices): profsubd whole pipeline "
          << t_profsubd * 1e3 << " ms (one thread " << t_one * 1e3
          << " ms); OpenSubdiv limit stencil table (isolation " << isolation << ") " << t_osd * 1e3
          << " ms; ratio profsubd/OpenSubdiv " << t_profsubd / t_osd << " (one thread "
          << t_one / t_osd << "); processor time, one thread: " << cpu_one * 1e3 << " vs "
          << cpu_osd * 1e3 << " ms, ratio " << cpu_one / cpu_osd << " (target <= 1.0)"
          << "; OpenSubdiv stencils vs targets max " << worst;
        ck.note(s.str());
        ck.check(worst < 1e-6, "OpenSubdiv's limit stencils reproduce the targets");
    }
    return ck.finish();
}
