// A .rlt file that is not exactly what RltWriter wrote is refused with InputError naming
// the file and the reason: cut short anywhere, any byte of the header, table, payloads
// or padding changed, another file type, another format version or byte order, a section
// that claims more than the file holds although every checksum matches.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "rlt_test_support.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"
#include "store/xxh64.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

using test::expect_input_error;
using test::read_bytes;
using test::write_bytes;

// Three sections: metadata at 256 (14 bytes), "receivers" at 320 (4000 bytes),
// "transfer" at 4352 (1000 bytes); 5376 bytes in all.
class RltCorruption : public ::testing::Test {
 protected:
  void SetUp() override {
    for (std::size_t i = 0; i < floats_.size(); ++i) floats_[i] = static_cast<float>(i) * 0.5f;
    for (std::size_t i = 0; i < words_.size(); ++i) words_[i] = static_cast<std::uint16_t>(i * 7);
    RltWriter writer;
    writer.add_text(rlt_fourcc("META"), "metadata", R"({"scene": 1.5})");
    writer.add_f32(rlt_fourcc("RCVR"), "receivers", floats_);
    writer.add_u16(rlt_fourcc("TRAN"), "transfer", words_);
    writer.write(good_);
    bytes_ = read_bytes(good_);
  }

  // Writes a changed copy of the good file and returns its path.
  std::filesystem::path variant(const std::vector<std::byte>& bytes) const {
    write_bytes(bad_, bytes);
    return bad_;
  }
  std::string open_error(const std::vector<std::byte>& bytes,
                         std::initializer_list<std::string> parts) const {
    const auto file = variant(bytes);
    return expect_input_error([&] { RltFile::open(file); }, parts);
  }

  std::vector<float> floats_ = std::vector<float>(1000);
  std::vector<std::uint16_t> words_ = std::vector<std::uint16_t>(500);
  testing::TempDir dir_;
  std::filesystem::path good_ = dir_.path() / "good.rlt";
  std::filesystem::path bad_ = dir_.path() / "bad.rlt";
  std::vector<std::byte> bytes_;
};

TEST_F(RltCorruption, TheUnchangedFileOpens) {
  ASSERT_EQ(bytes_.size(), 5376u);
  const RltFile rlt = RltFile::open(good_);
  EXPECT_EQ(rlt.sections().size(), 3u);
  EXPECT_EQ(rlt.sections()[1].offset, 320u);
  EXPECT_EQ(rlt.sections()[2].offset, 4352u);
}

TEST_F(RltCorruption, ATruncatedFileIsRefusedWhereverItIsCut) {
  // Empty, inside the magic, inside the header, inside the table, at a payload's start,
  // inside each payload, inside the last padding.
  for (const std::size_t cut :
       {0, 5, 40, 63, 64, 100, 255, 256, 300, 2000, 4352, 5000, 5352, 5375}) {
    SCOPED_TRACE("cut at " + std::to_string(cut));
    const std::vector<std::byte> cut_bytes(bytes_.begin(), bytes_.begin() + static_cast<long>(cut));
    const std::string message = open_error(cut_bytes, {bad_.string() + ": truncated: "});
    if (cut >= 64) {
      EXPECT_NE(message.find("the header says 5376"), std::string::npos) << message;
    }
  }
}

TEST_F(RltCorruption, AFlippedPayloadByteNamesTheSection) {
  const std::vector<std::pair<std::size_t, std::string>> cases = {
      {256, "metadata"},   {268, "metadata"},  {320, "receivers"}, {2222, "receivers"},
      {4319, "receivers"}, {4352, "transfer"}, {5351, "transfer"}};
  for (const auto& [at, name] : cases) {
    SCOPED_TRACE("byte " + std::to_string(at));
    std::vector<std::byte> bytes = bytes_;
    bytes[at] ^= std::byte{0x10};
    open_error(bytes, {bad_.string() + ": section " + name + " is corrupted (checksum mismatch)"});
  }
}

TEST_F(RltCorruption, AnyChangedHeaderOrTableByteIsRefused) {
  int accepted = 0;
  for (std::size_t at = 0; at < 256; ++at) {
    for (const std::byte flip : {std::byte{0x01}, std::byte{0x80}}) {
      std::vector<std::byte> bytes = bytes_;
      bytes[at] ^= flip;
      const auto file = variant(bytes);
      try {
        RltFile::open(file);
        ++accepted;
      } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
      }
    }
  }
  EXPECT_EQ(accepted, 0);

  std::vector<std::byte> bytes = bytes_;
  bytes[30] ^= std::byte{1};  // file size
  open_error(bytes, {"header is corrupted (checksum mismatch)"});
  bytes = bytes_;
  bytes[64 + 64 + 8] ^= std::byte{1};  // receivers' offset
  open_error(bytes, {"section table is corrupted (checksum mismatch)"});
}

// A hostile file whose checksums are all right but whose section claims 2^40 bytes: refused by the
// bounds check, before anything reads or allocates that much.
TEST_F(RltCorruption, ASectionClaimingMoreThanTheFileHoldsIsRefusedThoughItsChecksumsMatch) {
  std::vector<std::byte> bytes = bytes_;
  const auto put_u64 = [&](std::size_t at, std::uint64_t value) {
    std::memcpy(bytes.data() + at, &value, sizeof value);
  };
  put_u64(64 + 64 + 16, std::uint64_t{1} << 40);  // receivers' size
  const std::size_t sections = 3;
  put_u64(32, xxh64(std::span(bytes).subspan(64, 64 * sections)));  // table checksum
  put_u64(56, xxh64(std::span(bytes).subspan(0, 56)));              // header checksum
  open_error(bytes, {"section receivers", "past the end of the file"});
}

TEST_F(RltCorruption, ChangedPaddingIsRefused) {
  std::vector<std::byte> bytes = bytes_;
  bytes[300] = std::byte{1};  // between metadata's 13 bytes and receivers at 320
  open_error(bytes, {"padding after section metadata is corrupted"});
  bytes = bytes_;
  bytes.back() = std::byte{1};
  open_error(bytes, {"padding after section transfer is corrupted"});
}

TEST_F(RltCorruption, AppendedDataIsRefused) {
  std::vector<std::byte> bytes = bytes_;
  bytes.resize(bytes.size() + 64);
  open_error(bytes, {"5440 bytes, the header says 5376"});
}

TEST_F(RltCorruption, OtherFilesAreNotRltFiles) {
  const std::string png = "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x01\0\0\0\x01\x08\x02\0\0\0";
  std::vector<std::byte> bytes(png.size());
  std::memcpy(bytes.data(), png.data(), png.size());
  open_error(bytes, {bad_.string() + ": not a relight .rlt file (wrong magic bytes)"});

  const std::string json = R"({"materials": {}})";
  bytes.assign(json.size(), {});
  std::memcpy(bytes.data(), json.data(), json.size());
  open_error(bytes, {"not a relight .rlt file"});

  bytes.assign(3, std::byte{'R'});  // shorter than the magic, and wrong
  open_error(bytes, {"not a relight .rlt file"});
}

TEST_F(RltCorruption, AnotherFormatVersionAsksForANewPrecompute) {
  for (const std::uint32_t version : {0u, kRltFormatVersion - 1, kRltFormatVersion + 1, 17u}) {
    std::vector<std::byte> bytes = bytes_;
    std::memcpy(bytes.data() + 8, &version, 4);
    // A genuine file of that version: its header checksum is right.
    const std::uint64_t checksum = xxh64(std::span(bytes).first(56));
    std::memcpy(bytes.data() + 56, &checksum, 8);
    const std::string message = open_error(bytes, {});
    EXPECT_EQ(message, bad_.string() + ": format version " + std::to_string(version) +
                           ", this relight reads " + std::to_string(kRltFormatVersion) +
                           ": run relight precompute again");
  }
}

TEST_F(RltCorruption, AnotherByteOrderIsRefused) {
  std::vector<std::byte> bytes = bytes_;
  std::swap(bytes[12], bytes[15]);
  std::swap(bytes[13], bytes[14]);
  open_error(bytes, {"byte order"});
}

TEST_F(RltCorruption, MissingFilesAndFoldersCannotBeOpened) {
  expect_input_error([&] { RltFile::open(dir_.path() / "absent.rlt"); },
                     {(dir_.path() / "absent.rlt").string() + ": cannot open: No such file"});
  expect_input_error([&] { RltFile::open(dir_.path()); }, {"cannot open: not a regular file"});
}

}  // namespace
}  // namespace relight
