// validate_rlt: the header is checked before anything it describes is trusted, the
// table before any section, and a section's bounds before its bytes are hashed. The
// layout must be exactly the one RltWriter produces (each payload at the first 64-byte
// boundary after the previous one, zero padding), so no byte of the file goes unchecked.
#include "store/rlt_validation.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "common/input_error.h"
#include "store/xxh64.h"

namespace relight {

namespace {

using Bytes = std::span<const std::byte>;

template <class T>
T load(Bytes bytes, std::uint64_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

std::string str(std::uint64_t n) {
  return std::to_string(n);
}

RltHeader check_header(const std::filesystem::path& file, Bytes bytes) {
  const std::string where = file.string();
  const std::size_t magic_size = std::min(bytes.size(), kRltMagic.size());
  const bool magic_ok = std::equal(kRltMagic.begin(), kRltMagic.begin() + magic_size, bytes.begin(),
                                   [](unsigned char m, std::byte b) { return std::byte{m} == b; });
  if (!magic_ok) fail_input(where, "not a relight .rlt file (wrong magic bytes)");
  if (bytes.size() < sizeof(RltHeader)) {
    fail_input(where, "truncated: " + str(bytes.size()) + " bytes, shorter than the " +
                          str(sizeof(RltHeader)) + "-byte header");
  }
  const auto header = load<RltHeader>(bytes, 0);
  if (header.version != kRltFormatVersion) {
    fail_input(where, "format version " + str(header.version) + ", this relight reads " +
                          str(kRltFormatVersion) + ": run relight precompute again");
  }
  if (header.byte_order != kRltByteOrderMark) {
    fail_input(where,
               "written with a byte order other than this machine's: run relight "
               "precompute again on this machine");
  }
  if (xxh64(bytes.first(kRltHeaderChecksummed)) != header.header_checksum) {
    fail_input(where, "header is corrupted (checksum mismatch)");
  }
  if (bytes.size() < header.file_size) {
    fail_input(where, "truncated: " + str(bytes.size()) + " bytes, the header says " +
                          str(header.file_size));
  }
  if (bytes.size() > header.file_size) {
    fail_input(where, str(bytes.size()) + " bytes, the header says " + str(header.file_size) +
                          ": data after the end of the file");
  }
  return header;
}

std::string entry_name(const RltTableEntry& entry) {
  const auto end = std::find(entry.name.begin(), entry.name.end(), '\0');
  return {entry.name.begin(), end};
}

bool valid_name(const RltTableEntry& entry) {
  const auto end = std::find(entry.name.begin(), entry.name.end(), '\0');
  return end != entry.name.begin() && end != entry.name.end() &&
         std::all_of(entry.name.begin(), end, [](char c) { return c >= 0x20 && c <= 0x7E; }) &&
         std::all_of(end, entry.name.end(), [](char c) { return c == '\0'; });
}

RltSectionInfo check_entry(const std::filesystem::path& file, const RltTableEntry& entry,
                           std::uint64_t expected_offset, std::uint64_t file_size) {
  const std::string where = file.string();
  if (!valid_name(entry)) fail_input(where, "section table is corrupted (invalid section name)");
  const std::string name = entry_name(entry);
  const auto element = static_cast<RltElement>(entry.element & 0xFF);
  if ((entry.element & 0xFF) >= kRltElementCount) {
    fail_input(where, "section " + name + " has unknown element type " + str(entry.element & 0xFF));
  }
  if (entry.offset > file_size || entry.size > file_size - entry.offset) {
    fail_input(where, "section " + name + " (offset " + str(entry.offset) + ", " + str(entry.size) +
                          " bytes) extends past the end of the file (" + str(file_size) +
                          " bytes)");
  }
  if (entry.offset != expected_offset) {
    fail_input(where, "section " + name + " at offset " + str(entry.offset) + ", expected " +
                          str(expected_offset) +
                          " (the first 64-byte boundary after the previous section)");
  }
  if (entry.size % rlt_element_size(element) != 0) {
    fail_input(where, "section " + name + " has " + str(entry.size) +
                          " bytes, not a whole number of " + rlt_element_name(element) + " values");
  }
  return {entry.type, element, entry.element >> 8, name, entry.offset, entry.size, entry.checksum};
}

void check_zero_padding(const std::filesystem::path& file, Bytes padding,
                        const std::string& after) {
  if (std::any_of(padding.begin(), padding.end(), [](std::byte b) { return b != std::byte{0}; })) {
    fail_input(file.string(), "padding after " + after + " is corrupted (not zero)");
  }
}

}  // namespace

std::vector<RltSectionInfo> validate_rlt(const std::filesystem::path& file, Bytes bytes) {
  const std::string where = file.string();
  const RltHeader header = check_header(file, bytes);
  const std::uint64_t table_end =
      sizeof(RltHeader) + std::uint64_t{header.section_count} * sizeof(RltTableEntry);
  if (table_end > header.file_size) {
    fail_input(where, "header is corrupted (the section table extends past the end of the file)");
  }
  const Bytes table = bytes.subspan(sizeof(RltHeader), table_end - sizeof(RltHeader));
  if (xxh64(table) != header.table_checksum) {
    fail_input(where, "section table is corrupted (checksum mismatch)");
  }

  std::vector<RltSectionInfo> sections;
  sections.reserve(header.section_count);
  std::uint64_t end = table_end;
  for (std::uint32_t i = 0; i < header.section_count; ++i) {
    const auto entry = load<RltTableEntry>(table, std::uint64_t{i} * sizeof(RltTableEntry));
    sections.push_back(check_entry(file, entry, rlt_align(end), header.file_size));
    const RltSectionInfo& s = sections.back();
    const auto same_type = [&](const RltSectionInfo& other) { return other.type == s.type; };
    if (std::any_of(sections.begin(), sections.end() - 1, same_type)) {
      fail_input(where, "section table is corrupted (section type " + rlt_type_label(s.type) +
                            " appears twice)");
    }
    end = s.offset + s.size;
  }
  if (header.file_size != rlt_align(end)) {
    fail_input(where, str(header.file_size) + " bytes, the sections end at " + str(rlt_align(end)) +
                          ": header is corrupted");
  }

  for (std::size_t i = 0; i < sections.size(); ++i) {
    const RltSectionInfo& s = sections[i];
    const std::uint64_t next = i + 1 < sections.size() ? sections[i + 1].offset : header.file_size;
    check_zero_padding(file, bytes.subspan(s.offset + s.size, next - s.offset - s.size),
                       "section " + s.name);
    if (xxh64(bytes.subspan(s.offset, s.size)) != s.checksum) {
      fail_input(where, "section " + s.name + " is corrupted (checksum mismatch)");
    }
  }
  return sections;
}

}  // namespace relight
