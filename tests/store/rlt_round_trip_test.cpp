// What RltWriter writes, RltFile reads back byte for byte: sections of every size
// (empty, one byte, around a cache line, thousands of values), each payload at a
// 64-byte aligned address, typed views, metadata text, and the byte layout that
// docs/rlt-format.md documents.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
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

constexpr std::uint32_t kMeta = rlt_fourcc("META");

std::vector<std::byte> pattern(std::size_t size, unsigned seed) {
  std::vector<std::byte> bytes(size);
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<std::byte>((i * 131 + seed) >> 1);
  return bytes;
}

bool aligned64(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % 64 == 0;
}

TEST(RltRoundTrip, SectionsOfEverySizeComeBackByteForByteAt64ByteAlignedAddresses) {
  const std::vector<std::size_t> sizes = {0, 1, 63, 64, 65, 127, 1000, 4097, 100003, 0};
  std::vector<std::vector<std::byte>> payloads;
  RltWriter writer;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    payloads.push_back(pattern(sizes[i], static_cast<unsigned>(i)));
    writer.add_section(static_cast<std::uint32_t>(100 + i), "blob " + std::to_string(i),
                       payloads.back(), RltElement::bytes, static_cast<std::uint32_t>(i * 1000));
  }
  const testing::TempDir dir;
  const auto file = dir.path() / "scene.rlt";
  writer.write(file);

  const RltFile rlt = RltFile::open(file);
  ASSERT_EQ(rlt.sections().size(), sizes.size());
  EXPECT_EQ(rlt.total_bytes(), std::filesystem::file_size(file));
  EXPECT_EQ(rlt.total_bytes(), writer.file_size());
  EXPECT_EQ(rlt.total_bytes() % 64, 0u);
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    SCOPED_TRACE("section " + std::to_string(i));
    const RltSectionInfo& info = rlt.sections()[i];
    EXPECT_EQ(info.type, 100 + i);
    EXPECT_EQ(info.name, "blob " + std::to_string(i));
    EXPECT_EQ(info.element, RltElement::bytes);
    EXPECT_EQ(info.flags, i * 1000);
    EXPECT_EQ(info.size, sizes[i]);
    EXPECT_EQ(info.offset % 64, 0u);
    EXPECT_EQ(info.checksum, xxh64(payloads[i]));
    const std::span<const std::byte> read = rlt.section(info.type);
    EXPECT_TRUE(aligned64(read.data()));
    ASSERT_EQ(read.size(), sizes[i]);
    EXPECT_TRUE(std::equal(read.begin(), read.end(), payloads[i].begin()));
  }
}

TEST(RltRoundTrip, TypedSectionsAndMetadataComeBackAsWritten) {
  std::vector<float> floats(1001);
  for (std::size_t i = 0; i < floats.size(); ++i) floats[i] = 0.25f * static_cast<float>(i) - 3.0f;
  const std::vector<double> doubles = {3.141592653589793, -0.0, 1e300, 5e-324};
  const std::vector<std::uint32_t> indices = {0, 1, 4294967295u, 123456789};
  const std::vector<std::uint16_t> halves_bits = {0x3C00, 0xC000, 0x7BFF};
  const std::vector<std::uint16_t> counts = {1, 2, 3, 65535, 7};
  const std::vector<std::uint64_t> big = {1ull << 40};
  const std::vector<RltHalf> halves = {{0x3C00}, {0xC000}, {0x7BFF}};
  const std::string metadata = R"({"scene": "room.json", "receivers": 1001})";

  RltWriter writer;
  writer.add_text(kMeta, "metadata", metadata);
  writer.add_f32(rlt_fourcc("F32 "), "floats", floats, 7);
  writer.add_f64(rlt_fourcc("F64 "), "doubles", doubles);
  writer.add_u32(rlt_fourcc("U32 "), "indices", indices);
  writer.add_u16(rlt_fourcc("U16 "), "counts", counts);
  writer.add_u64(rlt_fourcc("U64 "), "big", big);
  writer.add_f16(rlt_fourcc("F16 "), "halves", halves);
  const testing::TempDir dir;
  const auto file = dir.path() / "typed.rlt";
  writer.write(file);

  const RltFile rlt = RltFile::open(file);
  EXPECT_EQ(rlt.text(kMeta), metadata);
  const auto f = rlt.view<float>(rlt_fourcc("F32 "));
  EXPECT_TRUE(std::equal(f.begin(), f.end(), floats.begin(), floats.end()));
  EXPECT_EQ(rlt.info(rlt_fourcc("F32 ")).flags, 7u);
  EXPECT_EQ(rlt.info(rlt_fourcc("F32 ")).element, RltElement::f32);
  const auto d = rlt.view<double>(rlt_fourcc("F64 "));
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(std::memcmp(d.data(), doubles.data(), 4 * sizeof(double)), 0);  // -0.0 and denormal
  const auto u = rlt.view<std::uint32_t>(rlt_fourcc("U32 "));
  EXPECT_TRUE(std::equal(u.begin(), u.end(), indices.begin(), indices.end()));
  const auto c = rlt.view<std::uint16_t>(rlt_fourcc("U16 "));
  EXPECT_TRUE(std::equal(c.begin(), c.end(), counts.begin(), counts.end()));
  EXPECT_EQ(rlt.view<std::uint64_t>(rlt_fourcc("U64 "))[0], 1ull << 40);
  const auto h = rlt.view<RltHalf>(rlt_fourcc("F16 "));
  ASSERT_EQ(h.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(h[i].bits, halves_bits[i]);
  for (const RltSectionInfo& s : rlt.sections()) {
    EXPECT_TRUE(aligned64(rlt.section(s.type).data())) << s.name;
  }
}

TEST(RltRoundTrip, MissingSectionsAndWrongElementTypesAreReported) {
  const std::vector<float> floats = {1, 2, 3};
  RltWriter writer;
  writer.add_f32(rlt_fourcc("F32 "), "floats", floats);
  const testing::TempDir dir;
  const auto file = dir.path() / "few.rlt";
  writer.write(file);
  const RltFile rlt = RltFile::open(file);

  EXPECT_FALSE(rlt.find_section(kMeta).has_value());
  EXPECT_EQ(rlt.find_info(kMeta), nullptr);
  ASSERT_TRUE(rlt.find_section(rlt_fourcc("F32 ")).has_value());
  EXPECT_EQ(rlt.find_section(rlt_fourcc("F32 "))->size(), 12u);
  expect_input_error([&] { rlt.section(kMeta); },
                     {file.string() + ": ", "missing section of type 'META' (0x4154454d)"});
  expect_input_error([&] { rlt.section(42); }, {"missing section of type 42 (0x0000002a)"});
  expect_input_error([&] { rlt.view<std::uint32_t>(rlt_fourcc("F32 ")); },
                     {file.string(), "section floats holds f32 values, read as u32"});
  expect_input_error([&] { rlt.text(rlt_fourcc("F32 ")); }, {"read as text"});
}

TEST(RltRoundTrip, AFileWithoutSectionsIsJustTheHeader) {
  const testing::TempDir dir;
  const auto file = dir.path() / "empty.rlt";
  RltWriter{}.write(file);
  EXPECT_EQ(std::filesystem::file_size(file), 64u);
  const RltFile rlt = RltFile::open(file);
  EXPECT_TRUE(rlt.sections().empty());
  EXPECT_EQ(rlt.total_bytes(), 64u);
}

TEST(RltRoundTrip, SpansSurviveMovingTheFile) {
  const std::vector<double> values = {1.5, 2.5};
  RltWriter writer;
  writer.add_f64(1, "values", values);
  const testing::TempDir dir;
  writer.write(dir.path() / "moved.rlt");
  RltFile first = RltFile::open(dir.path() / "moved.rlt");
  const std::span<const double> view = first.view<double>(1);
  const RltFile second = std::move(first);
  EXPECT_EQ(second.view<double>(1).data(), view.data());
  EXPECT_EQ(view[1], 2.5);
}

// Pins the layout table of docs/rlt-format.md.
TEST(RltRoundTrip, BytesOnDiskFollowTheDocumentedLayout) {
  const std::vector<std::byte> payload = pattern(70, 3);
  RltWriter writer;
  writer.add_text(kMeta, "metadata", "{}");
  writer.add_section(rlt_fourcc("BLOB"), "blob", payload, RltElement::bytes, 0x123456);
  const testing::TempDir dir;
  const auto file = dir.path() / "layout.rlt";
  writer.write(file);
  const std::vector<std::byte> raw = read_bytes(file);
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, raw.data() + at, 4);
    return v;
  };
  const auto u64 = [&](std::size_t at) {
    std::uint64_t v;
    std::memcpy(&v, raw.data() + at, 8);
    return v;
  };
  const std::span<const std::byte> all(raw);

  // 64-byte header + 2 table entries, then "{}" at 192 padded to 256, then 70 bytes at 256.
  ASSERT_EQ(raw.size(), 384u);
  EXPECT_EQ(std::memcmp(raw.data(), "\x89RLT\r\n\x1a\n", 8), 0);
  EXPECT_EQ(u32(8), 5u);             // version (docs/rlt-format.md, "Versioning")
  EXPECT_EQ(u32(12), 0x01020304u);   // byte order mark
  EXPECT_EQ(raw[12], std::byte{4});  // little-endian on disk
  EXPECT_EQ(u32(16), 2u);            // section count
  EXPECT_EQ(u32(20), 0u);
  EXPECT_EQ(u64(24), 384u);  // file size
  EXPECT_EQ(u64(32), xxh64(all.subspan(64, 128)));
  EXPECT_EQ(u64(40), 0u);
  EXPECT_EQ(u64(48), 0u);
  EXPECT_EQ(u64(56), xxh64(all.first(56)));

  EXPECT_EQ(u32(64), kMeta);
  EXPECT_EQ(std::memcmp(raw.data() + 64, "META", 4), 0);
  EXPECT_EQ(u32(68), 1u);  // text, no flags
  EXPECT_EQ(u64(72), 192u);
  EXPECT_EQ(u64(80), 2u);
  EXPECT_EQ(u64(88), xxh64(all.subspan(192, 2)));
  EXPECT_EQ(std::memcmp(raw.data() + 96, "metadata\0\0\0\0", 12), 0);
  EXPECT_EQ(std::memcmp(raw.data() + 192, "{}", 2), 0);
  EXPECT_TRUE(std::all_of(raw.begin() + 194, raw.begin() + 256,
                          [](std::byte b) { return b == std::byte{0}; }));

  EXPECT_EQ(std::memcmp(raw.data() + 128, "BLOB", 4), 0);
  EXPECT_EQ(u32(132), 0x12345600u);  // bytes (0) | flags << 8
  EXPECT_EQ(u64(136), 256u);
  EXPECT_EQ(u64(144), 70u);
  EXPECT_EQ(u64(152), xxh64(payload));
  EXPECT_EQ(std::memcmp(raw.data() + 160, "blob\0", 5), 0);
  EXPECT_EQ(std::memcmp(raw.data() + 256, payload.data(), 70), 0);
}

TEST(RltWriter, RefusesDuplicateTypesBadNamesAndPartialElements) {
  const std::vector<std::byte> three(3);
  RltWriter writer;
  writer.add_text(kMeta, "metadata", "{}");
  EXPECT_THROW(writer.add_text(kMeta, "again", "{}"), std::invalid_argument);
  EXPECT_THROW(writer.add_section(1, "", three), std::invalid_argument);
  EXPECT_THROW(writer.add_section(1, std::string(32, 'x'), three), std::invalid_argument);
  EXPECT_THROW(writer.add_section(1, "tab\there", three), std::invalid_argument);
  EXPECT_THROW(writer.add_section(1, "odd", three, RltElement::u16), std::invalid_argument);
  EXPECT_THROW(writer.add_section(1, "flags", three, RltElement::bytes, 1u << 24),
               std::invalid_argument);
  writer.add_section(1, std::string(31, 'x'), three);  // the longest name
  EXPECT_EQ(writer.file_size(), 64u + 2 * 64 + 64 + 64);
}

TEST(RltWriter, AProducedSectionIsWrittenByteForByteAsTheSameBytesAdded) {
  std::vector<float> values(300'000);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.5f * static_cast<float>(i);
  const testing::TempDir dir;
  RltWriter added, produced;
  for (RltWriter* w : {&added, &produced}) w->add_text(kMeta, "metadata", "{}");
  added.add_f32(7, "values", values);
  // In pieces of 4,097 floats, as ranks' blocks arrive.
  produced.add_produced_section(
      7, "values",
      [&](const RltWriter::Sink& sink) {
        for (std::size_t at = 0; at < values.size(); at += 4097) {
          sink(std::as_bytes(
              std::span(values).subspan(at, std::min<std::size_t>(4097, values.size() - at))));
        }
      },
      RltElement::f32);
  EXPECT_THROW((void)produced.file_size(), std::logic_error);
  added.write(dir.path() / "added.rlt");
  produced.write(dir.path() / "produced.rlt");
  EXPECT_EQ(read_bytes(dir.path() / "added.rlt"), read_bytes(dir.path() / "produced.rlt"));

  RltWriter odd;
  odd.add_produced_section(
      8, "odd", [](const RltWriter::Sink& sink) { sink(std::as_bytes(std::span("abc", 3))); },
      RltElement::u16);
  EXPECT_THROW(odd.write(dir.path() / "odd.rlt"), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "odd.rlt"));
}

}  // namespace
}  // namespace relight
