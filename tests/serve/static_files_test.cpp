// serve/static_files.h: the client's files by path, three.js under /vendor/three/, and nothing
// outside the client folder however the path is spelled.
#include <gtest/gtest.h>

#include "common/input_error.h"
#include "serve/static_files.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

using testing::TempDir;

class StaticFiles : public ::testing::Test {
 protected:
  StaticFiles() {
    dir.write("index.html", "<html>studio</html>");
    std::filesystem::create_directories(dir.path() / "src");
    dir.write("src/main.js", "export const x = 1;");
    std::filesystem::create_directories(dir.path() / "node_modules/three/build");
    dir.write("node_modules/three/build/three.module.js", "// three");
    dir.write("node_modules/other.js", "secret");
  }
  HttpResponse get(const std::string& path) const {
    return serve_static_file(dir.path(), "GET", path);
  }
  TempDir dir;
};

TEST_F(StaticFiles, ServesIndexFilesAndThreeWithTheirTypes) {
  EXPECT_EQ(get("/").body, "<html>studio</html>");
  EXPECT_EQ(get("/").content_type, "text/html; charset=utf-8");
  EXPECT_EQ(get("/src/main.js").body, "export const x = 1;");
  EXPECT_EQ(get("/src/main.js").content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(get("/vendor/three/build/three.module.js").body, "// three");
  EXPECT_EQ(serve_static_file(dir.path(), "HEAD", "/").status, 200);
  EXPECT_EQ(serve_static_file(dir.path(), "HEAD", "/").body, "");
}

TEST_F(StaticFiles, RefusesEscapesAndMissingFiles) {
  EXPECT_EQ(get("/missing.js").status, 404);
  EXPECT_EQ(get("/src").status, 404);  // a folder
  EXPECT_EQ(get("/node_modules/other.js").status, 404);
  for (const char* bad : {"/../secret", "/src/../../x", "/./index.html", "//etc/passwd",
                          "/src\\..\\x", "/%2e%2e/x", "relative", ""}) {
    EXPECT_EQ(get(bad).status, 400) << bad;
  }
  EXPECT_EQ(get(std::string("/index.html\0.js", 15)).status, 400);
  EXPECT_EQ(serve_static_file(dir.path(), "POST", "/").status, 405);
}

TEST_F(StaticFiles, ClientFolderMustHoldIndexAndThree) {
  EXPECT_EQ(studio_client_folder(dir.path()), dir.path());
  TempDir empty;
  EXPECT_THROW(studio_client_folder(empty.path()), InputError);
  empty.write("index.html", "x");
  try {
    studio_client_folder(empty.path());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bootstrap"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace relight
