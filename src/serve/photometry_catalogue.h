// The studio's photometry catalogue (`relight serve --photometry DIR`, docs/studio-protocol.md
// "catalogue"): every IES LM-63 and EULUMDAT file under DIR with what a designer reads off it
// (light/photometry_summary.h) and its polar plot, and the files a client uploads. An upload is
// parsed by the same parsers as any photometric file and refused with the parser's message; it
// is stored under a name the server chooses (`upload-N.ies`) in the catalogue's own folder
// DIR/uploads, never under a path a client sent. Pinned by
// tests/serve/photometry_catalogue_test.cpp and the studio's hostile-client tests.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "light/photometry_summary.h"

namespace relight {

// The largest photometric file a client may upload (real files are under 100 KB).
inline constexpr std::size_t kMaxUploadBytes = std::size_t{5} << 20;

struct CatalogueEntry {
  std::string id;              // the file's path under the catalogue's folder, '/'-separated
  std::filesystem::path file;  // absolute: what a state's distribution names
  bool uploaded = false;
  std::string original_name;  // an upload's name as the client gave it (shown, never a path)
  PhotometrySummary summary;
};

struct RejectedFile {
  std::string id;
  std::string message;  // the parser's
};

class PhotometryCatalogue {
 public:
  // Lists the photometric files under `folder` (recursively, uploads included); files that do
  // not parse are listed as rejected with the parser's message. InputError when `folder` is not
  // a folder.
  explicit PhotometryCatalogue(const std::filesystem::path& folder);

  // Checks, parses and stores an uploaded file and lists it. InputError (where "message:/name"
  // or "message:/text") for a name that is not a plain .ies/.ldt file name, text over
  // kMaxUploadBytes, binary data, a file the parser refuses, or a folder it cannot write.
  const CatalogueEntry& add_upload(std::string_view name, std::string_view text);

  const std::vector<CatalogueEntry>& entries() const { return entries_; }
  const std::vector<RejectedFile>& rejected() const { return rejected_; }
  const std::filesystem::path& uploads_folder() const { return uploads_; }

 private:
  std::filesystem::path folder_, uploads_;
  std::vector<CatalogueEntry> entries_;
  std::vector<RejectedFile> rejected_;
};

// One entry as the catalogue message lists it: id, file, type ("ies"/"ldt"), uploaded,
// name, summary (the keys of `relight info`) and polar.
nlohmann::json catalogue_entry_json(const CatalogueEntry& entry);

// {"type": "catalogue", "entries": [...], "rejected": [...]}.
nlohmann::json catalogue_message(const PhotometryCatalogue& catalogue);

}  // namespace relight
