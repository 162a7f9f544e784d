#include "serve/model_opening.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <fstream>
#include <mutex>
#include <thread>
#include <utility>

#include "common/child_process.h"
#include "common/input_error.h"
#include "common/progress.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kModelExtensions[] = {".ifc", ".gltf", ".glb", ".obj"};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

// A new folder MODELS/model-N with the smallest N free.
fs::path new_model_folder(const fs::path& models) {
  std::error_code ec;
  fs::create_directories(models, ec);
  if (ec) fail_input(models.string(), "cannot create the models folder: " + ec.message());
  for (int n = 1; n < 1000000; ++n) {
    fs::path folder = models / ("model-" + std::to_string(n));
    if (fs::create_directory(folder, ec)) return folder;
    if (ec) fail_input(folder.string(), "cannot create a folder for the model: " + ec.message());
  }
  fail_input(models.string(), "no free model-N folder name left");
}

}  // namespace

struct ModelOpening::Impl {
  enum class Stage { idle, receiving, working };

  fs::path models;
  fs::path program;
  ModelOpeningEvents events;

  std::mutex mutex;  // guards everything below but the job's own locals
  Stage stage = Stage::idle;
  std::uint64_t uploader = 0;
  std::optional<std::uint32_t> seq;
  std::string name;  // as the client gave it: only for messages
  fs::path folder;   // model-N
  fs::path model;    // model-N/model.EXT
  std::ofstream out;
  std::uint64_t expected = 0, received = 0;
  std::thread job;
  std::atomic<bool> cancel{false};

  nlohmann::json message(const char* stage_name) const {
    return {{"type", "model"},
            {"seq", seq ? nlohmann::json(*seq) : nlohmann::json(nullptr)},
            {"client", uploader},
            {"name", name},
            {"stage", stage_name}};
  }

  fs::path part_file() const { return fs::path(model.string() + ".part"); }

  // Drops a model being received or one that failed (under the mutex).
  void drop() {
    if (out.is_open()) out.close();
    std::error_code ec;
    if (!folder.empty()) fs::remove_all(folder, ec);
    folder.clear();
    stage = Stage::idle;
  }

  // A child's message as the designer should read it: without its "error: " or "warning: " and
  // with the server's paths replaced by the model's name and the files' own names.
  std::string tidy(std::string line, std::string_view prefix) const {
    if (line.rfind(prefix, 0) == 0) line.erase(0, prefix.size());
    replace_all(line, model.string(), name);
    replace_all(line, (folder / "").string(), "");
    return line;
  }

  std::string reason(const ChildResult& r, const char* what) const {
    const std::string line = tidy(last_line(r.err_end), "error: ");
    return line.empty() ? std::string(what) + " ended with status " + std::to_string(r.status)
                        : line;
  }

  // The server is stopping: what the model left so far goes with it.
  void abandon() {
    std::lock_guard lock(mutex);
    drop();
  }

  void run() {
    const std::string base = folder.filename().string();
    const fs::path scene = folder / (base + ".json"), rlt = folder / (base + ".rlt");
    ChildOptions options;
    options.cancelled = [this] { return cancel.load(); };
    try {
      const ChildResult imported =
          run_child({program.string(), "import", model.string(), "-o", scene.string()}, options);
      if (cancel) {
        abandon();
        return;
      }
      if (imported.status != 0) throw InputError(reason(imported, "the import"));
      nlohmann::json summary = nlohmann::json::parse(last_line(imported.out), nullptr, false);
      if (summary.is_discarded()) summary = nullptr;
      nlohmann::json reply = message("imported");
      reply["summary"] = summary;
      events.broadcast(reply);

      nlohmann::json warnings = nlohmann::json::array();
      options.on_error_line = [&](const std::string& line) {
        if (line.rfind("warning: ", 0) == 0) warnings.push_back(tidy(line, "warning: "));
        const std::optional<ProgressLine> p = parse_progress_line(line);
        if (!p) return;
        nlohmann::json progress = message("precomputing");
        progress["phase"] = p->label;
        progress["fraction"] = p->fraction;
        events.broadcast(progress);
      };
      const ChildResult precomputed =
          run_child({program.string(), "precompute", scene.string(), "-o", rlt.string()}, options);
      if (cancel) {
        abandon();
        return;
      }
      if (precomputed.status != 0) throw InputError(reason(precomputed, "the precompute"));
      nlohmann::json opening = message("opening");
      opening["scene"] = rlt.filename().string();
      opening["warnings"] = warnings;
      events.broadcast(opening);
      {
        std::lock_guard lock(mutex);
        stage = Stage::idle;
      }
      events.opened(rlt);
    } catch (const std::exception& e) {
      nlohmann::json failed;
      {
        std::lock_guard lock(mutex);
        failed = message("failed");
        failed["message"] = e.what();
        drop();
      }
      if (!cancel) events.broadcast(failed);
    }
  }
};

ModelOpening::ModelOpening(const fs::path& folder, fs::path program, ModelOpeningEvents events)
    : impl_(std::make_unique<Impl>()) {
  impl_->models = fs::absolute(folder);
  impl_->program = std::move(program);
  impl_->events = std::move(events);
}

ModelOpening::~ModelOpening() {
  impl_->cancel = true;
  if (impl_->job.joinable()) impl_->job.join();
  std::lock_guard lock(impl_->mutex);
  if (impl_->stage == Impl::Stage::receiving) impl_->drop();
}

nlohmann::json ModelOpening::begin(std::uint64_t from, std::optional<std::uint32_t> seq,
                                   const std::string& name, std::uint64_t bytes) {
  Impl& s = *impl_;
  const std::string extension = lower(fs::path(name).extension().string());
  if (std::find(std::begin(kModelExtensions), std::end(kModelExtensions), extension) ==
      std::end(kModelExtensions)) {
    fail_input(
        "message:/name",
        "\"" + name + "\" is not a model the studio opens: expected .ifc, .gltf, .glb or .obj");
  }
  if (bytes > kMaxModelBytes) {
    fail_input("message:/bytes", name + " is " + std::to_string(bytes >> 20) +
                                     " MB, over the 200 MB limit of a model upload");
  }
  std::lock_guard lock(s.mutex);
  if (s.stage != Impl::Stage::idle) {
    fail_input("message",
               "another model (" + s.name + ") is being opened; wait for it to open or fail");
  }
  if (s.job.joinable()) s.job.join();  // the last opening's thread, finished
  s.folder = new_model_folder(s.models);
  s.model = s.folder / ("model" + extension);
  s.out.open(s.part_file(), std::ios::binary | std::ios::trunc);
  if (!s.out) {
    s.drop();
    fail_input(s.models.string(), "cannot write a model file there");
  }
  s.stage = Impl::Stage::receiving;
  s.uploader = from;
  s.seq = seq;
  s.name = name;
  s.expected = bytes;
  s.received = 0;
  nlohmann::json reply = s.message("receiving");
  reply["done"] = 0;
  reply["total"] = bytes;
  return reply;
}

nlohmann::json ModelOpening::receive(std::uint64_t from, std::string_view message) {
  Impl& s = *impl_;
  if (message.substr(0, kModelChunkTag.size()) != kModelChunkTag) {
    fail_input("message", "a binary message must be an RLMU piece of a model being opened");
  }
  message.remove_prefix(kModelChunkTag.size());
  nlohmann::json importing;
  {
    std::lock_guard lock(s.mutex);
    if (s.stage != Impl::Stage::receiving || s.uploader != from) {
      fail_input("message", "no model is being sent on this connection (send open_model first)");
    }
    if (message.size() > s.expected - s.received) {
      s.drop();
      fail_input("message", "more bytes of " + s.name + " than the " + std::to_string(s.expected) +
                                " announced; the upload is dropped");
    }
    s.out.write(message.data(), static_cast<std::streamsize>(message.size()));
    s.received += message.size();
    if (s.received < s.expected) {
      if (!s.out) {
        s.drop();
        fail_input("message", "the server cannot store " + s.name + " (disk full?)");
      }
      nlohmann::json reply = s.message("receiving");
      reply["done"] = s.received;
      reply["total"] = s.expected;
      return reply;
    }
    s.out.close();
    std::error_code ec;
    if (!s.out) ec = std::make_error_code(std::errc::io_error);
    if (!ec) fs::rename(s.part_file(), s.model, ec);
    if (ec) {
      s.drop();
      fail_input("message", "the server cannot store " + s.name + ": " + ec.message());
    }
    s.stage = Impl::Stage::working;
    s.cancel = false;
    importing = s.message("importing");
  }
  // Before the job starts, so that every client reads "importing" before what follows it.
  s.events.broadcast(importing);
  std::lock_guard lock(s.mutex);
  s.job = std::thread([&s] { s.run(); });
  return nullptr;
}

void ModelOpening::disconnected(std::uint64_t from) {
  std::lock_guard lock(impl_->mutex);
  if (impl_->stage == Impl::Stage::receiving && impl_->uploader == from) impl_->drop();
}

}  // namespace relight
