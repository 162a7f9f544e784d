// OpenEXR writing and reading (see image_exr.h). The file is encoded into memory through
// an Imf::OStream and then written by write_bytes_atomically, so EXR and PNG share one
// atomic, errno-reporting write path.
#include "image/image_exr.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfTestFile.h>
#include <half.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/input_error.h"
#include "image/image_bytes.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kPixelStride = 3 * sizeof(float);  // interleaved R, G, B floats

class MemoryOStream final : public Imf::OStream {
 public:
  MemoryOStream() : Imf::OStream("memory") {}

  void write(const char c[], int n) override {
    const std::size_t end = position_ + static_cast<std::size_t>(n);
    if (end > bytes_.size()) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
    position_ = end;
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t position) override { position_ = position; }

  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
  std::size_t position_ = 0;
};

bool needs_float(const Image& image) {
  for (const Rgb& p : image.pixels) {
    for (const double v : {p.r, p.g, p.b}) {
      if (std::isfinite(v) && std::abs(v) > kHalfMax) return true;
    }
  }
  return false;
}

// Interleaved R, G, B samples of type T (half or float), the frame buffer for them, and
// the encoded file. The buffer type must match the file's channel type on output.
template <typename T>
std::vector<std::uint8_t> encode_exr_as(const Image& image, Imf::PixelType type) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  std::vector<T> data;
  data.reserve(3 * image.pixels.size());
  for (const Rgb& p : image.pixels) {
    data.insert(data.end(), {T(static_cast<float>(p.r)), T(static_cast<float>(p.g)),
                             T(static_cast<float>(p.b))});
  }
  const std::size_t pixel_stride = 3 * sizeof(T);
  const std::size_t row_stride = pixel_stride * static_cast<std::size_t>(image.width);
  Imf::FrameBuffer frame;
  const char* names[] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    header.channels().insert(names[c], Imf::Channel(type));
    char* base = reinterpret_cast<char*>(data.data() + c);
    frame.insert(names[c], Imf::Slice(type, base, pixel_stride, row_stride));
  }

  MemoryOStream stream;
  {
    Imf::OutputFile file(stream, header);  // the offset table is written on destruction
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  }
  return stream.bytes();
}

std::vector<std::uint8_t> encode_exr(const Image& image, ExrChannels channels) {
  if (channels == ExrChannels::kFloat || needs_float(image)) {
    return encode_exr_as<float>(image, Imf::FLOAT);
  }
  return encode_exr_as<Imath::half>(image, Imf::HALF);
}

// Reads the named channels as floats into interleaved slots 0..2 of `data` (3 floats a pixel
// of the window); a channel the file lacks is filled with 0 by the library, so every slot is
// written. `data` is not initialised before: a file that declares a large window and ends
// early fails on its first missing chunk having touched only the rows it decoded.
void read_float_channels(Imf::InputFile& file, const Imath::Box2i& window,
                         const char* const (&names)[3], float* data) {
  const auto width =
      static_cast<std::size_t>(static_cast<long long>(window.max.x) - window.min.x + 1);
  Imf::FrameBuffer frame;
  for (int c = 0; c < 3; ++c) {
    frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, data + c, window, kPixelStride,
                                            kPixelStride * width, 1, 1, 0.0));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
}

Image to_image(int width, int height, const float* data) {
  Image image = make_image(width, height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    image.pixels[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
  }
  return image;
}

// Luminance-chroma files need the library's YC → RGB reconstruction (half precision).
Image read_luminance_chroma(const fs::path& path, const Imath::Box2i& window, int width,
                            int height) {
  Imf::RgbaInputFile file(path.c_str());
  std::vector<Imf::Rgba> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  // The library addresses pixel (x, y) at base + x + y * width, x and y in data-window
  // coordinates; offset the base so that the window's corner lands on pixels[0].
  const std::ptrdiff_t origin =
      static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * width;
  file.setFrameBuffer(pixels.data() - origin, 1, static_cast<std::size_t>(width));
  file.readPixels(window.min.y, window.max.y);
  Image image = make_image(width, height);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    image.pixels[i] = {float(pixels[i].r), float(pixels[i].g), float(pixels[i].b)};
  }
  return image;
}

Image decode_exr(const fs::path& path, std::size_t max_pixels) {
  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
  const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
  if (w <= 0 || h <= 0 || static_cast<std::size_t>(w * h) > max_pixels) {
    fail_input(path.string(),
               "unsupported data window " + std::to_string(w) + "x" + std::to_string(h));
  }
  const int width = static_cast<int>(w), height = static_cast<int>(h);
  const Imf::ChannelList& channels = file.header().channels();
  const auto find = [&](const char* name) -> const char* {
    const Imf::Channel* channel = channels.findChannel(name);
    if (channel == nullptr) return nullptr;
    if (channel->xSampling != 1 || channel->ySampling != 1) {
      fail_input(path.string(), std::string("subsampled channel ") + name + " is not supported");
    }
    return name;
  };

  const std::size_t samples = 3 * static_cast<std::size_t>(w * h);
  if (channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B")) {
    for (const char* name : {"R", "G", "B"}) find(name);
    const auto data = std::make_unique_for_overwrite<float[]>(samples);
    read_float_channels(file, window, {"R", "G", "B"}, data.get());
    return to_image(width, height, data.get());
  }
  if (channels.findChannel("RY") || channels.findChannel("BY")) {
    return read_luminance_chroma(path, window, width, height);
  }
  if (channels.findChannel("Y")) {
    find("Y");
    const auto data = std::make_unique_for_overwrite<float[]>(samples);
    // Y into slot 0; the two names the file lacks are filled with 0, then overwritten.
    read_float_channels(file, window, {"Y", "relight.absent.1", "relight.absent.2"}, data.get());
    for (std::size_t i = 0; i < samples; i += 3) data[i + 1] = data[i + 2] = data[i];
    return to_image(width, height, data.get());
  }
  fail_input(path.string(), "no R, G, B or Y channel");
}

std::int32_t little_endian_i32(const unsigned char* b) {
  return static_cast<std::int32_t>(
      static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
      static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24);
}

// Refuses a data window (box2i: xMin, yMin, xMax, yMax) that decode_exr would refuse, before
// OpenEXR sizes its line buffers by it: a header declaring 10⁹ × 768 pixels makes OpenEXR spend
// seconds before decode_exr sees the window (fuzz_envmap).
void check_data_window(const fs::path& path, const unsigned char (&box)[16],
                       std::size_t max_pixels) {
  const long long w =
      static_cast<long long>(little_endian_i32(box + 8)) - little_endian_i32(box) + 1;
  const long long h =
      static_cast<long long>(little_endian_i32(box + 12)) - little_endian_i32(box + 4) + 1;
  if (w <= 0 || h <= 0 ||
      static_cast<unsigned long long>(w) * static_cast<unsigned long long>(h) > max_pixels) {
    fail_input(path.string(),
               "unsupported data window " + std::to_string(w) + "x" + std::to_string(h));
  }
}

// The bytes OpenEXR reads for a value of a predefined attribute type of fixed size, whatever
// size the attribute declares (OpenEXR file layout, "Predefined Attribute Types"); 0 for the
// others (string, vectors, chlist, preview, unknown types).
std::size_t fixed_attribute_size(const std::string& type) {
  static const std::pair<const char*, std::size_t> kSizes[] = {
      {"box2i", 16},      {"box2f", 16},   {"chromaticities", 32},
      {"compression", 1}, {"double", 8},   {"envmap", 1},
      {"float", 4},       {"int", 4},      {"keycode", 28},
      {"lineOrder", 1},   {"m33f", 36},    {"m33d", 72},
      {"m44f", 64},       {"m44d", 128},   {"rational", 8},
      {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
      {"v2f", 8},         {"v2d", 16},     {"v3i", 12},
      {"v3f", 12},        {"v3d", 24},     {"deepImageState", 1}};
  for (const auto& [name, size] : kSizes) {
    if (type == name) return size;
  }
  return 0;
}

// Every attribute of an OpenEXR file's first header (OpenEXR file layout: magic, version, then
// attributes of name, type name, a little-endian int32 size and the value, up to an empty name)
// must fit in the file. OpenEXR allocates an attribute of a type it does not know by its
// declared size before reading it, so a file of a few hundred bytes could ask for 2 GiB.
// Refused here, naming the attribute; what this walk cannot follow is left to OpenEXR. The walk
// reads as OpenEXR 3.1 does, which reads a value of a known type by its type, not by its
// declared size: a fixed-size type by its size (fixed_attribute_size; a box2i declaring 0
// bytes hid a data window of ~10⁹ pixels: fuzz_envmap), a channel list (chlist) channel by
// channel up to its empty name, whatever its declared size (a chlist declaring more bytes than its
// channels hid, from a walk by sizes, the next attribute's 1.7 GB, which OpenEXR then allocated:
// fuzz_envmap), and a preview image's width × height × 4 bytes must lie within its declared size
// (OpenEXR allocates them first). The data window is checked here too (check_data_window).
void check_exr_header(const fs::path& path, std::size_t max_pixels) {
  std::error_code error;
  const std::uintmax_t file_bytes = fs::file_size(path, error);
  if (error) return;
  std::ifstream in(path, std::ios::binary);
  in.seekg(8);  // magic number and version field
  const auto read_name = [&in]() {
    std::string name;
    char c = 0;
    while (in.get(c) && c != '\0' && name.size() < 256) name.push_back(c);
    return name;
  };
  while (in) {
    const std::string name = read_name();
    if (name.empty()) return;  // the end of the header
    const std::string type = read_name();
    unsigned char size_bytes[4] = {};
    if (!in.read(reinterpret_cast<char*>(size_bytes), 4)) return;
    const std::int64_t size = little_endian_i32(size_bytes);
    const auto at = static_cast<std::uintmax_t>(in.tellg());
    if (size < 0 || static_cast<std::uintmax_t>(size) > file_bytes - at) {
      fail_input(path.string(), "attribute \"" + name + "\" declares " + std::to_string(size) +
                                    " bytes but the file has " + std::to_string(file_bytes - at) +
                                    " after it: truncated or corrupt");
    }
    if (name == "dataWindow" && type == "box2i") {
      unsigned char box[16] = {};
      if (!in.read(reinterpret_cast<char*>(box), 16)) return;
      check_data_window(path, box, max_pixels);
      continue;
    }
    if (const std::size_t fixed = fixed_attribute_size(type); fixed > 0) {
      in.seekg(static_cast<std::streamoff>(fixed), std::ios::cur);
      continue;
    }
    if (type == "chlist") {  // name, then pixel type, linearity, reserved, x and y sampling
      while (in && !read_name().empty()) in.seekg(16, std::ios::cur);
      continue;
    }
    if (type == "preview" && size >= 8) {
      unsigned char dimensions[8] = {};
      if (!in.read(reinterpret_cast<char*>(dimensions), 8)) return;
      const auto width = static_cast<std::uint32_t>(little_endian_i32(dimensions));
      const auto height = static_cast<std::uint32_t>(little_endian_i32(dimensions + 4));
      if (std::uint64_t{4} * width * height > static_cast<std::uint64_t>(size) - 8) {
        fail_input(path.string(), "preview image of " + std::to_string(width) + "x" +
                                      std::to_string(height) + " pixels in a " +
                                      std::to_string(size) + "-byte attribute: corrupt");
      }
      in.seekg(static_cast<std::streamoff>(size - 8), std::ios::cur);
      continue;
    }
    in.seekg(static_cast<std::streamoff>(size), std::ios::cur);
  }
}

}  // namespace

void write_exr(const fs::path& path, const Image& image, ExrChannels channels) {
  if (!is_valid(image)) throw std::invalid_argument("write_exr: pixel count != width × height");
  std::vector<std::uint8_t> bytes;
  try {
    bytes = encode_exr(image, channels);
  } catch (const std::exception& e) {  // Iex::BaseExc derives from std::exception
    fail_input(path.string(), std::string("cannot encode OpenEXR: ") + e.what());
  }
  write_bytes_atomically(path, bytes);
}

Image read_exr(const fs::path& path, std::size_t max_pixels) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) fail_input(path.string(), "no such file");
  if (!Imf::isOpenExrFile(path.c_str())) fail_input(path.string(), "not an OpenEXR file");
  check_exr_header(path, max_pixels);
  try {
    return decode_exr(path, max_pixels);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {  // damaged or truncated file
    fail_input(path.string(), std::string("cannot read OpenEXR: ") + e.what());
  }
}

}  // namespace relight
