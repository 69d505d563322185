// Random (face, u, v) evaluation points shared by the evaluator conformance test and the
// benchmark.
#pragma once

#include <cstdint>
#include <vector>

namespace profsubd_test {

// Parallel arrays of points: point i is (faces[i], us[i], vs[i]).
struct FacePoints {
    std::vector<uint32_t> faces;
    std::vector<double> us, vs;
};

// `count` points with faces uniform in [0, num_faces) and u, v uniform in [0, 1), drawn from
// std::mt19937_64(seed) face, u, v for each point in turn: a seed always gives the same points.
FacePoints random_face_points(int count, int num_faces, uint64_t seed);

}  // namespace profsubd_test
