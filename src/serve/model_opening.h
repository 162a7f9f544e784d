// The studio's "Open model…" (docs/studio-protocol.md, "open_model"): a building model sent in
// chunks to a folder the server names, imported with `relight import` and precomputed with
// `relight precompute` — the commands a designer would run, in child processes of this
// program, so that a model that fails or exhausts memory cannot take the studio down — with
// progress reported to every client; then the server reopens on the new .rlt.
//
// One model at a time. Stored as MODELS/model-N/model.EXT (the client's name gives only the
// extension), imported to model-N/model-N.json and precompute to model-N/model-N.rlt; a
// model that fails leaves nothing behind. Pinned by tests/studio/open_model.test.mjs.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace relight {

// The largest model a client may send: 200 MB.
inline constexpr std::uint64_t kMaxModelBytes = std::uint64_t{200} << 20;
// The binary message that carries a piece of the model: "RLMU" and the bytes.
inline constexpr std::string_view kModelChunkTag = "RLMU";

struct ModelOpeningEvents {
  // A `model` message for every client (from the network thread or the opening's own).
  std::function<void(const nlohmann::json& message)> broadcast;
  // The model is precomputed: serve `rlt` (from the opening's own thread, as its last act).
  std::function<void(const std::filesystem::path& rlt)> opened;
};

class ModelOpening {
 public:
  // `folder`: where models are kept (created when first needed); `program`: the relight to run.
  ModelOpening(const std::filesystem::path& folder, std::filesystem::path program,
               ModelOpeningEvents events);
  ~ModelOpening();  // ends a running import or precompute and waits for it
  ModelOpening(const ModelOpening&) = delete;
  ModelOpening& operator=(const ModelOpening&) = delete;

  // `open_model` from connection `from`: prepares to receive `bytes` bytes of `name`. Returns
  // the reply ("receiving", 0 of `bytes`). Throws InputError for a name without a model's
  // extension, a size over kMaxModelBytes, or while another model is being opened.
  nlohmann::json begin(std::uint64_t from, std::optional<std::uint32_t> seq,
                       const std::string& name, std::uint64_t bytes);
  // An RLMU message from `from`: appends its bytes and returns the reply ("receiving", bytes
  // so far). The last piece starts the import and the precompute. Throws InputError when no
  // model is being received from `from`, or for more bytes than announced.
  nlohmann::json receive(std::uint64_t from, std::string_view message);
  // Connection `from` closed: a model it was still sending is dropped.
  void disconnected(std::uint64_t from);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace relight
