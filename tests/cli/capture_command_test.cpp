// `relight capture` end to end: a synthetic capture of Blender's interior.exr becomes a float
// OpenEXR whose map lights a window like the truth map (work-plane illuminance within 2 %), --debug
// writes its PNGs, clipped highlights warn, and bad input exits 2 naming the file or option.
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "capture/capture.h"
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

TEST(CaptureCommand, TheCapturedMapLightsAWindowLikeTheTruthWithin2PercentAndIsFloatExr) {
  if (!fs::exists(kInterior)) GTEST_SKIP() << kInterior << " not found (Debian blender-data)";
  const testing::TempDir dir;
  const EquirectMap truth =
      testing::within_bracket(read_environment_map(kInterior), testing::small_capture_spec());
  write_exr(dir.path() / "truth.exr", Image{truth.width, truth.height, truth.texels},
            ExrChannels::kFloat);
  const testing::SyntheticCapture photos =
      testing::make_synthetic_capture(truth, dir.path(), testing::small_capture_spec());
  const double reading = map_horizontal_illuminance(truth);
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
  testing::SyntheticCaptureSpec spec = testing::small_capture_spec();
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

// Two photos of `width` × 48 px, 0.01 and 0.02 s, uniformly grey (so no fisheye circle).
std::vector<fs::path> grey_pair(const testing::TempDir& dir, const std::string& name, int width) {
  const Photo photo{width, 48, 8, std::vector<std::uint16_t>(3 * width * 48, 100)};
  std::vector<fs::path> files;
  for (int k = 0; k < 2; ++k) {
    files.push_back(dir.path() / (name + std::to_string(k) + ".jpg"));
    write_photo_jpeg(files.back(), photo, 90, {0.01 * (k + 1), std::nullopt, std::nullopt});
  }
  return files;
}

TEST(CaptureCommand, BadInputExitsTwoNamingTheFileOrOption) {
  const testing::TempDir dir;
  const std::vector<fs::path> files = grey_pair(dir, "p", 64), wide = grey_pair(dir, "wide", 80);
  const auto quoted = [](const std::vector<fs::path>& paths) {
    std::string list;
    for (const fs::path& p : paths) list += " '" + p.string() + "'";
    return list;
  };
  const std::string two = quoted(files), gone = (dir.path() / "gone.jpg").string();
  const std::string pair = " --front" + two + " --back" + two;
  const std::pair<std::string, std::string> cases[] = {
      {pair + " --exposure-times 1,2,3", "--exposure-times: 3 times for 2 front and 2 back photos"},
      {pair + " --exposure-times 1/x", "--exposure-times: \"1/x\" is not a time in seconds"},
      {pair + " --fov-deg 170", "--fov-deg: two views cover the sphere only with more than 180°"},
      {pair + " --width 301", "--width: must be an even number of texels, at least 16"},
      {pair + " --lens fisheye",
       "--lens: \"fisheye\" is not equidistant, equisolid or stereographic"},
      {" --front '" + files[0].string() + "' --back" + two,
       "--front: " + files[0].string() + " is a single exposure"},
      {" --front" + two + " '" + gone + "' --back" + two, gone + ": no such file"},
      {" --front" + two + " --back" + quoted(wide), wide[0].string() +
                                                        ": 80 × 48 px, but the front photos (" +
                                                        files[0].string() + ") are 64 × 48"},
      // A uniformly lit photo has no black surround: no fisheye circle in it.
      {pair, files[1].string() + ": no fisheye image circle found"},
  };
  const std::string out = " -o '" + (dir.path() / "x.exr").string() + "'";
  for (const auto& [arguments, error] : cases) {
    testing::expect_input_error(run_relight("capture" + arguments + out), error);
  }
  EXPECT_FALSE(fs::exists(dir.path() / "x.exr"));
}

}  // namespace
}  // namespace relight
