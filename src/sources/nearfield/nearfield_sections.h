// The near-field emitters' sections of a transfer file (docs/rlt-format.md, "Sections of a
// transfer file"): the shadowed SH transfer per receiver (NFTR) and, with
// "nearfield_interreflection", the gather operator in compressed rows (NGRO, NGCO, NGVA) that
// the run time bounces the emitters' light through. Written and read here; store/ holds the
// container.
#pragma once

#include <cstddef>
#include <string>

#include "sources/nearfield/nearfield_precompute.h"
#include "sources/nearfield/nearfield_transfer_view.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// The writer keeps spans into `nearfield` until it writes (its gather operator compressed).
void write_nearfield_sections(RltWriter& writer, const NearfieldTransfer& nearfield);

// Fills the transfer and gather spans of `view` (its sh_order set) from `file`; InputError
// naming `where` when they are missing or their sizes disagree.
void read_nearfield_sections(const RltFile& file, std::size_t receivers, std::size_t vertices,
                             NearfieldTransferView& view, const std::string& where);

}  // namespace relight
