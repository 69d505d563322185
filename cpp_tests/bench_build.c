/* Benchmark of the evaluator's construction alone: processor time of profsubd_evaluator_new
 * (best of 7) for each OBJ given, under uniform and under Chaikin creasing (default boundary
 * rule, edge-and-corner; tags other than creases, corners and holes are not consulted). Processor time rather than wall time: on a shared, loaded machine it moves less.
 * Built by cmake, not run by ctest:
 *   cmake --build build --target bench_build && build/cpp_tests/bench_build MESH.obj...
 */
#include <profsubd.h>

#include <stdio.h>
#include <time.h>

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: bench_build MESH.obj...\n");
        return 2;
    }
    for (int i = 1; i < argc; ++i) {
        profsubd_mesh *mesh = NULL;
        if (profsubd_mesh_read_obj(argv[i], &mesh) != PROFSUBD_OK) {
            fprintf(stderr, "%s: %s\n", argv[i], profsubd_last_error_message());
            return 1;
        }
        for (int chaikin = 0; chaikin < 2; ++chaikin) {
            profsubd_options *options = NULL;
            if (profsubd_options_new(&options) != PROFSUBD_OK ||
                profsubd_options_set_crease_method(
                    options, chaikin ? PROFSUBD_CREASE_CHAIKIN : PROFSUBD_CREASE_UNIFORM) != PROFSUBD_OK) {
                fprintf(stderr, "%s: %s\n", argv[i], profsubd_last_error_message());
                return 1;
            }
            double best = 1e300;
            for (int run = 0; run < 7; ++run) {
                profsubd_evaluator *ev = NULL;
                clock_t start = clock();
                if (profsubd_evaluator_new(mesh, options, &ev) != PROFSUBD_OK) {
                    fprintf(stderr, "%s: %s\n", argv[i], profsubd_last_error_message());
                    return 1;
                }
                double t = (double)(clock() - start) / CLOCKS_PER_SEC;
                best = t < best ? t : best;
                profsubd_evaluator_free(ev);
            }
            printf("%s %s: build %.1f ms\n", argv[i], chaikin ? "chaikin" : "uniform", 1e3 * best);
            profsubd_options_free(options);
        }
        profsubd_mesh_free(mesh);
    }
    return 0;
}
