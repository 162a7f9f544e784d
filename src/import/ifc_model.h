// IFC files (IFC2X3, IFC4) read by web-ifc, a maintained IFC library from npm, driven by node
// (importer/ifc-extract.mjs; docs/decisions.md "Model import" says why this library). The STEP
// header and trailer are checked here first, so that a file that is not IFC, or is cut short,
// is refused with its reason before node starts. Pinned by tests/import/ifc_model_test.cpp (the
// FZK-Haus: 11 windows, 7 spaces, 2 storeys, the site at 49.1° N).
#pragma once

#include <filesystem>

#include "import/building_model.h"

namespace relight {

// The folder of ifc-extract.mjs and its node_modules: PREFIX/share/relight/importer beside an
// installed relight, else the checkout's importer/.
std::filesystem::path importer_folder();

// Reads `file`. InputError "FILE: reason" when it is not IFC, truncated, or web-ifc cannot read
// it; also when node or web-ifc is missing (the reason says how to install them).
BuildingModel read_ifc_model(const std::filesystem::path& file);

// The reader's JSON (importer/ifc-extract.mjs, its header says the fields) as a model; `file`
// names the IFC file in messages. InputError when a field is missing, of the wrong type, or an
// index is out of range.
BuildingModel parse_ifc_extract(const std::string& json, const std::filesystem::path& file);

}  // namespace relight
