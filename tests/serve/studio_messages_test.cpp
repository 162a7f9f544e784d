// serve/studio_messages.h: what a client may send (validated, errors naming the JSON path and
// echoing a readable seq) and the hello a client gets first.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "common/input_error.h"
#include "runtime/lighting_state.h"
#include "serve/studio_messages.h"
#include "support/synthetic_epw.h"
#include "tiny_studio_room.h"

namespace relight {
namespace {

const testing::TinyStudioRoom& room() {
  static const testing::TinyStudioRoom r;
  return r;
}

ClientMessage parse(const std::string& text) {
  std::optional<std::uint32_t> seq;
  return parse_client_message(text, room().transfer.scene, seq);
}

// The error text of a malformed message, and the seq it could still read.
std::pair<std::string, std::optional<std::uint32_t>> refusal(const std::string& text) {
  std::optional<std::uint32_t> seq;
  try {
    parse_client_message(text, room().transfer.scene, seq);
  } catch (const InputError& e) {
    return {e.what(), seq};
  }
  ADD_FAILURE() << "accepted: " << text;
  return {};
}

TEST(StudioMessages, StatePickDistributionPing) {
  const ClientMessage s =
      parse(R"({"type":"state","seq":3,"state":{"luminaires":{"down":{"dimmer":0.5}}}})");
  EXPECT_EQ(s.seq, 3u);
  ASSERT_TRUE(std::holds_alternative<StateRequest>(s.request));
  EXPECT_EQ(std::get<StateRequest>(s.request).document["luminaires"]["down"]["dimmer"], 0.5);
  // A bare state document is a state message.
  const ClientMessage bare = parse(R"({"luminaires":{"down":{"on":false}}})");
  EXPECT_FALSE(bare.seq);
  EXPECT_TRUE(std::holds_alternative<StateRequest>(bare.request));
  const ClientMessage pick = parse(R"({"type":"pick","origin":[1,1,1],"direction":[0,-2,0]})");
  ASSERT_TRUE(std::holds_alternative<PickRequest>(pick.request));
  EXPECT_EQ(std::get<PickRequest>(pick.request).direction.y, -1);
  const ClientMessage d = parse(R"({"type":"distribution","luminaire":"down","samples":91})");
  EXPECT_EQ(std::get<DistributionRequest>(d.request).samples, 91);
  EXPECT_TRUE(std::holds_alternative<PingRequest>(parse(R"({"type":"ping","seq":0})").request));
  const ClientMessage u = parse(R"({"type":"upload","seq":4,"name":"a.ies","text":"IES"})");
  EXPECT_EQ(std::get<UploadRequest>(u.request).name, "a.ies");
  EXPECT_EQ(std::get<UploadRequest>(u.request).text, "IES");
  EXPECT_TRUE(
      std::holds_alternative<ExportSceneRequest>(parse(R"({"type":"export_scene"})").request));
}

TEST(StudioMessages, MalformedMessagesNameWhereAndKeepTheirSeq) {
  EXPECT_NE(refusal("not json").first.find("malformed JSON"), std::string::npos);
  EXPECT_NE(refusal("[1,2]").first.find("expected a JSON object"), std::string::npos);
  EXPECT_NE(refusal(R"({"type":"fly","seq":5})").first.find("/type"), std::string::npos);
  EXPECT_EQ(refusal(R"({"type":"fly","seq":5})").second, 5u);
  EXPECT_NE(refusal(R"({"type":"pick","seq":6,"origin":[0,0,0],"direction":[0,0,0]})")
                .first.find("/direction"),
            std::string::npos);
  EXPECT_NE(
      refusal(R"({"type":"pick","origin":[0,"a",0],"direction":[0,1,0]})").first.find("/origin"),
      std::string::npos);
  EXPECT_NE(refusal(R"({"type":"distribution","luminaire":7})").first.find("/luminaire"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"upload","name":"a.ies"})").first.find("text"), std::string::npos);
  EXPECT_NE(refusal(R"({"type":"export_scene","scene":{}})").first.find("scene"),
            std::string::npos);
  EXPECT_NE(
      refusal(R"({"type":"distribution","luminaire":"down","samples":1})").first.find("/samples"),
      std::string::npos);
  EXPECT_NE(refusal(R"({"type":"state","seq":-1,"state":{}})").first.find("/seq"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"state","state":[]})").first.find("/state"), std::string::npos);
  EXPECT_NE(refusal(R"({"type":"ping","extra":1})").first.find("extra"), std::string::npos);
}

// A day of a weather file: its 24 records in hour order, each hour the same Perez sky as
// `relight annual` lights the windows with (record_sky), in the state form that reads back
// into it, with the sun's altitude at h − 30 min (Munich, 22 June: about 65° at 12:30 CET,
// below the horizon at 00:30); a bad date or record is refused with its path.
TEST(StudioMessages, WeatherDayGivesEachHourTheAnnualSky) {
  const std::string epw = testing::synthetic_epw();
  const nlohmann::json message = {
      {"type", "weather_day"}, {"seq", 9}, {"weather", epw}, {"date", "06-22"}};
  const ClientMessage m = parse(message.dump());
  ASSERT_TRUE(std::holds_alternative<WeatherDayRequest>(m.request));
  const WeatherDayRequest& r = std::get<WeatherDayRequest>(m.request);
  ASSERT_EQ(r.records.size(), 24u);
  for (std::size_t h = 0; h < 24; ++h) EXPECT_EQ(r.records[h].hour, static_cast<int>(h) + 1);
  const nlohmann::json reply = weather_day_message(9, r);
  EXPECT_EQ(reply["seq"], 9);
  EXPECT_EQ(reply["date"], "06-22");
  ASSERT_EQ(reply["hours"].size(), 24u);
  const nlohmann::json& noon = reply["hours"][12];
  EXPECT_EQ(noon["hour"], 13);
  EXPECT_EQ(noon["time"], "12:30");
  EXPECT_NEAR(noon["sun_altitude_deg"].get<double>(), 65, 1.5);
  EXPECT_LT(reply["hours"][0]["sun_altitude_deg"].get<double>(), 0);
  EXPECT_EQ(noon["direct_normal_irradiance"], r.records[12].direct_normal_irradiance);
  const nlohmann::json doc = {{"env", noon["environment"]}};
  EnvironmentSpec back = parse_environment(JsonNode(doc, "reply", "/").at("env"), ".");
  EnvironmentSpec sky = record_sky(r.location, r.records[12], 0);
  back.where = sky.where = "";
  EXPECT_EQ(back, sky);

  const auto refused = [&](const std::string& date) {
    return refusal(nlohmann::json{{"type", "weather_day"}, {"weather", epw}, {"date", date}}.dump())
        .first;
  };
  EXPECT_NE(refused("13-01").find("message:/date: expected a day of the year"), std::string::npos);
  EXPECT_NE(refused("02-30").find("message:/date"), std::string::npos);
  EXPECT_NE(refused("6-22").find("message:/date"), std::string::npos);
  std::string bad = epw;
  bad.replace(bad.find("\n", bad.find("DATA PERIODS")) + 1, 4, "year");
  EXPECT_NE(
      refusal(nlohmann::json{{"type", "weather_day"}, {"weather", bad}, {"date", "06-22"}}.dump())
          .first.find("message:/weather:9"),
      std::string::npos);
}

// A client's eye for glossy shading (RLGV): three finite numbers, else refused at /eye.
TEST(StudioMessages, ViewCarriesTheEye) {
  const ClientMessage v = parse(R"({"type":"view","seq":4,"eye":[1.5,1.6,-2]})");
  ASSERT_TRUE(std::holds_alternative<ViewRequest>(v.request));
  EXPECT_EQ(std::get<ViewRequest>(v.request).eye, (Vec3{1.5, 1.6, -2}));
  EXPECT_EQ(v.seq, 4u);
  EXPECT_NE(refusal(R"({"type":"view","eye":[1,"a",2]})").first.find("message:/eye"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"view","eye":[1,2]})").first.find("/eye"), std::string::npos);
  EXPECT_NE(refusal(R"({"type":"view"})").first.find("eye"), std::string::npos);
  EXPECT_NE(refusal(R"({"type":"view","eye":[1,2,3],"up":[0,1,0]})").first.find("up"),
            std::string::npos);
}

// The optimise panel's message: its targets parsed against the scene, bad ones refused with
// their path inside the message.
TEST(StudioMessages, OptimizeCarriesCheckedTargets) {
  const ClientMessage m = parse(
      R"({"type":"optimize","seq":9,"targets":{"sensors":{"floor":{"em_min":200}},
          "objective":"uniformity"},"daylight":true})");
  ASSERT_TRUE(std::holds_alternative<OptimizeRequest>(m.request));
  const OptimizeRequest& r = std::get<OptimizeRequest>(m.request);
  EXPECT_TRUE(r.daylight);
  ASSERT_EQ(r.targets.targets.size(), 1u);
  EXPECT_EQ(r.targets.targets[0].value, 200);
  EXPECT_EQ(r.targets.objective, DesignObjective::kUniformity);
  const auto [error, seq] =
      refusal(R"({"type":"optimize","seq":4,"targets":{"sensors":{"hall":{"em_min":1}}}})");
  EXPECT_EQ(seq, 4u);
  EXPECT_NE(error.find("message:/targets/sensors/hall: no sensor set named \"hall\""),
            std::string::npos)
      << error;
  EXPECT_NE(refusal(R"({"type":"optimize","targets":{"sensors":{"floor":{"e_min":5,"e_max":1}}}})")
                .first.find("/targets/sensors/floor/e_min: is above e_max"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"optimize","targets":{}})").first.find("no target"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"optimize","targets":{"sensors":{"floor":{"em_min":1}}},
                       "daylight":"yes"})")
                .first.find("/daylight"),
            std::string::npos);
}

TEST(StudioMessages, DeepNestingIsRefusedBeforeParsing) {
  EXPECT_EQ(json_nesting_depth(R"({"a":[1,{"b":"[[[[{{"}],"c":"\"["}])"), 3u);
  const std::string deep =
      R"({"luminaires":)" + std::string(100000, '[') + std::string(100000, ']') + "}";
  EXPECT_NE(refusal(deep).first.find("nested deeper than 64"), std::string::npos);
  std::string ok = R"({"type":"state","state":{"luminaires":{"down":{"distribution":)"
                   R"({"type":"curve","gamma_deg":[0,90],"candela":[1,0]}}}}})";
  EXPECT_TRUE(std::holds_alternative<StateRequest>(parse(ok).request));
}

TEST(StudioMessages, HelloDescribesTheScene) {
  const TransferFile& t = room().transfer;
  const nlohmann::json h = hello_message(t, "tiny.rlt", nlohmann::json::object());
  EXPECT_EQ(h["type"], "hello");
  EXPECT_EQ(h["protocol"], 1);
  EXPECT_EQ(h["vertices"], t.vertex_count);
  EXPECT_EQ(h["triangles"], t.triangles.size());
  EXPECT_EQ(h["luminaires"][0]["name"], "down");
  EXPECT_EQ(h["luminaires"][0]["distribution"]["type"], "curve");
  EXPECT_EQ(h["portals"][0]["name"], "south");
  EXPECT_EQ(h["portals"][0]["environment"]["luminance"], 1000);
  EXPECT_EQ(h["portals"][0]["outward"][2], 1);
  EXPECT_EQ(h["cameras"][0]["name"], "in");
  EXPECT_EQ(h["sensors"][0]["points"].size(), 6u);
  EXPECT_EQ(h["sensors"][0]["nu"], 3);
  for (const nlohmann::json& m : h["materials"]) {
    EXPECT_EQ(m["portal"],
              m["name"] == "glass" ? nlohmann::json("south") : nlohmann::json(nullptr));
  }
  EXPECT_EQ(h["sh_order"], 4);
  EXPECT_EQ(h["state"], nlohmann::json::object());
  EXPECT_EQ(h["emitters"], nlohmann::json::array());
  EXPECT_EQ(h["objects"], nlohmann::json::array());
}

TEST(StudioMessages, HelloListsTheObjects) {
  const testing::TinyStudioRoom furnished(testing::tiny_studio_room_with_object_json());
  const TransferFile& t = furnished.transfer;
  const nlohmann::json h = hello_message(t, "tiny.rlt", nlohmann::json::object());
  ASSERT_EQ(h["objects"].size(), 1u);
  const nlohmann::json& o = h["objects"][0];
  EXPECT_EQ(o["name"], "cabinet");
  // (the .rlt stores the objects' meshes in single precision)
  const std::vector<double> pivot = o["pivot"];
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(pivot[k], (testing::kCabinetMin[k] + testing::kCabinetMax[k]) / 2, 1e-6);
  }
  // Half the diagonal of the 0.5 × 1.2 × 0.4 m box.
  EXPECT_NEAR(o["size"].get<double>(), 0.5 * std::sqrt(0.25 + 1.44 + 0.16), 1e-6);
  EXPECT_EQ(o["vertices"], t.view.objects[0].positions.size());
  EXPECT_EQ(o["triangles"], t.view.objects[0].triangles.size());
  EXPECT_GE(o["vertices"].get<std::size_t>(), 8u);
  EXPECT_GE(o["triangles"].get<std::size_t>(), 12u);
}

TEST(StudioMessages, HelloListsTheEmitters) {
  const testing::TinyStudioRoom lit(testing::tiny_studio_room_with_emitter_json());
  const nlohmann::json h = hello_message(lit.transfer, "tiny.rlt", nlohmann::json::object());
  ASSERT_EQ(h["emitters"].size(), 1u);
  const nlohmann::json& e = h["emitters"][0];
  EXPECT_EQ(e["name"], "panel");
  EXPECT_DOUBLE_EQ(e["luminance"].get<double>(), 2000);
  // The scene's chromaticity, scaled to luminance 1.
  const std::vector<double> c = e["color"];
  EXPECT_NEAR(0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2], 1, 1e-9);
  EXPECT_NEAR(c[0] / c[1], 2, 1e-9);
  const std::vector<double> pivot = e["pivot"];
  EXPECT_NEAR(pivot[0], 1.2, 1e-12);
  EXPECT_NEAR(pivot[1], 2, 1e-12);
  EXPECT_NEAR(pivot[2], 1.2, 1e-12);
  EXPECT_NEAR(e["size"].get<double>(), 0.2 * std::sqrt(2.0), 1e-12);  // half the diagonal
}

// What the server does with a state message on arrival (StudioServer: apply_lighting_state,
// whose InputError goes back to the sender as an error naming the JSON path): emitter states
// for an unknown name or with a non-number placement are refused.
TEST(StudioMessages, BadEmitterStatesAreRefusedWithTheirJsonPath) {
  const testing::TinyStudioRoom lit(testing::tiny_studio_room_with_emitter_json());
  const Scene& scene = lit.transfer.scene;
  const auto error = [&](const char* text) -> std::string {
    LightingState state = default_lighting_state(scene);
    try {
      apply_lighting_state(state, scene, nlohmann::json::parse(text), "message", ".");
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(error(R"({"emitters":{"lamp":{"on":true}}})"),
            "message:/emitters/lamp: no emitter named \"lamp\" in the precomputed scene");
  EXPECT_NE(error(R"({"emitters":{"panel":{"rotate_deg":"NaN"}}})")
                .find("message:/emitters/panel/rotate_deg: expected a number"),
            std::string::npos);
  EXPECT_NE(error(R"({"emitters":{"panel":{"translate":[0,"x",0]}}})")
                .find("message:/emitters/panel/translate"),
            std::string::npos);
  EXPECT_EQ(error(R"({"emitters":{"panel":{"translate":[0.5,0,0],"luminance":100}}})"), "accepted");
}

// Likewise for movable objects' placements.
TEST(StudioMessages, BadObjectStatesAreRefusedWithTheirJsonPath) {
  const testing::TinyStudioRoom furnished(testing::tiny_studio_room_with_object_json());
  const Scene& scene = furnished.transfer.scene;
  const auto error = [&](const char* text) -> std::string {
    LightingState state = default_lighting_state(scene);
    try {
      apply_lighting_state(state, scene, nlohmann::json::parse(text), "message", ".");
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(error(R"({"objects":{"sofa":{"visible":false}}})"),
            "message:/objects/sofa: no movable object named \"sofa\" in the precomputed scene");
  EXPECT_NE(
      error(R"({"objects":{"cabinet":{"visible":"no"}}})").find("message:/objects/cabinet/visible"),
      std::string::npos);
  EXPECT_NE(error(R"({"objects":{"cabinet":{"rotate_deg":"90"}}})")
                .find("message:/objects/cabinet/rotate_deg"),
            std::string::npos);
  EXPECT_NE(error(R"({"objects":{"cabinet":{"scale":2}}})").find("scale"), std::string::npos);
  EXPECT_NE(error(R"({"objects":[]})").find("message:/objects"), std::string::npos);
  EXPECT_EQ(
      error(R"({"objects":{"cabinet":{"translate":[1,0,0.5],"rotate_deg":30,"visible":true}}})"),
      "accepted");
}

}  // namespace
}  // namespace relight
