// A whole file mapped read-only into memory, unmapped when the owner goes away.
//
// .rlt transfer data is read in place by the run-time loop: the kernel pages it in from the
// page cache, nothing is copied or parsed, and several processes relighting the same scene share
// the same physical pages.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>

namespace relight {

class MappedFile {
 public:
  // Maps the file (MAP_PRIVATE, PROT_READ, pre-faulted where the system allows).
  // InputError "FILE: cannot open: REASON" when it cannot be opened, is not a regular
  // file, or cannot be mapped. An empty file gives empty bytes().
  static MappedFile open_read_only(const std::filesystem::path& file);

  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  // Page-aligned (the mapping starts on a page boundary).
  std::span<const std::byte> bytes() const { return {data_, size_}; }

 private:
  MappedFile(const std::byte* data, std::size_t size) : data_(data), size_(size) {}
  void unmap() noexcept;

  const std::byte* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace relight
