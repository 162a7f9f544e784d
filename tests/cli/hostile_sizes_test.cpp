// Hostile sizes: inputs that declare far more data than they hold — an IES with 10⁹ vertical
// angles, an LDT with 10⁹ C planes, a glTF accessor of 10⁹ elements, a PLY header with 10¹²
// faces — are refused as bad input (exit 2, one line naming the file and the count) before anything
// that large is allocated: the command runs under a 4 GiB address-space limit, which an allocation
// of the declared size would break. (A .rlt whose sections claim more than the file holds:
// tests/store/rlt_corruption_test.cpp; a studio message over its limit:
// tests/studio/fuzz.test.mjs.)

#include <chrono>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "run_command.h"

namespace relight {
namespace {

using testing::expect_input_error;
using testing::run_relight;
using testing::TempDir;

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer reserves terabytes of address space for its shadow, which a ulimit -v forbids
// (make test-sanitize); its own limit on one allocation, 4 GiB, stands in (exceeding it aborts).
const char* kLimit =
    "export ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}max_allocation_size_mb=4096\"";
#else
const char* kLimit = "ulimit -v 4194304";  // KiB: 4 GiB of address space
#endif

std::string scene_with_luminaire(const std::string& type, const std::string& file) {
  return R"({"materials": {"g": {"albedo": [0.5, 0.5, 0.5]}},
  "geometry": [{"type": "box", "min": [0, 0, 0], "max": [2, 2, 2], "normals": "inward",
                "material": "g"}],
  "luminaires": [{"name": "l", "position": [1, 1.9, 1],
                  "distribution": {"type": ")" +
         type + R"(", "file": ")" + file + R"("}}],
  "sensors": [{"name": "s", "points": [[1, 0, 1]]}]})";
}

std::string scene_with_mesh(const std::string& file) {
  return R"({"materials": {"g": {"albedo": [0.5, 0.5, 0.5]}},
  "geometry": [{"type": "mesh", "file": ")" +
         file + R"(", "material": "g"}],
  "sensors": [{"name": "s", "points": [[1, 0, 1]]}]})";
}

// Runs precompute on `scene` under the limit; expects exit 2 with `message` and prints the time.
void expect_refused(const TempDir& dir, const std::string& scene, const std::string& message) {
  const auto path = dir.write("scene.json", scene);
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_relight("precompute '" + path.string() + "' -o '" +
                                 (dir.path() / "out.rlt").string() + "' --no-progress",
                             kLimit);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s refused in %.3f s\n", message.c_str(), seconds);
  expect_input_error(r, "");
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

TEST(HostileSizes, AnIesDeclaringABillionAnglesIsRefusedBeforeAllocating) {
  TempDir dir;
  dir.write("big.ies",
            "IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 1000000000 1000000000 1 1 0.1 0.1 0.1\n"
            "1 1 100\n0 1 2\n");
  expect_refused(dir, scene_with_luminaire("ies", "big.ies"),
                 "number of vertical angles must be between 2 and 100000, found 1000000000");
}

TEST(HostileSizes, AnLdtDeclaringABillionPlanesIsRefusedBeforeAllocating) {
  TempDir dir;
  // EULUMDAT lines 1–6: company, type, symmetry, Mc (C planes), Dc, Ng.
  dir.write("big.ldt", "ACME\n1\n1\n1000000000\n0\n37\n2.5\n");
  expect_refused(dir, scene_with_luminaire("ldt", "big.ldt"),
                 "number of C planes Mc must be between 1 and 100000, found 1000000000");
}

TEST(HostileSizes, AGltfAccessorOfABillionElementsIsRefusedBeforeAllocating) {
  TempDir dir;
  // One triangle's 36 bytes of positions (zeros will do) behind an accessor claiming 10⁹.
  dir.write("big.gltf", R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,)" +
                            std::string(59, 'A') + R"(="}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 1000000000, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})");
  expect_refused(dir, scene_with_mesh("big.gltf"),
                 "accessor reaches past the end of its bufferView");
}

TEST(HostileSizes, APlyDeclaringATrillionFacesIsRefusedBeforeAllocating) {
  TempDir dir;
  dir.write("big.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1000000000000\n"
            "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_refused(dir, scene_with_mesh("big.ply"), "in element 'face' 1 of 1000000000000");
}

}  // namespace
}  // namespace relight
