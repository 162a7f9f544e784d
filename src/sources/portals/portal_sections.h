// The portals' part of a transfer file (docs/rlt-format.md, "Sections of a transfer file"):
// per portal p its direct cubemap records ("CR" + p, bytes), their offsets ("CO", u64,
// receivers + 1) and its interreflected SH transfer ("PI", blocked RGB), and its entry in the
// metadata's "portals" (name, cubemap face size, shell centre and outward normal, diameter,
// and statistics). Written and read here; store/ holds the container.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/transfer_sections.h"
#include "scene/scene.h"
#include "sources/portals/portal_precompute.h"
#include "sources/portals/portal_transfer_view.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// Through `sink` (engine/transfer_sections.h: the writing rank adds, the others send their
// share of the direct records and of the indirect transfer, "PI" in blocks of
// `indirect_block_bytes`). The writer keeps spans into `portals` until it writes.
void write_portal_sections(SectionSink& sink, std::span<const PortalTransfer> portals,
                           std::size_t indirect_block_bytes);
// `indirect_bytes`: the size of each portal's "PI" section (on several ranks, rank 0 holds only
// its own blocks of it).
nlohmann::json portal_metadata(std::span<const PortalTransfer> portals, std::size_t indirect_bytes);

// Views of every portal's sections, from the metadata's "portals"; InputError (naming `where`
// and the portal) when it disagrees with the scene or a size with `receivers` and K.
std::vector<PortalTransferView> read_portal_sections(const RltFile& file,
                                                     const nlohmann::json& metadata,
                                                     std::span<const Portal> portals,
                                                     std::size_t receivers, int sh_order,
                                                     const std::string& where);

}  // namespace relight
