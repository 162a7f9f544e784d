// The acceptance test of `relight capture` (capture/capture.h) on a synthetic capture of Blender's
// interior.exr (Debian blender-data): two 190° equidistant fisheye brackets with an off-centre
// circle, a concave response, five exposures two stops apart in EXIF, 8-bit JPEG, a dark lens-frame
// band and a photographer low in the back view. Tolerances from the acceptance criteria.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "capture/capture.h"
#include "light/environment_map_io.h"
#include "math/equirect.h"
#include "support/synthetic_capture.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

const fs::path kInterior = "/usr/share/blender/datafiles/studiolights/world/interior.exr";

double plane_illuminance(const EquirectMap& map, Vec3 normal) {
  double e = 0;
  for (int j = 0; j < map.height; ++j) {
    const double omega = equirect_row_solid_angle(map.width, map.height, j);
    for (int i = 0; i < map.width; ++i) {
      const double c = dot(equirect_texel_direction(map.width, map.height, i, j), normal);
      if (c > 0)
        e += luminance(map.texels[static_cast<std::size_t>(j) * map.width + i]) * c * omega;
    }
  }
  return e;
}

// Solid-angle-weighted mean luminance of the texels whose direction passes `keep`.
template <typename Keep>
double mean_luminance(const EquirectMap& map, Keep keep) {
  double sum = 0, weight = 0;
  for (int j = 0; j < map.height; ++j) {
    const double omega = equirect_row_solid_angle(map.width, map.height, j);
    for (int i = 0; i < map.width; ++i) {
      if (!keep(equirect_texel_direction(map.width, map.height, i, j))) continue;
      sum += luminance(map.texels[static_cast<std::size_t>(j) * map.width + i]) * omega;
      weight += omega;
    }
  }
  return sum / weight;
}

// Solid-angle-weighted mean luminance per cell of a 32 × 16 grid over (u, v).
std::vector<double> grid_luminance(const EquirectMap& map) {
  std::vector<double> sum(32 * 16, 0), weight(32 * 16, 0);
  for (int j = 0; j < map.height; ++j) {
    const double omega = equirect_row_solid_angle(map.width, map.height, j);
    const int row = j * 16 / map.height;
    for (int i = 0; i < map.width; ++i) {
      const std::size_t cell = static_cast<std::size_t>(row) * 32 + i * 32 / map.width;
      sum[cell] += luminance(map.texels[static_cast<std::size_t>(j) * map.width + i]) * omega;
      weight[cell] += omega;
    }
  }
  for (std::size_t c = 0; c < sum.size(); ++c) sum[c] /= weight[c];
  return sum;
}

class CaptureAcceptance : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!fs::exists(kInterior)) return;
    truth_ =
        std::make_unique<EquirectMap>(testing::within_bracket(read_environment_map(kInterior)));
    folder_ = std::make_unique<testing::TempDir>();
    const testing::SyntheticCapture photos =
        testing::make_synthetic_capture(*truth_, folder_->path());
    spec_circle_ = {photos.circle_cx, photos.circle_cy};
    CaptureOptions options;
    options.front = photos.front;
    options.back = photos.back;
    options.width = 512;
    reading_ = plane_illuminance(*truth_, {0, 1, 0});
    options.illuminance_lux = reading_;
    result_ = std::make_unique<CaptureResult>(capture_environment(options));
  }
  static void TearDownTestSuite() {
    result_.reset();
    folder_.reset();
    truth_.reset();
  }
  void SetUp() override {
    if (!truth_) GTEST_SKIP() << kInterior << " not found (Debian blender-data)";
  }

  static inline std::unique_ptr<EquirectMap> truth_;
  static inline std::unique_ptr<testing::TempDir> folder_;
  static inline std::unique_ptr<CaptureResult> result_;
  static inline std::pair<double, double> spec_circle_;
  static inline double reading_ = 0;
};

TEST_F(CaptureAcceptance, IlluminanceOnPlanesFacingUpAndTheFourCardinalsIsWithin3Percent) {
  const Vec3 normals[] = {{0, 1, 0}, {0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}};
  const char* names[] = {"up", "north", "south", "east", "west"};
  for (int k = 0; k < 5; ++k) {
    const double truth = plane_illuminance(*truth_, normals[k]);
    const double captured = plane_illuminance(result_->map, normals[k]);
    EXPECT_NEAR(captured / truth, 1.0, 0.03) << names[k] << ": " << captured << " lx vs " << truth;
    std::printf("plane facing %s: %+.2f %%\n", names[k], 100 * (captured / truth - 1));
  }
  EXPECT_TRUE(result_->calibrated);
  EXPECT_NEAR(result_->horizontal_illuminance / reading_, 1.0, 1e-9);
}

TEST_F(CaptureAcceptance, A32By16LuminanceGridHasAMeanRelativeErrorOfAtMost5Percent) {
  const std::vector<double> truth = grid_luminance(*truth_);
  const std::vector<double> captured = grid_luminance(result_->map);
  double error = 0;
  for (std::size_t c = 0; c < truth.size(); ++c) error += std::abs(captured[c] / truth[c] - 1);
  error /= static_cast<double>(truth.size());
  EXPECT_LE(error, 0.05);
  std::printf("32 x 16 grid: mean relative error %.2f %%\n", 100 * error);
}

TEST_F(CaptureAcceptance, ThePhotographersDirectionsAreFilledWithin20PercentOfTheTruth) {
  const double truth = mean_luminance(*truth_, testing::photographer_direction);
  const double captured = mean_luminance(result_->map, testing::photographer_direction);
  EXPECT_NEAR(captured / truth, 1.0, 0.20) << captured << " vs " << truth;
  std::printf("photographer's directions: mean luminance %+.1f %%, %.3f sr removed\n",
              100 * (captured / truth - 1), result_->removed_sr);
  EXPECT_GT(result_->removed_sr, 0.0);
}

TEST_F(CaptureAcceptance, TheImageCircleCentreIsFoundWithin2Pixels) {
  for (const CapturedView* view : {&result_->front, &result_->back}) {
    EXPECT_NEAR(view->circle.cx, spec_circle_.first, 2.0);
    EXPECT_NEAR(view->circle.cy, spec_circle_.second, 2.0);
    EXPECT_NEAR(view->circle.radius, testing::SyntheticCaptureSpec{}.radius, 2.0);
    std::printf("circle centre off by (%+.2f, %+.2f) px, radius %+.2f px\n",
                view->circle.cx - spec_circle_.first, view->circle.cy - spec_circle_.second,
                view->circle.radius - testing::SyntheticCaptureSpec{}.radius);
  }
}

TEST_F(CaptureAcceptance, TheRecoveredResponseIsWithin5PercentOfTheTrueCurveWhereWellExposed) {
  // Both are known up to a factor: compare X(z)/X(128) over z = 16..240.
  for (const auto& channel : result_->response.exposure) {
    double worst = 0;
    for (int z = 16; z <= 240; ++z) {
      const double recovered = channel[static_cast<std::size_t>(z)] / channel[128];
      const double truth = testing::true_inverse_response(z) / testing::true_inverse_response(128);
      worst = std::max(worst, std::abs(recovered / truth - 1));
    }
    EXPECT_LE(worst, 0.05);
    std::printf("response: worst %.2f %% over z = 16..240\n", 100 * worst);
  }
}

TEST_F(CaptureAcceptance, TheLensFrameBandIsCutFromEachView) {
  // The band starts at 92.5° off axis: each view is used to just inside it, not beyond.
  for (const CapturedView* view : {&result_->front, &result_->back}) {
    EXPECT_LE(view->clean_limit_deg, 92.5);
    EXPECT_GE(view->clean_limit_deg, 90.5);
  }
}

TEST(CaptureClipping, AReadingGivesTheMissingFluxToClippedTexelsWhenExifFixesTheExposure) {
  // The unclamped map: its ceiling lamps clip even in the shortest exposure. The camera records
  // ISO 100 and f/2 and follows the meter equation, so the unclipped texels are absolute.
  if (!fs::exists(kInterior)) GTEST_SKIP() << kInterior << " not found (Debian blender-data)";
  const EquirectMap truth = read_environment_map(kInterior);
  const testing::TempDir dir;
  testing::SyntheticCaptureSpec spec = testing::small_capture_spec();
  spec.iso = 100;
  spec.f_number = 2;
  spec.middle_time_s = 1.0 / 30;
  const testing::SyntheticCapture photos = testing::make_synthetic_capture(truth, dir.path(), spec);
  CaptureOptions options;
  options.front = photos.front;
  options.back = photos.back;
  options.width = 512;
  const double reading = plane_illuminance(truth, {0, 1, 0});
  options.illuminance_lux = reading;
  const CaptureResult attributed = capture_environment(options);
  EXPECT_GT(attributed.clipped_share, 0.01);
  ASSERT_FALSE(attributed.warnings.empty());
  EXPECT_NEAR(attributed.horizontal_illuminance / reading, 1.0, 1e-9);
  // The same photos without ISO and f-number in EXIF: the whole map is scaled instead.
  options.exposure_times = photos.times;
  options.exposure_times.insert(options.exposure_times.end(), photos.times.begin(),
                                photos.times.end());
  for (auto* files : {&options.front, &options.back}) {
    for (fs::path& f : *files) {
      const fs::path plain = f.parent_path() / ("plain_" + f.filename().string());
      write_photo_jpeg(plain, read_photo(f), 100, {});  // no EXIF at all
      f = plain;
    }
  }
  const CaptureResult scaled = capture_environment(options);
  double error_attributed = 0, error_scaled = 0;
  for (const Vec3 n : {Vec3{0, 0, -1}, Vec3{0, 0, 1}, Vec3{1, 0, 0}, Vec3{-1, 0, 0}}) {
    const double t = plane_illuminance(truth, n);
    error_attributed += std::abs(plane_illuminance(attributed.map, n) / t - 1) / 4;
    error_scaled += std::abs(plane_illuminance(scaled.map, n) / t - 1) / 4;
  }
  std::printf(
      "clipped share %.1f %%: cardinal planes off by %.1f %% (flux to the clipped "
      "texels) against %.1f %% (whole map scaled)\n",
      100 * attributed.clipped_share, 100 * error_attributed, 100 * error_scaled);
  EXPECT_LT(error_attributed, error_scaled);
}

// A capture of other photos than the acceptance's: small, through `spec`, with the times given.
CaptureResult capture_of(const EquirectMap& truth, const testing::SyntheticCaptureSpec& spec,
                         FisheyeLens lens) {
  const testing::TempDir dir;
  const testing::SyntheticCapture photos = testing::make_synthetic_capture(truth, dir.path(), spec);
  CaptureOptions options;
  options.front = photos.front;
  options.back = photos.back;
  options.exposure_times = photos.times;  // one list both brackets share
  options.lens = lens;
  options.width = 256;
  options.illuminance_lux = plane_illuminance(truth, {0, 1, 0});
  return capture_environment(options);
}

void expect_planes_within(const EquirectMap& truth, const EquirectMap& map, double tolerance) {
  for (const Vec3 n : {Vec3{0, 0, -1}, Vec3{0, 0, 1}, Vec3{1, 0, 0}, Vec3{-1, 0, 0}}) {
    EXPECT_NEAR(plane_illuminance(map, n) / plane_illuminance(truth, n), 1.0, tolerance)
        << n.x << ", " << n.y << ", " << n.z;
  }
}

TEST(CaptureLenses, AnEquisolidLensCapturedAsEquisolidKeepsThePlanesWithin3Percent) {
  if (!fs::exists(kInterior)) GTEST_SKIP() << kInterior << " not found (Debian blender-data)";
  testing::SyntheticCaptureSpec spec = testing::small_capture_spec();
  spec.equisolid = true;
  const EquirectMap truth = testing::within_bracket(read_environment_map(kInterior), spec);
  const CaptureResult result =
      capture_of(truth, spec, {FisheyeProjection::kEquisolid, 190 * kPi / 180});
  expect_planes_within(truth, result.map, 0.03);
}

TEST(CaptureLenses, SixteenBitLinearPngsNeedNoResponseAndKeepThePlanesWithin3Percent) {
  if (!fs::exists(kInterior)) GTEST_SKIP() << kInterior << " not found (Debian blender-data)";
  testing::SyntheticCaptureSpec spec = testing::small_capture_spec();
  spec.linear16 = true;
  spec.shots = 3;
  const EquirectMap truth = testing::within_bracket(read_environment_map(kInterior), spec);
  const CaptureResult result = capture_of(truth, spec, {});
  EXPECT_TRUE(result.response.linear);
  expect_planes_within(truth, result.map, 0.03);
}

TEST(CaptureLenses, BracketsAtDifferentIsoShareOneScaleThroughTheirExif) {
  // The back bracket at a quarter of the front's ISO and the same times: its photos are two
  // stops darker, which the photographic exposure t · (S/100) / N² takes out.
  if (!fs::exists(kInterior)) GTEST_SKIP() << kInterior << " not found (Debian blender-data)";
  testing::SyntheticCaptureSpec spec = testing::small_capture_spec();
  spec.iso = 400;
  spec.f_number = 2;
  spec.back_iso_factor = 0.25;
  const EquirectMap truth = testing::within_bracket(read_environment_map(kInterior));
  const testing::TempDir dir;
  const testing::SyntheticCapture photos = testing::make_synthetic_capture(truth, dir.path(), spec);
  CaptureOptions options;
  options.front = photos.front;
  options.back = photos.back;
  options.width = 256;
  options.illuminance_lux = plane_illuminance(truth, {0, 1, 0});
  expect_planes_within(truth, capture_environment(options).map, 0.03);
}

}  // namespace
}  // namespace relight
