// Shared helpers of the C++ harness: a minimal check recorder (no test framework needed on a
// fresh machine) and the location of OpenSubdiv's regression shapes.
#pragma once

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace profsubd_test {

// Records checks and failures; prints each failure with the current context (e.g. a shape
// name) and a summary at the end. A test's main() returns `finish()`.
class Checker {
public:
    explicit Checker(std::string test_name);

    // What is being checked now, printed with every failure (e.g. "catmark_cube.obj").
    void set_context(std::string context);

    // Records one check; prints `what` when it fails. Returns `ok`.
    bool check(bool ok, const std::string &what);

    // Records an equality check and prints both values when they differ.
    template <class A, class B>
    bool equal(const A &actual, const B &expected, const std::string &what) {
        if (actual == expected) {
            return check(true, what);
        }
        std::ostringstream s;
        s << what << ": got " << actual << ", expected " << expected;
        return check(false, s.str());
    }

    // Prints a line, prefixed with the test name.
    void note(const std::string &message) const;

    int failures() const { return failures_; }
    int checks() const { return checks_; }

    // Prints "<test>: N checks, M failed" and returns the process exit code.
    int finish() const;

private:
    std::string name_;
    std::string context_;
    int checks_ = 0;
    int failures_ = 0;
};

// The folder of OpenSubdiv's regression shapes: $PROFSUBD_OSD_SHAPES if set, otherwise the
// path configured in CMake (PROFSUBD_OSD_SHAPES cache variable). Empty if it does not exist.
std::string osd_shapes_dir();

// Where the shapes were looked for (for the "absent" message).
std::string osd_shapes_dir_searched();

// Full paths of the *.obj files directly in `dir`, sorted by name.
std::vector<std::string> list_obj_files(const std::string &dir);

// File name without folder and extension ("catmark_cube").
std::string shape_name(const std::string &path);

// The 10 shapes of the folder that a topology check flags as non-manifold (see its README).
bool is_known_non_manifold(const std::string &name);

// Number of shapes the folder is documented to hold (README.md: 87).
constexpr std::size_t kExpectedShapeCount = 87;

// A temporary directory removed at destruction.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir &) = delete;
    TempDir &operator=(const TempDir &) = delete;
    const std::string &path() const { return path_; }
    std::string file(const std::string &name) const { return path_ + "/" + name; }

private:
    std::string path_;
};

// Diagonal of the bounding box of `xyz` (3 doubles per point).
double bbox_diagonal(const std::vector<double> &xyz);

// Writes `text` to `path`; false on failure.
bool write_text_file(const std::string &path, const std::string &text);

}  // namespace profsubd_test
