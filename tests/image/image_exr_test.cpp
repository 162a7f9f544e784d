// OpenEXR writing and reading: physical values survive a round trip within half-float
// precision, values beyond half range survive in float, and files from elsewhere (DWAB,
// luminance-only, offset data windows) read correctly.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <gtest/gtest.h>
#include <half.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "common/input_error.h"
#include "image/image_exr.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

class ImageExr : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() /
              ("relight_exr_" + std::to_string(::getpid()) + "_" + test->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path path(const std::string& name) const { return folder_ / name; }
  // The bytes of a 4 × 2 image as write_exr writes it, for tests that edit its header.
  std::string small_exr_bytes() const {
    write_exr(path("whole.exr"), make_image(4, 2, {1, 2, 3}));
    std::ifstream in(path("whole.exr"), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }

  fs::path folder_;
};

void expect_relative(double expected, double actual, double tolerance) {
  EXPECT_NEAR(actual, expected, tolerance * std::abs(expected)) << "expected " << expected;
}

// Writes a file with the given half-float channels (planar values) directly through
// OpenEXR, as another program would.
void write_foreign_exr(const fs::path& file, const Imath::Box2i& window,
                       const std::vector<std::string>& channels, Imf::Compression compression,
                       const std::vector<float>& values) {
  const std::vector<Imath::half> planar(values.begin(), values.end());
  Imf::Header header(window, window);
  header.compression() = compression;
  const std::size_t width = static_cast<std::size_t>(window.max.x - window.min.x + 1);
  const std::size_t count = width * static_cast<std::size_t>(window.max.y - window.min.y + 1);
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    header.channels().insert(channels[c], Imf::Channel(Imf::HALF));
    frame.insert(channels[c], Imf::Slice::Make(Imf::HALF, planar.data() + c * count, window,
                                               sizeof(Imath::half), sizeof(Imath::half) * width));
  }
  Imf::OutputFile out(file.c_str(), header);
  out.setFrameBuffer(frame);
  out.writePixels(window.max.y - window.min.y + 1);
}

TEST_F(ImageExr, RoundTripPreservesValuesWithinHalfPrecision) {
  Image image = make_image(7, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      const double v = 1e-3 * std::pow(10.0, (x + 7 * y) * 7.0 / 35);  // 1e-3 … 5e3
      image.at(x, y) = {v, 2 * v, 0.5 * v};
    }
  }
  image.at(0, 0) = {60000, 0, 123.456};
  write_exr(path("round.exr"), image);

  const Image read = read_exr(path("round.exr"));
  ASSERT_EQ(read.width, 7);
  ASSERT_EQ(read.height, 5);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    expect_relative(image.pixels[i].r, read.pixels[i].r, 1e-3);
    expect_relative(image.pixels[i].g, read.pixels[i].g, 1e-3);
    expect_relative(image.pixels[i].b, read.pixels[i].b, 1e-3);
  }
  EXPECT_EQ(read.pixels[0].g, 0.0);
}

TEST_F(ImageExr, ValuesBeyondHalfRangeAreKeptInFloat) {
  Image image = make_image(2, 1, {100, 200, 300});
  image.at(1, 0) = {1.2e5, 3.4e7, 1.6e9};  // sunlight in lux, a lamp, the sun in cd/m²
  write_exr(path("bright.exr"), image);

  const Image read = read_exr(path("bright.exr"));
  expect_relative(1.2e5, read.at(1, 0).r, 1e-6);
  expect_relative(3.4e7, read.at(1, 0).g, 1e-6);
  expect_relative(1.6e9, read.at(1, 0).b, 1e-6);
  expect_relative(200, read.at(0, 0).g, 1e-6);
}

TEST_F(ImageExr, NanMarksSurvive) {
  Image image = make_image(2, 1, {1, 2, 3});
  image.at(1, 0) = {NAN, NAN, NAN};
  write_exr(path("nan.exr"), image);
  const Image read = read_exr(path("nan.exr"));
  EXPECT_TRUE(std::isnan(read.at(1, 0).g));
  EXPECT_NEAR(read.at(0, 0).b, 3.0, 1e-3);
}

TEST_F(ImageExr, ReadsDwabCompressedRgba) {
  const Imath::Box2i window({0, 0}, {63, 47});
  const std::size_t count = 64 * 48;
  std::vector<float> planar(4 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const double x = static_cast<double>(i % 64) / 63, y = static_cast<double>(i / 64) / 47;
    planar[i] = static_cast<float>(1 + 9 * x);          // R
    planar[count + i] = static_cast<float>(1 + 4 * y);  // G
    planar[2 * count + i] = 2.0f;                       // B
    planar[3 * count + i] = 1.0f;                       // A (ignored)
  }
  write_foreign_exr(path("dwab.exr"), window, {"R", "G", "B", "A"}, Imf::DWAB_COMPRESSION, planar);

  const Image read = read_exr(path("dwab.exr"));
  ASSERT_EQ(read.width, 64);
  ASSERT_EQ(read.height, 48);
  for (std::size_t i = 0; i < count; i += 37) {  // DWAB is lossy: a few per cent
    expect_relative(planar[i], read.pixels[i].r, 0.03);
    expect_relative(planar[count + i], read.pixels[i].g, 0.03);
    expect_relative(2.0, read.pixels[i].b, 0.03);
  }
}

TEST_F(ImageExr, LuminanceOnlyFileReadsAsGrey) {
  const Imath::Box2i window({0, 0}, {3, 1});
  write_foreign_exr(path("grey.exr"), window, {"Y"}, Imf::ZIP_COMPRESSION,
                    {1, 2, 3, 4, 5, 6, 7, 8});
  const Image read = read_exr(path("grey.exr"));
  ASSERT_EQ(read.width, 4);
  ASSERT_EQ(read.height, 2);
  EXPECT_EQ(read.at(2, 1).r, 7.0);
  EXPECT_EQ(read.at(2, 1).g, 7.0);
  EXPECT_EQ(read.at(2, 1).b, 7.0);
}

// The decode buffer is not initialised (a truncated file touches only what it decoded), so a
// channel the file lacks must still read as exactly 0, never as what the memory held.
TEST_F(ImageExr, AChannelTheFileLacksReadsAsZero) {
  const Imath::Box2i window({0, 0}, {3, 1});
  write_foreign_exr(path("rb.exr"), window, {"R", "B"}, Imf::NO_COMPRESSION,
                    {1, 2, 3, 4, 5, 6, 7, 8, 10, 20, 30, 40, 50, 60, 70, 80});
  for (int round = 0; round < 3; ++round) {  // reuse of freed memory must not show through
    const Image read = read_exr(path("rb.exr"));
    ASSERT_EQ(read.pixels.size(), 8u);
    EXPECT_EQ(read.at(2, 1).r, 7.0);
    EXPECT_EQ(read.at(2, 1).b, 70.0);
    for (const Rgb& p : read.pixels) EXPECT_EQ(p.g, 0.0);
  }
}

TEST_F(ImageExr, LuminanceChromaFileReadsAsRgb) {
  {
    Imf::RgbaOutputFile out(path("yc.exr").c_str(), 8, 8, Imf::WRITE_YC);
    const std::vector<Imf::Rgba> pixels(64, Imf::Rgba(0.5f, 0.25f, 0.125f));
    out.setFrameBuffer(pixels.data(), 1, 8);
    out.writePixels(8);
  }
  const Image read = read_exr(path("yc.exr"));
  ASSERT_EQ(read.width, 8);
  expect_relative(0.5, read.at(3, 3).r, 0.02);
  expect_relative(0.25, read.at(3, 3).g, 0.02);
  expect_relative(0.125, read.at(3, 3).b, 0.02);
}

TEST_F(ImageExr, DataWindowOffsetBecomesTheImage) {
  const Imath::Box2i window({10, 20}, {12, 21});  // 3 × 2 pixels
  std::vector<float> planar(3 * 6);
  for (std::size_t i = 0; i < planar.size(); ++i) planar[i] = static_cast<float>(i);
  write_foreign_exr(path("offset.exr"), window, {"R", "G", "B"}, Imf::PIZ_COMPRESSION, planar);
  const Image read = read_exr(path("offset.exr"));
  ASSERT_EQ(read.width, 3);
  ASSERT_EQ(read.height, 2);
  EXPECT_EQ(read.at(2, 1).r, 5.0);
  EXPECT_EQ(read.at(2, 1).g, 11.0);
  EXPECT_EQ(read.at(0, 0).b, 12.0);
}

TEST_F(ImageExr, MissingOrForeignFileIsInputError) {
  EXPECT_THROW(read_exr(path("none.exr")), InputError);
  std::ofstream(path("text.exr")) << "not an image";
  try {
    read_exr(path("text.exr"));
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path("text.exr").string() + ": not an OpenEXR file");
  }
}

TEST_F(ImageExr, TruncatedFileIsInputError) {
  write_exr(path("whole.exr"), make_image(64, 64, {1, 2, 3}));
  const auto size = fs::file_size(path("whole.exr"));
  fs::copy_file(path("whole.exr"), path("cut.exr"));
  fs::resize_file(path("cut.exr"), size / 2);
  EXPECT_THROW(read_exr(path("cut.exr")), InputError);
}

// OpenEXR allocates an attribute by its declared size before reading it; a header attribute
// larger than the rest of the file is refused first, naming it.
TEST_F(ImageExr, AnAttributeLargerThanTheFileIsRefusedNamingIt) {
  std::string bytes = small_exr_bytes();
  const std::string attribute("channels\0chlist\0", 16);
  const std::size_t at = bytes.find(attribute);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at + attribute.size(), 4, "\xFF\xFF\xFF\x7F");  // 2^31 - 1 bytes
  std::ofstream(path("big.exr"), std::ios::binary) << bytes;
  try {
    read_exr(path("big.exr"));
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path("big.exr").string() +
                                         ": attribute \"channels\" declares 2147483647 bytes"),
              std::string::npos)
        << e.what();
  }
}

// A header declaring ~10⁹ × 769 pixels (fuzz_envmap's input) is refused from the header, before
// OpenEXR sizes its buffers by it (that took seconds), and names the window.
TEST_F(ImageExr, AHugeDataWindowIsRefusedFromTheHeader) {
  std::string bytes = small_exr_bytes();
  const std::string attribute("dataWindow\0box2i\0\x10\0\0\0", 21);
  const std::size_t at = bytes.find(attribute);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at + attribute.size() + 8, 8, std::string("\x00\x07\x00\x3f\x00\x03\x00\x00", 8));
  std::ofstream(path("huge.exr"), std::ios::binary) << bytes;
  const auto start = std::chrono::steady_clock::now();
  try {
    read_exr(path("huge.exr"));
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path("huge.exr").string() + ": unsupported data window 1056966401x769");
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

// OpenEXR reads a box2i's 16 bytes whatever size the attribute declares; so does the header walk,
// which still sees a huge data window behind a declared size of 0 (fuzz_envmap's input took
// 0.85 s under ASan before decode_exr refused it).
TEST_F(ImageExr, ADataWindowDeclaringZeroBytesIsStillChecked) {
  std::string bytes = small_exr_bytes();
  const std::string attribute("dataWindow\0box2i\0", 17);
  const std::size_t at = bytes.find(attribute);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at + attribute.size(), 4, std::string(4, '\0'));  // declares 0 bytes
  bytes.replace(at + attribute.size() + 12, 8, std::string("\x00\x07\x00\x3f\x00\x03\x00\x00", 8));
  // Cut after the window: only the walk can refuse it by its window (OpenEXR would fail first
  // on the truncated header, with another message).
  bytes.resize(at + attribute.size() + 4 + 16);
  std::ofstream(path("zero.exr"), std::ios::binary) << bytes;
  try {
    read_exr(path("zero.exr"));
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path("zero.exr").string() + ": unsupported data window 1056966401x769");
  }
}

// OpenEXR reads a channel list channel by channel up to its empty name, whatever size it
// declares; the header walk does the same, so a list declaring 12 bytes more than its channels
// still reads (a walk by sizes landed inside the next attribute: fuzz_envmap's
// chlist-hides-a-1.7-GB-attribute input).
TEST_F(ImageExr, AChannelListIsWalkedChannelByChannelAsOpenExrReadsIt) {
  std::string bytes = small_exr_bytes();
  const std::string attribute("channels\0chlist\0", 16);
  const std::size_t at = bytes.find(attribute);
  ASSERT_NE(at, std::string::npos);
  const auto size_at = at + attribute.size();
  const auto declared = static_cast<unsigned char>(bytes[size_at]);
  ASSERT_LT(declared, 200);
  bytes[size_at] = static_cast<char>(declared + 12);
  std::ofstream(path("longer.exr"), std::ios::binary) << bytes;
  const Image read = read_exr(path("longer.exr"));
  EXPECT_EQ(read.width, 4);
  EXPECT_FLOAT_EQ(static_cast<float>(read.at(3, 1).b), 3.0f);
}

// Blender's studio-light environment maps are DWAB-compressed, which tinyexr cannot read.
TEST(ImageExrBlenderData, ReadsStudioLightEnvironmentMaps) {
  const fs::path folder = "/usr/share/blender/datafiles/studiolights/world";
  if (!fs::is_directory(folder)) GTEST_SKIP() << "blender-data is not installed";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".exr") continue;
    const Image image = read_exr(entry.path());
    EXPECT_GT(image.width, 0);
    EXPECT_GT(image.height, 0);
    double sum = 0;
    for (const Rgb& p : image.pixels) sum += luminance(p);
    EXPECT_TRUE(std::isfinite(sum) && sum > 0) << entry.path();
    ++files;
  }
  EXPECT_GT(files, 0);
}

}  // namespace
}  // namespace relight
