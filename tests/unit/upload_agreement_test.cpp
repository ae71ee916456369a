// What `toon upload` sends is what the daemon uses: each bundle is found on
// disk by the CLI's scan, then imported from exactly the files it sent. The
// cases are the texture statements the two sides once read differently.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "bundle_scan.h"
#include "cli_test_helpers.h"
#include "model_checks.h"
#include "scene/import/obj_import.h"

namespace toond {
namespace {

using cli::cli_test::TempDir;

// One triangle with texture coordinates and material `a`, after the mtllib line.
const std::string kMesh = "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3\n";

struct Outcome {
  std::set<std::string> sent;  // texture files the scan found and sent
  std::set<std::string> used;  // textures the import decoded from them
  std::vector<std::string> warnings;
};

Outcome upload(const TempDir& dir) {
  const cli::BundleScan scan = cli::scan_obj_bundle(dir.path() / "m.obj");
  scene::Bundle bundle;
  Outcome out;
  for (const cli::BundleFile& f : scan.files) {
    bundle.add(f.name, f.content);
    if (!f.name.ends_with(".obj") && !f.name.ends_with(".mtl")) out.sent.insert(f.name);
  }
  const scene::Model model = scene::import_obj_bundle(bundle);
  for (const scene::Texture& t : model.textures) out.used.insert(t.path);
  out.warnings = model.warnings;
  return out;
}

struct Case {
  const char* name;       // for the test's name
  const char* statement;  // the texture statement of material `a`
  const char* file;       // the one file on disk beside the MTL that it means
};

class UploadAgreement : public ::testing::TestWithParam<Case> {};

TEST_P(UploadAgreement, TheDaemonUsesTheTextureTheCliSent) {
  TempDir dir;
  dir.write("m.obj", "mtllib m.mtl" + kMesh);
  dir.write("m.mtl", std::string("newmtl a\nKd 1 1 1\n") + GetParam().statement + "\n");
  dir.write(GetParam().file, scene::test_checks::tiny_png(10, 20, 30));
  const Outcome outcome = upload(dir);
  EXPECT_EQ(outcome.sent, std::set<std::string>{GetParam().file});
  EXPECT_EQ(outcome.used, outcome.sent);
  for (const std::string& w : outcome.warnings) EXPECT_EQ(w.find("not in the bundle"), std::string::npos) << w;
}

TEST(UploadAgreement, TheDaemonReadsEveryMaterialLibraryTheCliSent) {
  struct Library {
    const char* mtllib;  // the OBJ's line
    const char* file;    // the library on disk it means
  };
  // The daemon read only the first name of a line, and cut names at blanks.
  for (const Library& library :
       {Library{"mtllib gone.mtl m.mtl", "m.mtl"}, Library{"mtllib my model.mtl", "my model.mtl"}}) {
    SCOPED_TRACE(library.mtllib);
    TempDir dir;
    dir.write("m.obj", library.mtllib + kMesh);
    dir.write(library.file, "newmtl a\nKd 1 1 1\nmap_Kd skin.png\n");
    dir.write("skin.png", scene::test_checks::tiny_png(10, 20, 30));
    const Outcome outcome = upload(dir);
    EXPECT_EQ(outcome.sent, std::set<std::string>{"skin.png"});
    EXPECT_EQ(outcome.used, outcome.sent);
  }
}

INSTANTIATE_TEST_SUITE_P(Statements, UploadAgreement,
                         ::testing::Values(
                             // The daemon read the first word, the CLI the last.
                             Case{"UnescapedSpace", "map_Kd scanned texture.png", "texture.png"},
                             // The CLI refused the absolute path; the daemon falls back to the file name.
                             Case{"ForeignAbsolutePath", "map_Kd C:\\Users\\artist\\skin.png", "skin.png"},
                             // The daemon took off the quotes, the CLI did not.
                             Case{"Quoted", "map_Kd \"my skin.png\"", "my skin.png"},
                             // tinyobjloader reads the name as the second or third number of -o or -s.
                             Case{"ShortOffset", "map_Kd -o 0.1 diffuse.jpg", "diffuse.jpg"},
                             Case{"ShortScale", "norm -s 2 2 normal.png", "normal.png"},
                             Case{"OptionAfterTheName", "map_Kd wood.png -BM 1.5", "wood.png"},
                             Case{"BackslashesAndCase", "map_Kd -bm 1 .\\TEX\\Wood.PNG", "Tex/wood.png"}),
                         [](const ::testing::TestParamInfo<Case>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace toond
