#include "sources/luminaires/luminaire_sections.h"

#include "common/input_error.h"
#include "engine/transfer_blocks.h"
#include "engine/transfer_sections.h"
#include "math/sh.h"
#include "store/rlt_format.h"

namespace relight {

void write_luminaire_sections(SectionSink& sink, std::span<const LuminaireTransfer> luminaires,
                              std::span<const std::string> photometry,
                              const LuminaireBlockBytes& block) {
  for (std::size_t j = 0; j < luminaires.size(); ++j) {
    const LuminaireTransfer& l = luminaires[j];
    sink.rows(rlt_indexed('D', 'X', j), rlt_indexed_name("direct dir x", j), l.direct.dir_x, 1);
    sink.rows(rlt_indexed('D', 'Y', j), rlt_indexed_name("direct dir y", j), l.direct.dir_y, 1);
    sink.rows(rlt_indexed('D', 'Z', j), rlt_indexed_name("direct dir z", j), l.direct.dir_z, 1);
    sink.rows(rlt_indexed('D', 'F', j), rlt_indexed_name("direct factor", j), l.direct.factor, 1);
    sink.transfer(rlt_indexed('T', 'I', j), rlt_indexed_name("indirect sh", j), l.indirect.view(),
                  block.indirect);
    if (RltWriter* w = sink.writer(); w != nullptr && !photometry[j].empty()) {
      w->add_text(rlt_indexed('P', 'H', j), rlt_indexed_name("photometry", j), photometry[j]);
    }
    if (sink.alone() ? !l.direct_sh_blocks.empty() : block.direct_sh > 0) {
      sink.transfer(rlt_indexed('T', 'D', j), rlt_indexed_name("direct sh", j),
                    BlockedTransfer{l.direct_sh_blocks, {}}, block.direct_sh);
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
