#include "talus/world/sub_contact_store.h"

#include <stdexcept>

namespace talus {

std::vector<SubContactList> SubContactStore::lists() const {
  std::vector<SubContactList> out(entries());
  for (std::size_t e = 0; e < out.size(); ++e) {
    const std::span<const SubContact> points = of(e);
    out[e].assign(points.begin(), points.end());
  }
  return out;
}

void SubContactStore::finish_block(std::size_t b) {
  Block& block = blocks_[b];
  if (block.cursor != block.current.size())
    throw std::logic_error("contact points of a sleeping body pair were skipped (SubContactStore)");
  block.current.swap(block.next);
}

}  // namespace talus
