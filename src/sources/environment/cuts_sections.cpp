#include "sources/environment/cuts_sections.h"

#include <stdexcept>

#include "common/input_error.h"

namespace relight {

namespace {

constexpr std::uint32_t kCutDirections = rlt_fourcc("CDIR");
// A store of cuts is three sections: starts (u64), heights and bits (bytes).
struct StoreTypes {
  std::uint32_t starts, heights, bits;
  const char* name;
};
constexpr StoreTypes kSelfVisibility{rlt_fourcc("SVCF"), rlt_fourcc("SVCH"), rlt_fourcc("SVCV"),
                                     "self-visibility cut"};
constexpr StoreTypes kFieldCuts{rlt_fourcc("VCFF"), rlt_fourcc("VCFH"), rlt_fourcc("VCFV"),
                                "field cut"};
constexpr StoreTypes kObjectSelf{rlt_fourcc("OSVF"), rlt_fourcc("OSVH"), rlt_fourcc("OSVV"),
                                 "object self cut"};
constexpr std::uint32_t kFieldLayouts = rlt_fourcc("VCFL");
constexpr std::size_t kLayoutValues = 9;  // centre, radius, spheres, points, inner, outer, first

void write_store(RltWriter& w, const StoreTypes& t, const HeightCuts& cuts) {
  const std::string name = t.name;
  w.add_u64(t.starts, name + " starts", cuts.first);
  w.add_section(t.heights, name + " heights", std::as_bytes(std::span(cuts.heights)));
  w.add_section(t.bits, name + " bits", std::as_bytes(std::span(cuts.visible)));
}

HeightCutsView read_store(const RltFile& file, const StoreTypes& t, std::uint32_t leaves,
                          std::size_t cuts, const std::string& where) {
  const auto bytes = [&](std::uint32_t type) {
    const std::span<const std::byte> b = file.section(type);
    return std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(b.data()), b.size());
  };
  const HeightCutsView out{leaves, file.view<std::uint64_t>(t.starts), bytes(t.heights),
                           bytes(t.bits)};
  try {
    check_height_cuts(out);
  } catch (const std::invalid_argument& e) {
    fail_input(where, std::string(t.name) + "s: " + e.what());
  }
  if (out.cut_count() != cuts) {
    fail_input(where, std::string(t.name) + "s: " + std::to_string(out.cut_count()) +
                          " cuts where " + std::to_string(cuts) + " belong");
  }
  return out;
}

}  // namespace

void write_cuts_sections(RltWriter& w, const CutsTransfer& cuts, CutsSectionData& data) {
  if (cuts.empty()) return;
  data.directions.clear();
  for (const Vec3& d : cuts.directions) {
    data.directions.insert(data.directions.end(), {static_cast<float>(d.x), static_cast<float>(d.y),
                                                   static_cast<float>(d.z)});
  }
  w.add_f32(kCutDirections, "cut directions", data.directions);
  write_store(w, kSelfVisibility, cuts.self_visibility);
  if (cuts.fields.empty()) return;
  data.fields.clear();
  for (std::size_t o = 0; o < cuts.fields.size(); ++o) {
    const VisibilityFieldLayout& l = cuts.fields[o];
    data.fields.insert(data.fields.end(),
                       {l.bounds.centre.x, l.bounds.centre.y, l.bounds.centre.z, l.bounds.radius,
                        static_cast<double>(l.spheres), static_cast<double>(l.points), l.inner,
                        l.outer, static_cast<double>(cuts.field_first[o])});
  }
  w.add_f64(kFieldLayouts, "field layouts", data.fields);
  write_store(w, kFieldCuts, cuts.field_cuts);
  write_store(w, kObjectSelf, cuts.object_self_visibility);
}

CutsTransferView read_cuts_sections(const RltFile& file, std::size_t receivers, std::size_t objects,
                                    std::size_t object_vertices, const std::string& where) {
  CutsTransferView out;
  if (!file.find_section(kCutDirections)) return out;
  const std::span<const float> d = file.view<float>(kCutDirections);
  if (d.size() % 3 != 0) fail_input(where, "cut directions: not three floats each");
  for (std::size_t i = 0; i < d.size(); i += 3) {
    out.directions.push_back({d[i], d[i + 1], d[i + 2]});
  }
  const auto leaves = static_cast<std::uint32_t>(out.directions.size());
  out.self_visibility = read_store(file, kSelfVisibility, leaves, receivers, where);
  if (objects == 0) return out;
  const std::span<const double> l = file.view<double>(kFieldLayouts);
  if (l.size() != kLayoutValues * objects) fail_input(where, "field layouts: wrong count");
  std::uint64_t samples = 0;
  for (std::size_t o = 0; o < objects; ++o) {
    const double* v = &l[kLayoutValues * o];
    VisibilityFieldLayout layout;
    layout.bounds = {{v[0], v[1], v[2]}, v[3]};
    layout.spheres = static_cast<int>(v[4]);
    layout.points = static_cast<int>(v[5]);
    layout.inner = v[6];
    layout.outer = v[7];
    if (!(layout.bounds.radius > 0) || layout.spheres < 1 || layout.points < 1 ||
        !(layout.inner >= 1) || !(layout.outer >= layout.inner) ||
        v[8] != static_cast<double>(samples)) {
      fail_input(where, "field layout of object " + std::to_string(o) + " is damaged");
    }
    out.field_first.push_back(samples);
    samples += layout.sample_count();
    out.fields.push_back(layout);
  }
  out.field_first.push_back(samples);
  out.field_cuts = read_store(file, kFieldCuts, leaves, samples, where);
  out.object_self_visibility = read_store(file, kObjectSelf, leaves, object_vertices, where);
  return out;
}

CutsTransferView cuts_view(const CutsTransfer& cuts) {
  if (cuts.empty()) return {};
  return {cuts.directions,  cuts.self_visibility.view(), cuts.fields,
          cuts.field_first, cuts.field_cuts.view(),      cuts.object_self_visibility.view()};
}

}  // namespace relight
