/* Progress, cancellation and the memory budget through the C API (include/profsubd.h only):
 * a revolution (its fit), an evaluator build, a uniform refinement and a fold check
 * (`profsubd_check_folds_with_options`), each
 *  - run to the end: the callback sees 0 first, 1 last, non-decreasing fractions;
 *  - cancelled at the first callback and at 50 %: PROFSUBD_ERROR_CANCELLED, a message, the
 *    output pointer untouched;
 *  - under a 1 KiB memory budget: PROFSUBD_ERROR_LIMIT_EXCEEDED before any callback past 0.
 * Run plain, under valgrind (`cancel_valgrind`: nothing leaked by a cancelled call) and
 * under AddressSanitizer. With the argument `--latency` it instead measures, on larger
 * work, the time from the callback's non-zero return to the call's return (printed, not
 * asserted). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "profsubd.h"

static int failures = 0;

#define EXPECT(cond, ...)                                  \
    do {                                                   \
        if (!(cond)) {                                     \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__); \
            fprintf(stderr, __VA_ARGS__);                  \
            fprintf(stderr, "\n");                         \
            failures++;                                    \
        }                                                  \
    } while (0)

#define CHECK(call)                                                                     \
    do {                                                                                \
        enum profsubd_status s_ = (call);                                               \
        if (s_ != PROFSUBD_OK) {                                                        \
            fprintf(stderr, "FAIL: %s: %d: %s\n", #call, (int)s_,                        \
                    profsubd_last_error_message());                                     \
            exit(1);                                                                    \
        }                                                                               \
    } while (0)

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* What the callback records, and when it cancels. */
typedef struct {
    double cancel_at; /* cancel at the first fraction >= this (> 1: never) */
    int calls;
    double first, last, cancelled_fraction;
    int decreasing;
    double cancelled_time;
    double last_time, max_gap; /* the longest wait between two calls (or from the start) */
} probe;

static int progress(double fraction, void *user) {
    probe *p = user;
    double t = now();
    if (p->last_time > 0 && t - p->last_time > p->max_gap) p->max_gap = t - p->last_time;
    p->last_time = t;
    if (p->calls == 0) p->first = fraction;
    if (p->calls > 0 && fraction < p->last) p->decreasing = 1;
    p->last = fraction;
    p->calls++;
    if (fraction >= p->cancel_at) {
        p->cancelled_fraction = fraction;
        p->cancelled_time = now();
        return 1;
    }
    return 0;
}

static const double profile[] = {0.0, 0.0, 0.6, 0.0, 0.8, 0.5, 0.4, 1.2, 0.5, 1.6};

/* The three kinds of work, each writing one handle through `out`; the latency run adds a
 * partial turn (270 degrees, the profile without its axis point), whose build ends with the
 * fold check. */
typedef enum { REVOLVE, EVALUATOR, REFINE, REVOLVE_PARTIAL, FOLDS } kind;
static const char *names[] = {"revolve", "evaluator", "refine", "revolve 270", "fold check"};

static const struct profsubd_mesh *g_mesh;
static const struct profsubd_evaluator *g_ev; /* of g_mesh, for the fold check */
static uint32_t g_level = 3;

static enum profsubd_status run(kind k, const struct profsubd_options *o, void **out) {
    switch (k) {
    case REVOLVE:
        return profsubd_revolve(profile, 5, o, (struct profsubd_fitted **)out);
    case REVOLVE_PARTIAL:
        return profsubd_revolve(profile + 2, 4, o, (struct profsubd_fitted **)out);
    case EVALUATOR:
        return profsubd_evaluator_new(g_mesh, o, (struct profsubd_evaluator **)out);
    case FOLDS:
        return profsubd_check_folds_with_options(g_ev, NULL, o, (struct profsubd_fold_report **)out);
    default:
        return profsubd_refine_uniform(g_mesh, o, g_level, (struct profsubd_mesh **)out);
    }
}

static void release(kind k, void *h) {
    switch (k) {
    case REVOLVE:
    case REVOLVE_PARTIAL: profsubd_fitted_free(h); break;
    case EVALUATOR: profsubd_evaluator_free(h); break;
    case FOLDS: profsubd_fold_report_free(h); break;
    default: profsubd_mesh_free(h); break;
    }
}

/* Run `k` with a callback cancelling at `cancel_at`; return the status, fill `p`. */
static enum profsubd_status with_progress(kind k, double cancel_at, probe *p, void **out) {
    struct profsubd_options *o = NULL;
    CHECK(profsubd_options_new(&o));
    CHECK(profsubd_options_set_samples(o, 24, 48));
    memset(p, 0, sizeof *p);
    p->cancel_at = cancel_at;
    CHECK(profsubd_options_set_progress(o, progress, p));
    enum profsubd_status s = run(k, o, out);
    profsubd_options_free(o);
    return s;
}

static void test_kind(kind k) {
    const char *name = names[k];
    void *sentinel = (void *)&failures; /* any non-NULL value the call must not overwrite */
    probe p;
    void *out = NULL;

    /* To the end. */
    enum profsubd_status s = with_progress(k, 2.0, &p, &out);
    EXPECT(s == PROFSUBD_OK, "%s: status %d (%s)", name, (int)s, profsubd_last_error_message());
    EXPECT(out != NULL, "%s: no output", name);
    EXPECT(p.calls >= 3 && p.first == 0.0 && p.last == 1.0 && !p.decreasing,
           "%s: %d calls, first %g, last %g, decreasing %d", name, p.calls, p.first, p.last,
           p.decreasing);
    int full_calls = p.calls;
    release(k, out);

    /* Cancelled at the first callback. */
    out = sentinel;
    s = with_progress(k, 0.0, &p, &out);
    EXPECT(s == PROFSUBD_ERROR_CANCELLED, "%s: status %d", name, (int)s);
    EXPECT(out == sentinel, "%s: output written on cancel", name);
    EXPECT(p.calls == 1, "%s: %d calls after cancelling at the first", name, p.calls);
    EXPECT(strstr(profsubd_last_error_message(), "cancelled by the progress callback at 0.0 %") != NULL,
           "%s: message '%s'", name, profsubd_last_error_message());

    /* Cancelled at 50 %: stops at the first report at or above it. */
    out = sentinel;
    s = with_progress(k, 0.5, &p, &out);
    EXPECT(s == PROFSUBD_ERROR_CANCELLED, "%s at 50%%: status %d", name, (int)s);
    EXPECT(out == sentinel, "%s: output written on cancel at 50%%", name);
    EXPECT(p.cancelled_fraction >= 0.5 && p.cancelled_fraction < 1.0 && p.last == p.cancelled_fraction &&
               p.calls > 1 && p.calls < full_calls,
           "%s at 50%%: stopped at %g after %d of %d calls", name, p.cancelled_fraction, p.calls,
           full_calls);
    EXPECT(strstr(profsubd_last_error_message(), "cancelled") != NULL, "%s: message '%s'", name,
           profsubd_last_error_message());

    /* A 1 KiB memory budget: refused before the work, output untouched. */
    struct profsubd_options *o = NULL;
    CHECK(profsubd_options_new(&o));
    CHECK(profsubd_options_set_samples(o, 24, 48));
    CHECK(profsubd_options_set_memory_budget(o, 1024));
    out = sentinel;
    s = run(k, o, &out);
    EXPECT(s == PROFSUBD_ERROR_LIMIT_EXCEEDED, "%s: budget status %d", name, (int)s);
    EXPECT(out == sentinel, "%s: output written over budget", name);
    EXPECT(strstr(profsubd_last_error_message(), "above the memory budget of 1024 bytes") != NULL,
           "%s: message '%s'", name, profsubd_last_error_message());
    /* Budget 0 removes it again. */
    CHECK(profsubd_options_set_memory_budget(o, 0));
    out = NULL;
    s = run(k, o, &out);
    EXPECT(s == PROFSUBD_OK, "%s: no budget: status %d", name, (int)s);
    if (s == PROFSUBD_OK) release(k, out);
    profsubd_options_free(o);
}

/* Larger work, cancelled at 50 %: time from the callback's return to the call's. */
static void latency(void) {
    struct profsubd_options *o = NULL;
    CHECK(profsubd_options_new(&o));
    CHECK(profsubd_options_set_samples(o, 256, 512));
    struct profsubd_fitted *big = NULL;
    double t0 = now();
    CHECK(profsubd_revolve(profile, 5, o, &big));
    double full = now() - t0;
    struct profsubd_mesh *mesh = NULL;
    CHECK(profsubd_fitted_get_mesh(big, &mesh));
    g_mesh = mesh;
    g_level = 2;
    printf("revolve: 256 x 512 revolution; evaluator, refine (level 2), fold check (defaults): "
           "of that revolution; revolve 270: 128 x 256, 270 degrees\n");
    struct profsubd_evaluator *ev = NULL;
    CHECK(profsubd_evaluator_new(mesh, NULL, &ev));
    g_ev = ev;
    for (int k = 0; k < 5; k++) {
        if (k == REVOLVE_PARTIAL) {
            CHECK(profsubd_options_set_samples(o, 128, 256));
            CHECK(profsubd_options_set_revolve_angle(o, 270.0));
        }
        probe p;
        memset(&p, 0, sizeof p);
        p.cancel_at = 0.5;
        CHECK(profsubd_options_set_progress(o, progress, &p));
        void *out = NULL;
        double start = now();
        enum profsubd_status s = run((kind)k, o, &out);
        double end = now();
        if (s == PROFSUBD_OK) release((kind)k, out);
        /* The whole call, never cancelling: the longest wait between two callbacks (or from
         * the call to the first, or from the last to the return) bounds how long a cancel
         * request waits for its next chance. */
        probe q;
        memset(&q, 0, sizeof q);
        q.cancel_at = 2.0;
        CHECK(profsubd_options_set_progress(o, progress, &q));
        start = now();
        q.last_time = start;
        s = run((kind)k, o, &out);
        double t_end = now(), whole = t_end - start;
        /* The wait from the last callback to the return counts too. */
        if (t_end - q.last_time > q.max_gap) q.max_gap = t_end - q.last_time;
        if (s == PROFSUBD_OK) release((kind)k, out);
        printf("latency %-11s: cancelled at %.3f after %d "
               "calls, %.3f ms from the callback to the return; whole call %.1f ms, %d calls, "
               "longest wait between calls %.1f ms\n",
               names[k], p.cancelled_fraction, p.calls, 1e3 * (end - p.cancelled_time),
               1e3 * whole, q.calls, 1e3 * q.max_gap);
    }
    printf("(revolution built in %.1f ms)\n", 1e3 * full);
    profsubd_evaluator_free(ev);
    profsubd_mesh_free(mesh);
    profsubd_fitted_free(big);
    profsubd_options_free(o);
}

int main(int argc, char **argv) {
    if (argc > 1 && strcmp(argv[1], "--latency") == 0) {
        latency();
        return 0;
    }
    /* The mesh the evaluator and the refinement work on: a small revolution. */
    struct profsubd_fitted *vase = NULL;
    struct profsubd_mesh *mesh = NULL;
    CHECK(profsubd_revolve(profile, 5, NULL, &vase));
    CHECK(profsubd_fitted_get_mesh(vase, &mesh));
    g_mesh = mesh;
    struct profsubd_evaluator *ev = NULL;
    CHECK(profsubd_evaluator_new(mesh, NULL, &ev));
    g_ev = ev;
    for (int k = 0; k < 3; k++) test_kind((kind)k);
    test_kind(FOLDS);
    profsubd_evaluator_free(ev);
    profsubd_mesh_free(mesh);
    profsubd_fitted_free(vase);
    if (failures) {
        fprintf(stderr, "%d failures\n", failures);
        return 1;
    }
    printf("cancel: revolve, evaluator, refine, fold check: full run, cancel at the first callback and at "
           "50 %%, 1 KiB memory budget\n");
    return 0;
}
