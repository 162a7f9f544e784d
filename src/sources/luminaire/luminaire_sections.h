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

#include "scene/scene.h"
#include "sources/luminaire/luminaire_precompute.h"
#include "sources/luminaire/luminaire_transfer_view.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// `photometry[j]`: the file text of luminaire j, empty when it has none. The writer keeps
// spans into both until it writes.
void write_luminaire_sections(RltWriter& writer, std::span<const LuminaireTransfer> luminaires,
                              std::span<const std::string> photometry);

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
