// The byte layout of a .rlt file (docs/rlt-format.md): a 64-byte header, a table of
// 64-byte section entries, then the section payloads, each starting on a 64-byte
// boundary so that a memory-mapped section is ready for SIMD loads and whole cache
// lines (transfer is read in place, with no parse step).
//
// Multi-byte fields are stored in the writer's byte order, which is little-endian on
// every machine relight supports; the byte-order mark turns a mismatch into an error.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace relight {

// Bump on any change to this layout or to the layout of any section type (the
// registry in docs/rlt-format.md). Readers accept exactly this version: a .rlt file is
// a cache that `relight precompute` regenerates from the scene.
inline constexpr std::uint32_t kRltFormatVersion = 5;

// "\x89RLT\r\n\x1A\n": the high byte catches 7-bit transfers, CR LF and LF catch
// line-ending conversion, ^Z stops DOS `type` (the PNG signature's scheme).
inline constexpr std::array<unsigned char, 8> kRltMagic = {0x89, 'R',  'L',  'T',
                                                           '\r', '\n', 0x1A, '\n'};
inline constexpr std::uint32_t kRltByteOrderMark = 0x01020304;
inline constexpr std::size_t kRltAlignment = 64;
inline constexpr std::size_t kRltNameCapacity = 32;  // bytes, NUL-padded, 31 characters at most

// What a section's values are. Stored in the low 8 bits of the element field.
enum class RltElement : std::uint8_t {
  bytes = 0,  // opaque: read with RltFile::section only
  text = 1,   // UTF-8 text (JSON metadata)
  u16 = 2,
  u32 = 3,
  u64 = 4,
  f16 = 5,  // IEEE 754 binary16, viewed as RltHalf
  f32 = 6,
  f64 = 7,
};
inline constexpr std::uint32_t kRltElementCount = 8;

// Flags occupy the upper 24 bits of the element field; their meaning belongs to the
// section type.
inline constexpr std::uint32_t kRltMaxFlags = (1u << 24) - 1;

// A binary16 value as stored; conversion is the caller's (F16C on x86).
struct RltHalf {
  std::uint16_t bits;
};

template <class T>
struct RltElementOf;
template <>
struct RltElementOf<std::uint16_t> {
  static constexpr RltElement value = RltElement::u16;
};
template <>
struct RltElementOf<std::uint32_t> {
  static constexpr RltElement value = RltElement::u32;
};
template <>
struct RltElementOf<std::uint64_t> {
  static constexpr RltElement value = RltElement::u64;
};
template <>
struct RltElementOf<RltHalf> {
  static constexpr RltElement value = RltElement::f16;
};
template <>
struct RltElementOf<float> {
  static constexpr RltElement value = RltElement::f32;
};
template <>
struct RltElementOf<double> {
  static constexpr RltElement value = RltElement::f64;
};

// The value types a section can be viewed as.
template <class T>
concept RltValue = requires {
  RltElementOf<T>::value;
};

std::size_t rlt_element_size(RltElement element);
std::string rlt_element_name(RltElement element);

// A readable type id from four characters: rlt_fourcc("META") is stored as the bytes
// 'M' 'E' 'T' 'A', so section types show up in a hex dump.
constexpr std::uint32_t rlt_fourcc(const char (&code)[5]) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(code[0])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(code[1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(code[2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(code[3])) << 24;
}

// The type of one of a family of indexed sections: two characters, then the index (of a
// luminaire, a portal, …) in the upper 16 bits ("DX" + j).
constexpr std::uint32_t rlt_indexed(char a, char b, std::size_t index) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(a)) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b)) << 8 |
         static_cast<std::uint32_t>(index) << 16;
}

// "what j": the name of section j of a family.
inline std::string rlt_indexed_name(const char* what, std::size_t index) {
  return std::string(what) + " " + std::to_string(index);
}

// "'META' (0x4154454d)" for a four-character type, "7 (0x00000007)" otherwise.
std::string rlt_type_label(std::uint32_t type);

// Bytes 0..63 of the file.
struct RltHeader {
  std::array<unsigned char, 8> magic;  // kRltMagic
  std::uint32_t version;               // kRltFormatVersion
  std::uint32_t byte_order;            // kRltByteOrderMark
  std::uint32_t section_count;
  std::uint32_t reserved0;                // 0
  std::uint64_t file_size;                // bytes, the whole file
  std::uint64_t table_checksum;           // XXH64 (seed 0) of the section table
  std::array<std::uint64_t, 2> reserved;  // 0
  std::uint64_t header_checksum;          // XXH64 (seed 0) of bytes 0..55
};

// One entry of the section table, which starts at byte 64.
struct RltTableEntry {
  std::uint32_t type;      // what the section holds (registry in docs/rlt-format.md)
  std::uint32_t element;   // RltElement in bits 0..7, the section's flags in bits 8..31
  std::uint64_t offset;    // from the start of the file, a multiple of 64
  std::uint64_t size;      // payload bytes, excluding padding
  std::uint64_t checksum;  // XXH64 (seed 0) of the payload
  std::array<char, kRltNameCapacity> name;  // NUL-padded
};

static_assert(sizeof(RltHeader) == 64 && offsetof(RltHeader, version) == 8 &&
              offsetof(RltHeader, section_count) == 16 && offsetof(RltHeader, file_size) == 24 &&
              offsetof(RltHeader, table_checksum) == 32 &&
              offsetof(RltHeader, header_checksum) == 56);
static_assert(sizeof(RltTableEntry) == 64 && offsetof(RltTableEntry, offset) == 8 &&
              offsetof(RltTableEntry, checksum) == 24 && offsetof(RltTableEntry, name) == 32);
inline constexpr std::size_t kRltHeaderChecksummed = offsetof(RltHeader, header_checksum);

constexpr std::uint64_t rlt_align(std::uint64_t offset) {
  return (offset + kRltAlignment - 1) / kRltAlignment * kRltAlignment;
}

}  // namespace relight
