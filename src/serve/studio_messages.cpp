#include "serve/studio_messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/input_error.h"
#include "light/environment.h"
#include "scene/json_node.h"

namespace relight {

namespace {

nlohmann::json vec3_json(Vec3 v) {
  return {v.x, v.y, v.z};
}
nlohmann::json rgb_json(Rgb c) {
  return {c.r, c.g, c.b};
}

// Where a weather file stands, as the replies that read one give it.
nlohmann::json weather_location_json(const WeatherLocation& at) {
  return {{"city", at.city},
          {"latitude", at.latitude_deg},
          {"longitude", at.longitude_deg},
          {"time_zone", at.time_zone_hours}};
}

// "MM-DD": the day of the weather file to scrub; its records in hour order.
WeatherDayRequest weather_day_request(const JsonNode& weather, const JsonNode& date) {
  WeatherDayRequest r;
  r.date = date.string();
  int month = 0, day = 0;
  char tail = 0;
  if (std::sscanf(r.date.c_str(), "%2d-%2d%c", &month, &day, &tail) != 2 || r.date.size() != 5 ||
      month < 1 || month > 12 || day < 1 || day > days_in_month(2000, month)) {
    date.fail("expected a day of the year \"MM-DD\", got \"" + r.date + "\"");
  }
  WeatherFile file = parse_epw(weather.string(), weather.where());
  r.location = file.location;
  for (WeatherRecord& record : file.records) {
    if (record.month == month && record.day == day) r.records.push_back(record);
  }
  if (r.records.empty()) date.fail("the weather file has no records on " + r.date);
  std::stable_sort(r.records.begin(), r.records.end(),
                   [](const WeatherRecord& a, const WeatherRecord& b) { return a.hour < b.hour; });
  return r;
}

std::optional<std::uint32_t> read_seq(const JsonNode& root) {
  const auto s = root.find("seq");
  if (!s || s->value().is_null()) return std::nullopt;
  if (!s->value().is_number_unsigned() || s->value().get<std::uint64_t>() >= 0xFFFFFFFFu) {
    s->fail("expected a non-negative integer below 4294967295");
  }
  return s->value().get<std::uint32_t>();
}

}  // namespace

nlohmann::json seq_json(std::optional<std::uint32_t> seq) {
  return seq ? nlohmann::json(*seq) : nlohmann::json(nullptr);
}

std::size_t json_nesting_depth(std::string_view text) {
  std::size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

ClientMessage parse_client_message(const std::string& text, const Scene& scene,
                                   std::optional<std::uint32_t>& seq) {
  // The JSON library copies and destroys documents recursively: a message nested deeper than
  // any message of the protocol is refused before it is parsed.
  if (json_nesting_depth(text) > kMaxMessageDepth) {
    fail_input("message", "nested deeper than " + std::to_string(kMaxMessageDepth) + " levels");
  }
  nlohmann::json document = parse_json_text(text, "message");
  const JsonNode root(document, "message", "/");
  if (!root.is_object()) root.fail("expected a JSON object");
  ClientMessage m;
  if (!root.has("type")) {  // a bare lighting state document
    m.request = StateRequest{std::move(document)};
    return m;
  }
  m.seq = seq = read_seq(root);
  const std::string type = root.at("type").string();
  if (type == "state") {
    root.expect_keys({"type", "seq", "state"});
    const JsonNode state = root.at("state");
    if (!state.is_object()) state.fail("expected a lighting state object");
    m.request = StateRequest{std::move(document["state"])};
  } else if (type == "pick") {
    root.expect_keys({"type", "seq", "origin", "direction"});
    m.request = PickRequest{root.at("origin").vec3(), root.at("direction").direction()};
  } else if (type == "distribution") {
    root.expect_keys({"type", "seq", "luminaire", "samples"});
    DistributionRequest r;
    r.luminaire = root.at("luminaire").string();
    if (const auto s = root.find("samples")) r.samples = s->integer_in(2, 1801);
    m.request = r;
  } else if (type == "ping") {
    root.expect_keys({"type", "seq"});
    m.request = PingRequest{};
  } else if (type == "view") {
    root.expect_keys({"type", "seq", "eye"});
    m.request = ViewRequest{root.at("eye").vec3()};
  } else if (type == "annual") {
    root.expect_keys({"type", "seq", "weather", "occupied"});
    AnnualRequest r;
    r.weather = parse_epw(root.at("weather").string(), "message:/weather");
    if (const auto o = root.find("occupied")) {
      r.occupied = o->string();
      const std::optional<OccupiedPeriod> period = parse_occupied_period(r.occupied);
      if (!period) o->fail("expected HH:MM-HH:MM with the end after the start (up to 24:00)");
      r.period = *period;
    }
    m.request = std::move(r);
  } else if (type == "weather_day") {
    root.expect_keys({"type", "seq", "weather", "date"});
    m.request = weather_day_request(root.at("weather"), root.at("date"));
  } else if (type == "upload") {
    root.expect_keys({"type", "seq", "name", "text"});
    m.request = UploadRequest{root.at("name").string(), root.at("text").string()};
  } else if (type == "open_model") {
    root.expect_keys({"type", "seq", "name", "bytes"});
    const JsonNode bytes = root.at("bytes");
    const double n = bytes.number();
    if (n < 1 || n != std::floor(n) || n > 1e15) bytes.fail("expected the file's size in bytes");
    m.request = OpenModelRequest{root.at("name").string(), static_cast<std::uint64_t>(n)};
  } else if (type == "export_scene") {
    root.expect_keys({"type", "seq"});
    m.request = ExportSceneRequest{};
  } else if (type == "optimize") {
    root.expect_keys({"type", "seq", "targets", "daylight"});
    OptimizeRequest r{parse_design_targets(root.at("targets"), scene)};
    if (const auto d = root.find("daylight")) r.daylight = d->boolean();
    m.request = std::move(r);
  } else {
    root.at("type").fail("unknown message type \"" + type +
                         "\" (expected state, pick, distribution, ping, annual, weather_day, "
                         "optimize, view, upload, export_scene or open_model)");
  }
  return m;
}

nlohmann::json annual_progress_message(std::optional<std::uint32_t> seq, std::size_t done,
                                       std::size_t total, const char* stage) {
  return {{"type", "annual_progress"},
          {"seq", seq_json(seq)},
          {"stage", stage},
          {"done", done},
          {"total", total}};
}

nlohmann::json weather_day_message(std::optional<std::uint32_t> seq, const WeatherDayRequest& r) {
  nlohmann::json hours = nlohmann::json::array();
  for (const WeatherRecord& record : r.records) {
    // The JSON carries no north: the document it is put in turns it by its site.
    const EnvironmentSpec sky = record_sky(r.location, record, 0);
    const double altitude = degrees(std::asin(std::clamp(sun_direction(sky.sun).y, -1.0, 1.0)));
    char time[16];
    std::snprintf(time, sizeof time, "%02d:30", record.hour - 1);
    hours.push_back({{"hour", record.hour},
                     {"time", time},
                     {"sun_altitude_deg", altitude},
                     {"direct_normal_irradiance", record.direct_normal_irradiance},
                     {"diffuse_horizontal_irradiance", record.diffuse_horizontal_irradiance},
                     {"environment", perez_sky_json(sky)}});
  }
  return {{"type", "weather_day"},
          {"seq", seq_json(seq)},
          {"weather", weather_location_json(r.location)},
          {"date", r.date},
          {"hours", std::move(hours)}};
}

nlohmann::json annual_message(std::optional<std::uint32_t> seq, const Scene& scene,
                              const WeatherFile& weather, const std::string& occupied,
                              const AnnualHours& hours, const AnnualDaylight& year,
                              double seconds) {
  nlohmann::json sets = nlohmann::json::array();
  std::size_t column = 0;
  for (std::size_t k = 0; k < scene.sensors.size(); ++k) {
    const SensorSet& set = scene.sensors[k];
    const SetDaylight& d = year.per_set.at(k);
    nlohmann::json da = nlohmann::json::array(), fell_short = nlohmann::json::array(),
                   useful = nlohmann::json::array(), exceeded = nlohmann::json::array(),
                   ase_hours = nlohmann::json::array();
    for (std::size_t i = 0; i < set.points.size(); ++i, ++column) {
      const SensorDaylight& s = year.per_sensor.at(column);
      da.push_back(s.da300);
      fell_short.push_back(s.udi_fell_short);
      useful.push_back(s.udi_useful);
      exceeded.push_back(s.udi_exceeded);
      ase_hours.push_back(s.ase_hours);
    }
    sets.push_back({{"name", set.name},
                    {"points", set.points.size()},
                    {"sda300", d.sda300},
                    {"ase", d.ase},
                    {"mean_da300", d.mean_da300},
                    {"en17037", daylight_provision_name(d.en17037)},
                    {"da300", std::move(da)},
                    {"udi_fell_short", std::move(fell_short)},
                    {"udi_useful", std::move(useful)},
                    {"udi_exceeded", std::move(exceeded)},
                    {"ase_hours", std::move(ase_hours)}});
  }
  nlohmann::json place = weather_location_json(weather.location);
  place["records"] = weather.records.size();
  return {{"type", "annual"},
          {"seq", seq_json(seq)},
          {"weather", std::move(place)},
          {"occupied", occupied},
          {"occupied_hours", hours.occupied},
          {"hours", hours.hours.size()},
          {"seconds", seconds},
          {"sets", std::move(sets)}};
}

namespace {

nlohmann::json glazing_json(const Glazing& g) {
  return {{"visible_transmittance", g.visible_transmittance},
          {"panes", g.panes},
          {"diffusing", g.diffusing}};
}

}  // namespace

nlohmann::json hello_message(const TransferFile& t, const std::string& scene_file_name,
                             const nlohmann::json& state) {
  const Scene& scene = t.scene;
  const nlohmann::json& scene_json = t.metadata.at("scene");
  const Bounds b = t.bounds();
  nlohmann::json materials = nlohmann::json::array();
  const std::vector<int> portal_of = scene.portal_of_material();
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    materials.push_back(
        {{"name", m.name},
         {"albedo", rgb_json(m.albedo)},
         {"glossy", m.glossy},
         {"metallic", m.metallic},
         {"roughness", m.roughness},
         {"portal", portal_of[i] >= 0
                        ? nlohmann::json(scene.portals[static_cast<std::size_t>(portal_of[i])].name)
                        : nlohmann::json(nullptr)}});
  }
  nlohmann::json luminaires = nlohmann::json::array();
  for (std::size_t j = 0; j < scene.luminaires.size(); ++j) {
    const Luminaire& l = scene.luminaires[j];
    luminaires.push_back({{"name", l.name},
                          {"position", vec3_json(l.position)},
                          {"aim", vec3_json(l.aim)},
                          {"c0", vec3_json(l.c0)},
                          {"color", rgb_json(l.color)},
                          {"dimmer", l.dimmer},
                          {"size", vec3_json(l.size)},
                          {"distribution", scene_json.at("luminaires").at(j).at("distribution")}});
  }
  nlohmann::json portals = nlohmann::json::array();
  for (std::size_t p = 0; p < scene.portals.size(); ++p) {
    const Portal& portal = scene.portals[p];
    const PortalTransferView& v = t.view.portals.at(p);
    portals.push_back(
        {{"name", portal.name},
         {"centre", vec3_json(v.centre)},
         {"outward", vec3_json(v.outward)},
         {"diameter", v.diameter},
         {"environment", scene_json.at("portals").at(p).at("environment")},
         {"tint", rgb_json(portal.tint)},
         {"frost_deg", portal.frost_deg},
         {"glazing", portal.glazing ? glazing_json(*portal.glazing) : nlohmann::json(nullptr)}});
  }
  nlohmann::json exterior = nlohmann::json::array();
  for (const ExteriorGeometry& x : scene.exterior) {
    if (!x.name.empty()) exterior.push_back(x.name);
  }
  nlohmann::json emitters = nlohmann::json::array();
  for (const Emitter& e : scene.emitters) {
    Vec3 lo = e.geometry.positions.front(), hi = lo;
    for (const Vec3 p : e.geometry.positions) {
      lo = min(lo, p);
      hi = max(hi, p);
    }
    emitters.push_back({{"name", e.name},
                        {"luminance", e.luminance},
                        {"color", rgb_json(e.color)},
                        {"pivot", vec3_json(e.pivot)},
                        {"size", 0.5 * length(hi - lo)}});
  }
  nlohmann::json objects = nlohmann::json::array();
  for (const ObjectMesh& o : t.view.objects) {
    Vec3 lo = o.pivot, hi = lo;
    for (const Vec3 p : o.positions) {
      lo = min(lo, p);
      hi = max(hi, p);
    }
    objects.push_back({{"name", o.name},
                       {"pivot", vec3_json(o.pivot)},
                       {"size", 0.5 * length(hi - lo)},
                       {"vertices", o.positions.size()},
                       {"triangles", o.triangles.size()}});
  }
  nlohmann::json cameras = nlohmann::json::array();
  for (const Camera& c : scene.cameras) {
    cameras.push_back({{"name", c.name},
                       {"eye", vec3_json(c.eye)},
                       {"target", vec3_json(c.target)},
                       {"up", vec3_json(c.up)},
                       {"fov_deg", c.fov_deg}});
  }
  nlohmann::json sensors = nlohmann::json::array();
  for (const SensorSet& s : scene.sensors) {
    nlohmann::json points = nlohmann::json::array();
    for (const Vec3 p : s.points) points.push_back(vec3_json(p));
    sensors.push_back({{"name", s.name},
                       {"normal", vec3_json(s.normal)},
                       {"nu", s.nu},
                       {"nv", s.nv},
                       {"points", points}});
  }
  return {{"type", "hello"},
          {"protocol", 1},
          {"scene_file", scene_file_name},
          {"vertices", t.vertex_count},
          {"triangles", t.triangles.size()},
          {"bounds", {{"min", vec3_json(b.min)}, {"max", vec3_json(b.max)}}},
          {"materials", materials},
          {"luminaires", luminaires},
          {"portals", portals},
          {"environment", scene_json.value("environment", nlohmann::json())},
          {"site", scene_json.value("site", nlohmann::json())},
          {"exterior", exterior},
          {"emitters", emitters},
          {"objects", objects},
          {"cameras", cameras},
          {"sensors", sensors},
          {"sh_order", t.view.sh_order},
          {"direct", t.view.direct_sh_mode ? "sh" : "exact"},
          {"state", state}};
}

nlohmann::json error_message(std::optional<std::uint32_t> seq, const std::string& message) {
  return {{"type", "error"}, {"seq", seq_json(seq)}, {"message", message}};
}

nlohmann::json distribution_message(std::optional<std::uint32_t> seq, const std::string& luminaire,
                                    const DistributionSpec& spec,
                                    const DistributionProfile& profile, int sh_order,
                                    std::size_t incremental_updates) {
  static constexpr const char* kPlanes[] = {"c0", "c90", "c180", "c270"};
  static constexpr const char* kKinds[] = {"isotropic", "cosine_power", "curve", "ies", "ldt"};
  const auto planes = [&](const std::array<std::vector<double>, 4>& values) {
    nlohmann::json out = nlohmann::json::object();
    for (std::size_t k = 0; k < 4; ++k) out[kPlanes[k]] = values[k];
    return out;
  };
  nlohmann::json m = {
      {"type", "distribution"},         {"seq", seq_json(seq)},
      {"luminaire", luminaire},         {"kind", kKinds[static_cast<int>(spec.type)]},
      {"sh_order", sh_order},           {"window", "sigma"},
      {"gamma_deg", profile.gamma_deg}, {"exact", planes(profile.exact)},
      {"sh", planes(profile.sh)},       {"sh_windowed", planes(profile.sh_windowed)},
      {"flux_lm", profile.flux_lm},     {"incremental_updates", incremental_updates}};
  if (spec.type == DistributionType::kCurve) {
    m["control_points"] = {{"gamma_deg", spec.gamma_deg}, {"candela", spec.curve_candela}};
  }
  return m;
}

nlohmann::json optimized_message(std::optional<std::uint32_t> seq, const Scene& scene,
                                 const OptimizeResult& result) {
  return {{"type", "optimized"},
          {"seq", seq_json(seq)},
          {"result", optimize_summary(scene, result)},
          {"state", result.state}};
}

}  // namespace relight
