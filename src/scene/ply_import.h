// Stanford PLY import (ascii, binary_little_endian, binary_big_endian), read by our own
// parser: Debian ships no PLY library.
#pragma once

#include <filesystem>

#include "scene/mesh_import.h"

namespace relight {

// Reads vertex x, y, z (any scalar type) and the face list `vertex_indices` or `vertex_index`
// (any count and index types); polygons become a fan around their first corner (ear-clipped
// when concave). Other elements and properties are skipped. Colours: when the face element
// has uchar red, green and blue, each distinct colour becomes a material named "rgb(R,G,B)"
// whose albedo is the sRGB-decoded colour; per-vertex colours are ignored (materials are per
// triangle here). Without face colours every triangle gets the "default" material.
ImportedMesh import_ply(const std::filesystem::path& file);

}  // namespace relight
