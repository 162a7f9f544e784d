// A file written through a small buffer: small pieces (header, padding) are gathered,
// large pieces (section payloads) go from the caller's memory straight to write(2), so
// hundreds of MB of transfer are never copied into an intermediate buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace relight {

class OutputFile {
 public:
  // Creates or truncates path. Errors throw std::runtime_error "cannot write NAME: REASON",
  // NAME being `name` (the user's target, not a temporary).
  OutputFile(const std::filesystem::path& path, std::string name);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();  // closes without reporting errors when finish() was not reached

  void append(std::span<const std::byte> bytes);
  // Overwrites bytes already written (the header, once the checksums are known).
  void write_at(std::uint64_t offset, std::span<const std::byte> bytes);
  // Flushes, syncs to disk and closes; only then is the content safe to rename.
  void finish();

 private:
  void flush();
  void write_all(std::span<const std::byte> bytes);
  [[noreturn]] void fail(const std::string& what) const;

  int fd_ = -1;
  std::string name_;
  std::vector<std::byte> buffer_;
};

}  // namespace relight
