#include "sources/luminaire/luminaire_sections.h"

#include "common/input_error.h"
#include "engine/transfer_blocks.h"
#include "engine/transfer_sections.h"
#include "math/sh.h"
#include "store/rlt_format.h"

namespace relight {

void write_luminaire_sections(RltWriter& w, std::span<const LuminaireTransfer> luminaires,
                              std::span<const std::string> photometry, const RankShares& ranks,
                              const LuminaireBlockBytes& block) {
  for (std::size_t j = 0; j < luminaires.size(); ++j) {
    const LuminaireTransfer& l = luminaires[j];
    add_row_section(w, rlt_indexed('D', 'X', j), rlt_indexed_name("direct dir x", j),
                    l.direct.dir_x, 1, ranks);
    add_row_section(w, rlt_indexed('D', 'Y', j), rlt_indexed_name("direct dir y", j),
                    l.direct.dir_y, 1, ranks);
    add_row_section(w, rlt_indexed('D', 'Z', j), rlt_indexed_name("direct dir z", j),
                    l.direct.dir_z, 1, ranks);
    add_row_section(w, rlt_indexed('D', 'F', j), rlt_indexed_name("direct factor", j),
                    l.direct.factor, 1, ranks);
    add_transfer_section(w, rlt_indexed('T', 'I', j), rlt_indexed_name("indirect sh", j),
                         l.indirect.view(), ranks, block.indirect);
    if (!photometry[j].empty()) {
      w.add_text(rlt_indexed('P', 'H', j), rlt_indexed_name("photometry", j), photometry[j]);
    }
    if (ranks.alone() ? !l.direct_sh_blocks.empty() : block.direct_sh > 0) {
      add_transfer_section(w, rlt_indexed('T', 'D', j), rlt_indexed_name("direct sh", j),
                           BlockedTransfer{l.direct_sh_blocks, {}}, ranks, block.direct_sh);
    }
  }
}

void send_luminaire_sections(std::span<const LuminaireTransfer> luminaires, const RankShares& ranks,
                             const LuminaireBlockBytes& block) {
  for (const LuminaireTransfer& l : luminaires) {
    for (const std::vector<float>* v :
         {&l.direct.dir_x, &l.direct.dir_y, &l.direct.dir_z, &l.direct.factor}) {
      send_row_section(*v, 1, ranks);
    }
    send_transfer_section(l.indirect.view(), ranks, block.indirect);
    if (block.direct_sh > 0) {
      send_transfer_section(BlockedTransfer{l.direct_sh_blocks, {}}, ranks, block.direct_sh);
    }
  }
}

std::string_view luminaire_photometry(const RltFile& file, std::size_t j) {
  return file.text(rlt_indexed('P', 'H', j));
}

std::vector<LuminaireTransferView> read_luminaire_sections(const RltFile& file,
                                                           std::span<const Luminaire> luminaires,
                                                           std::size_t receivers, int sh_order,
                                                           bool direct_sh_mode,
                                                           const std::string& where) {
  const auto k = static_cast<std::size_t>(sh_count(sh_order));
  std::vector<LuminaireTransferView> out;
  for (std::size_t j = 0; j < luminaires.size(); ++j) {
    LuminaireTransferView v;
    v.dir_x = file.view<float>(rlt_indexed('D', 'X', j));
    v.dir_y = file.view<float>(rlt_indexed('D', 'Y', j));
    v.dir_z = file.view<float>(rlt_indexed('D', 'Z', j));
    v.factor = file.view<float>(rlt_indexed('D', 'F', j));
    v.indirect = transfer_section(file, rlt_indexed('T', 'I', j));
    if (direct_sh_mode) v.direct_sh = file.view<float>(rlt_indexed('T', 'D', j));
    if (v.dir_x.size() != receivers || v.dir_y.size() != receivers || v.dir_z.size() != receivers ||
        v.factor.size() != receivers || v.indirect.size() != blocked_floats(receivers, k, 3) ||
        (direct_sh_mode && v.direct_sh.size() != blocked_floats(receivers, k, 1))) {
      fail_input(where,
                 "transfer of luminaire \"" + luminaires[j].name + "\" has inconsistent sizes");
    }
    out.push_back(v);
  }
  return out;
}

}  // namespace relight
