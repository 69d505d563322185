// Bad input to every C entry point of the mesh and options API and of the fold check: the
// status must be the documented one, the message (profsubd_last_error_message) must say what
// is wrong, and a failed call must leave every output untouched. Also: status strings,
// version, handles of the wrong kind, thread-local messages and concurrent use of one handle.
#include "capi_mesh.h"
#include "test_support.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <set>
#include <thread>

using namespace profsubd_test;

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// Checks the status and that the message contains every word (case-insensitive).
void expect(Checker &ck, profsubd_status st, profsubd_status want, std::initializer_list<std::string> words,
            const std::string &what) {
    const char *msg = profsubd_last_error_message();
    std::string m = msg ? msg : "";
    if (!ck.check(st == want, what + ": status " + std::to_string(int(st)) + " (" +
                                  profsubd_status_string(int32_t(st)) + "), expected " + std::to_string(int(want)) +
                                  "; message: " + m)) {
        return;
    }
    for (const std::string &w : words) {
        ck.check(lower(m).find(lower(w)) != std::string::npos,
                 what + ": message '" + m + "' should mention '" + w + "'");
    }
}

profsubd_mesh *const kSentinelMesh = reinterpret_cast<profsubd_mesh *>(uintptr_t(0x5eed));

// A unit square, valid, used as the base of the descriptor cases.
struct SquareDesc {
    double positions[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    uint32_t sizes[1] = {4};
    uint32_t indices[4] = {0, 1, 2, 3};
    uint32_t crease_vertices[2] = {0, 1};
    float crease_sharpness[1] = {1.0f};
    uint32_t corner_vertices[1] = {2};
    float corner_sharpness[1] = {2.0f};
    uint32_t holes[1] = {0};
    profsubd_mesh_desc d;

    SquareDesc() {
        std::memset(&d, 0, sizeof d);
        d.struct_size = sizeof d;
        d.positions = positions;
        d.num_vertices = 4;
        d.face_sizes = sizes;
        d.num_faces = 1;
        d.face_indices = indices;
        d.num_face_indices = 4;
        d.crease_vertices = crease_vertices;
        d.crease_sharpness = crease_sharpness;
        d.num_creases = 1;
        d.corner_vertices = corner_vertices;
        d.corner_sharpness = corner_sharpness;
        d.num_corners = 1;
        d.hole_faces = holes;
        d.num_holes = 0;
    }
};

// mesh_new with a modified descriptor must fail with `want` and leave *out alone.
template <class Modify>
void bad_desc(Checker &ck, const std::string &what, profsubd_status want, std::initializer_list<std::string> words,
              Modify modify) {
    SquareDesc s;
    modify(s);
    profsubd_mesh *out = kSentinelMesh;
    profsubd_status st = profsubd_mesh_new(&s.d, &out);
    expect(ck, st, want, words, "mesh_new with " + what);
    ck.check(out == kSentinelMesh, "mesh_new with " + what + ": *out untouched");
    if (out != kSentinelMesh) {
        profsubd_mesh_free(out);
    }
}

void check_mesh_new(Checker &ck) {
    ck.set_context("profsubd_mesh_new");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    {
        SquareDesc s;
        profsubd_mesh *m = nullptr;
        ck.equal(int(profsubd_mesh_new(&s.d, &m)), int(PROFSUBD_OK), "valid square");
        profsubd_mesh_free(m);
        profsubd_mesh *out = kSentinelMesh;
        expect(ck, profsubd_mesh_new(nullptr, &out), PROFSUBD_ERROR_NULL_ARGUMENT, {"desc"}, "NULL desc");
        ck.check(out == kSentinelMesh, "NULL desc: *out untouched");
        expect(ck, profsubd_mesh_new(&s.d, nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"}, "NULL out");
    }
    bad_desc(ck, "struct_size too small", PROFSUBD_ERROR_INVALID_ARGUMENT, {"struct_size"},
             [](SquareDesc &s) { s.d.struct_size = sizeof(profsubd_mesh_desc) - 8; });
    bad_desc(ck, "struct_size too large", PROFSUBD_ERROR_INVALID_ARGUMENT, {"struct_size"},
             [](SquareDesc &s) { s.d.struct_size = sizeof(profsubd_mesh_desc) + 8; });
    bad_desc(ck, "NULL positions", PROFSUBD_ERROR_NULL_ARGUMENT, {"positions"},
             [](SquareDesc &s) { s.d.positions = nullptr; });
    bad_desc(ck, "NULL face_sizes", PROFSUBD_ERROR_NULL_ARGUMENT, {"face_sizes"},
             [](SquareDesc &s) { s.d.face_sizes = nullptr; });
    bad_desc(ck, "NULL face_indices", PROFSUBD_ERROR_NULL_ARGUMENT, {"face_indices"},
             [](SquareDesc &s) { s.d.face_indices = nullptr; });
    bad_desc(ck, "NULL crease_sharpness", PROFSUBD_ERROR_NULL_ARGUMENT, {"crease_sharpness"},
             [](SquareDesc &s) { s.d.crease_sharpness = nullptr; });
    bad_desc(ck, "NULL hole_faces", PROFSUBD_ERROR_NULL_ARGUMENT, {"hole_faces"}, [](SquareDesc &s) {
        s.d.num_holes = 1;
        s.d.hole_faces = nullptr;
    });
    bad_desc(ck, "absurd num_vertices", PROFSUBD_ERROR_INVALID_ARGUMENT, {"num_vertices"},
             [](SquareDesc &s) { s.d.num_vertices = SIZE_MAX; });
    bad_desc(ck, "absurd num_face_indices", PROFSUBD_ERROR_INVALID_ARGUMENT, {"num_face_indices"},
             [](SquareDesc &s) { s.d.num_face_indices = SIZE_MAX / 2; });
    bad_desc(ck, "no faces", PROFSUBD_ERROR_INVALID_MESH, {"no faces"}, [](SquareDesc &s) {
        s.d.num_faces = 0;
        s.d.num_face_indices = 0;
        s.d.num_creases = 0;
    });
    bad_desc(ck, "a face with 2 vertices", PROFSUBD_ERROR_INVALID_MESH, {"at least 3"}, [](SquareDesc &s) {
        s.sizes[0] = 2;
        s.d.num_face_indices = 2;
        s.d.num_creases = 0;
        s.d.num_corners = 0;
    });
    bad_desc(ck, "face sizes not adding up", PROFSUBD_ERROR_INVALID_MESH, {"face indices"},
             [](SquareDesc &s) { s.d.num_face_indices = 3; });
    bad_desc(ck, "vertex index out of range", PROFSUBD_ERROR_INVALID_MESH, {"vertex 4"},
             [](SquareDesc &s) { s.indices[3] = 4; });
    bad_desc(ck, "NaN coordinate", PROFSUBD_ERROR_INVALID_MESH, {"non-finite"},
             [nan](SquareDesc &s) { s.positions[4] = nan; });
    bad_desc(ck, "infinite coordinate", PROFSUBD_ERROR_INVALID_MESH, {"non-finite"},
             [inf](SquareDesc &s) { s.positions[8] = -inf; });
    bad_desc(ck, "crease vertex out of range", PROFSUBD_ERROR_INVALID_MESH, {"crease", "out of range"},
             [](SquareDesc &s) { s.crease_vertices[1] = 7; });
    bad_desc(ck, "crease on a diagonal", PROFSUBD_ERROR_INVALID_MESH, {"crease", "edge"},
             [](SquareDesc &s) { s.crease_vertices[1] = 2; });
    bad_desc(ck, "negative crease sharpness", PROFSUBD_ERROR_INVALID_MESH, {"sharpness"},
             [](SquareDesc &s) { s.crease_sharpness[0] = -1.0f; });
    bad_desc(ck, "NaN crease sharpness", PROFSUBD_ERROR_INVALID_MESH, {"sharpness"},
             [](SquareDesc &s) { s.crease_sharpness[0] = std::numeric_limits<float>::quiet_NaN(); });
    bad_desc(ck, "corner out of range", PROFSUBD_ERROR_INVALID_MESH, {"corner"},
             [](SquareDesc &s) { s.corner_vertices[0] = 4; });
    bad_desc(ck, "negative corner sharpness", PROFSUBD_ERROR_INVALID_MESH, {"sharpness"},
             [](SquareDesc &s) { s.corner_sharpness[0] = -0.5f; });
    bad_desc(ck, "hole out of range", PROFSUBD_ERROR_INVALID_MESH, {"hole"}, [](SquareDesc &s) {
        s.holes[0] = 1;
        s.d.num_holes = 1;
    });
}

// read_obj of `text` must fail with `want`, a message naming the file and the words.
void bad_file(Checker &ck, const TempDir &tmp, const std::string &name, const std::string &text,
              profsubd_status want, std::initializer_list<std::string> words) {
    std::string path = tmp.file(name);
    write_text_file(path, text);
    profsubd_mesh *out = kSentinelMesh;
    profsubd_status st = profsubd_mesh_read_obj(path.c_str(), &out);
    expect(ck, st, want, words, "read_obj of " + name);
    expect(ck, st, want, {path}, "read_obj of " + name + " names the file");
    ck.check(out == kSentinelMesh, "read_obj of " + name + ": *out untouched");
}

void check_read_write(Checker &ck, const TempDir &tmp) {
    ck.set_context("profsubd_mesh_read_obj / write_obj");
    profsubd_mesh *out = kSentinelMesh;
    expect(ck, profsubd_mesh_read_obj(nullptr, &out), PROFSUBD_ERROR_NULL_ARGUMENT, {"path"}, "NULL path");
    expect(ck, profsubd_mesh_read_obj("", &out), PROFSUBD_ERROR_INVALID_ARGUMENT, {"path"}, "empty path");
    std::string missing = tmp.file("does_not_exist.obj");
    expect(ck, profsubd_mesh_read_obj(missing.c_str(), &out), PROFSUBD_ERROR_IO, {missing}, "missing file");
    expect(ck, profsubd_mesh_read_obj(tmp.path().c_str(), &out), PROFSUBD_ERROR_IO, {tmp.path()},
           "a directory");
    ck.check(out == kSentinelMesh, "failed reads leave *out untouched");
    std::string good = tmp.file("good.obj");
    write_text_file(good, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect(ck, profsubd_mesh_read_obj(good.c_str(), nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"}, "NULL out");

    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
    bad_file(ck, tmp, "short_v.obj", "v 0 0\n", PROFSUBD_ERROR_PARSE, {":1:", "v x y z"});
    bad_file(ck, tmp, "word_v.obj", "v 0 zero 0\n", PROFSUBD_ERROR_PARSE, {":1:", "zero"});
    bad_file(ck, tmp, "two_vertex_face.obj", tri + "f 1 2\n", PROFSUBD_ERROR_PARSE, {":5:", "at least 3"});
    bad_file(ck, tmp, "zero_index.obj", tri + "f 1 0 2\n", PROFSUBD_ERROR_PARSE, {":5:", "0"});
    bad_file(ck, tmp, "index_range.obj", tri + "f 1 2 9\n", PROFSUBD_ERROR_PARSE, {":5:", "9"});
    bad_file(ck, tmp, "crease_range.obj", tri + "f 1 2 4 3\nt crease 2/1/0 0 6 1\n", PROFSUBD_ERROR_PARSE,
             {":6:", "crease", "6"});
    bad_file(ck, tmp, "crease_not_edge.obj", tri + "f 1 2 4 3\nt crease 2/1/0 0 3 1\n", PROFSUBD_ERROR_PARSE,
             {":6:", "crease"});
    bad_file(ck, tmp, "crease_counts.obj", tri + "f 1 2 4 3\nt crease 2/1/0 0 1\n", PROFSUBD_ERROR_PARSE,
             {":6:", "2/1/0"});
    bad_file(ck, tmp, "corner_range.obj", tri + "f 1 2 4 3\nt corner 1/1/0 4 1\n", PROFSUBD_ERROR_PARSE,
             {":6:", "corner"});
    bad_file(ck, tmp, "hole_range.obj", tri + "f 1 2 4 3\nt hole 1/0/0 3\n", PROFSUBD_ERROR_PARSE,
             {":6:", "hole"});
    bad_file(ck, tmp, "boundary_value.obj", tri + "f 1 2 4 3\nt interpolateboundary 1/0/0 3\n",
             PROFSUBD_ERROR_PARSE, {":6:"});
    bad_file(ck, tmp, "creasemethod_value.obj", tri + "f 1 2 4 3\nt creasemethod 0/0/1 uniform\n",
             PROFSUBD_ERROR_PARSE, {":6:", "chaikin"});
    bad_file(ck, tmp, "no_faces.obj", tri, PROFSUBD_ERROR_INVALID_MESH, {"no faces"});

    MeshPtr m = load_obj_capi(good, nullptr);
    if (!ck.check(m != nullptr, "a valid triangle loads")) {
        return;
    }
    expect(ck, profsubd_mesh_write_obj(nullptr, good.c_str()), PROFSUBD_ERROR_NULL_ARGUMENT, {"mesh"},
           "write_obj NULL mesh");
    expect(ck, profsubd_mesh_write_obj(m.get(), nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"path"},
           "write_obj NULL path");
    std::string unwritable = tmp.file("no/such/dir/out.obj");
    expect(ck, profsubd_mesh_write_obj(m.get(), unwritable.c_str()), PROFSUBD_ERROR_IO, {unwritable},
           "write_obj into a missing directory");
}

// Stand-in that the lambdas below replace by the real mesh (so that NULL can be tested).
profsubd_mesh *const kNoMesh = reinterpret_cast<profsubd_mesh *>(uintptr_t(0x1));

// The copy-out protocol of one get function, on a mesh whose count is `count` (> 0) items of
// `per` elements of T. `others_untouched` checks any second output array.
template <class T, class Call>
void check_copy_out(Checker &ck, const std::string &name, size_t count, size_t per, Call call,
                    const std::function<bool()> &others_untouched = [] { return true; }) {
    const T sentinel = T(77);
    std::vector<T> buf((count + 2) * per, sentinel);
    auto untouched_from = [&](size_t first) {
        return std::all_of(buf.begin() + first, buf.end(), [&](T x) { return x == sentinel; });
    };
    size_t needed = 999;
    expect(ck, call(nullptr, buf.data(), count, &needed), PROFSUBD_ERROR_NULL_ARGUMENT, {"mesh"}, name + " NULL mesh");
    expect(ck, call(kNoMesh, nullptr, count, &needed), PROFSUBD_ERROR_NULL_ARGUMENT, {"NULL"},
           name + " NULL output with capacity > 0");
    ck.equal(needed, size_t(999), name + ": failed call leaves *needed alone");
    expect(ck, call(kNoMesh, buf.data(), count - 1, &needed), PROFSUBD_ERROR_BUFFER_TOO_SMALL,
           {std::to_string(count)}, name + " capacity one short");
    ck.equal(needed, count, name + ": *needed when too small");
    ck.check(untouched_from(0) && others_untouched(), name + ": outputs untouched when too small");
    expect(ck, call(kNoMesh, buf.data(), count - 1, nullptr), PROFSUBD_ERROR_BUFFER_TOO_SMALL, {},
           name + " too small with NULL needed");
    needed = 999;
    ck.equal(int(call(kNoMesh, buf.data(), count + 2, &needed)), int(PROFSUBD_OK), name + " larger capacity");
    ck.equal(needed, count, name + ": *needed on success");
    ck.check(untouched_from(count * per), name + ": nothing written past the count");
    ck.check(!untouched_from(0), name + ": something was written");
    ck.equal(int(call(kNoMesh, buf.data(), count, nullptr)), int(PROFSUBD_OK), name + " NULL needed on success");
}

void check_queries(Checker &ck) {
    ck.set_context("counts and copy-out");
    SquareDesc s;
    s.d.num_holes = 1;
    profsubd_mesh *raw = nullptr;
    if (!ck.equal(int(profsubd_mesh_new(&s.d, &raw)), int(PROFSUBD_OK), "square with tags")) {
        return;
    }
    MeshPtr m(raw);
    auto real = [&](const profsubd_mesh *p) { return p == kNoMesh ? m.get() : p; };

    using CountFn = profsubd_status (*)(const profsubd_mesh *, size_t *);
    const std::pair<const char *, CountFn> counts[] = {
        {"num_vertices", profsubd_mesh_num_vertices}, {"num_faces", profsubd_mesh_num_faces},
        {"num_face_indices", profsubd_mesh_num_face_indices}, {"num_edges", profsubd_mesh_num_edges},
        {"num_creases", profsubd_mesh_num_creases}, {"num_corners", profsubd_mesh_num_corners},
        {"num_holes", profsubd_mesh_num_holes},
    };
    const size_t expected_counts[] = {4, 1, 4, 4, 1, 1, 1};
    for (size_t i = 0; i < std::size(counts); ++i) {
        size_t n = 12345;
        expect(ck, counts[i].second(nullptr, &n), PROFSUBD_ERROR_NULL_ARGUMENT, {"mesh"},
               std::string(counts[i].first) + " NULL mesh");
        ck.equal(n, size_t(12345), std::string(counts[i].first) + ": failed call leaves *out alone");
        expect(ck, counts[i].second(m.get(), nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"},
               std::string(counts[i].first) + " NULL out");
        ck.equal(int(counts[i].second(m.get(), &n)), int(PROFSUBD_OK), counts[i].first);
        ck.equal(n, expected_counts[i], counts[i].first);
    }

    check_copy_out<double>(ck, "get_positions", 12, 1, [&](const profsubd_mesh *p, double *o, size_t c, size_t *n) {
        return profsubd_mesh_get_positions(real(p), o, c, n);
    });
    check_copy_out<uint32_t>(ck, "get_face_sizes", 1, 1, [&](const profsubd_mesh *p, uint32_t *o, size_t c, size_t *n) {
        return profsubd_mesh_get_face_sizes(real(p), o, c, n);
    });
    check_copy_out<uint32_t>(ck, "get_face_indices", 4, 1, [&](const profsubd_mesh *p, uint32_t *o, size_t c, size_t *n) {
        return profsubd_mesh_get_face_indices(real(p), o, c, n);
    });
    check_copy_out<uint32_t>(ck, "get_holes", 1, 1, [&](const profsubd_mesh *p, uint32_t *o, size_t c, size_t *n) {
        return profsubd_mesh_get_holes(real(p), o, c, n);
    });
    check_copy_out<uint32_t>(ck, "get_valences", 4, 1, [&](const profsubd_mesh *p, uint32_t *o, size_t c, size_t *n) {
        return profsubd_mesh_get_valences(real(p), o, c, n);
    });
    check_copy_out<uint32_t>(ck, "get_edges", 4, 2, [&](const profsubd_mesh *p, uint32_t *o, size_t c, size_t *n) {
        return profsubd_mesh_get_edges(real(p), o, c, n);
    });
    // Creases and corners fill two arrays: vertices (2 resp. 1 per item) and sharpness.
    std::vector<uint32_t> pairs(2 * 3, 77);
    auto pairs_untouched = [&] { return std::all_of(pairs.begin(), pairs.end(), [](uint32_t x) { return x == 77; }); };
    check_copy_out<float>(
        ck, "get_creases", 1, 1,
        [&](const profsubd_mesh *p, float *o, size_t c, size_t *n) {
            return profsubd_mesh_get_creases(real(p), o ? pairs.data() : nullptr, o, c, n);
        },
        pairs_untouched);
    std::fill(pairs.begin(), pairs.end(), 77);
    check_copy_out<float>(
        ck, "get_corners", 1, 1,
        [&](const profsubd_mesh *p, float *o, size_t c, size_t *n) {
            return profsubd_mesh_get_corners(real(p), o ? pairs.data() : nullptr, o, c, n);
        },
        pairs_untouched);
    std::vector<float> sharp(3, 77.0f);
    expect(ck, profsubd_mesh_get_creases(m.get(), pairs.data(), nullptr, 1, nullptr), PROFSUBD_ERROR_NULL_ARGUMENT,
           {"sharpness"}, "get_creases NULL sharpness");
    expect(ck, profsubd_mesh_get_corners(m.get(), nullptr, sharp.data(), 1, nullptr), PROFSUBD_ERROR_NULL_ARGUMENT,
           {"vertices"}, "get_corners NULL vertices");

    size_t nw = 7;
    ck.equal(int(profsubd_mesh_num_warnings(m.get(), &nw)), int(PROFSUBD_OK), "num_warnings");
    ck.equal(nw, size_t(0), "a mesh from profsubd_mesh_new has no reader warnings");
    expect(ck, profsubd_mesh_num_warnings(nullptr, &nw), PROFSUBD_ERROR_NULL_ARGUMENT, {"mesh"}, "num_warnings NULL mesh");
    expect(ck, profsubd_mesh_num_warnings(m.get(), nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"}, "num_warnings NULL out");
    const char *w = "untouched";
    expect(ck, profsubd_mesh_get_warning(m.get(), 0, &w), PROFSUBD_ERROR_INVALID_ARGUMENT, {"0"},
           "get_warning index past the end");
    expect(ck, profsubd_mesh_get_warning(nullptr, 0, &w), PROFSUBD_ERROR_NULL_ARGUMENT, {"mesh"}, "get_warning NULL mesh");
    expect(ck, profsubd_mesh_get_warning(m.get(), 0, nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"},
           "get_warning NULL out");
    ck.equal(std::string(w), std::string("untouched"), "get_warning: failed call leaves *out alone");

    profsubd_mesh_report r;
    std::memset(&r, 0, sizeof r);
    r.struct_size = sizeof r;
    expect(ck, profsubd_mesh_check(nullptr, &r), PROFSUBD_ERROR_NULL_ARGUMENT, {"mesh"}, "mesh_check NULL mesh");
    expect(ck, profsubd_mesh_check(m.get(), nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"}, "mesh_check NULL out");
    r.struct_size = 8;
    r.num_vertices = 4242;
    expect(ck, profsubd_mesh_check(m.get(), &r), PROFSUBD_ERROR_INVALID_ARGUMENT, {"struct_size"},
           "mesh_check small struct_size");
    ck.equal(r.num_vertices, size_t(4242), "mesh_check: failed call writes nothing");
    r.struct_size = sizeof r;
    ck.equal(int(profsubd_mesh_check(m.get(), &r)), int(PROFSUBD_OK), "mesh_check");
    ck.equal(r.num_boundary_edges, size_t(4), "square: 4 boundary edges");
    ck.equal(r.num_boundary_loops, size_t(1), "square: 1 boundary loop");
    ck.equal(r.euler_characteristic, int64_t(1), "square: Euler characteristic 1");
}

void check_handles(Checker &ck) {
    ck.set_context("handles");
    profsubd_options *o = nullptr;
    ck.equal(int(profsubd_options_new(&o)), int(PROFSUBD_OK), "options_new");
    OptionsPtr opts(o);
    size_t n = 0;
    // A live handle of another kind, and zeroed memory, must be refused, not used.
    expect(ck, profsubd_mesh_num_vertices(reinterpret_cast<const profsubd_mesh *>(o), &n),
           PROFSUBD_ERROR_INVALID_HANDLE, {"profsubd_mesh"}, "options handle passed as a mesh");
    alignas(16) static uint64_t zeros[16] = {};
    expect(ck, profsubd_mesh_num_vertices(reinterpret_cast<const profsubd_mesh *>(zeros), &n),
           PROFSUBD_ERROR_INVALID_HANDLE, {"profsubd_mesh"}, "zeroed memory passed as a mesh");
    SquareDesc s;
    profsubd_mesh *m = nullptr;
    profsubd_mesh_new(&s.d, &m);
    MeshPtr mesh(m);
    expect(ck, profsubd_options_set_boundary(reinterpret_cast<profsubd_options *>(m), PROFSUBD_BOUNDARY_NONE),
           PROFSUBD_ERROR_INVALID_HANDLE, {"profsubd_options"}, "mesh handle passed as options");
    profsubd_mesh_free(nullptr);
    profsubd_options_free(nullptr);
    ck.check(true, "free(NULL) is a no-op");
}

void check_options(Checker &ck) {
    ck.set_context("options");
    expect(ck, profsubd_options_new(nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"}, "options_new NULL out");
    profsubd_options *raw = nullptr;
    ck.equal(int(profsubd_options_new(&raw)), int(PROFSUBD_OK), "options_new");
    OptionsPtr o(raw);
    for (int32_t v : {PROFSUBD_BOUNDARY_NONE, PROFSUBD_BOUNDARY_EDGE_ONLY, PROFSUBD_BOUNDARY_EDGE_AND_CORNER}) {
        ck.equal(int(profsubd_options_set_boundary(o.get(), v)), int(PROFSUBD_OK), "set_boundary " + std::to_string(v));
    }
    for (int32_t v : {-1, 3, INT32_MAX, INT32_MIN}) {
        expect(ck, profsubd_options_set_boundary(o.get(), v), PROFSUBD_ERROR_INVALID_ARGUMENT, {std::to_string(v)},
               "set_boundary " + std::to_string(v));
    }
    for (int32_t v : {PROFSUBD_CREASE_UNIFORM, PROFSUBD_CREASE_CHAIKIN}) {
        ck.equal(int(profsubd_options_set_crease_method(o.get(), v)), int(PROFSUBD_OK), "set_crease_method");
    }
    for (int32_t v : {-1, 2, 100}) {
        expect(ck, profsubd_options_set_crease_method(o.get(), v), PROFSUBD_ERROR_INVALID_ARGUMENT,
               {std::to_string(v)}, "set_crease_method " + std::to_string(v));
    }
    for (int32_t v : {PROFSUBD_TRIANGLES_CATMARK, PROFSUBD_TRIANGLES_SMOOTH}) {
        ck.equal(int(profsubd_options_set_triangle_rule(o.get(), v)), int(PROFSUBD_OK), "set_triangle_rule");
    }
    for (int32_t v : {-7, 2}) {
        expect(ck, profsubd_options_set_triangle_rule(o.get(), v), PROFSUBD_ERROR_INVALID_ARGUMENT,
               {std::to_string(v)}, "set_triangle_rule " + std::to_string(v));
    }
    expect(ck, profsubd_options_set_boundary(nullptr, 0), PROFSUBD_ERROR_NULL_ARGUMENT, {"options"},
           "set_boundary NULL");
    expect(ck, profsubd_options_set_crease_method(nullptr, 0), PROFSUBD_ERROR_NULL_ARGUMENT, {"options"},
           "set_crease_method NULL");
    expect(ck, profsubd_options_set_triangle_rule(nullptr, 0), PROFSUBD_ERROR_NULL_ARGUMENT, {"options"},
           "set_triangle_rule NULL");
}

// Uniform refinement and its vertex-order setting.
void check_refine(Checker &ck) {
    ck.set_context("refine");
    profsubd_options *raw = nullptr;
    ck.equal(int(profsubd_options_new(&raw)), int(PROFSUBD_OK), "options_new");
    OptionsPtr o(raw);
    for (int32_t v : {PROFSUBD_ORDER_VERTICES_FIRST, PROFSUBD_ORDER_FACES_FIRST}) {
        ck.equal(int(profsubd_options_set_vertex_order(o.get(), v)), int(PROFSUBD_OK),
                 "set_vertex_order " + std::to_string(v));
    }
    for (int32_t v : {-1, 2, INT32_MAX, INT32_MIN}) {
        expect(ck, profsubd_options_set_vertex_order(o.get(), v), PROFSUBD_ERROR_INVALID_ARGUMENT,
               {"vertex order", std::to_string(v)}, "set_vertex_order " + std::to_string(v));
    }
    expect(ck, profsubd_options_set_vertex_order(nullptr, 0), PROFSUBD_ERROR_NULL_ARGUMENT, {"options"},
           "set_vertex_order NULL");
    SquareDesc s;
    profsubd_mesh *m = nullptr;
    profsubd_mesh_new(&s.d, &m);
    MeshPtr mesh(m);
    expect(ck, profsubd_options_set_vertex_order(reinterpret_cast<profsubd_options *>(m), 0),
           PROFSUBD_ERROR_INVALID_HANDLE, {"profsubd_options"}, "mesh handle passed as options");
    profsubd_mesh *out = nullptr;
    expect(ck, profsubd_refine_uniform(nullptr, o.get(), 1, &out), PROFSUBD_ERROR_NULL_ARGUMENT, {"mesh"},
           "refine_uniform NULL mesh");
    expect(ck, profsubd_refine_uniform(m, o.get(), 1, nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"},
           "refine_uniform NULL out");
    expect(ck, profsubd_refine_uniform(m, o.get(), 9, &out), PROFSUBD_ERROR_INVALID_ARGUMENT, {"maximum 8"},
           "refine_uniform level 9");
    expect(ck, profsubd_refine_uniform(reinterpret_cast<profsubd_mesh *>(o.get()), o.get(), 1, &out),
           PROFSUBD_ERROR_INVALID_HANDLE, {"profsubd_mesh"}, "options handle passed as a mesh");
    ck.check(out == nullptr, "out untouched on error");
    // The last valid order (faces first) stays set after the refused values: the face point
    // of the square (0.5, 0.5, 0) is vertex 0 of the refined mesh.
    ck.equal(int(profsubd_refine_uniform(m, o.get(), 1, &out)), int(PROFSUBD_OK), "refine_uniform level 1");
    MeshPtr refined(out);
    double p[27] = {};
    size_t needed = 0;
    ck.equal(int(profsubd_mesh_get_positions(out, p, 27, &needed)), int(PROFSUBD_OK), "get_positions");
    ck.check(needed == 27 && p[0] == 0.5 && p[1] == 0.5 && p[2] == 0.0,
             "faces-first order kept: vertex 0 is the face point");
}

void check_strings_and_version(Checker &ck) {
    ck.set_context("status strings and version");
    std::set<std::string> seen;
    for (int32_t code : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 99}) {
        const char *s = profsubd_status_string(code);
        ck.check(s != nullptr && s[0] != '\0', "status_string(" + std::to_string(code) + ") is not empty");
        if (s != nullptr) {
            seen.insert(s);
        }
    }
    ck.equal(seen.size(), size_t(11), "every status has its own string");
    const char *unknown = profsubd_status_string(12345);
    ck.check(unknown != nullptr && unknown[0] != '\0', "status_string of an unknown code is a string");
    char expected[64];
    std::snprintf(expected, sizeof expected, "%u.%u.%u", profsubd_version_major(), profsubd_version_minor(),
                  profsubd_version_patch());
    ck.equal(std::string(profsubd_version_string()), std::string(expected), "version string vs numbers");
    ck.equal(std::string(profsubd_version_string()), std::string(PROFSUBD_EXPECTED_VERSION),
             "version vs Cargo.toml (via CMake)");
    ck.check(profsubd_last_error_message() != nullptr, "last_error_message is never NULL");
}

// The evaluator's marking entry points (profsubd_evaluator_evaluate_points,
// profsubd_evaluator_limit_vertices_masked): bad arguments get their status and write
// nothing; a point or vertex without limit surface is NaN + mask 0, or with strict = 1 an
// error that writes nothing.
void check_evaluator_points(Checker &ck) {
    ck.set_context("evaluator points");
    for (int holed = 0; holed < 2; ++holed) {
        SquareDesc s;
        s.d.num_holes = holed;  // the one face a hole: no point and no vertex has a surface
        profsubd_mesh *raw = nullptr;
        profsubd_mesh_new(&s.d, &raw);
        MeshPtr m(raw);
        profsubd_evaluator *ev = nullptr;
        if (!ck.check(profsubd_evaluator_new(m.get(), nullptr, &ev) == PROFSUBD_OK, "evaluator_new")) return;
        const std::string tag = holed ? " (hole)" : "";
        uint32_t face = 0;
        double u = 0.25, v = 0.5, p[3] = {7, 7, 7}, du[3] = {7, 7, 7};
        uint8_t mask = 7;
        auto eval = [&](const profsubd_evaluator *e, int32_t domain, int32_t strict, const uint32_t *f,
                        double uu, double *pos) {
            return profsubd_evaluator_evaluate_points(e, domain, strict, f, &uu, &v, 1, pos, du, nullptr, &mask);
        };
        auto untouched = [&](const std::string &what) {
            ck.check(p[0] == 7 && p[1] == 7 && p[2] == 7 && du[0] == 7 && mask == 7, what + ": outputs untouched");
        };
        expect(ck, eval(nullptr, PROFSUBD_DOMAIN_PTEX, 0, &face, u, p), PROFSUBD_ERROR_NULL_ARGUMENT,
               {"evaluator"}, "evaluate_points NULL evaluator" + tag);
        expect(ck, eval(reinterpret_cast<profsubd_evaluator *>(m.get()), PROFSUBD_DOMAIN_PTEX, 0, &face, u, p),
               PROFSUBD_ERROR_INVALID_HANDLE, {"evaluator"}, "evaluate_points with a mesh handle" + tag);
        expect(ck, eval(ev, 7, 0, &face, u, p), PROFSUBD_ERROR_INVALID_ARGUMENT, {"domain", "7"},
               "evaluate_points domain 7" + tag);
        expect(ck, eval(ev, PROFSUBD_DOMAIN_BFR, 2, &face, u, p), PROFSUBD_ERROR_INVALID_ARGUMENT, {"strict", "2"},
               "evaluate_points strict 2" + tag);
        expect(ck, eval(ev, PROFSUBD_DOMAIN_PTEX, 0, nullptr, u, p), PROFSUBD_ERROR_NULL_ARGUMENT, {"faces"},
               "evaluate_points NULL faces" + tag);
        expect(ck, eval(ev, PROFSUBD_DOMAIN_PTEX, 0, &face, u, nullptr), PROFSUBD_ERROR_NULL_ARGUMENT,
               {"positions"}, "evaluate_points NULL positions" + tag);
        uint32_t far_face = 1;
        expect(ck, eval(ev, PROFSUBD_DOMAIN_BFR, 0, &far_face, u, p), PROFSUBD_ERROR_INVALID_ARGUMENT,
               {"point 0", "face 1", "out of range"}, "evaluate_points Bfr face 1 of 1" + tag);
        expect(ck, eval(ev, PROFSUBD_DOMAIN_BFR, 0, &face, 1.5, p), PROFSUBD_ERROR_INVALID_ARGUMENT, {"outside"},
               "evaluate_points u = 1.5" + tag);
        expect(ck, eval(ev, PROFSUBD_DOMAIN_PTEX, 0, &face, std::nan(""), p), PROFSUBD_ERROR_INVALID_ARGUMENT,
               {"outside"}, "evaluate_points u = NaN" + tag);
        untouched("evaluate_points errors" + tag);
        if (holed) {
            expect(ck, eval(ev, PROFSUBD_DOMAIN_PTEX, 1, &face, u, p), PROFSUBD_ERROR_INVALID_ARGUMENT,
                   {"point 0", "no limit surface"}, "evaluate_points strict on a hole");
            untouched("evaluate_points strict on a hole");
        }
        ck.check(eval(ev, PROFSUBD_DOMAIN_BFR, 0, &face, u, p) == PROFSUBD_OK, "evaluate_points" + tag);
        ck.check(mask == (holed ? 0 : 1), "has_surface" + tag);
        ck.check(std::isnan(p[0]) == bool(holed) && std::isnan(du[2]) == bool(holed), "NaN iff no surface" + tag);

        // Vertex limits.
        double vp[12], big[12];
        std::fill(vp, vp + 12, 7.0);
        std::fill(big, big + 12, 7.0);
        uint8_t vm[4] = {7, 7, 7, 7};
        size_t needed = 0;
        expect(ck, profsubd_evaluator_limit_vertices_masked(nullptr, 0, vp, nullptr, nullptr, vm, 4, &needed),
               PROFSUBD_ERROR_NULL_ARGUMENT, {"evaluator"}, "limit_vertices_masked NULL evaluator" + tag);
        expect(ck, profsubd_evaluator_limit_vertices_masked(ev, 5, vp, nullptr, nullptr, vm, 4, &needed),
               PROFSUBD_ERROR_INVALID_ARGUMENT, {"strict", "5"}, "limit_vertices_masked strict 5" + tag);
        expect(ck, profsubd_evaluator_limit_vertices_masked(ev, 0, nullptr, nullptr, nullptr, vm, 4, &needed),
               PROFSUBD_ERROR_NULL_ARGUMENT, {"positions"}, "limit_vertices_masked NULL positions" + tag);
        expect(ck, profsubd_evaluator_limit_vertices_masked(ev, 0, vp, nullptr, nullptr, vm, 3, &needed),
               PROFSUBD_ERROR_BUFFER_TOO_SMALL, {"4"}, "limit_vertices_masked capacity 3" + tag);
        ck.equal(needed, size_t(4), "limit_vertices_masked needed" + tag);
        if (holed) {
            expect(ck, profsubd_evaluator_limit_vertices_masked(ev, 1, vp, nullptr, nullptr, vm, 4, &needed),
                   PROFSUBD_ERROR_INVALID_ARGUMENT, {"vertex 0", "no limit surface"},
                   "limit_vertices_masked strict with a hole");
        }
        ck.check(vp[0] == 7 && vm[0] == 7, "limit_vertices_masked errors: outputs untouched" + tag);
        ck.check(profsubd_evaluator_limit_vertices_masked(ev, 0, vp, nullptr, nullptr, vm, 4, &needed) ==
                     PROFSUBD_OK,
                 "limit_vertices_masked" + tag);
        for (int i = 0; i < 4; ++i) {
            ck.check(vm[i] == (holed ? 0 : 1) && std::isnan(vp[3 * i]) == bool(holed),
                     "vertex " + std::to_string(i) + " marked iff no surface" + tag);
        }
        ck.check(profsubd_evaluator_limit_vertices(ev, big, nullptr, nullptr, 4, &needed) == PROFSUBD_OK &&
                     std::isnan(big[0]) == bool(holed),
                 "limit_vertices: NaN iff no surface" + tag);
        profsubd_evaluator_free(ev);
    }
}

// Messages are per thread; one mesh handle may be read from several threads at once.
void check_threads(Checker &ck, const TempDir &tmp) {
    ck.set_context("threads");
    SquareDesc s;
    profsubd_mesh *raw = nullptr;
    profsubd_mesh_new(&s.d, &raw);
    MeshPtr m(raw);
    std::string messages[2];
    std::thread a([&] {
        profsubd_options_set_boundary(nullptr, 0);
        messages[0] = profsubd_last_error_message();
    });
    a.join();
    std::string missing = tmp.file("missing_in_thread.obj");
    std::thread b([&] {
        profsubd_mesh *out = nullptr;
        profsubd_mesh_read_obj(missing.c_str(), &out);
        messages[1] = profsubd_last_error_message();
    });
    b.join();
    ck.check(messages[0].find("options") != std::string::npos, "thread 1 sees its message: " + messages[0]);
    ck.check(messages[1].find(missing) != std::string::npos, "thread 2 sees its message: " + messages[1]);

    int ok[4] = {0, 0, 0, 0};
    std::vector<std::thread> readers;
    for (int t = 0; t < 4; ++t) {
        readers.emplace_back([&, t] {
            for (int i = 0; i < 200; ++i) {
                double p[12];
                size_t n = 0;
                ok[t] += profsubd_mesh_get_positions(m.get(), p, 12, &n) == PROFSUBD_OK && n == 12 && p[3] == 1.0;
            }
        });
    }
    for (auto &t : readers) {
        t.join();
    }
    ck.check(ok[0] + ok[1] + ok[2] + ok[3] == 800, "4 threads reading one mesh all succeed");
}

// The fold check: NULL and foreign handles, settings out of range, outputs untouched on
// error, the copy-out protocol for the folded faces.
void check_folds(Checker &ck) {
    ck.set_context("check_folds");
    SquareDesc s;
    profsubd_mesh *raw = nullptr;
    profsubd_mesh_new(&s.d, &raw);
    MeshPtr m(raw);
    profsubd_evaluator *ev = nullptr;
    ck.equal(int(profsubd_evaluator_new(m.get(), nullptr, &ev)), int(PROFSUBD_OK), "evaluator_new");
    profsubd_fold_report *const sentinel = reinterpret_cast<profsubd_fold_report *>(uintptr_t(0x5eed));
    profsubd_fold_report *out = sentinel;
    expect(ck, profsubd_check_folds(nullptr, nullptr, &out), PROFSUBD_ERROR_NULL_ARGUMENT, {"evaluator"},
           "check_folds NULL evaluator");
    expect(ck, profsubd_check_folds(ev, nullptr, nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"},
           "check_folds NULL out");
    expect(ck, profsubd_check_folds(reinterpret_cast<profsubd_evaluator *>(m.get()), nullptr, &out),
           PROFSUBD_ERROR_INVALID_HANDLE, {"profsubd_evaluator"}, "mesh passed as an evaluator");
    profsubd_fold_settings bad[3] = {{1, 4, 45.0}, {9, 17, 45.0}, {9, 4, std::nan("")}};
    const char *words[3] = {"samples per edge", "adaptive depth", "turn"};
    for (int i = 0; i < 3; ++i)
        expect(ck, profsubd_check_folds(ev, &bad[i], &out), PROFSUBD_ERROR_INVALID_ARGUMENT, {words[i]},
               std::string("check_folds with bad settings: ") + words[i]);
    ck.check(out == sentinel, "out untouched on error");
    // Work above the ceiling of 2^26 evaluations: 100,000 faces at 1025 x 1025, refused from
    // the counts before any evaluation (a 316 x 316 grid), with and without options.
    {
        const uint32_t n = 316;
        std::vector<double> pos;
        std::vector<uint32_t> sizes(size_t(n) * n, 4), idx;
        for (uint32_t j = 0; j <= n; ++j)
            for (uint32_t i = 0; i <= n; ++i) pos.insert(pos.end(), {double(i), double(j), 0.0});
        for (uint32_t j = 0; j < n; ++j)
            for (uint32_t i = 0; i < n; ++i) {
                uint32_t v = j * (n + 1) + i;
                idx.insert(idx.end(), {v, v + 1, v + n + 2, v + n + 1});
            }
        profsubd_mesh_desc d{};
        d.struct_size = sizeof d;
        d.positions = pos.data();
        d.num_vertices = pos.size() / 3;
        d.face_sizes = sizes.data();
        d.num_faces = sizes.size();
        d.face_indices = idx.data();
        d.num_face_indices = idx.size();
        profsubd_mesh *big_raw = nullptr;
        ck.equal(int(profsubd_mesh_new(&d, &big_raw)), int(PROFSUBD_OK), "316 x 316 grid");
        MeshPtr big_mesh(big_raw);
        profsubd_evaluator *big = nullptr;
        ck.equal(int(profsubd_evaluator_new(big_raw, nullptr, &big)), int(PROFSUBD_OK), "its evaluator");
        profsubd_fold_settings absurd = {1025, 16, 45.0};
        expect(ck, profsubd_check_folds(big, &absurd, &out), PROFSUBD_ERROR_LIMIT_EXCEEDED,
               {"99856 parametric faces at 1025 × 1025 samples", "above the limit of 67108864"},
               "check_folds above MAX_FOLD_SAMPLES");
        profsubd_options *o = nullptr;
        profsubd_options_new(&o);
        expect(ck, profsubd_check_folds_with_options(big, &absurd, o, &out), PROFSUBD_ERROR_LIMIT_EXCEEDED,
               {"104911210000"}, "check_folds_with_options above MAX_FOLD_SAMPLES");
        // A memory budget below one face's base lattice of samples.
        profsubd_options_set_memory_budget(o, 4096);
        expect(ck, profsubd_check_folds_with_options(ev, nullptr, o, &out), PROFSUBD_ERROR_LIMIT_EXCEEDED,
               {"the fold check of 1 parametric faces at 9 × 9 samples", "memory budget of 4096 bytes"},
               "check_folds_with_options over the memory budget");
        expect(ck, profsubd_check_folds_with_options(ev, nullptr, reinterpret_cast<profsubd_options *>(ev), &out),
               PROFSUBD_ERROR_INVALID_HANDLE, {"options"}, "an evaluator passed as options");
        profsubd_options_free(o);
        profsubd_evaluator_free(big);
    }
    ck.check(out == sentinel, "out untouched on error");

    // A flat square does not fold: one face checked, no folded face, worst angle 0.
    ck.equal(int(profsubd_check_folds(ev, nullptr, &out)), int(PROFSUBD_OK), "check_folds");
    profsubd_fold_summary sum;
    std::memset(&sum, 0xab, sizeof sum);
    profsubd_fold_summary before = sum;
    expect(ck, profsubd_fold_report_get_summary(nullptr, &sum), PROFSUBD_ERROR_NULL_ARGUMENT, {"report"},
           "get_summary NULL report");
    expect(ck, profsubd_fold_report_get_summary(out, nullptr), PROFSUBD_ERROR_NULL_ARGUMENT, {"out"},
           "get_summary NULL out");
    expect(ck, profsubd_fold_report_get_summary(reinterpret_cast<profsubd_fold_report *>(ev), &sum),
           PROFSUBD_ERROR_INVALID_HANDLE, {"profsubd_fold_report"}, "evaluator passed as a fold report");
    ck.check(std::memcmp(&sum, &before, sizeof sum) == 0, "summary untouched on error");
    ck.equal(int(profsubd_fold_report_get_summary(out, &sum)), int(PROFSUBD_OK), "get_summary");
    ck.check(sum.num_folded_faces == 0 && sum.faces_checked == 1 && sum.samples > 0 &&
                 sum.worst_reversal_deg < 1e-5 && sum.worst_face == 0 && sum.min_relative_jacobian > 0,
             "flat square: no fold");
    size_t needed = 99;
    uint32_t faces[1] = {7};
    expect(ck, profsubd_fold_report_get_folded_faces(out, nullptr, 1, &needed), PROFSUBD_ERROR_NULL_ARGUMENT,
           {"out"}, "get_folded_faces NULL buffer with capacity 1");
    ck.equal(int(profsubd_fold_report_get_folded_faces(out, faces, 1, &needed)), int(PROFSUBD_OK),
             "get_folded_faces");
    ck.check(needed == 0 && faces[0] == 7, "no folded face, buffer untouched");
    profsubd_fold_report_free(out);
    profsubd_fold_report_free(nullptr);
    profsubd_evaluator_free(ev);
}

// profsubd_mesh_get_osd_hazard_vertices / _faces on a cube with one infinitely sharp edge
// 1-5: both ends are darts (interior, one sharp edge), their faces are 0-3.
void check_osd_hazards(Checker &ck) {
    ck.set_context("osd hazards");
    OsdShape cube;
    std::string err;
    const char *obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\nt crease 2/1/0 1 5 10\n";
    if (!ck.check(parse_osd_shape(obj, &cube, &err), "cube: " + err)) return;
    MeshPtr m = new_mesh_capi(cube, &err);
    if (!ck.check(m != nullptr, "cube with a dart edge: " + err)) return;
    auto real = [&](const profsubd_mesh *p) { return p == kNoMesh ? m.get() : p; };
    check_copy_out<uint32_t>(ck, "get_osd_hazard_vertices", 2, 1,
                             [&](const profsubd_mesh *p, uint32_t *o, size_t c, size_t *n) {
                                 return profsubd_mesh_get_osd_hazard_vertices(real(p), nullptr,
                                                                              PROFSUBD_OSD_HAZARD_DART, o, c, n);
                             });
    check_copy_out<uint32_t>(ck, "get_osd_hazard_faces", 4, 1,
                             [&](const profsubd_mesh *p, uint32_t *o, size_t c, size_t *n) {
                                 return profsubd_mesh_get_osd_hazard_faces(real(p), nullptr,
                                                                           PROFSUBD_OSD_HAZARD_DART, o, c, n);
                             });
    uint32_t out[8] = {77, 77, 77, 77, 77, 77, 77, 77};
    size_t n = 999;
    ck.equal(int(profsubd_mesh_get_osd_hazard_vertices(m.get(), nullptr, PROFSUBD_OSD_HAZARD_DART, out, 8, &n)),
             int(PROFSUBD_OK), "dart vertices");
    ck.check(n == 2 && out[0] == 1 && out[1] == 5, "dart vertices are 1 and 5");
    ck.equal(int(profsubd_mesh_get_osd_hazard_faces(m.get(), nullptr, PROFSUBD_OSD_HAZARD_DART, out, 8, &n)),
             int(PROFSUBD_OK), "dart faces");
    ck.check(n == 4 && out[0] == 0 && out[1] == 1 && out[2] == 2 && out[3] == 3, "dart faces are 0-3");
    ck.equal(int(profsubd_mesh_get_osd_hazard_vertices(m.get(), nullptr, PROFSUBD_OSD_HAZARD_CHAIKIN, out, 8, &n)),
             int(PROFSUBD_OK), "no Chaikin hazard");
    ck.equal(n, size_t(0), "no Chaikin hazard: *needed = 0");
    std::fill(std::begin(out), std::end(out), 77);
    n = 999;
    for (int32_t kind : {-1, 7}) {
        expect(ck, profsubd_mesh_get_osd_hazard_vertices(m.get(), nullptr, kind, out, 8, &n),
               PROFSUBD_ERROR_INVALID_ARGUMENT, {"hazard kind", std::to_string(kind)}, "kind out of range");
        expect(ck, profsubd_mesh_get_osd_hazard_faces(m.get(), nullptr, kind, out, 8, &n),
               PROFSUBD_ERROR_INVALID_ARGUMENT, {"hazard kind"}, "kind out of range (faces)");
    }
    const auto *wrong = reinterpret_cast<const profsubd_options *>(m.get());
    expect(ck, profsubd_mesh_get_osd_hazard_vertices(m.get(), wrong, PROFSUBD_OSD_HAZARD_DART, out, 8, &n),
           PROFSUBD_ERROR_INVALID_HANDLE, {"options"}, "a mesh passed as options");
    ck.check(n == 999 && std::all_of(std::begin(out), std::end(out), [](uint32_t x) { return x == 77; }),
             "failed calls leave the outputs alone");
}

}  // namespace

int main() {
    Checker ck("bad_input");
    TempDir tmp;
    check_mesh_new(ck);
    check_read_write(ck, tmp);
    check_queries(ck);
    check_osd_hazards(ck);
    check_handles(ck);
    check_options(ck);
    check_refine(ck);
    check_folds(ck);
    check_strings_and_version(ck);
    check_evaluator_points(ck);
    check_threads(ck, tmp);
    return ck.finish();
}
