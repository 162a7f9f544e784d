// Where `cmake --install` puts relight's data beside its program: PREFIX/share/relight/NAME
// for PREFIX/bin/relight (the studio client, the IFC reader). A build tree has none there and
// falls back to the checkout's folder.
#pragma once

#include <filesystem>
#include <string_view>

namespace relight {

// The running program's own file (to run it again as a child); empty when it cannot be read.
std::filesystem::path running_program();

// PREFIX/share/relight/`name` for the running program; empty when its path cannot be read.
std::filesystem::path installed_share_folder(std::string_view name);

}  // namespace relight
