// Photographs as a camera writes them (`relight capture`): 8- or 16-bit RGB from JPEG, PNG or TIFF,
// decoded by OpenCV's imgcodecs (Debian libopencv-imgcodecs-dev; the EXIF orientation of a JPEG is
// applied), and the exposure its EXIF records, read by libexif (Debian libexif-dev). The writer
// makes JPEGs that carry an exposure in EXIF, as a phone's do: the tests' and the benchmark's
// synthetic brackets are such files. Pinned by tests/image/photo_test.cpp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace relight {

// Row-major, top row first, interleaved R, G, B, each 0 .. 2^bits − 1.
struct Photo {
  int width = 0, height = 0;
  int bits = 8;  // 8 or 16
  std::vector<std::uint16_t> rgb;

  int max_value() const { return (1 << bits) - 1; }
  std::size_t offset(int x, int y) const {
    return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x));
  }
};

// The most pixels read_photo decodes: 250 megapixels (a phone's largest sensor is 200).
inline constexpr double kMaxPhotoPixels = 250e6;

// Reads a JPEG, PNG or TIFF (any format imgcodecs decodes) of 8 or 16 bits per channel; grey
// images read as R = G = B. Throws InputError "FILE: reason" when the file is missing, cannot
// be decoded, has another bit depth (a float TIFF), or its header declares more than
// `max_pixels` (refused before decoding: JPEG, PNG and TIFF headers are read first; a smaller
// bound keeps fuzz_photo fast).
Photo read_photo(const std::filesystem::path& path, double max_pixels = kMaxPhotoPixels);

// The same from a file's bytes held in memory (a glTF texture, scene/gltf_import.cpp); `what`
// names them in errors ("FILE: image 2").
Photo decode_photo(std::span<const std::uint8_t> bytes, const std::string& what,
                   double max_pixels = kMaxPhotoPixels);

// What EXIF says of one exposure; each field is absent when the file has no such tag.
struct PhotoExposure {
  std::optional<double> exposure_time_s;  // ExposureTime
  std::optional<double> f_number;         // FNumber
  std::optional<double> iso;              // ISOSpeedRatings (PhotographicSensitivity)
};

// The EXIF exposure tags of a file; all absent when it has no EXIF (PNG, most TIFFs).
PhotoExposure read_photo_exposure(const std::filesystem::path& path);

// Writes an 8-bit photo as a baseline JPEG of `quality` (1..100) with the given exposure in
// an EXIF APP1 segment, atomically. Throws std::invalid_argument for a photo that is not
// 8-bit or whose buffer does not match its size, InputError "PATH: reason" when it cannot be
// written.
void write_photo_jpeg(const std::filesystem::path& path, const Photo& photo, int quality,
                      const PhotoExposure& exposure);

}  // namespace relight
