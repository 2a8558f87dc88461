// `cslice mesh`: a computed space's contact surface written as OBJ, PLY or STL, whole or in
// part; bad arguments exit 2 and leave no file.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "support/cli_run.hpp"
#include "support/examples.hpp"

using namespace cslice;
namespace fs = std::filesystem;

namespace {

int count_lines_starting(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) ++n;
  return n;
}

class MeshCli : public testkit::ScratchDirTest {
 protected:
  MeshCli() : ScratchDirTest("cslice_mesh") {}

  std::string space() {
    const std::string path = (dir_ / "cam-space.json").string();
    const testkit::RunResult r = testkit::run_cli(
        "compute " + testkit::quoted(testkit::example_path("cam")) + " -o " + testkit::quoted(path),
        dir_);
    EXPECT_EQ(r.status, 0) << r.err;
    return path;
  }

  testkit::RunResult mesh(const std::string& space_path, const std::string& args) {
    return testkit::run_cli("mesh " + testkit::quoted(space_path) + " " + args, dir_);
  }
};

}  // namespace

TEST_F(MeshCli, WritesTheSameSurfaceInEveryFormat) {
  const std::string s = space();
  for (const char* ext : {"obj", "ply", "stl"}) {
    const fs::path out = dir_ / (std::string("cam.") + ext);
    const testkit::RunResult r = mesh(s, "-o " + testkit::quoted(out.string()));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const int obj_faces = count_lines_starting(testkit::read_file(dir_ / "cam.obj"), "f ");
  const int stl_facets = count_lines_starting(testkit::read_file(dir_ / "cam.stl"), "  facet");
  const std::string ply = testkit::read_file(dir_ / "cam.ply");
  EXPECT_GT(obj_faces, 100);
  EXPECT_EQ(stl_facets, obj_faces);
  EXPECT_NE(ply.find("element face " + std::to_string(obj_faces)), std::string::npos);
  EXPECT_NE(ply.find("property int moving_feature"), std::string::npos);
}

// --tolerance trades the mesh's size for its accuracy: the knee (contact tolerance 0.01) at
// ten times that makes a quarter of the triangles, at half of it about twice as many. (A
// space computed to a fine tolerance, 1e-5 for the knee, made a 6.7 GB mesh in 17 GB of
// memory at its own tolerance; 128 MB at 0.01.)
TEST_F(MeshCli, ToleranceTradesTheMeshSizeForItsAccuracy) {
  const std::string s = (dir_ / "knee-space.json").string();
  ASSERT_EQ(testkit::run_cli("compute " + testkit::quoted(testkit::example_path("knee")) + " -o " +
                                 testkit::quoted(s),
                             dir_)
                .status,
            0);
  const auto faces = [&](const std::string& args) {
    const fs::path out = dir_ / "knee.obj";
    const testkit::RunResult r = mesh(s, "-o " + testkit::quoted(out.string()) + args);
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    return count_lines_starting(testkit::read_file(out), "f ");
  };
  const int standard = faces(""), coarse = faces(" --tolerance 0.1"),
            fine = faces(" --tolerance 0.005");
  EXPECT_EQ(faces(" --tolerance 0.01"), standard);
  EXPECT_LT(4 * coarse, standard);
  EXPECT_GT(fine, standard + standard / 2);
}

TEST_F(MeshCli, PartialReconstructionKeepsFewerTriangles) {
  const std::string s = space();
  const fs::path whole = dir_ / "whole.obj", part = dir_ / "part.obj";
  ASSERT_EQ(mesh(s, "-o " + testkit::quoted(whole.string())).status, 0);
  ASSERT_EQ(mesh(s, "-o " + testkit::quoted(part.string()) + " --theta -0.5,0.5").status, 0);
  const int all = count_lines_starting(testkit::read_file(whole), "f ");
  const int some = count_lines_starting(testkit::read_file(part), "f ");
  EXPECT_GT(some, 0);
  EXPECT_LT(some, all);
}

// The part is clipped at the range and the box: every vertex of the OBJ inside both.
TEST_F(MeshCli, PartialReconstructionIsClippedToTheRangeAndTheBox) {
  const std::string s = space();
  const fs::path part = dir_ / "part.obj";
  ASSERT_EQ(
      mesh(s, "-o " + testkit::quoted(part.string()) + " --theta -0.5,0.5 --box -1,-2,0.3,1.25")
          .status,
      0);
  std::istringstream in(testkit::read_file(part));
  int vertices = 0, outside = 0, on_cut = 0;
  for (std::string line; std::getline(in, line);) {
    double x, y, theta;
    if (std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &theta) != 3) continue;
    ++vertices;
    outside += theta < -0.5 || theta > 0.5 || x < -1 || x > 0.3 || y < -2 || y > 1.25;
    on_cut += theta == -0.5 || theta == 0.5 || x == 0.3 || y == 1.25;
  }
  EXPECT_GT(vertices, 0);
  EXPECT_EQ(outside, 0);
  EXPECT_GT(on_cut, 0);  // split along the cut, not stopped short of it
}

TEST_F(MeshCli, BadArgumentsExitTwoAndWriteNothing) {
  const std::string s = space();
  for (const std::string& args :
       {std::string("-o ") + testkit::quoted((dir_ / "m.xyz").string()),
        std::string("-o ") + testkit::quoted((dir_ / "m.obj").string()) + " --box 1,1,0,0",
        std::string("-o ") + testkit::quoted((dir_ / "m.obj").string()) + " --theta a,b",
        std::string("-o ") + testkit::quoted((dir_ / "m.obj").string()) + " --threads -2",
        std::string("-o ") + testkit::quoted((dir_ / "m.obj").string()) + " --tolerance 0",
        std::string("-o ") + testkit::quoted((dir_ / "m.obj").string()) + " --tolerance -1"}) {
    const testkit::RunResult r = mesh(s, args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  EXPECT_FALSE(fs::exists(dir_ / "m.xyz"));
  EXPECT_FALSE(fs::exists(dir_ / "m.obj"));
  testkit::write_file(dir_ / "bad.json", "{\"format\": \"cslice-space\"");
  const testkit::RunResult r =
      mesh((dir_ / "bad.json").string(), "-o " + testkit::quoted((dir_ / "m.obj").string()));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "m.obj"));
}
