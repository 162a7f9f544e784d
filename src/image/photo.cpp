// Photo I/O (see photo.h): OpenCV's imgcodecs decodes and encodes pixels, libexif reads and
// builds the EXIF block. A JPEG's EXIF is an APP1 segment right after the start-of-image
// marker: "FF E1", a big-endian length that counts itself, then "Exif\0\0" and a TIFF
// structure (the EXIF 2.3 standard, CIPA DC-008, §4.5.4).
#include "image/photo.h"

#include <libexif/exif-data.h>

#include <libexif/exif-mem.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/input_error.h"
#include "image/image_bytes.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

// What is read for the checks before decoding: EXIF and other APPn segments come first.
constexpr std::size_t kHeaderBytes = std::size_t{256} * 1024;

struct ExifDataUnref {
  void operator()(ExifData* data) const { exif_data_unref(data); }
};
using ExifDataPtr = std::unique_ptr<ExifData, ExifDataUnref>;

std::optional<double> rational_tag(ExifData* data, ExifTag tag) {
  ExifEntry* entry = exif_data_get_entry(data, tag);
  if (entry == nullptr || entry->format != EXIF_FORMAT_RATIONAL || entry->components < 1 ||
      entry->data == nullptr) {
    return std::nullopt;
  }
  const ExifRational r = exif_get_rational(entry->data, exif_data_get_byte_order(data));
  if (r.denominator == 0 || r.numerator == 0) return std::nullopt;
  return static_cast<double>(r.numerator) / static_cast<double>(r.denominator);
}

std::optional<double> integer_tag(ExifData* data, ExifTag tag) {
  ExifEntry* entry = exif_data_get_entry(data, tag);
  if (entry == nullptr || entry->components < 1 || entry->data == nullptr) return std::nullopt;
  const ExifByteOrder order = exif_data_get_byte_order(data);
  double value = 0;
  if (entry->format == EXIF_FORMAT_SHORT) {
    value = exif_get_short(entry->data, order);
  } else if (entry->format == EXIF_FORMAT_LONG) {
    value = exif_get_long(entry->data, order);
  } else {
    return std::nullopt;
  }
  if (value <= 0) return std::nullopt;
  return value;
}

// A rational close to t: 1/n for the usual shutter speeds, else millionths.
ExifRational to_rational(double t) {
  if (t > 0 && t < 1) {
    const double n = std::round(1 / t);
    if (std::abs(1 / n - t) <= 1e-6 * t) return {1, static_cast<ExifLong>(n)};
  }
  return {static_cast<ExifLong>(std::lround(t * 1e6)), 1000000};
}

// Adds a tag to an IFD, its data allocated by the entry's own allocator (which frees it).
void add_entry(ExifData* data, ExifIfd ifd, ExifTag tag, ExifFormat format, std::size_t byte_size,
               const auto& write) {
  ExifMem* mem = exif_mem_new_default();
  if (mem == nullptr) throw std::bad_alloc();
  ExifEntry* entry = exif_entry_new_mem(mem);
  auto* bytes = static_cast<unsigned char*>(
      entry == nullptr ? nullptr : exif_mem_alloc(mem, static_cast<ExifLong>(byte_size)));
  exif_mem_unref(mem);  // the entry holds its own reference
  if (bytes == nullptr) {
    if (entry != nullptr) exif_entry_unref(entry);
    throw std::bad_alloc();
  }
  entry->tag = tag;
  entry->format = format;
  entry->components = 1;
  entry->size = static_cast<unsigned int>(byte_size);
  entry->data = bytes;
  write(entry->data, exif_data_get_byte_order(data));
  exif_content_add_entry(data->ifd[ifd], entry);
  exif_entry_unref(entry);
}

std::vector<std::uint8_t> exif_block(const PhotoExposure& exposure) {
  const ExifDataPtr data(exif_data_new());
  if (!data) throw std::bad_alloc();
  exif_data_set_byte_order(data.get(), EXIF_BYTE_ORDER_INTEL);
  exif_data_set_data_type(data.get(), EXIF_DATA_TYPE_COMPRESSED);
  const auto add_rational = [&](ExifTag tag, double value) {
    add_entry(data.get(), EXIF_IFD_EXIF, tag, EXIF_FORMAT_RATIONAL, 8,
              [value](unsigned char* bytes, ExifByteOrder order) {
                exif_set_rational(bytes, order, to_rational(value));
              });
  };
  if (exposure.exposure_time_s) add_rational(EXIF_TAG_EXPOSURE_TIME, *exposure.exposure_time_s);
  if (exposure.f_number) add_rational(EXIF_TAG_FNUMBER, *exposure.f_number);
  if (exposure.iso) {
    const auto iso = static_cast<ExifShort>(std::lround(*exposure.iso));
    add_entry(
        data.get(), EXIF_IFD_EXIF, EXIF_TAG_ISO_SPEED_RATINGS, EXIF_FORMAT_SHORT, 2,
        [iso](unsigned char* bytes, ExifByteOrder order) { exif_set_short(bytes, order, iso); });
  }
  unsigned char* bytes = nullptr;
  unsigned int size = 0;
  exif_data_save_data(data.get(), &bytes, &size);
  const std::unique_ptr<unsigned char, decltype(&std::free)> owned(bytes, &std::free);
  if (bytes == nullptr || size == 0) throw std::runtime_error("libexif: cannot build EXIF");
  return {bytes, bytes + size};
}

std::uint32_t big_endian(std::span<const std::uint8_t> b, std::size_t at, int bytes) {
  std::uint32_t v = 0;
  for (int k = 0; k < bytes; ++k) v = (v << 8) | b[at + static_cast<std::size_t>(k)];
  return v;
}

std::uint32_t in_order(std::span<const std::uint8_t> b, std::size_t at, int bytes, bool little) {
  if (!little) return big_endian(b, at, bytes);
  std::uint32_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | b[at + static_cast<std::size_t>(k)];
  return v;
}

// The offset of the first marker segment of a JPEG (after its SOI) whose marker satisfies
// `wanted`, walking the segments' lengths (ITU-T T.81 §B.1.1.4); nullopt when none starts within
// these bytes (at least 10 of them from the marker on). Where a segment's length does not end at
// a marker, the walk skips to the next FF and a marker byte, as libjpeg does ("extraneous bytes
// before marker"): a 236-byte file whose APP1 declares 5 bytes hides from a strict walk a frame
// that libjpeg then decodes, for 32 s and 11 GB (fuzz_photo).
template <typename Wanted>
std::optional<std::size_t> find_jpeg_marker(std::span<const std::uint8_t> b, Wanted wanted) {
  std::size_t at = 2;
  while (at + 9 < b.size()) {
    const std::uint8_t marker = b[at + 1];
    if (b[at] != 0xFF || marker == 0xFF || marker == 0x00) {  // not a marker, or a fill byte
      ++at;
      continue;
    }
    if (wanted(marker)) return at;
    const bool standalone = marker == 0x01 || (marker >= 0xD0 && marker <= 0xD9);  // TEM, RSTn
    at += standalone ? 2 : 2 + big_endian(b, at + 2, 2);
  }
  return std::nullopt;
}

// Whether a JPEG's bytes from its first scan (SOS) on hold an EOI marker (FF D9): in
// entropy-coded data a byte FF is always followed by 00 or a marker (T.81 §B.1.1.5), so FF D9 is
// the end of the image, never data. A file cut inside its scans has none; libjpeg would decode
// the rest of the declared picture from nothing (a grey lower part) with only a warning.
bool jpeg_reaches_its_end(std::span<const std::uint8_t> b) {
  const auto scan = find_jpeg_marker(b.first(std::min(b.size(), kHeaderBytes)),
                                     [](std::uint8_t marker) { return marker == 0xDA; });
  if (!scan) return true;  // no scan within the header: imdecode says what is wrong
  for (std::size_t k = *scan; k + 1 < b.size(); ++k) {
    if (b[k] == 0xFF && b[k + 1] == 0xD9) return true;
  }
  return false;
}

// Refuses a JPEG whose scans cannot hold the picture its frame header (SOF, ITU-T T.81 §B.2.2)
// declares. Huffman coding spends at least one bit on every 8 × 8 block of every component (a
// DC difference's category is a code of 1 to 16 bits, §F.1.2.1, Annex C; a progressive file
// codes every DC first, §G.1.1.1.1), so the bytes from the first scan (SOS) on number at least
// the blocks / 8. libjpeg decodes the blocks a file lacks as grey with only a warning: 859 bytes
// declaring 12048 × 18956 px take 10 s to decode to nothing (fuzz_photo). Arithmetic coding
// (SOF9–11, 13–15) has no such bound and no camera writes it: refused as unsupported.
void check_jpeg_scans_hold_the_frame(std::span<const std::uint8_t> b, const std::string& what) {
  const std::span<const std::uint8_t> head = b.first(std::min(b.size(), kHeaderBytes));
  const auto frame = find_jpeg_marker(head, [](std::uint8_t marker) {
    return marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
  });
  const auto scan = find_jpeg_marker(head, [](std::uint8_t marker) { return marker == 0xDA; });
  if (!frame || !scan) return;  // imdecode says what is wrong
  const std::uint8_t marker = head[*frame + 1];
  if (marker >= 0xC9) {
    std::ostringstream reason;
    reason << "an arithmetic-coded JPEG (SOF" << (marker - 0xC0) << ") is not supported";
    fail_input(what, reason.str());
  }
  const std::uint64_t height = big_endian(head, *frame + 5, 2),
                      width = big_endian(head, *frame + 7, 2);
  const std::size_t components = head[*frame + 9];
  if (*frame + 10 + 3 * components > head.size()) return;
  std::uint64_t h_max = 1, v_max = 1;
  for (std::size_t c = 0; c < components; ++c) {
    const std::uint8_t sampling = head[*frame + 11 + 3 * c];
    h_max = std::max<std::uint64_t>(h_max, sampling >> 4);
    v_max = std::max<std::uint64_t>(v_max, sampling & 15);
  }
  const auto up = [](std::uint64_t a, std::uint64_t d) { return (a + d - 1) / d; };
  std::uint64_t blocks = 0;
  for (std::size_t c = 0; c < components; ++c) {
    const std::uint8_t sampling = head[*frame + 11 + 3 * c];
    blocks +=
        up(up(width * (sampling >> 4), h_max), 8) * up(up(height * (sampling & 15), v_max), 8);
  }
  const std::uint64_t needed = up(blocks, 8), held = b.size() - *scan;
  if (held < needed) {
    std::ostringstream reason;
    reason << width << " × " << height << " px in " << held << " bytes of scans (at least "
           << needed << " needed): truncated or corrupt";
    fail_input(what, reason.str());
  }
}

// Width × height from the first bytes of a JPEG (its start-of-frame marker, ITU-T T.81 §B.2.2),
// PNG (IHDR, PNG §11.2.2) or TIFF (ImageWidth 256 and ImageLength 257 of the first IFD,
// TIFF 6.0 §2); nullopt when the header does not say within these bytes.
std::optional<std::pair<std::uint32_t, std::uint32_t>> declared_size(
    std::span<const std::uint8_t> b) {
  const std::size_t n = b.size();
  if (n >= 24 && b[0] == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G') {
    return std::pair{big_endian(b, 16, 4), big_endian(b, 20, 4)};
  }
  if (n >= 4 && b[0] == 0xFF && b[1] == 0xD8) {
    const auto frame = find_jpeg_marker(b, [](std::uint8_t marker) {
      return marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    });
    if (!frame) return std::nullopt;
    return std::pair{big_endian(b, *frame + 7, 2), big_endian(b, *frame + 5, 2)};
  }
  const bool little = n >= 8 && b[0] == 'I' && b[1] == 'I' && b[2] == 42 && b[3] == 0;
  const bool big = n >= 8 && b[0] == 'M' && b[1] == 'M' && b[2] == 0 && b[3] == 42;
  if (!little && !big) return std::nullopt;
  const std::size_t ifd = in_order(b, 4, 4, little);
  if (ifd + 2 > n) return std::nullopt;
  const std::size_t entries = in_order(b, ifd, 2, little);
  std::uint32_t width = 0, height = 0;
  for (std::size_t e = 0; e < entries && ifd + 2 + 12 * (e + 1) <= n; ++e) {
    const std::size_t at = ifd + 2 + 12 * e;
    const std::uint32_t tag = in_order(b, at, 2, little), type = in_order(b, at + 2, 2, little);
    const std::uint32_t value =
        type == 3 ? in_order(b, at + 8, 2, little) : in_order(b, at + 8, 4, little);
    if (tag == 256) width = value;
    if (tag == 257) height = value;
  }
  if (width == 0 || height == 0) return std::nullopt;
  return std::pair{width, height};
}

// Whether the first bytes are a JPEG (SOI then a marker, ITU-T T.81 §B.1.1.3), PNG (its 8-byte
// signature, PNG §5.2) or TIFF/BigTIFF (byte order then 42 or 43, TIFF 6.0 §2). imdecode picks its
// decoder by signature among all it has; a file that is none of these three could reach another
// (libgdcm's DICOM reader aborts the process on some files:
// tests/fuzz/corpus/photo/not-a-photo-dicom).
bool is_jpeg_png_or_tiff(std::span<const std::uint8_t> b) {
  const auto starts = [&](std::initializer_list<std::uint8_t> magic) {
    return b.size() >= magic.size() && std::equal(magic.begin(), magic.end(), b.begin());
  };
  return starts({0xFF, 0xD8, 0xFF}) || starts({0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}) ||
         starts({'I', 'I', 42, 0}) || starts({'M', 'M', 0, 42}) || starts({'I', 'I', 43, 0}) ||
         starts({'M', 'M', 0, 43});
}

}  // namespace

Photo decode_photo(std::span<const std::uint8_t> bytes, const std::string& what,
                   double max_pixels) {
  // Refused before decoding: a header may declare a size whose pixels would not fit.
  const std::span<const std::uint8_t> head = bytes.first(std::min(bytes.size(), kHeaderBytes));
  if (!is_jpeg_png_or_tiff(head)) fail_input(what, "not a JPEG, PNG or TIFF file");
  if (const auto size = declared_size(head);
      size && static_cast<double>(size->first) * size->second > max_pixels) {
    std::ostringstream reason;
    reason << size->first << " × " << size->second << " px: more than relight reads ("
           << max_pixels / 1e6 << " megapixels)";
    fail_input(what, reason.str());
  }
  if (head[0] == 0xFF && !jpeg_reaches_its_end(bytes)) {
    fail_input(what, "a JPEG without its end (EOI marker): truncated");
  }
  if (head[0] == 0xFF) check_jpeg_scans_hold_the_frame(bytes, what);
  // imdecode reads from a Mat header over the bytes; it does not write them.
  const cv::Mat encoded(1, static_cast<int>(std::min<std::size_t>(bytes.size(), INT32_MAX)), CV_8U,
                        const_cast<std::uint8_t*>(bytes.data()));
  const cv::Mat decoded = cv::imdecode(encoded, cv::IMREAD_ANYDEPTH | cv::IMREAD_COLOR);
  if (decoded.empty()) fail_input(what, "cannot decode as JPEG, PNG or TIFF");
  if (decoded.depth() != CV_8U && decoded.depth() != CV_16U) {
    fail_input(what, "not 8 or 16 bits per channel");
  }
  cv::Mat rgb;
  cv::cvtColor(decoded, rgb, cv::COLOR_BGR2RGB);
  Photo photo;
  photo.width = rgb.cols;
  photo.height = rgb.rows;
  photo.bits = rgb.depth() == CV_8U ? 8 : 16;
  photo.rgb.resize(3 * static_cast<std::size_t>(rgb.cols) * static_cast<std::size_t>(rgb.rows));
  cv::Mat wide(rgb.rows, rgb.cols, CV_16UC3, photo.rgb.data());
  rgb.convertTo(wide, CV_16UC3);
  return photo;
}

Photo read_photo(const fs::path& path, double max_pixels) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) fail_input(path.string(), "no such file");
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  if (!in.eof() && in.fail()) fail_input(path.string(), "cannot read the file");
  if (bytes.empty()) fail_input(path.string(), "an empty file");
  return decode_photo(bytes, path.string(), max_pixels);
}

PhotoExposure read_photo_exposure(const fs::path& path) {
  const ExifDataPtr data(exif_data_new_from_file(path.c_str()));
  if (!data) return {};
  return {rational_tag(data.get(), EXIF_TAG_EXPOSURE_TIME),
          rational_tag(data.get(), EXIF_TAG_FNUMBER),
          integer_tag(data.get(), EXIF_TAG_ISO_SPEED_RATINGS)};
}

void write_photo_jpeg(const fs::path& path, const Photo& photo, int quality,
                      const PhotoExposure& exposure) {
  if (photo.bits != 8 || photo.width <= 0 || photo.height <= 0 ||
      photo.rgb.size() != 3 * static_cast<std::size_t>(photo.width) * photo.height) {
    throw std::invalid_argument("write_photo_jpeg: not an 8-bit photo of its size");
  }
  const cv::Mat wide(photo.height, photo.width, CV_16UC3,
                     const_cast<std::uint16_t*>(photo.rgb.data()));
  cv::Mat rgb;
  wide.convertTo(rgb, CV_8UC3);
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::vector<std::uint8_t> jpeg;
  if (!cv::imencode(".jpg", bgr, jpeg, {cv::IMWRITE_JPEG_QUALITY, quality}) || jpeg.size() < 2) {
    fail_input(path.string(), "cannot encode JPEG");
  }
  const std::vector<std::uint8_t> exif = exif_block(exposure);
  const std::size_t length = exif.size() + 2;
  if (length > 0xFFFF) throw std::runtime_error("write_photo_jpeg: EXIF block too large");
  std::vector<std::uint8_t> bytes(jpeg.begin(), jpeg.begin() + 2);  // SOI
  bytes.insert(bytes.end(), {0xFF, 0xE1, static_cast<std::uint8_t>(length >> 8),
                             static_cast<std::uint8_t>(length & 0xFF)});
  bytes.insert(bytes.end(), exif.begin(), exif.end());
  bytes.insert(bytes.end(), jpeg.begin() + 2, jpeg.end());
  write_bytes_atomically(path, bytes);
}

}  // namespace relight
