/*
 * profsubd from plain C99: the main job through the C API. Two silhouettes of a vase-like
 * body with a sharp shoulder become an interpolating Catmull-Clark mesh with a crease ring;
 * the example checks the fit, reads the data points and writes the mesh as OBJ.
 *
 *   profile_example [OUT.obj]      (default: profile.obj in the current directory)
 *
 * Exit code 0 when every step gives the expected answer.
 */
#include <profsubd.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int report(const char *call, profsubd_status status) {
    fprintf(stderr, "%s failed: %s: %s\n", call, profsubd_status_string((int32_t)status),
            profsubd_last_error_message());
    return 1;
}

#define CHECK(call)                         \
    do {                                    \
        profsubd_status st_ = (call);       \
        if (st_ != PROFSUBD_OK) {           \
            return report(#call, st_);      \
        }                                   \
    } while (0)

int main(int argc, char **argv) {
    /* (x, z) of the +x silhouette and (y, z) of the +y one, bottom to top; the -x and -y
     * silhouettes are their mirror images. Both start and end on the axis: closed body. */
    static const double c1[] = {0, 0, 1.0, 0.1, 1.4, 1.0, 1.3, 2.0, 0.5, 2.6, 0.45, 3.2, 0, 3.3};
    static const double c2[] = {0, 0, 0.7, 0.1, 1.0, 1.0, 0.9, 2.0, 0.5, 2.6, 0.45, 3.2, 0, 3.3};
    const char *path = argc > 1 ? argv[1] : "profile.obj";
    profsubd_profile_curves curves;
    profsubd_options *options = NULL;
    profsubd_fitted *model = NULL;
    profsubd_mesh *mesh = NULL;
    profsubd_mesh_report rep;
    size_t nv = 0, ncreases = 0, needed = 0;
    double residual = 0, tolerance = 0, *targets = NULL;
    int failed = 0;

    memset(&curves, 0, sizeof curves);
    curves.struct_size = sizeof curves;
    curves.c1 = c1;
    curves.c1_points = sizeof c1 / sizeof c1[0] / 2;
    curves.c2 = c2;
    curves.c2_points = sizeof c2 / sizeof c2[0] / 2;

    CHECK(profsubd_options_new(&options));
    CHECK(profsubd_options_set_samples(options, 16, 16));
    CHECK(profsubd_options_set_sharp_angle(options, 30.0));
    /* A bad setting is refused with a message, and the setting stays as it was. */
    if (profsubd_options_set_sharp_angle(options, 190.0) != PROFSUBD_ERROR_INVALID_ARGUMENT) {
        fprintf(stderr, "a sharp angle of 190 degrees was accepted\n");
        return 1;
    }
    printf("refused as expected: %s\n", profsubd_last_error_message());

    CHECK(profsubd_profile_build(&curves, options, &model));
    CHECK(profsubd_fitted_get_fit_residual(model, &residual, &tolerance));
    CHECK(profsubd_fitted_get_mesh(model, &mesh));
    CHECK(profsubd_mesh_num_vertices(mesh, &nv));
    CHECK(profsubd_mesh_num_creases(mesh, &ncreases));
    memset(&rep, 0, sizeof rep);
    rep.struct_size = sizeof rep;
    CHECK(profsubd_mesh_check(mesh, &rep));

    /* The data points: ask for the size, then copy. */
    if (profsubd_fitted_get_targets(model, NULL, 0, &needed) != PROFSUBD_ERROR_BUFFER_TOO_SMALL ||
        needed != 3 * nv) {
        fprintf(stderr, "targets size query gave %lu for %lu vertices\n", (unsigned long)needed,
                (unsigned long)nv);
        return 1;
    }
    targets = (double *)malloc(needed * sizeof *targets);
    if (targets == NULL) {
        return 1;
    }
    CHECK(profsubd_fitted_get_targets(model, targets, needed, &needed));

    printf("%lu vertices, %lu faces, %lu creases, Euler characteristic %lld, %lu boundary edges, "
           "fit residual %.3g (tolerance %.3g)\n",
           (unsigned long)nv, (unsigned long)rep.num_faces, (unsigned long)ncreases,
           (long long)rep.euler_characteristic, (unsigned long)rep.num_boundary_edges, residual,
           tolerance);
    printf("vertex 0 interpolates (%.6f, %.6f, %.6f)\n", targets[0], targets[1], targets[2]);
    if (!(residual <= tolerance) || rep.euler_characteristic != 2 || rep.num_boundary_edges != 0 ||
        !rep.is_manifold || !rep.is_consistently_oriented || ncreases == 0) {
        fprintf(stderr, "unexpected model\n");
        failed = 1;
    }
    if (!failed) {
        profsubd_status st = profsubd_mesh_write_obj(mesh, path);
        if (st != PROFSUBD_OK) {
            failed = report("profsubd_mesh_write_obj", st);
        } else {
            printf("wrote %s\n", path);
        }
    }
    free(targets);
    profsubd_mesh_free(mesh);
    profsubd_fitted_free(model);
    profsubd_options_free(options);
    return failed;
}
