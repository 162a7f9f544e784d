// mmap(2) behind MappedFile. The descriptor is closed right after mapping: the
// mapping keeps the file's pages reachable on its own.
#include "store/mapped_file.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/input_error.h"

namespace relight {

namespace {

// Closes a descriptor on every path out of open_read_only.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void fail_open(const std::filesystem::path& file, const std::string& reason) {
  fail_input(file.string(), "cannot open: " + reason);
}

}  // namespace

MappedFile MappedFile::open_read_only(const std::filesystem::path& file) {
  const Descriptor descriptor{::open(file.c_str(), O_RDONLY | O_CLOEXEC)};
  if (descriptor.fd < 0) fail_open(file, std::strerror(errno));
  struct stat status {};
  if (::fstat(descriptor.fd, &status) != 0) fail_open(file, std::strerror(errno));
  if (!S_ISREG(status.st_mode)) fail_open(file, "not a regular file");
  const auto size = static_cast<std::size_t>(status.st_size);
  if (size == 0) return MappedFile(nullptr, 0);

  int flags = MAP_PRIVATE;
#ifdef MAP_POPULATE
  // Every page is read at once anyway (the checksums cover the whole file), and the
  // run-time loop then takes no page faults.
  flags |= MAP_POPULATE;
#endif
  void* const address = ::mmap(nullptr, size, PROT_READ, flags, descriptor.fd, 0);
  if (address == MAP_FAILED) fail_open(file, std::string("mmap: ") + std::strerror(errno));
  ::madvise(address, size, MADV_WILLNEED);  // advice only: failure changes nothing
  return MappedFile(static_cast<const std::byte*>(address), size);
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    unmap();
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

MappedFile::~MappedFile() {
  unmap();
}

void MappedFile::unmap() noexcept {
  if (data_ != nullptr) ::munmap(const_cast<std::byte*>(data_), size_);
  data_ = nullptr;
  size_ = 0;
}

}  // namespace relight
