// One entry point for the CLI's output images: the file extension picks the format.
// .exr keeps the physical values (cd/m² or lux) unchanged; .png is for looking at, so it
// is either tone-mapped like a photograph (tone_map.h) or false colour with a legend
// (false_color.h), as DisplayOptions say. Writes are atomic and failures are InputError "PATH:
// reason".
#pragma once

#include <filesystem>
#include <optional>

#include "image/image.h"
#include "render/false_color.h"

namespace relight {

struct DisplayOptions {
  std::optional<double> exposure_ev;      // EV100 for tone mapping; empty: automatic
  std::optional<FalseColor> false_color;  // set: PNG in false colour instead of tone mapped
};

enum class ImageFormat { kExr, kPng };

// From the extension, case-insensitively: .exr or .png. Throws InputError "PATH: unknown
// image format ..." otherwise.
ImageFormat image_format(const std::filesystem::path& path);

// What write_image did, for the CLI to print (e.g. the automatic exposure).
struct DisplayReport {
  ImageFormat format = ImageFormat::kExr;
  std::optional<double> exposure_ev;           // PNG, tone mapped: the EV100 used
  std::optional<FalseColorScale> false_color;  // PNG, false colour: the scale used
};

// Writes hdr to path in the format its extension names (see above). Options that do not
// apply to the format are ignored (an EXR is never tone mapped).
DisplayReport write_image(const std::filesystem::path& path, const Image& hdr,
                          const DisplayOptions& options);

}  // namespace relight
