#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bundle_paths/bundle_path.h"
#include "bundle_paths/name_index.h"
#include "bundle_paths/statement_names.h"

namespace toond::bundle_paths {
namespace {

using namespace std::string_literals;

TEST(NormalizePath, CleansRelativePaths) {
  EXPECT_EQ(normalize_path("spot.obj"), "spot.obj");
  EXPECT_EQ(normalize_path("textures\\spot.png"), "textures/spot.png");
  EXPECT_EQ(normalize_path("./a/./b//c.png"), "a/b/c.png");
  EXPECT_EQ(normalize_path("a/b/../c.png"), "a/c.png");
  EXPECT_EQ(normalize_path("a/b/"), "a/b");
  EXPECT_EQ(normalize_path("My Model/Tex 01.PNG"), "My Model/Tex 01.PNG");
}

TEST(NormalizePath, RejectsEverythingThatLeavesTheBundle) {
  for (const std::string& bad : {"../x"s, "/etc/passwd"s, "C:\\x"s, "c:x"s, "C:/Users/me/tex.png"s, "a/../../x"s,
                                 "\\\\server\\share\\x"s, "a\0b"s, ""s, "."s, "a/.."s, "./"s, "//"s}) {
    EXPECT_EQ(normalize_path(bad), std::nullopt) << "accepted '" << bad << "'";
  }
}

TEST(ResolveReference, SaysWhyAReferenceNamesNoPath) {
  EXPECT_EQ(resolve_reference("model/m.mtl", ".\\Tex\\a.png").path, "model/Tex/a.png");
  EXPECT_EQ(resolve_reference("model/m.mtl", "../a.png").path, "a.png");
  EXPECT_EQ(resolve_reference("model/m.mtl", "").refusal, Refusal::empty);
  EXPECT_EQ(resolve_reference("m.mtl", "./").refusal, Refusal::empty);
  EXPECT_EQ(resolve_reference("model/m.mtl", "/a.png").refusal, Refusal::absolute);
  EXPECT_EQ(resolve_reference("model/m.mtl", "C:\\a.png").refusal, Refusal::absolute);
  // Only a drive path once read relative to the folder and normalised.
  EXPECT_EQ(resolve_reference("m.mtl", "./C:/a.png").refusal, Refusal::absolute);
  EXPECT_EQ(resolve_reference("model/m.mtl", "../../a.png").refusal, Refusal::outside);
  EXPECT_EQ(resolve_reference("m.mtl", "a\0.png"s).refusal, Refusal::malformed);
  EXPECT_EQ(resolve_reference("m.mtl", std::string(256, 'x')).refusal, Refusal::malformed);
}

TEST(BundlePath, FolderUriAndPrintableNames) {
  EXPECT_EQ(folder_of("a/b/c.mtl"), "a/b");
  EXPECT_EQ(folder_of("c.mtl"), "");
  EXPECT_EQ(uri_reference("tex/my%20skin.png"), "tex/my skin.png");
  EXPECT_EQ(uri_reference("100%.png"), "100%.png");
  EXPECT_EQ(uri_reference("%zz%4"), "%zz%4");
  EXPECT_EQ(unprintable_reason("Größe/ok.png"), std::nullopt);
  EXPECT_EQ(unprintable_reason("caf\xe9.png"), "bytes that are not UTF-8");
  EXPECT_EQ(unprintable_reason("a\nb.png"), "a control character");
}

TEST(NameIndex, ExactFirstThenTheLeastNameThatMatchesIgnoringCase) {
  NameIndex index;
  for (const char* name : {"tex/A.png", "Tex/a.png", "exact.png", "EXACT.png", "Only.png"}) index.add(name);
  EXPECT_EQ(index.find("exact.png"), "exact.png");
  EXPECT_EQ(index.find("EXACT.png"), "EXACT.png");
  EXPECT_EQ(index.find("Exact.PNG"), "EXACT.png");  // 'E' < 'e'
  EXPECT_EQ(index.find("only.PNG"), "Only.png");
  // Over the whole path, not folder by folder: "tex" exists as written, yet
  // "Tex/a.png" is the least spelling of "tex/a.png".
  EXPECT_EQ(index.find("tex/a.png"), "Tex/a.png");
  EXPECT_EQ(index.find("missing.png"), std::nullopt);
  EXPECT_TRUE(same_ignoring_case("-BM", "-bm"));
  EXPECT_EQ(case_folded("Größe.PNG"), "größe.png");
}

std::vector<std::string> names_of(std::string_view statement) {
  std::vector<std::string> out;
  for (const TextureName& t : texture_names(statement)) out.push_back((t.file_name_only ? "file:" : "") + t.name);
  return out;
}

TEST(TextureNames, OptionsEscapesQuotesAndFileNames) {
  using V = std::vector<std::string>;
  EXPECT_EQ(names_of("diffuse.jpg"), V{"diffuse.jpg"});
  EXPECT_EQ(names_of("-o 0.1 0.2 diffuse.jpg"), V{"diffuse.jpg"});
  EXPECT_EQ(names_of("-s 1 2 3 -clamp on a.png"), V{"a.png"});
  EXPECT_EQ(names_of("-colorspace sRGB -o 0.1 diffuse.jpg"), V{"diffuse.jpg"});
  EXPECT_EQ(names_of("-imfchan r bumpmap2.jpg -bm 1.5"), V{"bumpmap2.jpg"});
  EXPECT_EQ(names_of("-BM 2 spec.jpg"), V{"spec.jpg"});
  EXPECT_EQ(names_of("-mm 0.1 0.3 spec.jpg"), V{"spec.jpg"});
  EXPECT_EQ(names_of("-bm 2 bump 01.png"), (V{"bump 01.png", "01.png"}));
  EXPECT_EQ(names_of("my\\ tex.png"), V{"my tex.png"});
  EXPECT_EQ(names_of("\"my tex.png\" -bm 1"), V{"my tex.png"});
  EXPECT_EQ(names_of("'skin.png'"), V{"skin.png"});
  EXPECT_EQ(names_of("..\\Tex\\Wood.PNG"), (V{"..\\Tex\\Wood.PNG", "file:Wood.PNG"}));
  EXPECT_EQ(names_of("C:\\Users\\artist\\my skin.png"),
            (V{"C:\\Users\\artist\\my skin.png", "skin.png", "file:my skin.png"}));
  EXPECT_EQ(names_of(""), V{});
  EXPECT_EQ(names_of("-bm 2"), V{});
  EXPECT_EQ(names_of("\"\""), V{});
}

TEST(MtllibNames, WordsUnlessTheWholeLineIsAFile) {
  using V = std::vector<std::string>;
  const auto none = [](const std::string&) { return false; };
  const auto spaced = [](const std::string& name) { return name == "two words.mtl"; };
  EXPECT_EQ(mtllib_names("a.mtl  b\\ c.mtl", none), (V{"a.mtl", "b c.mtl"}));
  EXPECT_EQ(mtllib_names("two words.mtl", none), (V{"two", "words.mtl"}));
  EXPECT_EQ(mtllib_names("two words.mtl ", spaced), V{"two words.mtl"});
  EXPECT_EQ(mtllib_names("one.mtl", spaced), V{"one.mtl"});
}

TEST(PathNames, AsWrittenThenTheFileNameAlone) {
  const auto names = path_names("C:\\Users\\me\\maps\\Skin.png");
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names[0].name, "C:\\Users\\me\\maps\\Skin.png");
  EXPECT_FALSE(names[0].file_name_only);
  EXPECT_EQ(names[1].name, "Skin.png");
  EXPECT_TRUE(names[1].file_name_only);
  ASSERT_EQ(path_names("skin.png").size(), 1u);  // no folders: nothing else to try
  EXPECT_TRUE(path_names("").empty());
  EXPECT_EQ(path_names("maps/").size(), 1u);  // a folder names no file alone
}
}  // namespace
}  // namespace toond::bundle_paths
