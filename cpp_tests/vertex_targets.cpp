// Targets files and OpenSubdiv's limit position of every control vertex.

#include "vertex_targets.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyLevel.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace profsubd_test {

using namespace OpenSubdiv;

bool read_targets(const std::string &path, std::vector<double> *out) {
    std::ifstream in(path);
    double x;
    while (in >> x) {
        out->push_back(x);
    }
    return !out->empty() && out->size() % 3 == 0;
}

std::vector<double> bfr_vertex_limits(const Far::TopologyRefiner &refiner, const std::vector<double> &points) {
    Bfr::RefinerSurfaceFactory<>::Options options;
    options.SetApproxLevelSmooth(10).SetApproxLevelSharp(10);
    Bfr::RefinerSurfaceFactory<> factory(refiner, options);
    const Far::TopologyLevel &level = refiner.GetLevel(0);
    std::vector<double> out(points.size(), std::nan(""));
    Bfr::Surface<double> surface;
    Bfr::Surface<double>::PointDescriptor desc(3);
    std::vector<double> patch;
    for (int v = 0; v < level.GetNumVertices(); ++v) {
        Far::ConstIndexArray faces = level.GetVertexFaces(v);
        if (faces.size() == 0 || !factory.InitVertexSurface<double>(faces[0], &surface)) {
            continue;
        }
        Far::ConstIndexArray fv = level.GetFaceVertices(faces[0]);
        int corner = static_cast<int>(std::find(fv.begin(), fv.end(), v) - fv.begin());
        patch.resize(static_cast<size_t>(surface.GetNumPatchPoints()) * 3);
        surface.PreparePatchPoints(points.data(), desc, patch.data(), desc);
        double uv[2];
        surface.GetParameterization().GetVertexCoord(corner, uv);
        surface.Evaluate(uv, patch.data(), desc, &out[3 * static_cast<size_t>(v)]);
    }
    return out;
}

bool profsubd_vertex_limits(const profsubd_mesh *mesh, std::vector<double> *out) {
    profsubd_evaluator *ev = nullptr;
    if (profsubd_evaluator_new(mesh, nullptr, &ev) != PROFSUBD_OK) {
        return false;
    }
    size_t needed = 0;
    profsubd_evaluator_limit_vertices(ev, nullptr, nullptr, nullptr, 0, &needed);
    out->assign(needed * 3, 0.0);
    profsubd_status st = profsubd_evaluator_limit_vertices(ev, out->data(), nullptr, nullptr, needed, &needed);
    profsubd_evaluator_free(ev);
    return st == PROFSUBD_OK;
}

std::string shape_via_obj(const profsubd_mesh *mesh, const std::string &path, OsdShape *out) {
    profsubd_status st = profsubd_mesh_write_obj(mesh, path.c_str());
    if (st != PROFSUBD_OK) {
        return std::string("profsubd_mesh_write_obj: ") + profsubd_last_error_message();
    }
    std::string error;
    return read_osd_shape(path, out, &error) ? std::string() : "read " + path + ": " + error;
}

}  // namespace profsubd_test
