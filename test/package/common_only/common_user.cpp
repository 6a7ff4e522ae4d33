// Persistence of a small complex through the installed pcl_tda::common alone: a
// hollow triangle has one component and one hole.
#include <pcl/tda/common/persistence_engines.h>

#include <cstdio>

int
main ()
{
  const auto complex = pcl::tda::FilteredComplex::fromLists (
      3, {{0, 1, 1.0}, {0, 2, 1.0}, {1, 2, 1.0}}, {});
  const auto result = pcl::tda::computePersistence (complex);
  const auto diagram = result.diagram (complex);
  std::printf ("common only: intervals %zu\n", diagram.size());
  return diagram.size() == 4 ? 0 : 1;
}
