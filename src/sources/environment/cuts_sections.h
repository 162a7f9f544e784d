// The visibility cuts' sections of a transfer file (docs/rlt-format.md, "Visibility cuts"):
// the direction tree's leaves in leaf order (the tree is rebuilt from them, so a file never
// depends on how a later build spreads its directions), the self-visibility cut of every
// receiver, each movable object's visibility cut field (its layout and its samples' cuts) and
// its vertices' cuts of itself, each store height encoded (math/cut_encoding.h). Written and
// read here; store/ holds the container.
#pragma once

#include <string>
#include <vector>

#include "math/cut_encoding.h"
#include "sources/environment/cuts_precompute.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// The stored cuts as the run time reads them; empty directions: the file has none.
struct CutsTransferView {
  std::vector<Vec3> directions;               // leaf order
  HeightCutsView self_visibility;             // one cut per receiver
  std::vector<VisibilityFieldLayout> fields;  // per movable object
  std::vector<std::uint64_t> field_first;     // object o's samples from field_first[o]
  HeightCutsView field_cuts;
  HeightCutsView object_self_visibility;  // one cut per object vertex, objects back to back
};

// The arrays written, kept alive until the writer writes.
struct CutsSectionData {
  std::vector<float> directions;
  std::vector<double> fields;
};

// Adds the sections of `cuts` (none when it is empty) to `writer`, which keeps spans into
// `cuts` and `data`.
void write_cuts_sections(RltWriter& writer, const CutsTransfer& cuts, CutsSectionData& data);

// The cuts of `file` for `receivers` receivers, `objects` movable objects of
// `object_vertices` vertices in all (empty when it has none); InputError naming `where` when
// they are damaged or do not fit.
CutsTransferView read_cuts_sections(const RltFile& file, std::size_t receivers, std::size_t objects,
                                    std::size_t object_vertices, const std::string& where);

// The view of cuts in memory (a precompute not written to a file).
CutsTransferView cuts_view(const CutsTransfer& cuts);

}  // namespace relight
