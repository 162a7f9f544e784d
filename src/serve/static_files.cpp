#include "serve/static_files.h"

#include <fstream>
#include <sstream>

#include "common/input_error.h"
#include "common/installed_files.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

std::string content_type(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json") return "application/json";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".ico") return "image/x-icon";
  return "application/octet-stream";
}

// A URL path is safe when every segment is a plain name: no "..", no ".", no empty segment
// except a trailing one, no backslash or NUL, no percent-escapes (the client has none).
bool safe_path(const std::string& path) {
  if (path.empty() || path.front() != '/') return false;
  if (path.find_first_of(std::string("\\%\0", 3)) != std::string::npos) return false;
  std::size_t start = 1;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    const std::string segment = path.substr(start, end - start);
    if (segment == "." || segment == "..") return false;
    if (segment.empty() && end != path.size()) return false;
    start = end + 1;
  }
  return true;
}

HttpResponse text(int status, std::string body) {
  return {status, "text/plain; charset=utf-8", std::move(body)};
}

}  // namespace

fs::path studio_client_folder(const fs::path& requested) {
  fs::path folder = requested;
  if (folder.empty()) {
    // An installed relight serves its installed client; a build tree serves the checkout's.
    const fs::path installed = installed_share_folder("studio");
    std::error_code ec;
    folder = !installed.empty() && fs::is_regular_file(installed / "index.html", ec)
                 ? installed
                 : fs::path(RELIGHT_STUDIO_DIR);
  }
  const std::string where = requested.empty() ? folder.string() : "--client " + folder.string();
  if (!fs::is_regular_file(folder / "index.html")) {
    fail_input(where, "not a studio client folder (no index.html)");
  }
  if (!fs::is_regular_file(folder / "node_modules/three/build/three.module.js")) {
    fail_input(where,
               "three.js is not installed in node_modules/: run scripts/bootstrap.sh (npm ci "
               "--prefix studio), or install relight (make install PREFIX=...)");
  }
  return folder;
}

HttpResponse serve_static_file(const fs::path& client_folder, const std::string& method,
                               const std::string& path) {
  if (method != "GET" && method != "HEAD") return text(405, "method not allowed\n");
  if (!safe_path(path)) return text(400, "bad path\n");
  fs::path file;
  const std::string vendor = "/vendor/three/";
  if (path == "/") {
    file = client_folder / "index.html";
  } else if (path.rfind(vendor, 0) == 0) {
    file = client_folder / "node_modules/three" / path.substr(vendor.size());
  } else if (path.rfind("/node_modules/", 0) == 0) {
    return text(404, "not found\n");  // only three.js is served, under /vendor/three/
  } else {
    file = client_folder / path.substr(1);
  }
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return text(404, "not found\n");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream body;
  body << in.rdbuf();
  if (!in) return text(500, "cannot read file\n");
  return {200, content_type(file), method == "HEAD" ? std::string() : body.str()};
}

}  // namespace relight
