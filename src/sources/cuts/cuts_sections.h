// The visibility cuts' sections of a transfer file (docs/rlt-format.md, "Visibility cuts"):
// the direction tree's leaves in leaf order (the tree is rebuilt from them, so a file never
// depends on how a later build spreads its directions) and the self-visibility cut of every
// receiver, height encoded (math/cut_encoding.h). Written and read here; store/ holds the
// container.
#pragma once

#include <string>
#include <vector>

#include "math/cut_encoding.h"
#include "sources/cuts/cuts_precompute.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// The stored cuts as the run time reads them; empty directions: the file has none.
struct CutsTransferView {
  std::vector<Vec3> directions;    // leaf order
  HeightCutsView self_visibility;  // one cut per receiver
};

// The arrays written, kept alive until the writer writes.
struct CutsSectionData {
  std::vector<float> directions;
};

// Adds the sections of `cuts` (none when it is empty) to `writer`, which keeps spans into
// `cuts` and `data`.
void write_cuts_sections(RltWriter& writer, const CutsTransfer& cuts, CutsSectionData& data);

// The cuts of `file` for `receivers` receivers (empty when it has none); InputError naming
// `where` when they are damaged or not one per receiver.
CutsTransferView read_cuts_sections(const RltFile& file, std::size_t receivers,
                                    const std::string& where);

// The view of cuts in memory (a precompute not written to a file).
CutsTransferView cuts_view(const CutsTransfer& cuts);

}  // namespace relight
