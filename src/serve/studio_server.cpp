#include "serve/studio_server.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>

#include "common/input_error.h"
#include "common/installed_files.h"
#include "design/optimize.h"
#include "light/distribution.h"
#include "material/metallic_roughness.h"
#include "render/relit_scene_image.h"
#include "runtime/annual_daylight.h"
#include "runtime/luminaire_profile.h"
#include "runtime/progressive_frames.h"
#include "runtime/relit_scene.h"
#include "runtime/scene_export.h"
#include "runtime/window_view.h"
#include "scene/json_node.h"
#include "serve/model_opening.h"
#include "serve/photometry_catalogue.h"
#include "serve/static_files.h"
#include "serve/studio_frames.h"
#include "serve/studio_messages.h"
#include "serve/transport/websocket_server.h"
#include "trace/ray_tracer.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

// BRDF samples of the room's reflection per glossy vertex in a client's view (RLGV): a fifth
// of render's, for a reply within tens of milliseconds on a room.
constexpr int kViewGlossySamples = 16;

// A validated state waiting for the worker; a newer one replaces it (coalescing).
// As StateRequest (serve/studio_messages.h), a false positive of clang-tidy 14:
// NOLINTNEXTLINE(bugprone-exception-escape)
struct PendingState {
  LightingState state;
  nlohmann::json document;
  std::optional<std::uint32_t> seq;
  ConnectionId client = 0;
};

// What the latest frame showed, read by the network thread (new clients, picks, profiles).
struct Shown {
  std::shared_ptr<const std::string> frame;
  std::shared_ptr<const FrameValues> values;
  nlohmann::json document = nlohmann::json::object();
  LightingState state;
  std::uint32_t frame_number = 0;
  // The movable objects as `state` places them, with their own ray tracer, for picks; null
  // when the scene has none. The worker's relighter re-places its own copy on every change,
  // so picks on the network thread read this snapshot instead.
  std::shared_ptr<const PlacedObjects> objects;
};

// The objects as `state` places them, for picks (Shown::objects); null without objects.
std::shared_ptr<const PlacedObjects> placed_for_picks(const TransferFile& t,
                                                      const LightingState& state) {
  if (t.view.objects.empty()) return nullptr;
  return std::make_shared<const PlacedObjects>(place_objects(t.view.objects, state.objects));
}

nlohmann::json vec3_json(Vec3 v) {
  return {v.x, v.y, v.z};
}

// The distribution a state document gives luminaire `name`, or null when it keeps the scene's.
nlohmann::json named_distribution(const nlohmann::json& document, const std::string& name) {
  const auto lums = document.find("luminaires");
  if (lums == document.end() || !lums->is_object()) return nullptr;
  const auto l = lums->find(name);
  if (l == lums->end() || !l->is_object()) return nullptr;
  const auto d = l->find("distribution");
  return d == l->end() ? nlohmann::json(nullptr) : *d;
}

}  // namespace

struct StudioServer::Impl {
  fs::path rlt;
  StudioOptions options;
  fs::path client_folder;
  std::unique_ptr<RelitScene> relit;
  std::vector<int> vertex_portal;
  std::string geometry;
  std::string objects_message;        // RLOB; empty when the scene has no movable objects
  const RayTracer* picker = nullptr;  // relit's tracer of every triangle
  std::unique_ptr<WebSocketServer> transport;
  // Null without --photometry. Its own mutex: an upload parses and writes a file, which the
  // relighting's mutex need not wait for.
  std::unique_ptr<PhotometryCatalogue> catalogue;
  std::mutex catalogue_mutex;

  std::mutex mutex;  // guards everything below
  std::condition_variable wake;
  std::optional<PendingState> pending;
  bool quit = false;
  Shown shown;
  // The last state document accepted from any client (shown, pending or being relit): where
  // the optimise panel's run starts.
  nlohmann::json received_document = nlohmann::json::object();
  std::set<ConnectionId> clients;
  // Each client's eye as its last `view` said, and the clients whose RLGV is due (after a
  // new eye, and for every eye after each frame).
  std::map<ConnectionId, Vec3> eyes;
  std::set<ConnectionId> views_due;

  std::atomic<std::size_t> incremental_updates{0};  // written by the worker

  std::thread worker;
  // A year of daylight for one client at a time (handle(AnnualRequest)), on its own thread
  // and its own scene, so that relighting goes on meanwhile.
  std::thread annual;
  std::atomic<bool> annual_busy{false};
  std::atomic<bool> annual_stop{false};
  std::unique_ptr<RelitScene> year_scene;  // only the annual thread uses it
  // Inverse design for one client at a time (handle(OptimizeRequest)), on its own thread and
  // its own copy of the scene, opened on the first run and kept for the next.
  std::thread optimizer;
  std::atomic<bool> optimize_busy{false};
  std::unique_ptr<RelitScene> design_scene;  // only the optimizer thread uses it
  std::optional<fs::path> next_scene;        // guarded by `mutex`
  // The latest RLWV (what the windows show looking out), for clients that open; null when the
  // scene has no windows. Guarded by `mutex`.
  std::shared_ptr<const std::string> window_views;
  // The portals and site of the state the latest RLWV shows (the worker's): the views change
  // only with them.
  std::optional<std::pair<std::vector<PortalState>, std::optional<Site>>> window_views_of;
  // "Open model…"; last, so that it ends (and its thread stops) before the transport it sends on.
  std::unique_ptr<ModelOpening> opening;

  const TransferFile& transfer() const { return relit->transfer(); }
  const Scene& scene() const { return relit->scene(); }

  // Replies may quote what a client sent (a parse error's "last read"), cut inside a UTF-8
  // sequence: such bytes are replaced (U+FFFD), never thrown on.
  static std::string text_of(const nlohmann::json& message) {
    return message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }

  void send_json(ConnectionId to, const nlohmann::json& message) {
    transport->send(to, text_of(message), false);
  }

  // The frame's per-vertex values of the light `relit` holds.
  std::shared_ptr<const FrameValues> frame_values() const {
    auto values = std::make_shared<FrameValues>();
    compute_frame_values(transfer(), vertex_portal, relit->irradiance(), relit->window_radiance(),
                         relit->vertex_albedo(), *values);
    if (!relit->object_albedo().empty()) {
      compute_object_values(relit->object_albedo(), relit->object_irradiance(), *values);
    }
    return values;
  }

  void work() {
    LightingState last_good = shown.state;
    nlohmann::json shown_document = nlohmann::json::object();  // the worker's own copy
    std::uint32_t frame_number = shown.frame_number;           // only the worker advances it
    while (true) {
      PendingState p;
      std::vector<std::pair<ConnectionId, Vec3>> views;
      {
        std::unique_lock lock(mutex);
        wake.wait(lock, [&] { return quit || pending.has_value() || !views_due.empty(); });
        if (quit) return;
        if (!pending) {  // states first: a view of a state about to change is wasted
          for (const ConnectionId id : views_due) views.emplace_back(id, eyes.at(id));
          views_due.clear();
        } else {
          p = std::move(*pending);
          pending.reset();
        }
      }
      if (!views.empty()) {
        for (const auto& [id, eye] : views) {
          try {
            show_view(id, eye, frame_number);
          } catch (const std::exception& e) {
            send_json(id, error_message(std::nullopt, e.what()));
          }
        }
        continue;
      }
      try {
        // The first frame, then the converged one when they differ (runtime/
        // progressive_frames.h); the state messages say which is which.
        auto start = std::chrono::steady_clock::now();
        show_progressively(*relit, p.state, [&](bool converged) {
          show(p, shown_document, frame_number, converged, start);
          start = std::chrono::steady_clock::now();
        });
        last_good = std::move(p.state);
        std::lock_guard lock(mutex);
        for (const auto& [id, eye] : eyes) views_due.insert(id);
      } catch (const std::exception& e) {  // e.g. a map file that cannot be read
        send_json(p.client, error_message(p.seq, e.what()));
        try {
          relit->apply(last_good);
        } catch (const std::exception&) {  // it lit before: cannot fail again
        }
      }
    }
  }

  // Sends every client the pending state just relit (with "final": false for a first,
  // approximate frame), its frame, timed from `start`, and the profiles of distributions that
  // changed. Everything slow happens outside the mutex.
  void show(const PendingState& p, nlohmann::json& shown_document, std::uint32_t& frame_number,
            bool final, std::chrono::steady_clock::time_point start) {
    const std::shared_ptr<const FrameValues> values = frame_values();
    const std::chrono::duration<float, std::milli> ms = std::chrono::steady_clock::now() - start;
    const std::uint32_t number = frame_number + 1;
    const auto frame =
        std::make_shared<const std::string>(encode_frame(number, p.seq, ms.count(), *values));
    incremental_updates = relit->incremental_curve_updates();
    std::vector<std::string> profiles;
    // The scene's luminaires and those the state adds.
    for (std::size_t j = 0; j < p.state.luminaires.size(); ++j) {
      const std::string& name = p.state.luminaires[j].name;
      if (named_distribution(p.document, name) != named_distribution(shown_document, name)) {
        profiles.push_back(text_of(profile_message(std::nullopt, j, p.state)));
      }
    }
    std::shared_ptr<const PlacedObjects> placed;
    {
      std::lock_guard lock(mutex);
      if (shown.state.objects == p.state.objects) placed = shown.objects;
    }
    if (!placed) placed = placed_for_picks(transfer(), p.state);
    const std::string state_text = text_of({{"type", "state"},
                                            {"seq", seq_json(p.seq)},
                                            {"client", p.client},
                                            {"frame", number},
                                            {"final", final},
                                            {"state", p.document}});
    const std::shared_ptr<const std::string> views = changed_window_views(p.state, number);
    std::set<ConnectionId> to;
    {
      std::lock_guard lock(mutex);
      shown = {frame, values, p.document, p.state, number, std::move(placed)};
      if (views) window_views = views;
      to = clients;
    }
    frame_number = number;
    shown_document = p.document;
    // The state, its frame and the profiles are superseded by the next ones: a client that
    // does not read misses them (WebSocketServer::send), and its queue stays bounded.
    for (const ConnectionId c : to) {
      transport->send(c, state_text, false, true);
      transport->send(c, *frame, true, true);
      // Not droppable: a client that missed it would show stale windows until the sky changes.
      if (views) transport->send(c, *views, true);
      for (const std::string& m : profiles) transport->send(c, m, false, true);
    }
  }

  // The RLWV of what `relit` shows when the state's portals or site differ from those of the
  // last one (sky, sun, tint, frost, exterior objects), else null.
  std::shared_ptr<const std::string> changed_window_views(const LightingState& state,
                                                          std::uint32_t frame_number) {
    const std::size_t portals = transfer().view.portals.size();
    if (portals == 0) return nullptr;
    // Compared in place: a copy only when they changed (a dimmer drag copies nothing).
    if (window_views_of && window_views_of->first == state.portals &&
        window_views_of->second == state.site)
      return nullptr;
    window_views_of.emplace(state.portals, state.site);
    std::vector<WindowView> views;
    views.reserve(portals);
    const Relighter& r = relit->relighter();
    for (std::size_t p = 0; p < portals; ++p) {
      views.push_back(window_view(r.shell(p), transfer().view.portals[p].centre,
                                  static_cast<std::uint32_t>(p), r.suns()));
    }
    return std::make_shared<const std::string>(encode_window_views(frame_number, views));
  }

  // Sends client `id` its glossy vertices' luminance toward `eye` under the state shown
  // (frame `frame_number`).
  void show_view(ConnectionId id, Vec3 eye, std::uint32_t frame_number) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<float> luminance = glossy_vertex_luminance(*relit, eye, kViewGlossySamples);
    const std::chrono::duration<float, std::milli> ms = std::chrono::steady_clock::now() - start;
    transport->send(id, encode_glossy_view(frame_number, eye, ms.count(), luminance), true, true);
  }

  nlohmann::json profile_message(std::optional<std::uint32_t> seq, std::size_t j,
                                 const LightingState& state,
                                 int samples = kDefaultProfileSamples) const {
    const DistributionSpec& spec = state.luminaires.at(j).distribution;
    const int order = transfer().view.sh_order;
    const DistributionProfile profile = luminaire_profile(spec, order, samples);
    return distribution_message(seq, state.luminaires.at(j).name, spec, profile, order,
                                incremental_updates.load());
  }

  // hello, geometry and the latest frame are queued under the lock, so that the worker's next
  // broadcast (which copies `clients` under it) reaches this client only after them.
  void on_open(ConnectionId id) {
    std::lock_guard lock(mutex);
    nlohmann::json hello = hello_message(transfer(), rlt.filename().string(), shown.document);
    hello["client"] = id;
    clients.insert(id);
    send_json(id, hello);
    transport->send(id, geometry, true);
    if (!objects_message.empty()) transport->send(id, objects_message, true);
    transport->send(id, *shown.frame, true);
    if (window_views) transport->send(id, *window_views, true);
    if (catalogue) {
      std::lock_guard catalogue_lock(catalogue_mutex);
      send_json(id, catalogue_message(*catalogue));
    }
  }

  void on_close(ConnectionId id) {
    opening->disconnected(id);
    std::lock_guard lock(mutex);
    clients.erase(id);
    eyes.erase(id);
    views_due.erase(id);
  }

  void broadcast_json(const nlohmann::json& message) {
    const std::string text = text_of(message);
    std::lock_guard lock(mutex);
    for (const ConnectionId c : clients) transport->send(c, text, false);
  }

  void on_message(ConnectionId id, const std::string& payload, bool binary) {
    std::optional<std::uint32_t> seq;
    try {
      if (binary) {  // only the pieces of a model being opened
        const nlohmann::json reply = opening->receive(id, payload);
        if (!reply.is_null()) send_json(id, reply);
        return;
      }
      ClientMessage m = parse_client_message(payload, scene(), seq);
      std::visit([&](auto& request) { handle(id, m.seq, request); }, m.request);
    } catch (const InputError& e) {
      send_json(id, error_message(seq, e.what()));
    } catch (const std::exception& e) {
      send_json(id, error_message(seq, std::string("internal: ") + e.what()));
    }
  }

  void handle(ConnectionId id, std::optional<std::uint32_t> seq, StateRequest& r) {
    LightingState state = default_lighting_state(scene());
    apply_lighting_state(state, scene(), r.document, "message", rlt.parent_path());
    // Photometry files a state names are read now, so their errors reach this sender.
    for (std::size_t j = 0; j < state.luminaires.size(); ++j) {
      if (!named_distribution(r.document, state.luminaires[j].name).is_null()) {
        (void)load_distribution(state.luminaires[j].distribution);
      }
    }
    {
      std::lock_guard lock(mutex);
      received_document = r.document;
      pending = PendingState{std::move(state), std::move(r.document), seq, id};
    }
    wake.notify_one();
  }

  void handle(ConnectionId id, std::optional<std::uint32_t> seq, const PickRequest& r) {
    std::shared_ptr<const FrameValues> values;
    std::shared_ptr<const PlacedObjects> objects;
    {
      std::lock_guard lock(mutex);
      values = shown.values;
      objects = shown.objects;
    }
    const Ray ray{r.origin, r.direction};
    const RayHit room_hit = picker->intersect(ray);
    const RayHit object_hit = objects ? objects->tracer.intersect(ray) : RayHit{};
    if (!room_hit.hit() && !object_hit.hit()) {
      send_json(id, {{"type", "pick"}, {"seq", seq_json(seq)}, {"hit", false}});
      return;
    }
    const bool on_object = object_hit.hit() && (!room_hit.hit() || object_hit.t < room_hit.t);
    const RayHit& hit = on_object ? object_hit : room_hit;
    // The hit triangle's corners and, per corner, where its values are in the frame.
    const TransferFile& t = transfer();
    const Triangle& tri = on_object ? objects->triangles[hit.triangle] : t.triangles[hit.triangle];
    const std::vector<Vec3>& positions = on_object ? objects->positions : t.positions;
    const std::vector<float>& illuminance =
        on_object ? values->object_illuminance : values->illuminance;
    const std::vector<float>& radiance = on_object ? values->object_radiance : values->radiance;
    const Vec3 a = positions[tri[0]], b = positions[tri[1]], c = positions[tri[2]];
    Vec3 n = normalize(cross(b - a, c - a));
    if (dot(n, r.direction) > 0) n = -n;
    const double w[3] = {1 - hit.u - hit.v, hit.u, hit.v};
    double e = 0, l = 0;
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = tri[static_cast<std::size_t>(k)];
      e += w[k] * illuminance[v];
      l += w[k] * luminance(Rgb{radiance[3 * v], radiance[3 * v + 1], radiance[3 * v + 2]});
    }
    nlohmann::json reply = {{"type", "pick"},
                            {"seq", seq_json(seq)},
                            {"hit", true},
                            {"point", vec3_json(r.origin + hit.t * r.direction)},
                            {"normal", vec3_json(n)},
                            {"distance", hit.t},
                            {"illuminance", e},
                            {"luminance", l}};
    if (on_object) {
      // The object's own triangle number (as in RLOB): its triangles are back to back.
      const std::uint32_t object = objects->triangle_object[hit.triangle];
      const auto first = std::lower_bound(objects->triangle_object.begin(),
                                          objects->triangle_object.end(), object);
      reply["triangle"] =
          hit.triangle - static_cast<std::uint32_t>(first - objects->triangle_object.begin());
      reply["material"] = nullptr;
      reply["portal"] = nullptr;
      reply["object"] = t.view.objects[object].name;
      send_json(id, reply);
      return;
    }
    // Files written before the MMAT section name no material.
    const std::size_t material =
        t.triangle_material.empty() ? scene().materials.size() : t.triangle_material[hit.triangle];
    int portal = -1;
    for (std::size_t k = 0; k < t.portal_triangles.size(); ++k) {
      if (t.portal_triangles[k] == hit.triangle) portal = static_cast<int>(t.portal_of_triangle[k]);
    }
    reply["triangle"] = hit.triangle;
    reply["material"] = material < scene().materials.size()
                            ? nlohmann::json(scene().materials[material].name)
                            : nlohmann::json(nullptr);
    reply["portal"] = portal >= 0
                          ? nlohmann::json(scene().portals[static_cast<std::size_t>(portal)].name)
                          : nlohmann::json(nullptr);
    reply["object"] = nullptr;
    send_json(id, reply);
  }

  void handle(ConnectionId id, std::optional<std::uint32_t> seq, const DistributionRequest& r) {
    LightingState state;
    {
      std::lock_guard lock(mutex);
      state = shown.state;
    }
    for (std::size_t j = 0; j < state.luminaires.size(); ++j) {
      if (state.luminaires[j].name == r.luminaire) {
        send_json(id, profile_message(seq, j, state, r.samples));
        return;
      }
    }
    fail_input("message:/luminaire",
               "no luminaire named \"" + r.luminaire + "\" in the scene or the state shown");
  }

  // An upload joins the catalogue: the sender gets its entry, every client the new catalogue.
  void handle(ConnectionId id, std::optional<std::uint32_t> seq, const UploadRequest& r) {
    if (!catalogue) {
      fail_input("message",
                 "this server has no photometry catalogue (start relight serve with "
                 "--photometry DIR to accept uploads)");
    }
    nlohmann::json entry, listing;
    {
      std::lock_guard catalogue_lock(catalogue_mutex);
      entry = catalogue_entry_json(catalogue->add_upload(r.name, r.text));
      listing = catalogue_message(*catalogue);
    }
    send_json(id, {{"type", "uploaded"}, {"seq", seq_json(seq)}, {"entry", entry}});
    broadcast_json(listing);
  }

  // The scene with the layout of the latest state received (one sent just before this message
  // may not be shown yet) as ordinary luminaires.
  void handle(ConnectionId id, std::optional<std::uint32_t> seq, const ExportSceneRequest&) {
    nlohmann::json document;
    {
      std::lock_guard lock(mutex);
      document = received_document;
    }
    LightingState state = default_lighting_state(scene());
    apply_lighting_state(state, scene(), document, "message", rlt.parent_path());
    // The .rlt keeps the scene without its geometry: the exported scene is the file it was
    // precomputed from.
    const fs::path scene_file = transfer().metadata.at("scene_file").get<std::string>();
    std::error_code ec;
    if (!fs::is_regular_file(scene_file, ec)) {
      fail_input("message", "Export scene reads the scene file the .rlt was precomputed from, " +
                                scene_file.string() + ": not found");
    }
    const nlohmann::json scene_json = read_json_file(scene_file);
    send_json(id, {{"type", "scene"},
                   {"seq", seq_json(seq)},
                   {"scene", scene_json_with_layout(scene_json, scene_file, state)}});
  }

  void handle(ConnectionId id, std::optional<std::uint32_t> seq, AnnualRequest& r) {
    if (scene().portals.empty()) {
      fail_input("message", "the scene has no windows (portals) for daylight");
    }
    if (scene().sensor_count() == 0) fail_input("message", "the scene has no sensors");
    if (annual_busy.exchange(true)) {
      fail_input("message", "a year of daylight is already being computed; wait for its result");
    }
    if (annual.joinable()) annual.join();  // the last run's thread, finished
    LightingState base;
    {
      std::lock_guard lock(mutex);
      base = daylight_alone(shown.state);
    }
    annual = std::thread([this, id, seq, request = std::move(r), base = std::move(base)] {
      run_annual(id, seq, request, base);
      annual_busy = false;
    });
  }

  // One day of a weather file as each hour's sky, for the client to scrub: answered at once
  // (the skies are parsed, not solved; each hour the client shows is an ordinary state).
  void handle(ConnectionId id, std::optional<std::uint32_t> seq, const WeatherDayRequest& r) {
    send_json(id, weather_day_message(seq, r));
  }

  // The studio's annual panel: `relight annual` over every sensor set with the state shown now,
  // daylight alone (luminaires and emitters off); progress at most ten times a second.
  void run_annual(ConnectionId id, std::optional<std::uint32_t> seq, const AnnualRequest& r,
                  const LightingState& base) {
    try {
      const auto start = std::chrono::steady_clock::now();
      send_json(id, annual_progress_message(seq, 0, 0, "preparing"));
      const AnnualHours hours = annual_hours(r.weather, r.period, north_deg(base));
      if (hours.hours.empty()) fail_input("message:/weather", "no occupied hour has the sun up");
      // Opened (and the sensors' importance solved, seconds) on the first run, kept for the next.
      if (!year_scene) year_scene = open_for_annual(rlt);
      std::size_t done = 0;
      auto last = std::chrono::steady_clock::now();
      const AnnualDaylight year =
          annual_daylight(*year_scene, base, hours.hours, every_sensor_set(scene()), [&] {
            if (annual_stop) throw std::runtime_error("the server is stopping");
            ++done;
            const auto now = std::chrono::steady_clock::now();
            if (now - last > std::chrono::milliseconds(100)) {
              last = now;
              send_json(id, annual_progress_message(seq, done, hours.hours.size(), "hours"));
            }
          });
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      send_json(id, annual_message(seq, scene(), r.weather, r.occupied, hours, year, seconds));
    } catch (const std::exception& e) {
      if (!annual_stop) send_json(id, error_message(seq, e.what()));
    }
  }

  // The studio's optimise panel: `relight optimize` from the state shown now.
  void handle(ConnectionId id, std::optional<std::uint32_t> seq, OptimizeRequest& r) {
    if (scene().sensor_count() == 0) fail_input("message", "the scene has no sensors");
    if (optimize_busy.exchange(true)) {
      fail_input("message", "an optimisation is already running; wait for its result");
    }
    if (optimizer.joinable()) optimizer.join();  // the last run's thread, finished
    StartState start;
    {
      // The latest state received: one sent just before this message may not be shown yet.
      std::lock_guard lock(mutex);
      start.document = received_document;
    }
    start.dir = rlt.parent_path();
    start.where = "the state shown";
    optimizer = std::thread([this, id, seq, request = std::move(r), start = std::move(start)] {
      try {
        if (!design_scene) design_scene = std::make_unique<RelitScene>(rlt, std::nullopt);
        OptimizeOptions options;
        options.daylight = request.daylight;
        const OptimizeResult result =
            optimize_lighting(*design_scene, start, request.targets, options);
        optimize_busy = false;  // before the reply: the client may run again at once
        send_json(id, optimized_message(seq, scene(), result));
      } catch (const std::exception& e) {
        optimize_busy = false;
        send_json(id, error_message(seq, e.what()));
      }
    });
  }

  void handle(ConnectionId id, std::optional<std::uint32_t> seq, const OpenModelRequest& r) {
    send_json(id, opening->begin(id, seq, r.name, r.bytes));
  }

  // A model precomputed: run() ends and the caller serves it (StudioServer::next_scene).
  void open_next(const fs::path& next) {
    {
      std::lock_guard lock(mutex);
      next_scene = next;
    }
    transport->stop();
  }

  void handle(ConnectionId id, std::optional<std::uint32_t>, const ViewRequest& r) {
    {
      std::lock_guard lock(mutex);
      if (clients.count(id) == 0) return;  // closed meanwhile
      eyes[id] = r.eye;
      views_due.insert(id);
    }
    wake.notify_one();
  }

  void handle(ConnectionId id, std::optional<std::uint32_t> seq, const PingRequest&) {
    std::lock_guard lock(mutex);
    send_json(id, {{"type", "pong"},
                   {"seq", seq_json(seq)},
                   {"frames", shown.frame_number},
                   {"clients", clients.size()}});
  }
};

StudioServer::StudioServer(const fs::path& rlt, const StudioOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.rlt = rlt;
  s.options = options;
  s.client_folder = studio_client_folder(options.client);
  if (!options.photometry.empty()) {
    s.catalogue = std::make_unique<PhotometryCatalogue>(options.photometry);
  }
  // The glossy BRDF's albedo table, which a designer's first roughness or metallic edit needs:
  // built before serving (0.9 s of CPU once), not in that edit's frame.
  prepare_metallic_roughness_tables();
  s.relit = std::make_unique<RelitScene>(rlt, std::nullopt);
  const TransferFile& t = s.transfer();
  s.vertex_portal = vertex_portals(t);
  s.geometry = encode_geometry(t);
  if (!t.view.objects.empty()) s.objects_message = encode_objects(t.view.objects);
  s.picker = &s.relit->mesh_tracer();  // built here: picks run on the network thread
  const LightingState initial = default_lighting_state(t.scene);
  const auto start = std::chrono::steady_clock::now();
  s.relit->apply(initial);
  std::shared_ptr<const FrameValues> values = s.frame_values();
  const std::chrono::duration<float, std::milli> ms = std::chrono::steady_clock::now() - start;
  s.shown = {
      std::make_shared<const std::string>(encode_frame(1, std::nullopt, ms.count(), *values)),
      values,
      nlohmann::json::object(),
      initial,
      1,
      placed_for_picks(t, initial)};
  s.window_views = s.changed_window_views(initial, 1);

  WebSocketServerOptions transport_options;
  transport_options.host = options.host;
  transport_options.port = options.port;
  transport_options.stop_on_signals = options.stop_on_signals;
  transport_options.max_message_bytes = kMaxClientMessageBytes;
  WebSocketHandlers handlers;
  handlers.open = [&s](ConnectionId id) { s.on_open(id); };
  handlers.close = [&s](ConnectionId id) { s.on_close(id); };
  handlers.message = [&s](ConnectionId id, const std::string& payload, bool binary) {
    s.on_message(id, payload, binary);
  };
  handlers.http = [&s](const std::string& method, const std::string& path) {
    return serve_static_file(s.client_folder, method, path);
  };
  try {
    s.transport = std::make_unique<WebSocketServer>(transport_options, std::move(handlers));
  } catch (const std::runtime_error& e) {
    fail_input("--host/--port", e.what());
  }
  ModelOpeningEvents events;
  events.broadcast = [&s](const nlohmann::json& message) { s.broadcast_json(message); };
  events.opened = [&s](const fs::path& next) { s.open_next(next); };
  const fs::path models =
      options.models.empty() ? fs::absolute(rlt).parent_path() / "models" : options.models;
  s.opening = std::make_unique<ModelOpening>(models, running_program(), std::move(events));
  s.worker = std::thread([&s] { s.work(); });
}

StudioServer::~StudioServer() {
  {
    std::lock_guard lock(impl_->mutex);
    impl_->quit = true;
  }
  impl_->wake.notify_one();
  if (impl_->worker.joinable()) impl_->worker.join();
  impl_->annual_stop = true;
  if (impl_->annual.joinable()) impl_->annual.join();
  if (impl_->optimizer.joinable()) impl_->optimizer.join();
}

std::uint16_t StudioServer::port() const {
  return impl_->transport->port();
}

const std::filesystem::path& StudioServer::client_folder() const {
  return impl_->client_folder;
}

std::string StudioServer::url() const {
  const std::string& host = impl_->options.host;
  const bool ipv6 = host.find(':') != std::string::npos;
  return "http://" + (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port()) + "/";
}

void StudioServer::run() {
  impl_->transport->run();
}

void StudioServer::stop() {
  impl_->transport->stop();
}

std::optional<fs::path> StudioServer::next_scene() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->next_scene;
}

}  // namespace relight
