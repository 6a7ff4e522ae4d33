#pragma once

#include <pcl/tda/common/filtered_complex.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

namespace pcl {
namespace tda {
namespace test {

/** The bits of a double: values of two complexes must agree exactly, not within a
 * tolerance. */
inline std::uint64_t
doubleBits (double value)
{
  std::uint64_t bits;
  std::memcpy (&bits, &value, sizeof bits);
  return bits;
}

/** The first difference between two complexes, in words; empty when they are the
 * same: the vertex count, the edges and triangles in order with their values bit for
 * bit and, when \a with_point_indices, the input index of every vertex (leave it out
 * to compare complexes of the same points in another input order). */
inline std::string
complexDifference (const FilteredComplex& expected,
                   const FilteredComplex& actual,
                   bool with_point_indices = true)
{
  std::ostringstream difference;
  if (expected.numVertices() != actual.numVertices())
    difference << "vertices " << expected.numVertices() << " vs "
               << actual.numVertices();
  else if (with_point_indices && expected.pointIndices() != actual.pointIndices())
    difference << "point indices differ";
  else if (expected.numEdges() != actual.numEdges())
    difference << "edges " << expected.numEdges() << " vs " << actual.numEdges();
  else if (expected.numTriangles() != actual.numTriangles())
    difference << "triangles " << expected.numTriangles() << " vs "
               << actual.numTriangles();
  if (!difference.str().empty())
    return difference.str();
  for (std::size_t e = 0; e < expected.numEdges(); ++e) {
    const FilteredEdge &a = expected.edges()[e], &b = actual.edges()[e];
    if (a.source != b.source || a.target != b.target ||
        doubleBits (a.value) != doubleBits (b.value)) {
      difference << "edge " << e << ": (" << a.source << ", " << a.target << ", "
                 << a.value << ") vs (" << b.source << ", " << b.target << ", "
                 << b.value << ")";
      return difference.str();
    }
  }
  for (std::size_t t = 0; t < expected.numTriangles(); ++t) {
    const FilteredTriangle &a = expected.triangles()[t], &b = actual.triangles()[t];
    if (a.edges != b.edges || doubleBits (a.value) != doubleBits (b.value)) {
      difference << "triangle " << t << ": (" << a.edges[0] << ", " << a.edges[1]
                 << ", " << a.edges[2] << ") vs (" << b.edges[0] << ", " << b.edges[1]
                 << ", " << b.edges[2] << ")";
      return difference.str();
    }
  }
  return {};
}

} // namespace test
} // namespace tda
} // namespace pcl
