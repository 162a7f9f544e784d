#include "cli/serve_run.h"

#include <iostream>
#include <optional>

#include <CLI/CLI.hpp>

#include "common/input_error.h"

namespace relight {

void add_studio_address_options(CLI::App& command, StudioOptions& options) {
  command.add_option("--host", options.host, "address to listen on")->capture_default_str();
  command.add_option("--port", options.port, "TCP port (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
}

int serve_studio(const std::filesystem::path& rlt, const StudioOptions& options) {
  StudioOptions o = options;
  // Models opened in the studio stay where the first scene's were put, whichever is shown.
  if (o.models.empty()) o.models = std::filesystem::absolute(rlt).parent_path() / "models";
  std::filesystem::path scene = rlt;
  std::optional<std::filesystem::path> next;
  for (bool first = true; first || next; first = false) {
    std::optional<StudioServer> server;
    if (first) {
      server.emplace(scene, o);
      std::cout << "relight studio: " << server->url() << "  (open it in a browser; Ctrl-C stops)"
                << std::endl;
      std::cout << "relight studio: client files from " << server->client_folder().string()
                << std::endl;
      o.port = server->port();  // a model opened later is served at the same address
    } else {
      // The model's .rlt was just written by precompute; should it still not open, the scene
      // shown before comes back.
      try {
        server.emplace(*next, o);
        scene = *next;
        std::cout << "relight studio: opened " << scene.string() << std::endl;
      } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << std::endl;
        server.emplace(scene, o);
      }
    }
    server->run();
    next = server->next_scene();
  }
  std::cout << "relight studio: stopped" << std::endl;
  return 0;
}

}  // namespace relight
