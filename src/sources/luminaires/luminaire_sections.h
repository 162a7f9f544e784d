// The luminaires' sections of a transfer file (docs/rlt-format.md, "Sections of a transfer
// file"): per luminaire j the exact-direct geometry ("DX", "DY", "DZ", "DF" + j), the
// interreflected SH transfer ("TI"), the SH-basis direct in "sh" mode ("TD") and the IES/LDT
// text it was computed with ("PH"). Written and read here; store/ holds the container.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/transfer_sections.h"
#include "scene/scene.h"
#include "sources/luminaires/luminaire_precompute.h"
#include "sources/luminaires/luminaire_transfer_view.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// The bytes of one block of kBlock receivers of a luminaire's "TI" and "TD" sections (0: none).
struct LuminaireBlockBytes {
  std::size_t indirect = 0, direct_sh = 0;
};

// Through `sink` (engine/transfer_sections.h: the writing rank adds, the others send their
// share). `photometry[j]`: the file text of luminaire j, empty when it has none (read by the
// writing rank only). The writer keeps spans into both until it writes.
void write_luminaire_sections(SectionSink& sink, std::span<const LuminaireTransfer> luminaires,
                              std::span<const std::string> photometry,
                              const LuminaireBlockBytes& block);

// The stored photometry text of luminaire j.
std::string_view luminaire_photometry(const RltFile& file, std::size_t j);

// Views of every luminaire's sections; InputError (naming `where` and the luminaire) when a
// size disagrees with `receivers` and K = sh_order².
std::vector<LuminaireTransferView> read_luminaire_sections(const RltFile& file,
                                                           std::span<const Luminaire> luminaires,
                                                           std::size_t receivers, int sh_order,
                                                           bool direct_sh_mode,
                                                           const std::string& where);

}  // namespace relight
