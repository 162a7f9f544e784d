// What `relight serve` and the end of `relight demo` share: the address options and the
// serving itself (print the URL, serve until Ctrl-C).
#pragma once

#include <filesystem>

#include "serve/studio_server.h"

namespace CLI {
class App;
}

namespace relight {

// --host and --port into `options`.
void add_studio_address_options(CLI::App& command, StudioOptions& options);

// Opens the scene, listens, prints "relight studio: URL" and serves until stopped. Returns 0.
int serve_studio(const std::filesystem::path& rlt, const StudioOptions& options);

}  // namespace relight
