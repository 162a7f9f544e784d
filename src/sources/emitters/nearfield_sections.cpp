#include "sources/emitters/nearfield_sections.h"

#include <cstdint>

#include "common/input_error.h"
#include "engine/transfer_sections.h"
#include "math/sh.h"
#include "store/rlt_format.h"

namespace relight {

namespace {

constexpr std::uint32_t kTransfer = rlt_fourcc("NFTR");

}  // namespace

void write_nearfield_sections(SectionSink& sink, const NearfieldTransfer& nearfield) {
  if (nearfield.transfer.empty()) return;
  sink.rows(kTransfer, "near-field transfer", nearfield.transfer,
            static_cast<std::size_t>(sh_count(nearfield.sh_order)));
}

void read_nearfield_sections(const RltFile& file, std::size_t receivers, NearfieldTransferView& nf,
                             const std::string& where) {
  if (nf.sh_order < 1 || nf.sh_order > 16 || !file.find_info(kTransfer)) {
    fail_input(where, "the scene has emitters but the file holds no near-field transfer");
  }
  const auto k = static_cast<std::size_t>(sh_count(nf.sh_order));
  nf.transfer = file.view<float>(kTransfer);
  if (nf.transfer.size() != receivers * k) {
    fail_input(where, "near-field transfer has an inconsistent size");
  }
}

}  // namespace relight
