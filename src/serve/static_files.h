// The studio client's files over HTTP (docs/studio-protocol.md, "Files"): `/` is
// index.html, `/vendor/three/…` the three.js package npm installed under the client folder's
// node_modules, anything else a file under the client folder. Paths that leave the folder
// (`..`, absolute, backslashes, NUL) are refused; only GET and HEAD are answered.
#pragma once

#include <filesystem>
#include <string>

#include "serve/transport/websocket_server.h"

namespace relight {

// The client folder: `requested` when given; else the installed one (PREFIX/share/relight/studio
// beside PREFIX/bin/relight, put there by `cmake --install`) when it exists; else the one
// compiled in (the source tree's studio/). Throws InputError when it lacks index.html or
// three.js (with the fix).
std::filesystem::path studio_client_folder(const std::filesystem::path& requested);

HttpResponse serve_static_file(const std::filesystem::path& client_folder,
                               const std::string& method, const std::string& path);

}  // namespace relight
