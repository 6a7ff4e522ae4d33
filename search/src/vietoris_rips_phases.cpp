#include <pcl/tda/search/vietoris_rips_phases.h>

#include <algorithm>

namespace pcl {
namespace tda {

std::size_t
VietorisRipsProgress::permilleAt (Phase phase) const
{
  constexpr std::size_t WITH_TRIANGLES[] = {0, 150, 300, 400, 700, 1000};
  constexpr std::size_t EDGES_ONLY[] = {0, 350, 700, 1000, 1000, 1000};
  return (with_triangles_ ? WITH_TRIANGLES : EDGES_ONLY)[phase];
}

ProgressCallback
VietorisRipsProgress::between (Phase first, Phase last) const
{
  if (!progress_)
    return {};
  const std::size_t begin = permilleAt (first), end = permilleAt (last);
  return [progress = progress_, begin, end] (std::size_t done, std::size_t total) {
    progress (begin + (end - begin) * done / std::max<std::size_t> (total, 1), 1000);
  };
}

void
VietorisRipsProgress::reach (Phase phase) const
{
  if (progress_)
    progress_ (permilleAt (phase), 1000);
}

} // namespace tda
} // namespace pcl
