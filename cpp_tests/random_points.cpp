// Random (face, u, v) evaluation points.

#include "random_points.h"

#include <random>

namespace profsubd_test {

FacePoints random_face_points(int count, int num_faces, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> pick(0, num_faces - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    FacePoints out;
    out.faces.resize(count);
    out.us.resize(count);
    out.vs.resize(count);
    for (int i = 0; i < count; ++i) {
        out.faces[i] = static_cast<uint32_t>(pick(rng));
        out.us[i] = unit(rng);
        out.vs[i] = unit(rng);
    }
    return out;
}

}  // namespace profsubd_test
