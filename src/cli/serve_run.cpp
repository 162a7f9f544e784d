#include "cli/serve_run.h"

#include <iostream>

#include <CLI/CLI.hpp>

namespace relight {

void add_studio_address_options(CLI::App& command, StudioOptions& options) {
  command.add_option("--host", options.host, "address to listen on")->capture_default_str();
  command.add_option("--port", options.port, "TCP port (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
}

int serve_studio(const std::filesystem::path& rlt, const StudioOptions& options) {
  StudioServer server(rlt, options);
  std::cout << "relight studio: " << server.url() << "  (open it in a browser; Ctrl-C stops)"
            << std::endl;
  std::cout << "relight studio: client files from " << server.client_folder().string() << std::endl;
  server.run();
  std::cout << "relight studio: stopped" << std::endl;
  return 0;
}

}  // namespace relight
