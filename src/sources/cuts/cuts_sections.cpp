#include "sources/cuts/cuts_sections.h"

#include <stdexcept>

#include "common/input_error.h"

namespace relight {

namespace {

constexpr std::uint32_t kCutDirections = rlt_fourcc("CDIR");
constexpr std::uint32_t kSelfVisibilityStarts = rlt_fourcc("SVCF");
constexpr std::uint32_t kSelfVisibilityHeights = rlt_fourcc("SVCH");
constexpr std::uint32_t kSelfVisibilityBits = rlt_fourcc("SVCV");

}  // namespace

void write_cuts_sections(RltWriter& w, const CutsTransfer& cuts, CutsSectionData& data) {
  if (cuts.empty()) return;
  data.directions.clear();
  for (const Vec3& d : cuts.directions) {
    data.directions.insert(data.directions.end(), {static_cast<float>(d.x), static_cast<float>(d.y),
                                                   static_cast<float>(d.z)});
  }
  const HeightCuts& svc = cuts.self_visibility;
  w.add_f32(kCutDirections, "cut directions", data.directions);
  w.add_u64(kSelfVisibilityStarts, "self-visibility cut starts", svc.first);
  w.add_section(kSelfVisibilityHeights, "self-visibility cut heights",
                std::as_bytes(std::span(svc.heights)));
  w.add_section(kSelfVisibilityBits, "self-visibility cut bits",
                std::as_bytes(std::span(svc.visible)));
}

CutsTransferView read_cuts_sections(const RltFile& file, std::size_t receivers,
                                    const std::string& where) {
  CutsTransferView out;
  if (!file.find_section(kCutDirections)) return out;
  const std::span<const float> d = file.view<float>(kCutDirections);
  if (d.size() % 3 != 0) fail_input(where, "cut directions: not three floats each");
  for (std::size_t i = 0; i < d.size(); i += 3)
    out.directions.push_back({d[i], d[i + 1], d[i + 2]});
  const auto bytes = [&](std::uint32_t type) {
    const std::span<const std::byte> b = file.section(type);
    return std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(b.data()), b.size());
  };
  out.self_visibility = {static_cast<std::uint32_t>(out.directions.size()),
                         file.view<std::uint64_t>(kSelfVisibilityStarts),
                         bytes(kSelfVisibilityHeights), bytes(kSelfVisibilityBits)};
  try {
    check_height_cuts(out.self_visibility);
  } catch (const std::invalid_argument& e) {
    fail_input(where, std::string("self-visibility ") + e.what());
  }
  if (out.self_visibility.cut_count() != receivers) {
    fail_input(where, "self-visibility cuts: " + std::to_string(out.self_visibility.cut_count()) +
                          " cuts for " + std::to_string(receivers) + " receivers");
  }
  return out;
}

CutsTransferView cuts_view(const CutsTransfer& cuts) {
  if (cuts.empty()) return {};
  return {cuts.directions, cuts.self_visibility.view()};
}

}  // namespace relight
