// Bytes and kinds over a set of receivers' cubemap records (cubemap_encoding.h): what each record
// written costs against the other kinds, summed over chunks or ranks, or read back from a buffer.
#include <cstddef>
#include <cstdint>
#include <span>

#include "sources/portals/cubemap_encoding.h"

namespace relight {

void add_receiver(CubemapEncodingStats& stats, const EncodedReceiver& receiver) {
  ++stats.receivers;
  stats.bytes += receiver.bytes;
  stats.all_pulse_bytes += receiver.pulse_bytes;
  stats.all_haar_bytes += receiver.haar_bytes;
  stats.all_runs_bytes += receiver.runs_bytes;
  stats.all_rectangles_bytes += receiver.rectangles_bytes;
  switch (receiver.kind) {
    case CubemapCodeKind::kEmpty:
      ++stats.empty;
      break;
    case CubemapCodeKind::kPulse:
      ++stats.pulse;
      stats.pulse_bytes += receiver.bytes;
      break;
    case CubemapCodeKind::kHaar:
      ++stats.haar;
      stats.haar_bytes += receiver.bytes;
      break;
    case CubemapCodeKind::kRuns:
      ++stats.runs;
      stats.runs_bytes += receiver.bytes;
      break;
    case CubemapCodeKind::kRectangles:
      ++stats.rectangles;
      stats.rectangles_bytes += receiver.bytes;
      break;
  }
}

void add_stats(CubemapEncodingStats& sum, const CubemapEncodingStats& part) {
  sum.receivers += part.receivers;
  sum.empty += part.empty;
  sum.pulse += part.pulse;
  sum.haar += part.haar;
  sum.runs += part.runs;
  sum.rectangles += part.rectangles;
  sum.bytes += part.bytes;
  sum.pulse_bytes += part.pulse_bytes;
  sum.haar_bytes += part.haar_bytes;
  sum.runs_bytes += part.runs_bytes;
  sum.rectangles_bytes += part.rectangles_bytes;
  sum.all_pulse_bytes += part.all_pulse_bytes;
  sum.all_haar_bytes += part.all_haar_bytes;
  sum.all_runs_bytes += part.all_runs_bytes;
  sum.all_rectangles_bytes += part.all_rectangles_bytes;
}

CubemapEncodingStats cubemap_encoding_stats(int n, std::span<const std::uint8_t> records) {
  CubemapEncodingStats stats;
  for (std::size_t offset = 0; offset < records.size();) {
    const CubemapRecord rec = parse_cubemap_record(n, records.subspan(offset));
    EncodedReceiver r;
    r.kind = rec.kind;
    r.bytes = rec.bytes;
    add_receiver(stats, r);
    offset += rec.bytes;
  }
  stats.all_pulse_bytes = stats.all_haar_bytes = stats.all_runs_bytes = 0;
  stats.all_rectangles_bytes = 0;
  return stats;
}

double bytes_per_receiver(const CubemapEncodingStats& stats) {
  return stats.receivers == 0 ? 0.0 : static_cast<double>(stats.bytes) / stats.receivers;
}

}  // namespace relight
