#include <pcl/tda/common/persistence_diagram.h>

namespace pcl {
namespace tda {

PersistenceDiagram
PersistenceResult::diagram (int max_dimension) const
{
  PersistenceDiagram intervals;
  intervals.reserve (pairs.size());
  for (const auto& pair : pairs)
    if (pair.dimension <= max_dimension && pair.birth != pair.death)
      intervals.push_back ({pair.dimension, pair.birth, pair.death});
  return intervals;
}

} // namespace tda
} // namespace pcl
