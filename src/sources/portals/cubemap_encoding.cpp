// The encoder of a receiver's portal cubemap (paper 000 §4.1.2; layout and bounds in
// cubemap_encoding.h): every kind's record measured, and the smallest, or the one asked for,
// written, 8-bit quantised. Each kind's encoding steps are in its own file (cubemap_pulse.cpp,
// cubemap_haar.cpp, cubemap_runs.cpp, cubemap_rectangles.cpp); the records are read, decoded and
// summed in cubemap_sum.cpp, the shell's side is cubemap_shell.cpp and the stats cubemap_stats.cpp.
#include "sources/portals/cubemap_encoding.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sources/portals/cubemap_common.h"
#include "sources/portals/cubemap_face.h"
#include "sources/portals/cubemap_haar.h"
#include "sources/portals/cubemap_pulse.h"
#include "sources/portals/cubemap_rectangles.h"
#include "sources/portals/cubemap_runs.h"

namespace relight {

using cubemap_detail::cell_count;
using cubemap_detail::check_face_size;
using cubemap_detail::find_rectangles;
using cubemap_detail::find_runs;
using cubemap_detail::for_each_kept;
using cubemap_detail::haar_amplitudes;
using cubemap_detail::Quantiser;
using cubemap_detail::scale_at_least;
using cubemap_detail::write_record;
using cubemap_detail::write_rectangles_record;
using cubemap_detail::write_runs_record;

EncodedReceiver encode_receiver_cubemap(int n, std::span<const double> cells,
                                        const CubemapEncodeOptions& options,
                                        std::vector<std::uint8_t>& out,
                                        CubemapEncodeScratch& scratch) {
  check_face_size(n);
  if (cells.size() != cell_count(n))
    throw std::invalid_argument("cubemap encoding: " + std::to_string(cells.size()) +
                                " cells, expected 6·N² = " + std::to_string(cell_count(n)));
  if (!(options.threshold >= 0.0 && options.threshold <= 1.0))
    throw std::invalid_argument("cubemap encoding: threshold outside [0, 1]");
  double vmax = 0.0;
  for (double v : cells) {
    if (!(v >= 0.0 && std::isfinite(v)))
      throw std::invalid_argument("cubemap encoding: cell value negative or not finite");
    vmax = std::max(vmax, v);
  }
  EncodedReceiver result;
  if (vmax == 0.0) {
    out.push_back(static_cast<std::uint8_t>(CubemapCodeKind::kEmpty));
    result.bytes = result.pulse_bytes = result.haar_bytes = result.runs_bytes = 1;
    result.rectangles_bytes = cubemap_rectangles_fit(n) ? 1 : 0;
    return result;
  }

  const auto none = [](std::size_t, long) {};
  Quantiser pulse;
  pulse.scale = scale_at_least(vmax);
  pulse.threshold = options.threshold;
  const std::size_t pulse_count = for_each_kept(cells, pulse, none);

  const Quantiser haar = haar_amplitudes(n, cells, options.threshold, scratch);
  const std::vector<double>& amp = scratch.coefficients;
  const std::size_t haar_count = for_each_kept(amp, haar, none);

  const std::size_t run_levels = find_runs(n, cells, pulse, scratch.runs);
  result.pulse_bytes = cubemap_record_bytes(n, CubemapCodeKind::kPulse, pulse_count);
  result.haar_bytes = cubemap_record_bytes(n, CubemapCodeKind::kHaar, haar_count);
  result.runs_bytes =
      cubemap_record_bytes(n, CubemapCodeKind::kRuns, run_levels, scratch.runs.size() / 2);
  std::size_t rectangles = 0;
  const std::size_t rectangle_levels =
      cubemap_rectangles_fit(n) ? find_rectangles(n, cells, pulse, scratch.rectangles, rectangles)
                                : 0;
  result.rectangles_bytes =
      cubemap_rectangles_fit(n)
          ? cubemap_record_bytes(n, CubemapCodeKind::kRectangles, rectangle_levels, rectangles)
          : 0;
  CubemapCodeKind kind = CubemapCodeKind::kRuns;
  switch (options.choice) {
    case CubemapBasisChoice::kSmaller: {
      std::size_t smallest = result.runs_bytes;
      if (result.rectangles_bytes != 0 && result.rectangles_bytes <= smallest) {
        kind = CubemapCodeKind::kRectangles;
        smallest = result.rectangles_bytes;
      }
      if (result.pulse_bytes < smallest) {
        kind = CubemapCodeKind::kPulse;
        smallest = result.pulse_bytes;
      }
      if (result.haar_bytes < smallest) kind = CubemapCodeKind::kHaar;
      break;
    }
    case CubemapBasisChoice::kRectangles:
      if (!cubemap_rectangles_fit(n))
        throw std::invalid_argument(
            "cubemap encoding: rectangles for faces of more than 256 cells");
      kind = CubemapCodeKind::kRectangles;
      break;
    case CubemapBasisChoice::kPulse:
      kind = CubemapCodeKind::kPulse;
      break;
    case CubemapBasisChoice::kHaar:
      kind = CubemapCodeKind::kHaar;
      break;
    case CubemapBasisChoice::kRuns:
      break;
  }
  const std::size_t before = out.size();
  result.kind = kind;
  if (kind == CubemapCodeKind::kHaar) {
    result.scale = static_cast<float>(haar.scale);
    result.detail_scale = static_cast<float>(haar.detail_scale);
    write_record(n, kind, haar, amp, haar_count, out);
  } else if (kind == CubemapCodeKind::kPulse) {
    result.scale = static_cast<float>(pulse.scale);
    write_record(n, kind, pulse, cells, pulse_count, out);
  } else if (kind == CubemapCodeKind::kRuns) {
    result.scale = static_cast<float>(pulse.scale);
    write_runs_record(n, pulse, cells, scratch.runs, run_levels, out);
  } else {
    result.scale = static_cast<float>(pulse.scale);
    write_rectangles_record(n, pulse, cells, scratch.rectangles, rectangles, out);
  }
  result.bytes = out.size() - before;
  return result;
}

EncodedReceiver encode_receiver_cubemap(int n, std::span<const double> cells,
                                        const CubemapEncodeOptions& options,
                                        std::vector<std::uint8_t>& out) {
  CubemapEncodeScratch scratch;
  return encode_receiver_cubemap(n, cells, options, out, scratch);
}

}  // namespace relight
