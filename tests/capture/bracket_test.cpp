// Brackets (capture/bracket.h): exposures from EXIF or given times, scaled by ISO and f-number
// when they differ, and every bad bracket an InputError naming the file or option.
#include "capture/bracket.h"

#include <gtest/gtest.h>

#include <vector>

#include "common/input_error.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

fs::path shot(const testing::TempDir& dir, const std::string& name, int width, int level,
              PhotoExposure exposure) {
  Photo photo{width, 24, 8, std::vector<std::uint16_t>(3 * width * 24, level)};
  write_photo_jpeg(dir.path() / name, photo, 95, exposure);
  return dir.path() / name;
}

std::string error_of(std::span<const fs::path> files, std::span<const double> times = {}) {
  try {
    load_bracket("front", files, times);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Bracket, ExposuresArePhotographicWhenEveryShotRecordsIsoAndFNumber) {
  const testing::TempDir dir;
  const std::vector<fs::path> files = {shot(dir, "a.jpg", 32, 60, {0.01, 2.0, 100}),
                                       shot(dir, "b.jpg", 32, 120, {0.01, 2.0, 400}),
                                       shot(dir, "c.jpg", 32, 200, {0.01, 4.0, 100})};
  Bracket b = load_bracket("front", files, {});
  ASSERT_EQ(b.exposures.size(), 3u);
  EXPECT_TRUE(b.photographic_exposure);
  EXPECT_NEAR(b.exposures[0], 0.01 / 4, 1e-12);      // t · (S/100) / N²
  EXPECT_NEAR(b.exposures[1], 0.01 * 4 / 4, 1e-12);  // 4 × the ISO
  EXPECT_NEAR(b.exposures[2], 0.01 / 16, 1e-12);     // twice the f-number: a quarter
  EXPECT_EQ(longest_shot(b), 1u);
  EXPECT_EQ(shortest_shot(b), 2u);
  // Paired with a bracket that lacks them, only the times count — and one time thrice is a
  // single exposure.
  use_exposure_times_only(b);
  EXPECT_FALSE(b.photographic_exposure);
  EXPECT_NEAR(b.exposures[1], 0.01, 1e-12);
  EXPECT_THROW(check_exposure_spread(b), InputError);
  // Given times replace EXIF's.
  const double times[] = {0.5, 0.25, 0.125};
  const Bracket given = load_bracket("front", files, times);
  EXPECT_NEAR(given.exposures[0], 0.5 / 4, 1e-12);
}

TEST(Bracket, EveryBadBracketNamesTheFileOrOptionAndTheReason) {
  const testing::TempDir dir;
  const fs::path a = shot(dir, "a.jpg", 32, 60, {0.01, std::nullopt, std::nullopt});
  const fs::path b = shot(dir, "b.jpg", 32, 120, {0.04, std::nullopt, std::nullopt});
  const fs::path same = shot(dir, "same.jpg", 32, 120, {0.01, std::nullopt, std::nullopt});
  const fs::path wide = shot(dir, "wide.jpg", 40, 120, {0.04, std::nullopt, std::nullopt});
  const fs::path black = shot(dir, "black.jpg", 32, 0, {0.04, std::nullopt, std::nullopt});
  const fs::path no_exif = dir.path() / "plain.png";
  {
    Photo photo{32, 24, 8, std::vector<std::uint16_t>(3 * 32 * 24, 90)};
    write_photo_jpeg(no_exif.string() + ".jpg", photo, 95, {});
  }
  const fs::path plain = no_exif.string() + ".jpg";
  EXPECT_EQ(
      error_of(std::vector<fs::path>{a}),
      "--front: " + a.string() + " is a single exposure: a bracket needs at least two exposures");
  EXPECT_EQ(error_of(std::vector<fs::path>{a, same}),
            a.string() +
                ": every photo of the front bracket has the same exposure: a bracket "
                "needs at least two exposures");
  EXPECT_EQ(error_of(std::vector<fs::path>{a, wide}),
            wide.string() + ": 40 × 24 px, but " + a.string() + " is 32 × 24");
  EXPECT_EQ(error_of(std::vector<fs::path>{a, black}), black.string() + ": all black");
  EXPECT_EQ(error_of(std::vector<fs::path>{a, plain}),
            plain.string() + ": no EXIF ExposureTime: give --exposure-times");
  EXPECT_EQ(error_of(std::vector<fs::path>{a, b}, std::vector<double>{0.1}),
            "--exposure-times: 1 times for 2 photos");
  EXPECT_EQ(error_of(std::vector<fs::path>{a, dir.path() / "gone.jpg"}),
            (dir.path() / "gone.jpg").string() + ": no such file");
}

}  // namespace
}  // namespace relight
