// What the section table says about one section of an open .rlt file.
#pragma once

#include <cstdint>
#include <string>

#include "store/rlt_format.h"

namespace relight {

struct RltSectionInfo {
  std::uint32_t type = 0;
  RltElement element = RltElement::bytes;
  std::uint32_t flags = 0;  // meaning defined by the section type
  std::string name;
  std::uint64_t offset = 0;  // from the start of the file, a multiple of 64
  std::uint64_t size = 0;    // payload bytes
  std::uint64_t checksum = 0;
};

}  // namespace relight
