#include <pcl/tda/search/boruvka_forest.h>

#include <numeric>

namespace pcl {
namespace tda {

ComponentKdTree::ComponentKdTree (const std::vector<Point3d>& points)
: ids_ (points.size()), component_at_ (points.size())
{
  std::iota (ids_.begin(), ids_.end(), std::uint32_t{0});
  if (points.empty())
    return;
  points_ = points;
  nodes_.reserve (2 * (points.size() / LEAF_SIZE + 1));
  nodes_.push_back ({});
  build (0, 0, static_cast<std::uint32_t> (points.size()));
  for (std::uint32_t i = 0; i < ids_.size(); ++i)
    points_[i] = points[ids_[i]];
  node_component_.assign (nodes_.size(), MIXED);
}

void
ComponentKdTree::build (std::uint32_t node, std::uint32_t begin, std::uint32_t end)
{
  // points_ is still in id order here; ids_[begin..end) are the node's points.
  Point3d low = points_[ids_[begin]], high = low;
  for (std::uint32_t i = begin + 1; i < end; ++i)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min (low[k], points_[ids_[i]][k]);
      high[k] = std::max (high[k], points_[ids_[i]][k]);
    }
  nodes_[node] = {low, high, begin, end, 0};
  if (end - begin <= LEAF_SIZE)
    return;
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (high[k] - low[k] > high[axis] - low[axis])
      axis = k;
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element (ids_.begin() + begin,
                    ids_.begin() + middle,
                    ids_.begin() + end,
                    [this, axis] (std::uint32_t a, std::uint32_t b) {
                      return points_[a][axis] != points_[b][axis]
                                 ? points_[a][axis] < points_[b][axis]
                                 : a < b;
                    });
  const auto left = static_cast<std::uint32_t> (nodes_.size());
  nodes_[node].left = left;
  nodes_.push_back ({});
  nodes_.push_back ({});
  build (left, begin, middle);
  build (left + 1, middle, end);
}

void
ComponentKdTree::labelComponents (UnionFind& components)
{
  for (std::uint32_t i = 0; i < ids_.size(); ++i)
    component_at_[i] = components.find (ids_[i]);
  // Children come after their parent: label from the last node back.
  for (std::size_t n = nodes_.size(); n-- > 0;) {
    const Node& node = nodes_[n];
    std::uint32_t label = component_at_[node.begin];
    if (node.left != 0) {
      if (node_component_[node.left] != node_component_[node.left + 1])
        label = MIXED;
      else
        label = node_component_[node.left];
    }
    else
      for (std::uint32_t i = node.begin + 1; i < node.end && label != MIXED; ++i)
        if (component_at_[i] != label)
          label = MIXED;
    node_component_[n] = label;
  }
}

} // namespace tda
} // namespace pcl
