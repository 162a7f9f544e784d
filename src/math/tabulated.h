// Tables made once per key (a grid size, an SH order) for the life of the process and shared by
// every caller: Gauss–Legendre rules, a cubemap's solid angles, texel directions and SH weights,
// a sky's texel quadrature. The run time remakes shells every hour of `relight annual` from the
// same few grids. Safe to call from many threads; references stay valid (map nodes do not
// move).
#pragma once

#include <map>
#include <mutex>
#include <type_traits>

namespace relight {

// The table `make(key)` made on the first call for `key`. `make` must be a lambda: its type,
// unique to the call site, gives every call site its own tables.
template <class Value, class Key, class Make>
const Value& tabulated(const Key& key, Make&& make) {
  static_assert(std::is_class_v<std::remove_cvref_t<Make>>,
                "tabulated: pass a lambda, so that each call site keeps its own tables");
  static std::mutex mutex;
  static std::map<Key, Value> tables;
  const std::scoped_lock lock(mutex);
  auto it = tables.find(key);
  if (it == tables.end()) it = tables.emplace(key, make(key)).first;
  return it->second;
}

}  // namespace relight
