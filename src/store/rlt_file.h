// An open .rlt file: the whole file memory-mapped read-only and fully validated on
// open (docs/rlt-format.md), then handed out as spans that point into the mapping, so
// the run-time loop reads transfer data in place with no parse step.
// Every payload starts on a 64-byte boundary. Spans stay valid while the RltFile (or
// the RltFile it is moved into) lives.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "store/mapped_file.h"
#include "store/rlt_format.h"
#include "store/rlt_section_info.h"

namespace relight {

class RltFile {
 public:
  // Maps and validates the file: magic, version, byte order, size, table, bounds,
  // alignment, padding and every checksum. Throws InputError "FILE: reason".
  static RltFile open(const std::filesystem::path& file);

  RltFile(RltFile&&) noexcept = default;
  RltFile& operator=(RltFile&&) noexcept = default;
  RltFile(const RltFile&) = delete;
  RltFile& operator=(const RltFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::uint64_t total_bytes() const { return map_.bytes().size(); }
  // In file order.
  const std::vector<RltSectionInfo>& sections() const { return sections_; }

  const RltSectionInfo* find_info(std::uint32_t type) const;
  std::optional<std::span<const std::byte>> find_section(std::uint32_t type) const;
  // InputError "FILE: missing section of type 'META' (0x4154454d)" when absent.
  const RltSectionInfo& info(std::uint32_t type) const;
  std::span<const std::byte> section(std::uint32_t type) const;

  // The section's values; InputError when it is missing or holds another element type
  // (a section of raw bytes is read with section()).
  template <RltValue T>
  std::span<const T> view(std::uint32_t type) const {
    const std::span<const std::byte> bytes = typed_bytes(type, RltElementOf<T>::value, alignof(T));
    return {reinterpret_cast<const T*>(bytes.data()), bytes.size() / sizeof(T)};
  }
  // A text section (JSON metadata).
  std::string_view text(std::uint32_t type) const;

 private:
  RltFile(std::filesystem::path path, MappedFile map, std::vector<RltSectionInfo> sections)
      : path_(std::move(path)), map_(std::move(map)), sections_(std::move(sections)) {}
  std::span<const std::byte> bytes_of(const RltSectionInfo& info) const;
  std::span<const std::byte> typed_bytes(std::uint32_t type, RltElement element,
                                         std::size_t alignment) const;

  std::filesystem::path path_;
  MappedFile map_;
  std::vector<RltSectionInfo> sections_;
};

}  // namespace relight
