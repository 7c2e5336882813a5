#include "talus/world/distributed_snapshot.h"

#include <algorithm>
#include <stdexcept>

namespace talus {

Snapshot gather_snapshot(const Snapshot& piece, const Communicator& comm, std::size_t id_limit, int root) {
  std::vector<std::byte> mine;
  ByteWriter w(mine);
  w.put(static_cast<std::uint64_t>(piece.particles.size()));
  for (const ParticleRecord& r : piece.particles) w.put(r);
  w.put(static_cast<std::uint64_t>(piece.contacts.size()));
  for (const ContactRecord& c : piece.contacts) w.put(c);
  const std::vector<std::byte> all = root < 0 ? comm.all_gather(mine) : comm.gather(mine, root);

  Snapshot s = piece;
  s.particles.clear();
  s.contacts.clear();
  if (root >= 0 && comm.rank() != root) return s;
  ByteReader r(all);
  while (!r.done()) {
    for (auto n = r.get<std::uint64_t>(); n > 0; --n) s.particles.push_back(r.get<ParticleRecord>());
    for (auto n = r.get<std::uint64_t>(); n > 0; --n) s.contacts.push_back(r.get<ContactRecord>());
  }
  std::sort(s.particles.begin(), s.particles.end(),
            [](const ParticleRecord& a, const ParticleRecord& b) { return a.id < b.id; });
  std::vector<int> record_of(id_limit, -1);
  for (std::size_t k = 0; k < s.particles.size(); ++k) record_of[s.particles[k].id] = static_cast<int>(k);
  for (ContactRecord& c : s.contacts) {
    c.i = record_of[c.i];
    if (c.j >= 0) c.j = record_of[c.j];
    if (c.i < 0 || (c.j < 0 && c.wall < 0)) throw std::logic_error("a contact names a particle no rank owns");
  }
  return s;
}

}  // namespace talus
