// Fuzz target: a studio client's upload of a photometric file (serve/studio_messages.h "upload",
// serve/photometry_catalogue.h add_upload) into a catalogue in a temporary folder: the message
// parsed, the name checked, the text parsed by the IES/LDT parsers and, when valid, stored. Bad
// input must end in InputError; anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <variant>

#include <unistd.h>

#include "common/input_error.h"
#include "fuzz_room.h"
#include "serve/photometry_catalogue.h"
#include "serve/studio_messages.h"

namespace {

const std::filesystem::path& catalogue_folder() {
  static const std::filesystem::path folder = [] {
    std::filesystem::path p = std::filesystem::temp_directory_path() /
                              ("relight-fuzz-upload-" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::optional<std::uint32_t> seq;
  try {
    const relight::ClientMessage m = relight::parse_client_message(
        std::string(reinterpret_cast<const char*>(data), size), relight::fuzz::fuzz_room(), seq);
    const auto* upload = std::get_if<relight::UploadRequest>(&m.request);
    if (!upload) return 0;
    relight::PhotometryCatalogue catalogue(catalogue_folder());
    catalogue.add_upload(upload->name, upload->text);
  } catch (const relight::InputError&) {
  }
  std::error_code ignored;
  std::filesystem::remove_all(catalogue_folder() / "uploads", ignored);
  return 0;
}
