#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

namespace fs = std::filesystem;

namespace profsubd_test {

Checker::Checker(std::string test_name) : name_(std::move(test_name)) {}

void Checker::set_context(std::string context) { context_ = std::move(context); }

bool Checker::check(bool ok, const std::string &what) {
    ++checks_;
    if (!ok) {
        ++failures_;
        std::cerr << name_ << ": FAILED";
        if (!context_.empty()) {
            std::cerr << " [" << context_ << "]";
        }
        std::cerr << ": " << what << "\n";
    }
    return ok;
}

void Checker::note(const std::string &message) const {
    std::cout << name_ << ": " << message << "\n";
}

int Checker::finish() const {
    std::cout << name_ << ": " << checks_ << " checks, " << failures_ << " failed\n";
    if (checks_ == 0) {
        std::cout << name_ << ": FAILED: no checks ran\n";
        return 1;
    }
    return failures_ == 0 ? 0 : 1;
}

std::string osd_shapes_dir_searched() {
    const char *env = std::getenv("PROFSUBD_OSD_SHAPES");
    if (env != nullptr && env[0] != '\0') {
        return env;
    }
    return PROFSUBD_OSD_SHAPES_DEFAULT;
}

std::string osd_shapes_dir() {
    std::string dir = osd_shapes_dir_searched();
    std::error_code ec;
    if (fs::is_directory(dir, ec)) {
        return dir;
    }
    return std::string();
}

std::vector<std::string> list_obj_files(const std::string &dir) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto &entry : fs::directory_iterator(dir, ec)) {
        if (entry.is_regular_file() && entry.path().extension() == ".obj") {
            out.push_back(entry.path().string());
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string shape_name(const std::string &path) { return fs::path(path).stem().string(); }

bool is_known_non_manifold(const std::string &name) {
    static const char *const kNames[] = {
        "catmark_fan",           "catmark_gregory_test4",      "catmark_nonman_bareverts",
        "catmark_nonman_edge100", "catmark_nonman_edges",      "catmark_nonman_quadpole8",
        "catmark_nonman_quadpole64", "catmark_nonman_quadpole360", "catmark_nonman_verts",
        "catmark_val2_nonman",
    };
    return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

TempDir::TempDir() {
    std::string pattern = (fs::temp_directory_path() / "profsubd_test_XXXXXX").string();
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    if (mkdtemp(buf.data()) == nullptr) {
        std::perror("mkdtemp");
        std::abort();
    }
    path_ = buf.data();
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

bool write_text_file(const std::string &path, const std::string &text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    return static_cast<bool>(out);
}

double bbox_diagonal(const std::vector<double> &xyz) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (size_t i = 0; i < xyz.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], xyz[i]);
        hi[i % 3] = std::max(hi[i % 3], xyz[i]);
    }
    return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                     (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

}  // namespace profsubd_test
