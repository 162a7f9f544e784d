// The studio's text messages (docs/studio-protocol.md): the `hello` a client gets first, the
// validation of what clients send, and the replies. Every malformed message becomes an
// InputError naming the JSON path ("message:/origin: ..."), which the server turns into an
// `error` reply; nothing a client sends can stop the server.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "design/design_targets.h"
#include "design/optimize.h"
#include "light/epw_weather.h"
#include "math/vec3.h"
#include "runtime/annual_daylight.h"
#include "runtime/luminaire_profile.h"
#include "runtime/relit_scene.h"

namespace relight {

inline constexpr int kDefaultProfileSamples = 181;
// Deepest nesting of arrays and objects a message may have (the protocol's own need under 10).
inline constexpr std::size_t kMaxMessageDepth = 64;

// Nesting depth of arrays and objects in JSON text (strings skipped), without parsing it.
std::size_t json_nesting_depth(std::string_view text);

// nlohmann::json's noexcept move calls assert_invariant, which clang-tidy 14 cannot prove
// non-throwing:
// NOLINTNEXTLINE(bugprone-exception-escape)
struct StateRequest {
  nlohmann::json document;  // the lighting state (docs/lighting-state.md)
};
struct PickRequest {
  Vec3 origin, direction;  // direction normalised
};
// A luminaire of the scene or one the state shown adds, by name (resolved when answered).
struct DistributionRequest {
  std::string luminaire;
  int samples = kDefaultProfileSamples;
};
// A photometric file for the catalogue (serve/photometry_catalogue.h): its name as the client
// knows it (never used as a path) and its text.
struct UploadRequest {
  std::string name;
  std::string text;
};
// "Open model…": a model file the sender is about to send in RLMU chunks (serve/model_opening.h):
// its name as the client knows it (for its extension and for messages; never a path) and size.
struct OpenModelRequest {
  std::string name;
  std::uint64_t bytes = 0;
};
// The scene JSON with the layout shown as ordinary luminaires (runtime/scene_export.h).
struct ExportSceneRequest {};
struct PingRequest {};
// Where the sender's camera is: glossy surfaces are shaded toward it (RLGV).
struct ViewRequest {
  Vec3 eye;
};
// A year of daylight (`relight annual`) from the weather file's text, parsed and checked here.
struct AnnualRequest {
  WeatherFile weather;
  OccupiedPeriod period;
  std::string occupied = "08:00-18:00";  // as sent, for the reply
};

// The hours of one day of a weather file, for the studio to scrub (`weather_day`): the file's
// place and the day's records in hour order, chosen and checked here.
struct WeatherDayRequest {
  WeatherLocation location;
  std::string date;  // "MM-DD", as sent
  std::vector<WeatherRecord> records;
};

// Inverse design (`relight optimize`) from the state shown now: the targets parsed and checked
// here, and whether the windows' daylight is kept.
struct OptimizeRequest {
  DesignTargets targets;
  bool daylight = false;
};

// The largest message a client may send: a weather file of a year is 1.5–2 MB of text.
inline constexpr std::size_t kMaxClientMessageBytes = std::size_t{8} << 20;

struct ClientMessage {
  std::optional<std::uint32_t> seq;
  std::variant<StateRequest, PickRequest, DistributionRequest, PingRequest, AnnualRequest,
               WeatherDayRequest, OptimizeRequest, ViewRequest, UploadRequest, ExportSceneRequest,
               OpenModelRequest>
      request;
};

// Throws InputError for malformed text; `seq` is set as soon as a readable one was found, so
// the error reply can echo it.
ClientMessage parse_client_message(const std::string& text, const Scene& scene,
                                   std::optional<std::uint32_t>& seq);

nlohmann::json hello_message(const TransferFile& transfer, const std::string& scene_file_name,
                             const nlohmann::json& state);

nlohmann::json error_message(std::optional<std::uint32_t> seq, const std::string& message);

nlohmann::json distribution_message(std::optional<std::uint32_t> seq, const std::string& luminaire,
                                    const DistributionSpec& spec,
                                    const DistributionProfile& profile, int sh_order,
                                    std::size_t incremental_updates);

// How far a year of daylight has come: `stage` "preparing" (the sensors' importance) or
// "hours" (`done` of `total`).
nlohmann::json annual_progress_message(std::optional<std::uint32_t> seq, std::size_t done,
                                       std::size_t total, const char* stage);
// Its result: the weather file's place, the hours, and per sensor set the metrics of `relight
// annual` with one array per metric over the set's points.
// Each hour of the day as the Perez sky `relight annual` lights the windows with (record_sky),
// in the lighting-state form a portal's or the scene's environment takes, with the sun's
// altitude at the hour's evaluation time (h − 30 min).
nlohmann::json weather_day_message(std::optional<std::uint32_t> seq, const WeatherDayRequest& r);

nlohmann::json annual_message(std::optional<std::uint32_t> seq, const Scene& scene,
                              const WeatherFile& weather, const std::string& occupied,
                              const AnnualHours& hours, const AnnualDaylight& year, double seconds);

// Its result: the line `relight optimize` prints and the lighting state document it wrote.
nlohmann::json optimized_message(std::optional<std::uint32_t> seq, const Scene& scene,
                                 const OptimizeResult& result);

// A seq as JSON: the number, or null.
nlohmann::json seq_json(std::optional<std::uint32_t> seq);

}  // namespace relight
