// `relight serve`: the studio server (docs/studio-protocol.md). One precomputed scene, one
// lighting state shared by every connected client, relit on one worker thread. State messages
// are validated as they arrive and coalesced while the worker is busy (latest state wins);
// every client then gets the new state and the new radiance frame. Picks, distribution
// profiles and pings are answered on the network thread from the latest frame, so they never
// wait for a relight. Malformed messages get an `error` reply and change nothing. A model a
// client opens (serve/model_opening.h) ends run() once it is precomputed, with next_scene()
// naming it, so that the caller serves it next.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace relight {

struct StudioOptions {
  std::string host = "127.0.0.1";
  std::uint16_t port = 8080;     // 0: any free port
  std::filesystem::path client;  // empty: the studio/ folder compiled in
  // The photometry catalogue's folder (serve/photometry_catalogue.h); empty: no catalogue, and
  // uploads are refused.
  std::filesystem::path photometry;
  // Where "Open model…" keeps the models it imports and precomputes (serve/model_opening.h);
  // empty: a `models` folder beside the .rlt.
  std::filesystem::path models;
  bool stop_on_signals = true;  // Ctrl-C / SIGTERM end run()
};

class StudioServer {
 public:
  // Opens the .rlt, lights it with the scene's own state and listens. Throws InputError for a
  // bad file, a missing client or an address it cannot listen on.
  StudioServer(const std::filesystem::path& rlt, const StudioOptions& options);
  ~StudioServer();
  StudioServer(const StudioServer&) = delete;
  StudioServer& operator=(const StudioServer&) = delete;

  std::uint16_t port() const;
  std::string url() const;  // http://HOST:PORT/
  // The folder the client's files are served from (serve/static_files.h).
  const std::filesystem::path& client_folder() const;
  void run();   // serves until stop(), a signal, or a model opened
  void stop();  // from any thread
  // After run(): the .rlt of a model "Open model…" precomputed, to be served next (at the same
  // address); nullopt when run() ended for another reason.
  std::optional<std::filesystem::path> next_scene() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace relight
