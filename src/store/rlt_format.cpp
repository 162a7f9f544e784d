// Names for element types and section type ids, for messages and `relight info`.
#include "store/rlt_format.h"

#include <cstdio>

namespace relight {

std::size_t rlt_element_size(RltElement element) {
  switch (element) {
    case RltElement::bytes:
    case RltElement::text:
      return 1;
    case RltElement::u16:
    case RltElement::f16:
      return 2;
    case RltElement::u32:
    case RltElement::f32:
      return 4;
    case RltElement::u64:
    case RltElement::f64:
      return 8;
  }
  return 1;
}

std::string rlt_element_name(RltElement element) {
  switch (element) {
    case RltElement::bytes:
      return "bytes";
    case RltElement::text:
      return "text";
    case RltElement::u16:
      return "u16";
    case RltElement::u32:
      return "u32";
    case RltElement::u64:
      return "u64";
    case RltElement::f16:
      return "f16";
    case RltElement::f32:
      return "f32";
    case RltElement::f64:
      return "f64";
  }
  return "element " + std::to_string(static_cast<int>(element));
}

std::string rlt_type_label(std::uint32_t type) {
  std::string code;
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((type >> (8 * i)) & 0xFF);
    const bool readable = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                          (c >= '0' && c <= '9') || c == '_' || c == ' ';
    if (!readable) {
      code.clear();
      break;
    }
    code += c;
  }
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%08x", type);
  if (!code.empty()) return "'" + code + "' (" + hex + ")";
  return std::to_string(type) + " (" + hex + ")";
}

}  // namespace relight
