// The stored transfer of every source of a scene as the run time reads it: one view per
// source module (luminaires, portals, near-field emitters, movable objects), in scene order. Built
// by sources/transfer_file.h from a .rlt or from a precompute in memory.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/runtime_scene.h"
#include "sources/emitters/nearfield_transfer_view.h"
#include "sources/environment/cuts_sections.h"
#include "sources/luminaires/luminaire_transfer_view.h"
#include "sources/objects/object_mesh.h"
#include "sources/portals/portal_transfer_view.h"

namespace relight {

struct TransferView {
  std::size_t receivers = 0;
  int sh_order = 8;
  bool direct_sh_mode = false;
  std::vector<LuminaireTransferView> luminaires;  // scene order
  int portal_sh_order = 6;
  std::vector<PortalTransferView> portals;  // scene order
  NearfieldTransferView nearfield;          // sh_order 0 without emitters
  RuntimeSceneView scene;                   // what the run time traces and bounces itself
  std::vector<ObjectMesh> objects;          // the movable objects' prepared meshes, scene order
  CutsTransferView cuts;  // the top-level environment's visibility cuts (empty: none)
};

}  // namespace relight
