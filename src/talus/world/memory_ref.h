#pragma once
// The contact law's view of one list entry's memory (null where that memory is off).
#include "talus/collide/pair_list.h"
#include "talus/contact/contact_law.h"

namespace talus {

inline ContactHistoryRef memory_ref(ContactMemory& m, std::size_t e) {
  return {m.spring.empty() ? nullptr : &m.spring[e], m.normal_prev.empty() ? nullptr : &m.normal_prev[e],
          m.rolling.empty() ? nullptr : &m.rolling[e]};
}

}  // namespace talus
