#include "serve/photometry_catalogue.h"

#include <algorithm>
#include <system_error>

#include "common/atomic_file.h"
#include "common/input_error.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxNameBytes = 255;

// The distribution type a state names the file by.
const char* file_type(const PhotometrySummary& s) {
  return s.format == "EULUMDAT" ? "ldt" : "ies";
}

// A photometric file is text: the first byte that is a control character other than white
// space (a NUL in any binary file) marks it as binary.
std::optional<std::size_t> binary_byte(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const bool space = c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
    if ((c < 0x20 && !space) || c == 0x7F) return i;
  }
  return std::nullopt;
}

void check_upload_name(std::string_view name) {
  const std::string where = "message:/name";
  if (name.empty()) fail_input(where, "empty file name");
  if (name.size() > kMaxNameBytes) fail_input(where, "a file name is at most 255 bytes");
  const bool path = name.find('/') != std::string_view::npos ||
                    name.find('\\') != std::string_view::npos ||
                    name.find("..") != std::string_view::npos || name.front() == '.';
  if (path) {
    fail_input(where, "expected a plain file name, not a path (\"" + std::string(name) +
                          "\"); the server chooses where an upload is stored");
  }
  if (binary_byte(name)) fail_input(where, "control characters in the file name");
  if (!is_photometry_file(fs::path(std::string(name)))) {
    fail_input(where, "not a photometric file (the name must end in .ies or .ldt): \"" +
                          std::string(name) + "\"");
  }
}

// The first upload-N name not taken in `folder`.
fs::path free_upload_name(const fs::path& folder, const char* type) {
  for (int n = 1;; ++n) {
    fs::path p = folder / ("upload-" + std::to_string(n) + "." + type);
    std::error_code ec;
    if (!fs::exists(p, ec)) return p;
  }
}

}  // namespace

PhotometryCatalogue::PhotometryCatalogue(const fs::path& folder)
    : folder_(fs::absolute(folder).lexically_normal()), uploads_(folder_ / "uploads") {
  std::error_code ec;
  if (!fs::is_directory(folder_, ec))
    fail_input("--photometry", "not a folder: " + folder.string());
  std::vector<fs::path> files;
  for (fs::recursive_directory_iterator
           it(folder_, fs::directory_options::skip_permission_denied, ec),
       end;
       !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file(ec) && is_photometry_file(it->path())) files.push_back(it->path());
  }
  if (ec) fail_input("--photometry", folder.string() + ": " + ec.message());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const std::string id = file.lexically_relative(folder_).generic_string();
    try {
      CatalogueEntry e{id, file, file.parent_path() == uploads_, "",
                       summarize_photometry_file(file)};
      entries_.push_back(std::move(e));
    } catch (const InputError& error) {
      rejected_.push_back({id, error.what()});
    }
  }
}

const CatalogueEntry& PhotometryCatalogue::add_upload(std::string_view name,
                                                      std::string_view text) {
  check_upload_name(name);
  if (text.size() > kMaxUploadBytes) {
    fail_input("message:/text", std::string(name) + ": " + std::to_string(text.size()) +
                                    " bytes, over the upload limit of 5 MB");
  }
  if (const auto at = binary_byte(text)) {
    fail_input("message:/text", std::string(name) + ": binary data at byte " + std::to_string(*at) +
                                    " (an IES or EULUMDAT file is text)");
  }
  // The parsers' messages name the file as the client did.
  PhotometrySummary summary = summarize_photometry(text, fs::path(std::string(name)));
  std::error_code ec;
  fs::create_directories(uploads_, ec);
  if (ec)
    fail_input("message", "cannot store uploads in " + uploads_.string() + ": " + ec.message());
  const fs::path stored = free_upload_name(uploads_, file_type(summary));
  try {
    write_text_atomically(stored, text);
  } catch (const std::exception& e) {
    fail_input("message", std::string("cannot store the upload: ") + e.what());
  }
  entries_.push_back({stored.lexically_relative(folder_).generic_string(), stored, true,
                      std::string(name), std::move(summary)});
  return entries_.back();
}

nlohmann::json catalogue_entry_json(const CatalogueEntry& e) {
  return {{"id", e.id},
          {"file", e.file.string()},
          {"type", file_type(e.summary)},
          {"uploaded", e.uploaded},
          {"name",
           e.uploaded && !e.original_name.empty() ? e.original_name : e.file.filename().string()},
          {"summary", to_json(e.summary)},
          {"polar", polar_json(e.summary)}};
}

nlohmann::json catalogue_message(const PhotometryCatalogue& catalogue) {
  nlohmann::json entries = nlohmann::json::array(), rejected = nlohmann::json::array();
  for (const CatalogueEntry& e : catalogue.entries()) entries.push_back(catalogue_entry_json(e));
  for (const RejectedFile& r : catalogue.rejected()) {
    rejected.push_back({{"id", r.id}, {"message", r.message}});
  }
  return {{"type", "catalogue"}, {"entries", entries}, {"rejected", rejected}};
}

}  // namespace relight
