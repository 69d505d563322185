// Randomized meshes shared by the conformance tests, and the faces OpenSubdiv 3.5's Bfr
// must not be given (see shared/conformance/osd_shapes/README.md).
#pragma once

#include "osd_shape.h"

#include <opensubdiv/far/topologyLevel.h>

#include <vector>

namespace profsubd_test {

// A perturbed grid of 5-8 x 5-8 quads with faces merged and split (valences 2-8, triangles
// and n-gons up to 8 sides), an interior valence-2 vertex (a valence-2 dart on even seeds),
// semi-sharp, fractional and infinite creases, a dart, vertex sharpness, sometimes a hole;
// profsubd's default options.
OsdShape random_mesh(unsigned seed);

// Base faces OpenSubdiv 3.5's Bfr must not see or is not exact on.
struct Bfr35Faces {
    // Within two face-rings of an interior valence-2 vertex with sharpness in its faces:
    // 3.5's Bfr writes out of bounds / mixes up its cache there, never build these.
    std::vector<bool> avoid;
    // Touching an interior valence-2 vertex: 3.5's Bfr is wrong there (fixed in 3.6).
    std::vector<bool> near_val2;
};
Bfr35Faces bfr35_faces(const OpenSubdiv::Far::TopologyLevel &level);

}  // namespace profsubd_test
