// The layering of the source tree (docs/architecture.md, "Stages"), checked on the real tree,
// on its documentation, and on copies of it with a deliberate breach planted.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "layering_check.h"
#include "support/temp_dir.h"

namespace relight::layering {
namespace {

namespace fs = std::filesystem;

const fs::path kRoot = RELIGHT_SOURCE_DIR;

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

std::vector<std::string> stage_folders() {
  std::vector<std::string> folders;
  for (const Stage& s : read_stages(kRoot / "CMakeLists.txt")) folders.push_back(s.folder);
  return folders;
}

// A copy of CMakeLists.txt and src/ to plant a breach in.
struct TreeCopy {
  testing::TempDir dir;
  TreeCopy() {
    fs::copy_file(kRoot / "CMakeLists.txt", dir.path() / "CMakeLists.txt");
    fs::copy(kRoot / "src", dir.path() / "src", fs::copy_options::recursive);
  }
  void append(const std::string& file, const std::string& text) const {
    std::ofstream(dir.path() / file, std::ios::app) << text;
  }
  void replace(const std::string& file, const std::string& from, const std::string& to) const {
    std::ifstream in(dir.path() / file);
    std::stringstream s;
    s << in.rdbuf();
    std::string text = s.str();
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(dir.path() / file, std::ios::trunc) << text;
  }
};

TEST(Layering, NoStageIncludesALaterStageAndEachLinksOnlyWhatItIncludes) {
  EXPECT_GE(stage_folders().size(), 15u);
  const std::vector<std::string> v = layering_violations(kRoot);
  EXPECT_TRUE(v.empty()) << joined(v);
}

TEST(Layering, ArchitectureDocListsTheStagesInTheBuildOrder) {
  EXPECT_EQ(documented_stage_order(kRoot / "docs" / "architecture.md"), stage_folders());
}

TEST(Layering, ReadmeLayoutNamesTheStagesInTheBuildOrder) {
  std::ifstream in(kRoot / "README.md");
  std::stringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  const auto layout = text.find("## Layout");
  ASSERT_NE(layout, std::string::npos);
  std::size_t at = layout;
  for (const std::string& folder : stage_folders()) {
    const auto found = text.find("`" + folder + "`", at);
    ASSERT_NE(found, std::string::npos) << "`" << folder << "` missing or out of order";
    at = found;
  }
}

TEST(Layering, APlantedUpwardIncludeIsCaughtWithItsFileAndLine) {
  const TreeCopy tree;
  tree.append("src/math/vec3.h", "#include \"cli/cli.h\"\n");
  const std::vector<std::string> v = layering_violations(tree.dir.path());
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("src/math/vec3.h:"), std::string::npos) << v[0];
  EXPECT_NE(v[0].find("\"cli/cli.h\" of stage cli, which comes after math"), std::string::npos)
      << v[0];
}

TEST(Layering, AnIncludeBetweenSourceKindsOutOfOrderIsCaught) {
  const TreeCopy tree;
  tree.append("src/sources/luminaires/luminaire_transfer_view.h",
              "#include \"sources/portals/portal_transfer_view.h\"\n");
  const std::vector<std::string> v = layering_violations(tree.dir.path());
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("of stage sources/portals, which comes after sources/luminaires"),
            std::string::npos)
      << v[0];
}

// The reference tracer is the oracle the transfer is tested against: its stage comes before
// every stage of transfer code, so that sharing any of it is an upward include.
TEST(Layering, TheReferenceTracerIncludingTransferCodeIsCaught) {
  for (const std::string header : {"engine/receivers.h", "sources/luminaires/luminaire_direct.h",
                                   "runtime/relighter.h", "render/glare.h"}) {
    const TreeCopy tree;
    tree.append("src/reference/reference_tracer.cpp", "#include \"" + header + "\"\n");
    const std::vector<std::string> v = layering_violations(tree.dir.path());
    ASSERT_EQ(v.size(), 1u) << joined(v);
    EXPECT_NE(v[0].find("src/reference/reference_tracer.cpp:"), std::string::npos) << v[0];
    EXPECT_NE(v[0].find("which comes after reference"), std::string::npos) << v[0];
  }
}

// The studio's back end reaches the lit scene through runtime/ only, never the transfer's
// stages, although they come before it.
TEST(Layering, TheStudioServerIncludingTransferCodeIsCaught) {
  for (const std::string header :
       {"engine/receivers.h", "sources/portals/shell.h", "sources/transfer_file.h"}) {
    const TreeCopy tree;
    tree.append("src/serve/studio_frames.cpp", "#include \"" + header + "\"\n");
    const std::vector<std::string> v = layering_violations(tree.dir.path());
    ASSERT_EQ(v.size(), 1u) << joined(v);
    EXPECT_NE(v[0].find("src/serve/studio_frames.cpp:"), std::string::npos) << v[0];
    EXPECT_NE(v[0].find("which serve never includes"), std::string::npos) << v[0];
  }
  // The rule read from the build file: dropped, the same include passes.
  const TreeCopy tree;
  tree.replace("CMakeLists.txt", "\nrelight_stage_never_includes(serve engine sources)", "\n");
  tree.append("src/serve/studio_frames.cpp", "#include \"engine/receivers.h\"\n");
  EXPECT_TRUE(layering_violations(tree.dir.path()).empty());
}

TEST(Layering, ALinkToAStageThatIsNotIncludedIsCaught) {
  const TreeCopy tree;
  tree.replace(
      "CMakeLists.txt",
      "relight_stage(material relight_common relight_math relight_scene TBB::tbb)",
      "relight_stage(material relight_common relight_math relight_scene TBB::tbb relight_image)");
  const std::vector<std::string> v = layering_violations(tree.dir.path());
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("material links image but includes nothing of it"), std::string::npos)
      << v[0];
}

TEST(Layering, ALinkToALaterStageIsCaught) {
  const TreeCopy tree;
  tree.replace(
      "CMakeLists.txt",
      "relight_stage(material relight_common relight_math relight_scene TBB::tbb)",
      "relight_stage(material relight_common relight_math relight_scene TBB::tbb relight_trace)");
  const std::vector<std::string> v = layering_violations(tree.dir.path());
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("material links relight_trace, no earlier stage"), std::string::npos) << v[0];
}

TEST(Layering, AnIncludedStageThatIsNotLinkedIsCaught) {
  const TreeCopy tree;
  tree.replace("CMakeLists.txt",
               "relight_stage(material relight_common relight_math relight_scene TBB::tbb)",
               "relight_stage(material relight_common relight_math TBB::tbb)");
  const std::vector<std::string> v = layering_violations(tree.dir.path());
  ASSERT_EQ(v.size(), 1u) << joined(v);
  EXPECT_NE(v[0].find("material includes scene but does not link it"), std::string::npos) << v[0];
}

}  // namespace
}  // namespace relight::layering
