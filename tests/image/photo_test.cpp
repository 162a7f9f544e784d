// Photo I/O (image/photo.h): JPEG with the EXIF exposure a phone writes, 16-bit PNG, and
// errors naming the file.
#include "image/photo.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "common/input_error.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

Photo gradient(int width, int height) {
  Photo photo{width, height, 8, std::vector<std::uint16_t>(3 * width * height)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t o = photo.offset(x, y);
      photo.rgb[o] = static_cast<std::uint16_t>(255 * x / (width - 1));
      photo.rgb[o + 1] = static_cast<std::uint16_t>(255 * y / (height - 1));
      photo.rgb[o + 2] = 128;
    }
  }
  return photo;
}

TEST(Photo, AJpegCarriesTheExposureTimeFNumberAndIsoItWasWrittenWith) {
  const testing::TempDir dir;
  const Photo photo = gradient(64, 48);
  write_photo_jpeg(dir.path() / "a.jpg", photo, 95, {1.0 / 250, 2.8, 200});
  const PhotoExposure e = read_photo_exposure(dir.path() / "a.jpg");
  ASSERT_TRUE(e.exposure_time_s && e.f_number && e.iso);
  EXPECT_NEAR(*e.exposure_time_s, 0.004, 1e-9);
  EXPECT_NEAR(*e.f_number, 2.8, 1e-6);
  EXPECT_EQ(*e.iso, 200);
  // A time that is no 1/n is kept to a millionth of a second.
  write_photo_jpeg(dir.path() / "b.jpg", photo, 95, {0.016, std::nullopt, std::nullopt});
  const PhotoExposure b = read_photo_exposure(dir.path() / "b.jpg");
  ASSERT_TRUE(b.exposure_time_s);
  EXPECT_NEAR(*b.exposure_time_s, 0.016, 1e-6);
  EXPECT_FALSE(b.f_number);
  EXPECT_FALSE(b.iso);
}

TEST(Photo, AJpegReadsBackWithinThreeLevelsOnAverageInRgbOrder) {
  const testing::TempDir dir;
  const Photo photo = gradient(64, 48);
  write_photo_jpeg(dir.path() / "a.jpg", photo, 95, {0.01, std::nullopt, std::nullopt});
  const Photo read = read_photo(dir.path() / "a.jpg");
  ASSERT_EQ(read.width, 64);
  ASSERT_EQ(read.height, 48);
  EXPECT_EQ(read.bits, 8);
  double error = 0;
  for (std::size_t i = 0; i < photo.rgb.size(); ++i) error += std::abs(read.rgb[i] - photo.rgb[i]);
  EXPECT_LT(error / static_cast<double>(photo.rgb.size()), 3.0);
  // Red grows to the right: the channels are not swapped (OpenCV decodes BGR).
  EXPECT_GT(read.rgb[read.offset(63, 10)], 240);
  EXPECT_LT(read.rgb[read.offset(0, 10)], 15);
}

TEST(Photo, ASixteenBitPngReadsAsSixteenBitsAndHasNoExif) {
  const testing::TempDir dir;
  cv::Mat bgr(4, 5, CV_16UC3, cv::Scalar(1000, 30000, 65535));  // B, G, R
  ASSERT_TRUE(cv::imwrite((dir.path() / "a.png").string(), bgr));
  const Photo read = read_photo(dir.path() / "a.png");
  EXPECT_EQ(read.bits, 16);
  EXPECT_EQ(read.max_value(), 65535);
  EXPECT_EQ(read.rgb[0], 65535);
  EXPECT_EQ(read.rgb[1], 30000);
  EXPECT_EQ(read.rgb[2], 1000);
  const PhotoExposure e = read_photo_exposure(dir.path() / "a.png");
  EXPECT_FALSE(e.exposure_time_s);
}

TEST(Photo, AMissingOrUndecodableFileIsAnInputErrorNamingIt) {
  const testing::TempDir dir;
  const auto expect_error = [](const std::filesystem::path& file, const std::string& reason) {
    try {
      read_photo(file);
      FAIL() << "no error for " << file;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), file.string() + ": " + reason);
    }
  };
  expect_error(dir.path() / "none.jpg", "no such file");
  expect_error(dir.write("junk.jpg", "not a photo"), "not a JPEG, PNG or TIFF file");
  expect_error(dir.write("cut.jpg", std::string("\xFF\xD8\xFF\xE0\x00", 5)),
               "cannot decode as JPEG, PNG or TIFF");
  // Another format imread knows is refused before it is decoded: a DICOM preamble (which
  // libgdcm's reader, reached through imread, aborted on) and a Radiance picture.
  expect_error(dir.write("dicom.jpg", std::string(128, '\0') + "DICM"),
               "not a JPEG, PNG or TIFF file");
  expect_error(dir.write("picture.jpg", "#?RADIANCE\n\n-Y 1 +X 1\n\x80\x80\x80\x80"),
               "not a JPEG, PNG or TIFF file");
}

// libjpeg decodes a file cut inside its scans with a warning, the missing part grey; relight
// refuses it. The whole file and one with bytes after its EOI (cameras pad) still read.
TEST(Photo, AJpegCutBeforeItsEndIsRefusedAndTrailingBytesAreKept) {
  const testing::TempDir dir;
  write_photo_jpeg(dir.path() / "a.jpg", gradient(64, 48), 90, {0.01, std::nullopt, std::nullopt});
  const std::string jpeg = testing::read_text(dir.path() / "a.jpg");
  EXPECT_EQ(read_photo(dir.write("padded.jpg", jpeg + std::string(300, '\0'))).width, 64);
  const std::size_t scan = jpeg.find("\xFF\xDA");
  ASSERT_NE(scan, std::string::npos);
  for (const std::size_t cut : {jpeg.size() - 2, jpeg.size() - 1, (scan + jpeg.size()) / 2}) {
    const auto file = dir.write("cut.jpg", jpeg.substr(0, cut));
    try {
      read_photo(file);
      ADD_FAILURE() << "no error for a JPEG cut to " << cut << " bytes";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                file.string() + ": a JPEG without its end (EOI marker): truncated");
    }
  }
}

// Huffman coding spends at least a bit on every 8 × 8 block: a frame declaring 228 megapixels
// over a few hundred bytes of scans (fuzz_photo's input decoded for 10 s) is refused before
// decoding, and so is an arithmetic-coded frame. The photo as written still reads.
TEST(Photo, AJpegWhoseScansCannotHoldItsFrameIsRefused) {
  const testing::TempDir dir;
  write_photo_jpeg(dir.path() / "a.jpg", gradient(64, 48), 90, {0.01, std::nullopt, std::nullopt});
  const std::string jpeg = testing::read_text(dir.path() / "a.jpg");
  EXPECT_EQ(read_photo(dir.path() / "a.jpg").height, 48);
  const std::size_t sof = jpeg.find("\xFF\xC0");
  ASSERT_NE(sof, std::string::npos);
  std::string large = jpeg;
  large.replace(sof + 5, 4, "\x4a\x0c\x2f\x10");  // 12048 × 18956
  const auto file = dir.write("large.jpg", large);
  const std::size_t scans = jpeg.size() - jpeg.find("\xFF\xDA");
  try {
    read_photo(file);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    // 4:2:0: 1506 × 2370 luma blocks and 753 × 1185 of each chroma: 5,353,830 blocks, 669,229
    // bytes.
    EXPECT_EQ(std::string(e.what()), file.string() + ": 12048 × 18956 px in " +
                                         std::to_string(scans) +
                                         " bytes of scans (at least 669229 needed): truncated or "
                                         "corrupt");
  }
  std::string arithmetic = jpeg;
  arithmetic[sof + 1] = '\xC9';
  const auto coded = dir.write("arithmetic.jpg", arithmetic);
  try {
    read_photo(coded);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              coded.string() + ": an arithmetic-coded JPEG (SOF9) is not supported");
  }
}

// The caller's bound on pixels (fuzz_photo's is 2¹⁶) refuses a picture above it from its header.
TEST(Photo, APictureAboveTheCallersBoundIsRefused) {
  const testing::TempDir dir;
  write_photo_jpeg(dir.path() / "a.jpg", gradient(64, 48), 90, {0.01, std::nullopt, std::nullopt});
  EXPECT_EQ(read_photo(dir.path() / "a.jpg", 64 * 48).width, 64);
  try {
    read_photo(dir.path() / "a.jpg", 64 * 48 - 1);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("64 × 48 px: more than relight reads"), std::string::npos)
        << e.what();
  }
}

// libjpeg skips bytes between a segment's declared end and the next marker; the header checks
// do too, so a frame behind a segment of the wrong length is still seen and its size refused
// (fuzz_photo's 236-byte file decoded for 32 s into 11 GB).
TEST(Photo, AFrameBehindASegmentOfTheWrongLengthIsStillChecked) {
  const testing::TempDir dir;
  write_photo_jpeg(dir.path() / "a.jpg", gradient(64, 48), 90, {0.01, std::nullopt, std::nullopt});
  std::string jpeg = testing::read_text(dir.path() / "a.jpg");
  const std::size_t sof = jpeg.find("\xFF\xC0");
  ASSERT_NE(sof, std::string::npos);
  jpeg.replace(sof + 5, 4, "\x75\x30\x75\x30");  // 30000 × 30000
  // After SOI: an APP1 declaring 5 bytes, then 10 that are no marker.
  jpeg.insert(2, std::string("\xFF\xE1\x00\x05\x01\x02\x03", 7) + std::string(10, '\x41'));
  const auto file = dir.write("skewed.jpg", jpeg);
  try {
    read_photo(file);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("30000 × 30000 px: more than relight reads"),
              std::string::npos)
        << e.what();
  }
}

TEST(Photo, AHeaderDeclaringMoreThan250MegapixelsIsRefusedBeforeDecodingInUnderASecond) {
  const testing::TempDir dir;
  write_photo_jpeg(dir.path() / "a.jpg", gradient(64, 48), 90, {0.01, std::nullopt, std::nullopt});
  std::string jpeg = testing::read_text(dir.path() / "a.jpg");
  const std::size_t sof = jpeg.find("\xFF\xC0");
  ASSERT_NE(sof, std::string::npos);
  jpeg.replace(sof + 5, 4, "\x75\x30\x75\x30");  // 30000 × 30000: 900 megapixels
  const auto file = dir.write("huge.jpg", jpeg);
  cv::Mat small(4, 4, CV_8UC3, cv::Scalar(1, 2, 3));
  ASSERT_TRUE(cv::imwrite((dir.path() / "huge.png").string(), small));
  std::string png = testing::read_text(dir.path() / "huge.png");
  png.replace(16, 8, std::string("\x00\x01\x00\x00\x00\x01\x00\x00", 8));  // 65536²
  const auto png_file = dir.write("huge.png", png);
  for (const auto& [path, size] : {std::pair{file, std::string("30000 × 30000")},
                                   std::pair{png_file, std::string("65536 × 65536")}}) {
    const auto start = std::chrono::steady_clock::now();
    try {
      read_photo(path);
      FAIL() << "no error for " << path;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                path.string() + ": " + size + " px: more than relight reads (250 megapixels)");
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  }
}

}  // namespace
}  // namespace relight
