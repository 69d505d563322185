// Randomized meshes shared by the conformance tests, and the faces OpenSubdiv 3.5's Bfr
// must not be given.

#include "random_mesh.h"

#include <algorithm>
#include <random>
#include <set>
#include <utility>

namespace profsubd_test {

OsdShape random_mesh(unsigned seed) {
    std::mt19937 rng(seed);
    auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    auto pick = [&](size_t n) { return static_cast<size_t>(std::uniform_int_distribution<size_t>(0, n - 1)(rng)); };
    int n = 5 + static_cast<int>(pick(4));
    OsdShape s;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            s.positions.push_back(i + uni(-0.2, 0.2));
            s.positions.push_back(j + uni(-0.2, 0.2));
            s.positions.push_back(uni(-0.5, 0.5));
        }
    }
    std::vector<std::vector<int>> faces;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            int a = j * (n + 1) + i;
            faces.push_back({a, a + 1, a + n + 2, a + n + 1});
        }
    }
    // Remove the edge p -> q of a face (merging the two faces across it) when that leaves
    // a simple face of at most 8 vertices.
    auto merge = [&](int p, int q) {
        for (size_t a = 0; a < faces.size(); ++a) {
            std::vector<int> &A = faces[a];
            auto it_p = std::find(A.begin(), A.end(), p);
            if (it_p == A.end() || A[(it_p - A.begin() + 1) % A.size()] != q) continue;
            size_t k = static_cast<size_t>(it_p - A.begin());
            for (size_t b = 0; b < faces.size(); ++b) {
                if (b == a) continue;
                std::vector<int> &B = faces[b];
                auto it_q = std::find(B.begin(), B.end(), q);
                if (it_q == B.end() || B[(it_q - B.begin() + 1) % B.size()] != p) continue;
                int shared = 0;
                for (int x : A) shared += static_cast<int>(std::count(B.begin(), B.end(), x));
                if (shared != 2 || A.size() + B.size() - 2 > 8) return;
                std::vector<int> merged;  // A from q round to p, then B after p up to q
                for (size_t t = 0; t + 1 < A.size(); ++t) merged.push_back(A[(k + 1 + t) % A.size()]);
                size_t kb = static_cast<size_t>(it_q - B.begin());
                for (size_t t = 0; t + 1 < B.size(); ++t) merged.push_back(B[(kb + 1 + t) % B.size()]);
                faces[a] = merged;
                faces.erase(faces.begin() + static_cast<long>(b));
                return;
            }
            return;
        }
    };
    // An interior valence-2 vertex (two opposite edges removed), every other mesh with an
    // infinitely sharp edge on it: a valence-2 dart, which Bfr must not see.
    int ci = 1 + static_cast<int>(pick(n - 1)), cj = 1 + static_cast<int>(pick(n - 1));
    int c = cj * (n + 1) + ci;
    merge(c, c + 1);
    merge(c - 1, c);
    if (seed % 2 == 0) {
        s.crease_vertices.insert(s.crease_vertices.end(), {c, c + n + 1});
        s.crease_sharpness.push_back(10.0f);
    }
    // Merge faces across random edges (valences drop to 3 and 2), split quads into
    // triangles (valences rise up to 8).
    int merges = static_cast<int>(pick(n + 2)), splits = static_cast<int>(pick(n + 2));
    for (int it = 0; it < merges; ++it) {
        const std::vector<int> &A = faces[pick(faces.size())];
        size_t k = pick(A.size());
        merge(A[k], A[(k + 1) % A.size()]);
    }
    for (int it = 0; it < splits; ++it) {
        size_t a = pick(faces.size());
        if (faces[a].size() != 4) continue;
        std::vector<int> f = faces[a];
        int d = static_cast<int>(pick(2));
        faces[a] = {f[d], f[d + 1], f[d + 2]};
        faces.push_back({f[d + 2], f[(d + 3) % 4], f[d]});
    }
    for (auto &f : faces) {
        s.face_sizes.push_back(static_cast<int>(f.size()));
        for (int x : f) s.face_indices.push_back(x);
    }
    // Tags: semi-sharp and fractional creases, an infinitely sharp edge alone (a dart at
    // each interior end), semi-sharp and infinite corners, a hole.
    std::vector<std::pair<int, int>> edges;
    std::set<std::pair<int, int>> seen;
    for (auto &f : faces) {
        for (size_t k = 0; k < f.size(); ++k) {
            int a = f[k], b = f[(k + 1) % f.size()];
            if (seen.insert({std::min(a, b), std::max(a, b)}).second) edges.push_back({a, b});
        }
    }
    int creases = 1 + static_cast<int>(pick(5));
    for (int c = 0; c < creases; ++c) {
        auto e = edges[pick(edges.size())];
        s.crease_vertices.push_back(e.first);
        s.crease_vertices.push_back(e.second);
        s.crease_sharpness.push_back(pick(4) == 0 ? 10.0f : static_cast<float>(uni(0.05, 3.5)));
    }
    auto dart = edges[pick(edges.size())];
    s.crease_vertices.push_back(dart.first);
    s.crease_vertices.push_back(dart.second);
    s.crease_sharpness.push_back(10.0f);
    int corners = static_cast<int>(pick(3));
    for (int c = 0; c < corners; ++c) {
        s.corner_vertices.push_back(static_cast<int>(pick(s.positions.size() / 3)));
        s.corner_sharpness.push_back(pick(3) == 0 ? 10.0f : static_cast<float>(uni(0.1, 2.5)));
    }
    if (pick(2) == 0) s.holes.push_back(static_cast<int>(pick(faces.size())));
    s.options = profsubd_default_options();
    return s;
}


Bfr35Faces bfr35_faces(const OpenSubdiv::Far::TopologyLevel &L) {
    const int nv = L.GetNumVertices();
    // Interior manifold vertices with two faces and two edges.
    std::vector<bool> val2(nv, false);
    for (int v = 0; v < nv; ++v) {
        val2[v] = !L.IsVertexBoundary(v) && !L.IsVertexNonManifold(v) && L.GetVertexFaces(v).size() == 2 &&
                  L.GetVertexEdges(v).size() == 2;
    }
    auto grow = [&](const std::vector<bool> &marked) {
        std::vector<bool> out = marked;
        for (int f = 0; f < L.GetNumFaces(); ++f) {
            bool touch = false;
            for (int x : L.GetFaceVertices(f)) touch = touch || marked[x];
            if (touch) {
                for (int x : L.GetFaceVertices(f)) out[x] = true;
            }
        }
        return out;
    };
    // A valence-2 vertex with sharpness in its faces (a dart, or creases next to it as in
    // 3.6's catmark_val2_interior) is what makes 3.5's Bfr write out of bounds.
    std::vector<bool> val2_sharp(nv, false);
    for (int v = 0; v < nv; ++v) {
        if (!val2[v]) continue;
        for (int f : L.GetVertexFaces(v)) {
            for (int e : L.GetFaceEdges(f)) val2_sharp[v] = val2_sharp[v] || L.GetEdgeSharpness(e) > 0.0f;
            for (int x : L.GetFaceVertices(f)) val2_sharp[v] = val2_sharp[v] || L.GetVertexSharpness(x) > 0.0f;
        }
    }
    std::vector<bool> near_val2 = grow(val2), near_val2_sharp = grow(grow(val2_sharp));
    Bfr35Faces out;
    out.avoid.assign(L.GetNumFaces(), false);
    out.near_val2.assign(L.GetNumFaces(), false);
    for (int f = 0; f < L.GetNumFaces(); ++f) {
        for (int x : L.GetFaceVertices(f)) {
            out.avoid[f] = out.avoid[f] || near_val2_sharp[x];
            out.near_val2[f] = out.near_val2[f] || near_val2[x];
        }
    }
    return out;
}

}  // namespace profsubd_test
