/* 16 threads share one mesh, one options object and one evaluator (all read-only after
 * set-up) and at once evaluate, refine and construct (a revolution through the same options);
 * every result must be bit-identical to the same work done on one thread first. Run plain,
 * under valgrind's helgrind (data races; ctest `threads_helgrind`) and under
 * AddressSanitizer (-DPROFSUBD_SANITIZE=ON). Only the C API (include/profsubd.h). */
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "profsubd.h"

#define THREADS 16
#define POINTS 64
#define ROUNDS 10

static void fail(const char *what, enum profsubd_status s) {
    fprintf(stderr, "FAIL: %s: status %d: %s\n", what, (int)s, profsubd_last_error_message());
    exit(1);
}

#define CHECK(call)                                       \
    do {                                                  \
        enum profsubd_status s_ = (call);                 \
        if (s_ != PROFSUBD_OK) fail(#call, s_);           \
    } while (0)

/* What one round of work produces: evaluated points and derivatives, the refined mesh's
 * positions, and the constructed revolution's positions. */
typedef struct {
    double eval[3 * 3 * POINTS];
    double *refined;
    size_t refined_len;
    double *revolved;
    size_t revolved_len;
} result;

static const struct profsubd_mesh *g_mesh;
static const struct profsubd_options *g_options;
static const struct profsubd_evaluator *g_evaluator;
static uint32_t g_faces[POINTS];
static double g_u[POINTS], g_v[POINTS];

static double *positions_of(const struct profsubd_mesh *mesh, size_t *len) {
    size_t needed = 0, nv = 0;
    CHECK(profsubd_mesh_num_vertices(mesh, &nv));
    double *p = malloc(3 * nv * sizeof(double) + 1);
    CHECK(profsubd_mesh_get_positions(mesh, p, 3 * nv, &needed));
    *len = 3 * nv;
    return p;
}

static void work(result *r) {
    CHECK(profsubd_evaluator_evaluate(g_evaluator, g_faces, g_u, g_v, POINTS, r->eval,
                                      r->eval + 3 * POINTS, r->eval + 6 * POINTS));
    struct profsubd_mesh *refined = NULL;
    CHECK(profsubd_refine_uniform(g_mesh, g_options, 2, &refined));
    r->refined = positions_of(refined, &r->refined_len);
    profsubd_mesh_free(refined);
    /* A small vase profile (r, z), revolved under the shared options. */
    static const double profile[] = {0.0, 0.0, 0.6, 0.0, 0.8, 0.5, 0.4, 1.2, 0.5, 1.6};
    struct profsubd_fitted *swept = NULL;
    struct profsubd_mesh *mesh = NULL;
    CHECK(profsubd_revolve(profile, 5, g_options, &swept));
    CHECK(profsubd_fitted_get_mesh(swept, &mesh));
    r->revolved = positions_of(mesh, &r->revolved_len);
    profsubd_mesh_free(mesh);
    profsubd_fitted_free(swept);
}

static void *thread_main(void *arg) {
    result *r = arg;
    /* Several rounds, so the threads overlap whatever their start order. */
    for (int round = 0; round < ROUNDS; round++) {
        free(r->refined);
        free(r->revolved);
        work(r);
    }
    return NULL;
}

static int same(const double *a, const double *b, size_t n) {
    return memcmp(a, b, n * sizeof(double)) == 0;
}

int main(void) {
    /* A cube with a semi-sharp crease, a corner and an infinitely sharp edge. */
    static const double pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    static const uint32_t sizes[] = {4, 4, 4, 4, 4, 4};
    static const uint32_t idx[] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                                   1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    static const uint32_t creases[] = {4, 5, 0, 4};
    static const float sharp[] = {1.5f, 10.0f};
    static const uint32_t corners[] = {2};
    static const float corner_sharp[] = {3.0f};
    struct profsubd_mesh_desc d;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.positions = pos;
    d.num_vertices = 8;
    d.face_sizes = sizes;
    d.num_faces = 6;
    d.face_indices = idx;
    d.num_face_indices = 24;
    d.crease_vertices = creases;
    d.crease_sharpness = sharp;
    d.num_creases = 2;
    d.corner_vertices = corners;
    d.corner_sharpness = corner_sharp;
    d.num_corners = 1;
    struct profsubd_mesh *mesh = NULL;
    struct profsubd_options *options = NULL;
    struct profsubd_evaluator *evaluator = NULL;
    CHECK(profsubd_mesh_new(&d, &mesh));
    CHECK(profsubd_options_new(&options));
    CHECK(profsubd_options_set_samples(options, 16, 32));
    CHECK(profsubd_evaluator_new(mesh, options, &evaluator));
    g_mesh = mesh;
    g_options = options;
    g_evaluator = evaluator;
    for (int i = 0; i < POINTS; i++) {
        g_faces[i] = (uint32_t)(i % 6);
        g_u[i] = (double)((i * 37) % 64) / 63.0;
        g_v[i] = (double)((i * 11) % 64) / 63.0;
    }

    result reference;
    memset(&reference, 0, sizeof reference);
    work(&reference);

    static result results[THREADS];
    pthread_t threads[THREADS];
    for (int t = 0; t < THREADS; t++) {
        if (pthread_create(&threads[t], NULL, thread_main, &results[t]) != 0) {
            fprintf(stderr, "FAIL: pthread_create\n");
            return 1;
        }
    }
    for (int t = 0; t < THREADS; t++) pthread_join(threads[t], NULL);

    int bad = 0;
    for (int t = 0; t < THREADS; t++) {
        result *r = &results[t];
        if (!same(r->eval, reference.eval, 9 * POINTS) ||
            r->refined_len != reference.refined_len ||
            !same(r->refined, reference.refined, r->refined_len) ||
            r->revolved_len != reference.revolved_len ||
            !same(r->revolved, reference.revolved, r->revolved_len)) {
            fprintf(stderr, "FAIL: thread %d differs from the single-threaded run\n", t);
            bad = 1;
        }
        free(r->refined);
        free(r->revolved);
    }
    free(reference.refined);
    free(reference.revolved);
    profsubd_evaluator_free(evaluator);
    profsubd_options_free(options);
    profsubd_mesh_free(mesh);
    if (bad) return 1;
    printf("threads: %d threads x %d rounds (evaluate %d points, refine level 2 = %zu coordinates, "
           "revolve = %zu coordinates) bit-identical to one thread\n",
           THREADS, ROUNDS, POINTS, reference.refined_len, reference.revolved_len);
    return 0;
}
