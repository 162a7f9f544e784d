// `relight capture` end to end (issue 14): a synthetic capture of Blender's interior.exr
// becomes a float OpenEXR whose map lights a window like the truth map (work-plane
// illuminance within 2 %), --debug writes its PNGs, clipped highlights warn, and bad input
// exits 2 naming the file or option.
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "image/image.h"
#include "image/image_exr.h"
#include "light/environment_map_io.h"
#include "run_command.h"
#include "support/daylight_room.h"
#include "support/synthetic_capture.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::run_relight;

const fs::path kInterior = "/usr/share/blender/datafiles/studiolights/world/interior.exr";

std::string photo_arguments(const testing::SyntheticCapture& photos) {
  std::string args = "--front";
  for (const fs::path& f : photos.front) args += " '" + f.string() + "'";
  args += " --back";
  for (const fs::path& b : photos.back) args += " '" + b.string() + "'";
  return args;
}

testing::SyntheticCaptureSpec small_spec() {
  testing::SyntheticCaptureSpec spec;
  spec.width = 800;
  spec.height = 600;
  spec.radius = 285;
  return spec;
}

double horizontal_illuminance(const EquirectMap& map) {
  double e = 0;
  for (int j = 0; j < map.height / 2; ++j) {
    const double omega = equirect_row_solid_angle(map.width, map.height, j);
    const double up = equirect_texel_direction(map.width, map.height, 0, j).y;
    for (int i = 0; i < map.width; ++i) {
      e += luminance(map.texels[static_cast<std::size_t>(j) * map.width + i]) * up * omega;
    }
  }
  return e;
}

TEST(CaptureCommand, TheCapturedMapLightsAWindowLikeTheTruthWithin2PercentAndIsFloatExr) {
  if (!fs::exists(kInterior)) GTEST_SKIP() << kInterior << " not found (Debian blender-data)";
  const testing::TempDir dir;
  const EquirectMap truth = testing::within_bracket(read_environment_map(kInterior), small_spec());
  write_exr(dir.path() / "truth.exr", Image{truth.width, truth.height, truth.texels},
            ExrChannels::kFloat);
  const testing::SyntheticCapture photos =
      testing::make_synthetic_capture(truth, dir.path(), small_spec());
  const double reading = horizontal_illuminance(truth);
  const fs::path map = dir.path() / "room.exr";
  const testing::CommandResult r =
      run_relight("capture " + photo_arguments(photos) + " -o '" + map.string() +
                  "' --width 512 --illuminance " + std::to_string(reading) + " --debug '" +
                  (dir.path() / "debug").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("calibrated"), std::string::npos) << r.out;
  {
    Imf::InputFile file(map.c_str());
    const Imf::Channel* red = file.header().channels().findChannel("R");
    ASSERT_NE(red, nullptr);
    EXPECT_EQ(red->type, Imf::FLOAT);
    EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
  }
  const EquirectMap captured = read_environment_map(map);
  EXPECT_EQ(captured.width, 512);
  EXPECT_EQ(captured.height, 256);
  for (const char* name :
       {"front_merged.png", "back_merged.png", "response.png", "mask.png", "map.png"}) {
    EXPECT_TRUE(fs::is_regular_file(dir.path() / "debug" / name)) << name;
  }

  const fs::path rlt =
      testing::precompute_scene(dir, "room", testing::south_window_room(0.8).dump());
  const auto probe = [&](const fs::path& env_file, const std::string& name) {
    const nlohmann::json state = {
        {"portals",
         {{"south window", {{"environment", {{"type", "map"}, {"file", env_file.string()}}}}}}}};
    const fs::path state_file = dir.write(name + ".json", state.dump());
    const fs::path csv = dir.path() / (name + ".csv");
    const testing::CommandResult p =
        run_relight("probe '" + rlt.string() + "' --state '" + state_file.string() + "' -o '" +
                    csv.string() + "'");
    EXPECT_EQ(p.exit_code, 0) << p.err;
    return testing::sensor_lux(csv);
  };
  const std::vector<double> from_truth = probe(dir.path() / "truth.exr", "truth");
  const std::vector<double> from_capture = probe(map, "capture");
  ASSERT_EQ(from_truth.size(), from_capture.size());
  ASSERT_FALSE(from_truth.empty());
  double worst = 0;
  for (std::size_t s = 0; s < from_truth.size(); ++s) {
    EXPECT_NEAR(from_capture[s] / from_truth[s], 1.0, 0.02)
        << "sensor " << s << ": " << from_capture[s] << " vs " << from_truth[s] << " lx";
    worst = std::max(worst, std::abs(from_capture[s] / from_truth[s] - 1));
  }
  std::printf("work plane under the captured map: worst sensor %.2f %% off the truth map's\n",
              100 * worst);
}

TEST(CaptureCommand, HighlightsClippedInTheShortestExposureWarnWithTheirShare) {
  if (!fs::exists(kInterior)) GTEST_SKIP() << kInterior << " not found (Debian blender-data)";
  const testing::TempDir dir;
  testing::SyntheticCaptureSpec spec = small_spec();
  spec.middle_time_s = 1.0 / 15;  // the ceiling lamps clip even at 1/240 s
  const testing::SyntheticCapture photos =
      testing::make_synthetic_capture(read_environment_map(kInterior), dir.path(), spec);
  const testing::CommandResult r =
      run_relight("capture " + photo_arguments(photos) + " -o '" +
                  (dir.path() / "room.exr").string() + "' --width 256");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: highlights clipped even in the shortest exposure carry at least"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("not calibrated (no --illuminance): values are relative"), std::string::npos)
      << r.out;
}

TEST(CaptureCommand, BadInputExitsTwoNamingTheFileOrOption) {
  const testing::TempDir dir;
  Photo photo{64, 48, 8, std::vector<std::uint16_t>(3 * 64 * 48, 100)};
  std::vector<fs::path> files;
  for (int k = 0; k < 2; ++k) {
    files.push_back(dir.path() / ("p" + std::to_string(k) + ".jpg"));
    write_photo_jpeg(files.back(), photo, 90, {0.01 * (k + 1), std::nullopt, std::nullopt});
  }
  const std::string two = "'" + files[0].string() + "' '" + files[1].string() + "'";
  const std::string out = " -o '" + (dir.path() / "x.exr").string() + "'";
  testing::expect_input_error(
      run_relight("capture --front " + two + " --back " + two + out + " --exposure-times 1,2,3"),
      "--exposure-times: 3 times for 2 front and 2 back photos");
  testing::expect_input_error(
      run_relight("capture --front " + two + " --back " + two + out + " --exposure-times 1/x"),
      "--exposure-times: \"1/x\" is not a time in seconds");
  testing::expect_input_error(
      run_relight("capture --front " + two + " --back " + two + out + " --fov-deg 170"),
      "--fov-deg: two views cover the sphere only with more than 180°");
  testing::expect_input_error(
      run_relight("capture --front " + two + " --back " + two + out + " --width 301"),
      "--width: must be an even number of texels, at least 16");
  testing::expect_input_error(
      run_relight("capture --front " + two + " --back " + two + out + " --lens fisheye"),
      "--lens: \"fisheye\" is not equidistant, equisolid or stereographic");
  testing::expect_input_error(
      run_relight("capture --front '" + files[0].string() + "' --back " + two + out),
      "--front: " + files[0].string() + " is a single exposure");
  testing::expect_input_error(
      run_relight("capture --front " + two + " '" + (dir.path() / "gone.jpg").string() +
                  "' --back " + two + out),
      (dir.path() / "gone.jpg").string() + ": no such file");
  Photo wide{80, 48, 8, std::vector<std::uint16_t>(3 * 80 * 48, 100)};
  std::vector<fs::path> back;
  for (int k = 0; k < 2; ++k) {
    back.push_back(dir.path() / ("wide" + std::to_string(k) + ".jpg"));
    write_photo_jpeg(back.back(), wide, 90, {0.01 * (k + 1), std::nullopt, std::nullopt});
  }
  testing::expect_input_error(run_relight("capture --front " + two + " --back '" +
                                          back[0].string() + "' '" + back[1].string() + "'" + out),
                              back[0].string() + ": 80 × 48 px, but the front photos (" +
                                  files[0].string() + ") are 64 × 48");
  // A uniformly lit photo has no black surround: no fisheye circle in it.
  testing::expect_input_error(run_relight("capture --front " + two + " --back " + two + out),
                              files[1].string() + ": no fisheye image circle found");
  EXPECT_FALSE(fs::exists(dir.path() / "x.exr"));
}

}  // namespace
}  // namespace relight
