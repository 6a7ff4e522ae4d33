#include <pcl/tda/common/betti_numbers.h>
#include <pcl/exceptions.h>

#include <cmath>

namespace pcl {
namespace tda {

namespace {

void
checkMarks (const FilteredComplex& complex, const PersistenceResult& result)
{
  if (result.max_dimension < 1 || result.edge_positive.size() != complex.numEdges() ||
      result.triangle_positive.size() != complex.numTriangles())
    PCL_THROW_EXCEPTION (
        pcl::BadArgumentException,
        "the persistence result (of dimensions up to "
            << result.max_dimension << ") marks " << result.edge_positive.size()
            << " edges and " << result.triangle_positive.size()
            << " triangles, the complex has " << complex.numEdges() << " and "
            << complex.numTriangles() << ": Betti numbers need H1 persistence");
}

/** Adds the contribution of one simplex to \a betti (Alg 5.8's loop body). */
void
addSimplex (const SimplexRef& simplex,
            const PersistenceResult& result,
            BettiNumbers& betti)
{
  switch (simplex.dimension) {
  case 0:
    ++betti[0];
    break;
  case 1:
    result.edge_positive[simplex.index] ? ++betti[1] : --betti[0];
    break;
  default:
    result.triangle_positive[simplex.index] ? ++betti[2] : --betti[1];
  }
}

} // namespace

std::vector<BettiNumbers>
computePrefixBettiNumbers (const FilteredComplex& complex,
                           const PersistenceResult& result)
{
  checkMarks (complex, result);
  std::vector<BettiNumbers> prefixes;
  prefixes.reserve (complex.numSimplices());
  BettiNumbers betti{0, 0, 0};
  for (const SimplexRef& simplex : complex.filtrationOrder()) {
    addSimplex (simplex, result, betti);
    prefixes.push_back (betti);
  }
  return prefixes;
}

BettiNumbers
computeBettiNumbersAt (const FilteredComplex& complex,
                       const PersistenceResult& result,
                       double radius)
{
  checkMarks (complex, result);
  if (std::isnan (radius))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "the radius of the Betti numbers is NaN");
  BettiNumbers betti{0, 0, 0};
  if (radius < 0.0)
    return betti;
  for (SimplexIndex v = 0; v < complex.numVertices(); ++v)
    addSimplex ({0, v}, result, betti);
  for (SimplexIndex e = 0; e < complex.numEdges() && complex.edges()[e].value <= radius;
       ++e)
    addSimplex ({1, e}, result, betti);
  for (SimplexIndex t = 0;
       t < complex.numTriangles() && complex.triangles()[t].value <= radius;
       ++t)
    addSimplex ({2, t}, result, betti);
  return betti;
}

} // namespace tda
} // namespace pcl
