// The InputError message import_mesh gives for a file, or "" (and a test failure) when it
// accepts the file: the mesh importers' tests pin their messages with it.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "common/input_error.h"
#include "scene/mesh_import.h"

namespace relight::testing {

inline std::string mesh_import_error(const std::filesystem::path& path) {
  try {
    import_mesh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << path;
  return {};
}

}  // namespace relight::testing
