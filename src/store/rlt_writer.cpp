// RltWriter::write: the header and table go last, once every payload checksum is known;
// each payload is hashed and written piece by piece while the piece is still in cache,
// so the caller's data is read from memory once.
#include "store/rlt_writer.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

#include "common/atomic_file.h"
#include "store/output_file.h"
#include "store/xxh64.h"

namespace relight {

namespace {

constexpr std::size_t kPieceBytes = 1 << 20;

void check_name(const std::string& name) {
  if (name.empty() || name.size() >= kRltNameCapacity) {
    throw std::invalid_argument("rlt section name must have 1 to 31 bytes: '" + name + "'");
  }
  for (const char c : name) {
    if (c < 0x20 || c > 0x7E) {
      throw std::invalid_argument("rlt section name must be printable ASCII: '" + name + "'");
    }
  }
}

template <class T>
std::span<const std::byte> bytes_of(const T& value) {
  return std::as_bytes(std::span(&value, 1));
}

// Writes bytes and returns their XXH64.
std::uint64_t write_hashed(OutputFile& out, std::span<const std::byte> bytes) {
  Xxh64 hash;
  while (!bytes.empty()) {
    const auto piece = bytes.first(std::min(bytes.size(), kPieceBytes));
    hash.update(piece);
    out.append(piece);
    bytes = bytes.subspan(piece.size());
  }
  return hash.digest();
}

}  // namespace

void RltWriter::add_section(std::uint32_t type, std::string name, std::span<const std::byte> bytes,
                            RltElement element, std::uint32_t flags) {
  check_name(name);
  const bool taken = std::any_of(sections_.begin(), sections_.end(),
                                 [&](const Section& s) { return s.type == type; });
  if (taken) {
    throw std::invalid_argument("rlt section type " + rlt_type_label(type) + " added twice ('" +
                                name + "')");
  }
  if (static_cast<std::uint32_t>(element) >= kRltElementCount) {
    throw std::invalid_argument("rlt section '" + name + "': unknown element type");
  }
  if (flags > kRltMaxFlags) {
    throw std::invalid_argument("rlt section '" + name + "': flags exceed 24 bits");
  }
  if (bytes.size() % rlt_element_size(element) != 0) {
    throw std::invalid_argument("rlt section '" + name + "': size is not a whole number of " +
                                rlt_element_name(element) + " values");
  }
  sections_.push_back({type, element, flags, std::move(name), bytes, nullptr, nullptr});
}

void RltWriter::add_text(std::uint32_t type, std::string name, std::string text,
                         std::uint32_t flags) {
  auto owned = std::make_shared<const std::string>(std::move(text));
  add_section(type, std::move(name), std::as_bytes(std::span(*owned)), RltElement::text, flags);
  sections_.back().owned = std::move(owned);
}

void RltWriter::add_produced_section(std::uint32_t type, std::string name, Producer produce,
                                     RltElement element, std::uint32_t flags) {
  add_section(type, std::move(name), {}, element, flags);
  sections_.back().produce = std::move(produce);
}

std::uint64_t RltWriter::file_size() const {
  std::uint64_t end = sizeof(RltHeader) + sections_.size() * sizeof(RltTableEntry);
  for (const Section& s : sections_) {
    if (s.produce) throw std::logic_error("rlt file size: '" + s.name + "' is produced in write()");
    end = rlt_align(end) + s.bytes.size();
  }
  return rlt_align(end);
}

void RltWriter::write(const std::filesystem::path& file) const {
  std::vector<RltTableEntry> table(sections_.size());
  const std::uint64_t table_end = sizeof(RltHeader) + table.size() * sizeof(RltTableEntry);
  static constexpr std::array<std::byte, kRltAlignment> kZeros{};

  write_atomically(file, [&](const std::filesystem::path& tmp) {
    OutputFile out(tmp, file.string());
    // Placeholder for the header and table; table_end is a multiple of 64.
    for (std::uint64_t at = 0; at < table_end; at += kRltAlignment) out.append(kZeros);
    std::uint64_t offset = table_end;
    for (std::size_t i = 0; i < sections_.size(); ++i) {
      const Section& s = sections_[i];
      RltTableEntry& entry = table[i];
      entry = {};
      entry.type = s.type;
      entry.element = static_cast<std::uint32_t>(s.element) | s.flags << 8;
      entry.offset = offset;
      if (s.produce) {
        Xxh64 hash;
        std::uint64_t size = 0;
        s.produce([&](std::span<const std::byte> piece) {
          hash.update(piece);
          out.append(piece);
          size += piece.size();
        });
        if (size % rlt_element_size(s.element) != 0) {
          throw std::invalid_argument("rlt section '" + s.name +
                                      "': size is not a whole number of " +
                                      rlt_element_name(s.element) + " values");
        }
        entry.size = size;
        entry.checksum = hash.digest();
      } else {
        entry.size = s.bytes.size();
        entry.checksum = write_hashed(out, s.bytes);
      }
      std::memcpy(entry.name.data(), s.name.data(), s.name.size());
      const std::uint64_t end = offset + entry.size;
      offset = rlt_align(end);
      out.append(std::span(kZeros).first(offset - end));
    }

    RltHeader header{};
    header.magic = kRltMagic;
    header.version = kRltFormatVersion;
    header.byte_order = kRltByteOrderMark;
    header.section_count = static_cast<std::uint32_t>(table.size());
    header.file_size = offset;
    header.table_checksum = xxh64(std::as_bytes(std::span(table)));
    header.header_checksum = xxh64(bytes_of(header).first(kRltHeaderChecksummed));
    out.write_at(0, bytes_of(header));
    out.write_at(sizeof(RltHeader), std::as_bytes(std::span(table)));
    out.finish();
  });
}

}  // namespace relight
