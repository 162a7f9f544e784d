// RltFile: open = map + validate_rlt; accessors look sections up by type in the table
// (a handful of entries, so a linear search) and re-check what a typed view relies on.
#include "store/rlt_file.h"

#include <algorithm>
#include <cstdint>

#include "common/input_error.h"
#include "store/rlt_validation.h"

namespace relight {

RltFile RltFile::open(const std::filesystem::path& file) {
  MappedFile map = MappedFile::open_read_only(file);
  std::vector<RltSectionInfo> sections = validate_rlt(file, map.bytes());
  return RltFile(file, std::move(map), std::move(sections));
}

const RltSectionInfo* RltFile::find_info(std::uint32_t type) const {
  const auto it = std::find_if(sections_.begin(), sections_.end(),
                               [&](const RltSectionInfo& s) { return s.type == type; });
  return it == sections_.end() ? nullptr : &*it;
}

std::optional<std::span<const std::byte>> RltFile::find_section(std::uint32_t type) const {
  const RltSectionInfo* found = find_info(type);
  if (found == nullptr) return std::nullopt;
  return bytes_of(*found);
}

const RltSectionInfo& RltFile::info(std::uint32_t type) const {
  const RltSectionInfo* found = find_info(type);
  if (found == nullptr) {
    fail_input(path_.string(), "missing section of type " + rlt_type_label(type));
  }
  return *found;
}

std::span<const std::byte> RltFile::section(std::uint32_t type) const {
  return bytes_of(info(type));
}

std::string_view RltFile::text(std::uint32_t type) const {
  const std::span<const std::byte> bytes = typed_bytes(type, RltElement::text, 1);
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

std::span<const std::byte> RltFile::bytes_of(const RltSectionInfo& info) const {
  return map_.bytes().subspan(info.offset, info.size);
}

std::span<const std::byte> RltFile::typed_bytes(std::uint32_t type, RltElement element,
                                                std::size_t alignment) const {
  const RltSectionInfo& found = info(type);
  if (found.element != element) {
    fail_input(path_.string(), "section " + found.name + " holds " +
                                   rlt_element_name(found.element) + " values, read as " +
                                   rlt_element_name(element));
  }
  const std::span<const std::byte> bytes = bytes_of(found);
  // validate_rlt guarantees both; a typed view must never be built on less.
  if (bytes.size() % rlt_element_size(element) != 0 ||
      reinterpret_cast<std::uintptr_t>(bytes.data()) % alignment != 0) {
    fail_input(path_.string(), "section " + found.name + " is not a whole, aligned array of " +
                                   rlt_element_name(element) + " values");
  }
  return bytes;
}

}  // namespace relight
