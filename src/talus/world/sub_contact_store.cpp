#include "talus/world/sub_contact_store.h"

namespace talus {

std::vector<SubContactList> SubContactStore::lists() const {
  std::vector<SubContactList> out(entries());
  for (std::size_t e = 0; e < out.size(); ++e) {
    const std::span<const SubContact> points = of(e);
    out[e].assign(points.begin(), points.end());
  }
  return out;
}

}  // namespace talus
