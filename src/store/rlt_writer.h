// Builds a .rlt file from sections held by the caller (docs/rlt-format.md).
//
// Sections are added as spans of the caller's memory and streamed to disk by write():
// transfer matrices of hundreds of MB are neither copied into the writer nor buffered
// twice. The file appears atomically: a failed write leaves the previous file, if any, untouched
// and no temporary behind.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "store/rlt_format.h"

namespace relight {

struct RltWriter {
  // Adds a section; the bytes must stay alive and unchanged until write() returns.
  // Program errors throw std::invalid_argument: a type already added, a name that is
  // empty, longer than 31 bytes or not printable ASCII, flags above 24 bits, or a size
  // that is not a whole number of elements.
  void add_section(std::uint32_t type, std::string name, std::span<const std::byte> bytes,
                   RltElement element = RltElement::bytes, std::uint32_t flags = 0);

  void add_u16(std::uint32_t type, const std::string& name, std::span<const std::uint16_t> values,
               std::uint32_t flags = 0) {
    add_values(type, name, values, flags);
  }
  void add_u32(std::uint32_t type, const std::string& name, std::span<const std::uint32_t> values,
               std::uint32_t flags = 0) {
    add_values(type, name, values, flags);
  }
  void add_u64(std::uint32_t type, const std::string& name, std::span<const std::uint64_t> values,
               std::uint32_t flags = 0) {
    add_values(type, name, values, flags);
  }
  void add_f16(std::uint32_t type, const std::string& name, std::span<const RltHalf> values,
               std::uint32_t flags = 0) {
    add_values(type, name, values, flags);
  }
  void add_f32(std::uint32_t type, const std::string& name, std::span<const float> values,
               std::uint32_t flags = 0) {
    add_values(type, name, values, flags);
  }
  void add_f64(std::uint32_t type, const std::string& name, std::span<const double> values,
               std::uint32_t flags = 0) {
    add_values(type, name, values, flags);
  }
  // A section whose bytes `produce` hands to its sink in order, piece by piece, while write() runs:
  // bytes gathered from other ranks of a distributed precompute as the file is written, never held
  // whole. Its size is what it produced; a size that is not a whole number of elements throws
  // std::invalid_argument from write().
  using Sink = std::function<void(std::span<const std::byte>)>;
  using Producer = std::function<void(const Sink&)>;
  void add_produced_section(std::uint32_t type, std::string name, Producer produce,
                            RltElement element, std::uint32_t flags = 0);

  // A text section (JSON metadata); the writer keeps its own copy.
  void add_text(std::uint32_t type, std::string name, std::string text, std::uint32_t flags = 0);

  // The size the file will have; std::logic_error when a section is produced while writing.
  std::uint64_t file_size() const;

  // Writes the file atomically through write_atomically. I/O errors throw
  // std::runtime_error "cannot write FILE: ...".
  void write(const std::filesystem::path& file) const;

 private:
  struct Section {
    std::uint32_t type;
    RltElement element;
    std::uint32_t flags;
    std::string name;
    std::span<const std::byte> bytes;
    std::shared_ptr<const std::string> owned;  // backs `bytes` for text sections
    Producer produce;                          // instead of `bytes`, when set
  };

  template <RltValue T>
  void add_values(std::uint32_t type, const std::string& name, std::span<const T> values,
                  std::uint32_t flags) {
    add_section(type, name, std::as_bytes(values), RltElementOf<T>::value, flags);
  }

  std::vector<Section> sections_;
};

}  // namespace relight
