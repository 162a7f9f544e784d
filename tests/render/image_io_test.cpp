// write_image: the extension picks the format, PNGs are tone mapped or false colour, and
// every write is atomic — a failed write leaves neither a temporary nor a damaged target.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/input_error.h"
#include "image/image_exr.h"
#include "image/image_png.h"
#include "render/false_color_legend.h"
#include "render/image_io.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

class ImageFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() /
              ("relight_image_" + std::to_string(::getpid()) + "_" + test->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path path(const std::string& name) const { return folder_ / name; }

  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder_)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

  fs::path folder_;
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Writes beyond `bytes` fail with EFBIG for as long as this lives (SIGXFSZ ignored), which
// makes a write fail half-way even when the tests run as root.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    previous_signal_ = std::signal(SIGXFSZ, SIG_IGN);
    getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit limited = previous_;
    limited.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previous_signal_);
  }

 private:
  rlimit previous_{};
  void (*previous_signal_)(int) = nullptr;
};

Image noise(int width, int height) {
  Image image = make_image(width, height);
  std::uint32_t state = 12345;
  for (Rgb& p : image.pixels) {
    state = state * 1664525u + 1013904223u;
    const double v = (state >> 8) / double(1 << 24) * 1000;
    p = {v, v * 0.5, v * 0.25};
  }
  return image;
}

TEST_F(ImageFile, PngAtKnownExposureHasExpectedPixel) {
  // EV100 = 0: L_max = 1.2 cd/m², so 0.6 cd/m² is display 0.5 → sRGB 0.7354 → 188.
  Image image = make_image(5, 3, {0.6, 0.6, 0.6});
  image.at(4, 2) = {0, 0, 0};
  const DisplayReport report = write_image(path("view.png"), image, {0.0, std::nullopt});

  ASSERT_TRUE(report.exposure_ev);
  EXPECT_EQ(*report.exposure_ev, 0.0);
  EXPECT_EQ(report.format, ImageFormat::kPng);
  const Image8 read = read_png(path("view.png"));
  ASSERT_EQ(read.width, 5);
  ASSERT_EQ(read.height, 3);
  EXPECT_NEAR(read.at(1, 1).r, 188, 1);
  EXPECT_NEAR(read.at(1, 1).g, 188, 1);
  EXPECT_NEAR(read.at(1, 1).b, 188, 1);
  EXPECT_EQ(read.at(4, 2), (Rgb8{0, 0, 0}));
}

TEST_F(ImageFile, PngAutomaticExposureIsReported) {
  const Image image = make_image(4, 4, {50, 50, 50});
  const DisplayReport report = write_image(path("auto.png"), image, {});
  ASSERT_TRUE(report.exposure_ev);
  EXPECT_NEAR(*report.exposure_ev, std::log2(50 / (1.2 * 0.18)), 1e-12);
}

TEST_F(ImageFile, PngInFalseColourHasLegendAndReportsScale) {
  Image image = make_image(100, 300);
  for (int y = 0; y < 300; ++y) {
    for (int x = 0; x < 100; ++x) image.at(x, y) = {10.0 + y * 3, 10.0 + y * 3, 10.0 + y * 3};
  }
  FalseColor request;
  request.quantity = Quantity::kIlluminance;
  const DisplayReport report = write_image(path("lux.png"), image, {std::nullopt, request});
  ASSERT_TRUE(report.false_color);
  EXPECT_FALSE(report.exposure_ev);
  const Image8 read = read_png(path("lux.png"));
  EXPECT_EQ(read.width, 100 + kLegendWidth);
  EXPECT_EQ(read.height, 300);
}

TEST_F(ImageFile, ExrKeepsHdrValuesWhateverTheDisplayOptions) {
  const Image image = make_image(3, 2, {1234.5, 0.25, 7});
  FalseColor request;
  const DisplayReport report = write_image(path("hdr.EXR"), image, {3.0, request});
  EXPECT_EQ(report.format, ImageFormat::kExr);
  EXPECT_FALSE(report.exposure_ev);
  const Image read = read_exr(path("hdr.EXR"));
  EXPECT_NEAR(read.at(2, 1).r, 1234.5, 1234.5 * 1e-3);
  EXPECT_NEAR(read.at(2, 1).g, 0.25, 0.25 * 1e-3);
}

TEST_F(ImageFile, UppercasePngExtensionIsAccepted) {
  write_image(path("shout.PNG"), make_image(2, 2, {1, 1, 1}), {});
  EXPECT_EQ(read_png(path("shout.PNG")).width, 2);
}

TEST_F(ImageFile, UnknownExtensionIsInputError) {
  for (const std::string name : {"picture.jpg", "picture", "picture.exr.bak"}) {
    try {
      write_image(path(name), make_image(2, 2), {});
      FAIL() << name;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path(name).string() + ": unknown image format", 0), 0u)
          << e.what();
    }
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(ImageFile, UnwritableFolderIsInputError) {
  std::ofstream(path("file.txt")) << "a file, not a folder";
  for (const fs::path& target : {path("missing/out.png"), path("file.txt/out.exr")}) {
    try {
      write_image(target, make_image(2, 2), {});
      FAIL() << target;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(target.string() + ": ", 0), 0u) << e.what();
    }
  }
  EXPECT_EQ(entries(), std::vector<std::string>{"file.txt"});
}

TEST_F(ImageFile, FailedWriteKeepsExistingFileAndLeavesNoTemporary) {
  const Image big = noise(256, 256);  // compresses to far more than the 4 KiB allowed
  for (const std::string name : {"kept.exr", "kept.png"}) {
    std::ofstream(path(name)) << "precious";
    {
      const FileSizeLimit limit(4096);
      try {
        write_image(path(name), big, {});
        ADD_FAILURE() << name << " was written past the size limit";
      } catch (const InputError& e) {  // failed in the middle of writing the temporary
        EXPECT_EQ(std::string(e.what()), path(name).string() + ": cannot write: File too large");
      }
    }
    EXPECT_EQ(read_text(path(name)), "precious") << name;
  }
  std::vector<std::string> names = entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"kept.exr", "kept.png"}));
}

TEST_F(ImageFile, FailedRenameLeavesNoTemporary) {
  fs::create_directory(path("taken.png"));  // a folder where the file should go
  EXPECT_THROW(write_image(path("taken.png"), make_image(2, 2), {}), InputError);
  EXPECT_EQ(entries(), std::vector<std::string>{"taken.png"});
  EXPECT_TRUE(fs::is_directory(path("taken.png")));
}

TEST_F(ImageFile, SuccessfulWriteReplacesExistingFile) {
  std::ofstream(path("old.png")) << "old";
  write_image(path("old.png"), make_image(3, 1, {1, 1, 1}), {});
  EXPECT_EQ(read_png(path("old.png")).width, 3);
  EXPECT_EQ(entries(), std::vector<std::string>{"old.png"});
}

TEST_F(ImageFile, ReadPngOfMissingFileIsInputError) {
  EXPECT_THROW(read_png(path("none.png")), InputError);
}

}  // namespace
}  // namespace relight
