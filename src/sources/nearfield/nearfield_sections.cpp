#include "sources/nearfield/nearfield_sections.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <stdexcept>

#include "common/input_error.h"
#include "math/sh.h"
#include "store/rlt_format.h"

namespace relight {

namespace {

constexpr std::uint32_t kTransfer = rlt_fourcc("NFTR");
constexpr std::uint32_t kGatherRows = rlt_fourcc("NGRO");
constexpr std::uint32_t kGatherColumns = rlt_fourcc("NGCO");
constexpr std::uint32_t kGatherValues = rlt_fourcc("NGVA");

std::span<const std::uint32_t> indices(const int* p, Eigen::Index n) {
  return {reinterpret_cast<const std::uint32_t*>(p), static_cast<std::size_t>(n)};
}

}  // namespace

void write_nearfield_sections(RltWriter& w, const NearfieldTransfer& nearfield) {
  if (nearfield.transfer.empty()) return;
  w.add_f32(kTransfer, "near-field transfer", nearfield.transfer);
  const Eigen::SparseMatrix<float, Eigen::RowMajor>& g = nearfield.gather;
  if (g.nonZeros() == 0) return;
  if (!g.isCompressed()) throw std::invalid_argument("near-field gather operator not compressed");
  w.add_u32(kGatherRows, "near-field gather rows", indices(g.outerIndexPtr(), g.rows() + 1));
  w.add_u32(kGatherColumns, "near-field gather columns", indices(g.innerIndexPtr(), g.nonZeros()));
  w.add_f32(kGatherValues, "near-field gather values",
            std::span(g.valuePtr(), static_cast<std::size_t>(g.nonZeros())));
}

void read_nearfield_sections(const RltFile& file, std::size_t receivers, std::size_t vertices,
                             NearfieldTransferView& nf, const std::string& where) {
  if (nf.sh_order < 1 || nf.sh_order > 16 || !file.find_info(kTransfer)) {
    fail_input(where, "the scene has emitters but the file holds no near-field transfer");
  }
  const auto k = static_cast<std::size_t>(sh_count(nf.sh_order));
  nf.transfer = file.view<float>(kTransfer);
  if (nf.transfer.size() != receivers * k) {
    fail_input(where, "near-field transfer has an inconsistent size");
  }
  if (!file.find_info(kGatherRows)) return;
  nf.gather_rows = file.view<std::uint32_t>(kGatherRows);
  nf.gather_columns = file.view<std::uint32_t>(kGatherColumns);
  nf.gather_values = file.view<float>(kGatherValues);
  if (nf.gather_rows.size() != receivers + 1 || nf.gather_rows.front() != 0 ||
      nf.gather_rows.back() != nf.gather_columns.size() ||
      nf.gather_values.size() != nf.gather_columns.size() ||
      !std::is_sorted(nf.gather_rows.begin(), nf.gather_rows.end()) ||
      std::any_of(nf.gather_columns.begin(), nf.gather_columns.end(),
                  [&](std::uint32_t c) { return c >= vertices; })) {
    fail_input(where, "near-field gather operator has inconsistent sizes");
  }
}

}  // namespace relight
