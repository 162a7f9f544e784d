// RltWriter::write is atomic: when it fails, whatever was at the target stays as it was and no
// temporary file is left beside it; when it succeeds, the new file replaces the old one whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rlt_test_support.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

using test::read_bytes;

std::vector<std::string> folder_entries(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

RltWriter writer_of(const std::vector<float>& values) {
  RltWriter writer;
  writer.add_f32(1, "values", values);
  return writer;
}

// Lowers the file size limit so that writes past it fail with EFBIG, as on a full disk
// (this also binds root, unlike permissions); restores the limit and SIGXFSZ after.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*previous_handler_)(int) = nullptr;
};

TEST(RltAtomicWrite, AFullDiskLeavesTheExistingFileIntactAndNoTemporary) {
  const testing::TempDir dir;
  const auto file = dir.path() / "scene.rlt";
  const std::vector<float> old_values(100, 1.0f);
  writer_of(old_values).write(file);
  const std::vector<std::byte> old_bytes = read_bytes(file);

  const std::vector<float> new_values(1 << 20, 2.0f);  // 4 MiB
  {
    const FileSizeLimit limit(1 << 20);
    try {
      writer_of(new_values).write(file);
      ADD_FAILURE() << "the write did not fail";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("cannot write " + file.string()), std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"scene.rlt"});
  EXPECT_EQ(read_bytes(file), old_bytes);
  EXPECT_EQ(RltFile::open(file).view<float>(1).size(), 100u);
}

TEST(RltAtomicWrite, AnUnwritableFolderLeavesNothingBehind) {
  const testing::TempDir dir;
  const auto not_a_folder = dir.path() / "plain-file";
  dir.write("plain-file", "x");
  EXPECT_THROW(writer_of({1.0f}).write(not_a_folder / "scene.rlt"), std::runtime_error);
  EXPECT_THROW(writer_of({1.0f}).write(dir.path() / "absent" / "scene.rlt"), std::runtime_error);
  EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"plain-file"});
}

TEST(RltAtomicWrite, AReadOnlyFolderKeepsItsFile) {
  const testing::TempDir dir;
  const auto folder = dir.path() / "locked";
  std::filesystem::create_directory(folder);
  const auto file = folder / "scene.rlt";
  writer_of({1.0f, 2.0f}).write(file);
  const std::vector<std::byte> old_bytes = read_bytes(file);
  ::chmod(folder.c_str(), 0555);
  if (::access(folder.c_str(), W_OK) == 0) {  // root writes anywhere
    ::chmod(folder.c_str(), 0755);
    GTEST_SKIP() << "permissions do not apply to this user";
  }
  EXPECT_THROW(writer_of({3.0f}).write(file), std::runtime_error);
  ::chmod(folder.c_str(), 0755);
  EXPECT_EQ(folder_entries(folder), std::vector<std::string>{"scene.rlt"});
  EXPECT_EQ(read_bytes(file), old_bytes);
}

TEST(RltAtomicWrite, ASuccessfulWriteReplacesTheOldFileWhole) {
  const testing::TempDir dir;
  const auto file = dir.path() / "scene.rlt";
  writer_of(std::vector<float>(10, 1.0f)).write(file);
  writer_of(std::vector<float>(3, 2.0f)).write(file);
  EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"scene.rlt"});
  const RltFile rlt = RltFile::open(file);
  ASSERT_EQ(rlt.view<float>(1).size(), 3u);
  EXPECT_EQ(rlt.view<float>(1)[2], 2.0f);
}

// A process ended by SIGTERM or SIGINT while it writes (Ctrl-C; mpirun ending rank 0 because
// another rank died) leaves no temporary, and ends by that signal as it would have.
TEST(RltAtomicWrite, ASignalWhileWritingRemovesTheTemporaryAndEndsTheProcess) {
  // Forked (not re-run): the child writes into this test's folder.
  GTEST_FLAG_SET(death_test_style, "fast");
  for (const int signal_number : {SIGTERM, SIGINT}) {
    const testing::TempDir dir;
    const auto file = dir.path() / "scene.rlt";
    writer_of({1.0f}).write(file);
    const std::vector<std::byte> old_bytes = read_bytes(file);
    RltWriter writer;
    writer.add_produced_section(
        1, "values",
        [signal_number](const RltWriter::Sink& sink) {
          const float v = 2.0f;
          sink(std::as_bytes(std::span(&v, 1)));
          std::raise(signal_number);
        },
        RltElement::f32);
    EXPECT_EXIT(writer.write(file), ::testing::KilledBySignal(signal_number), "");
    EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"scene.rlt"});
    EXPECT_EQ(read_bytes(file), old_bytes);
  }
}

}  // namespace
}  // namespace relight
