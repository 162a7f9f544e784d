// The near-field emitters' sections of a transfer file (docs/rlt-format.md, "Sections of a
// transfer file"): the shadowed SH transfer per receiver (NFTR). The gather operator the run
// time bounces the emitters' light through is the scene's (sources/transfer_file.h). Written
// and read here; store/ holds the container.
#pragma once

#include <cstddef>
#include <string>

#include "engine/transfer_sections.h"
#include "sources/emitters/nearfield_precompute.h"
#include "sources/emitters/nearfield_transfer_view.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// Through `sink` (engine/transfer_sections.h: the writing rank adds, the others send their
// rows). The writer keeps spans into `nearfield` until it writes.
void write_nearfield_sections(SectionSink& sink, const NearfieldTransfer& nearfield);

// Fills the transfer span of `view` (its sh_order set) from `file`; InputError
// naming `where` when they are missing or their sizes disagree.
void read_nearfield_sections(const RltFile& file, std::size_t receivers,
                             NearfieldTransferView& view, const std::string& where);

}  // namespace relight
