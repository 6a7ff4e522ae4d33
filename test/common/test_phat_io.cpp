#include <pcl/tda/common/phat_io.h>
#include <pcl/tda/common/standard_reduction.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "test_utils.h"
#include <phat/algorithms/twist_reduction.h>
#include <phat/compute_persistence_pairs.h>
#include <phat/representations/default_representations.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace pcl::tda;

namespace {

/** Same simplices, faces and order; values may differ (PHAT files have none). */
void
expectSameStructure (const FilteredComplex& a, const FilteredComplex& b)
{
  ASSERT_EQ (a.numVertices(), b.numVertices());
  ASSERT_EQ (a.numEdges(), b.numEdges());
  ASSERT_EQ (a.numTriangles(), b.numTriangles());
  for (std::size_t e = 0; e < a.numEdges(); ++e) {
    EXPECT_EQ (a.edges()[e].source, b.edges()[e].source);
    EXPECT_EQ (a.edges()[e].target, b.edges()[e].target);
  }
  for (std::size_t t = 0; t < a.numTriangles(); ++t)
    EXPECT_EQ (a.triangles()[t].edges, b.triangles()[t].edges);
  const auto order_a = a.filtrationOrder(), order_b = b.filtrationOrder();
  for (std::size_t g = 0; g < order_a.size(); ++g) {
    EXPECT_EQ (order_a[g].dimension, order_b[g].dimension);
    EXPECT_EQ (order_a[g].index, order_b[g].index);
  }
}

FilteredComplex
readString (const std::string& text, PHATFormat format)
{
  std::istringstream in (text);
  return readPHATBoundaryMatrix (in, format);
}

std::string
binaryMatrix (const std::vector<std::int64_t>& numbers)
{
  return std::string (reinterpret_cast<const char*> (numbers.data()),
                      numbers.size() * sizeof (std::int64_t));
}

} // namespace

TEST (PHATIO, RoundTripKeepsStructureAndPairs)
{
  for (unsigned int k = 0; k < 300; ++k) {
    const FilteredComplex complex = test::randomComplexCase (k);
    for (const auto format : {PHATFormat::ASCII, PHATFormat::BINARY}) {
      std::stringstream buffer;
      writePHATBoundaryMatrix (buffer, complex, format);
      const FilteredComplex read = readPHATBoundaryMatrix (buffer, format);
      expectSameStructure (complex, read);
      EXPECT_EQ (test::globalPairs (complex, computeStandardReduction (complex)),
                 test::globalPairs (read, computeStandardReduction (read)))
          << "case " << k;
    }
  }
}

TEST (PHATIO, ReadsWhatPHATWrites)
{
  const FilteredComplex complex = test::randomComplexCase (10);
  const std::string ours = testing::TempDir() + "phat_io_ours.bin";
  const std::string theirs = testing::TempDir() + "phat_io_theirs.bin";
  savePHATBoundaryMatrix (ours, complex, PHATFormat::BINARY);
  phat::boundary_matrix<phat::vector_vector> matrix;
  ASSERT_TRUE (matrix.load_binary (ours));
  ASSERT_TRUE (matrix.save_ascii (theirs));
  expectSameStructure (complex, loadPHATBoundaryMatrix (theirs, PHATFormat::ASCII));
  std::remove (ours.c_str());
  std::remove (theirs.c_str());
}

TEST (PHATIO, AsciiAcceptsCommentsAndBlankLines)
{
  const FilteredComplex read = readString (
      "# a triangle\n0\n0\n\n0\n1 0 1\n1 1 2\n1 0 2\n2 3 4 5\n", PHATFormat::ASCII);
  EXPECT_EQ (read.numVertices(), 3u);
  EXPECT_EQ (read.numEdges(), 3u);
  EXPECT_EQ (read.numTriangles(), 1u);
  EXPECT_EQ (read.edges()[1].value, 4.0); // the column index
}

TEST (PHATIO, RejectsMalformedMatrices)
{
  const auto ascii = PHATFormat::ASCII;
  EXPECT_THROW (readString ("0\n0\n1 0\n", ascii),
                pcl::IOException); // edge with 1 face
  EXPECT_THROW (readString ("0\n0\n1 0 5\n", ascii),
                pcl::IOException);                                   // face not earlier
  EXPECT_THROW (readString ("0\n1 0 0\n", ascii), pcl::IOException); // repeated face
  EXPECT_THROW (readString ("0\n0\n1 0 1\n0\n", ascii),
                pcl::IOException); // late vertex
  EXPECT_THROW (readString ("0\n0\n0\n1 0 1\n2 0 1 3\n", ascii), pcl::IOException);
  EXPECT_THROW (readString ("3\n", ascii), pcl::IOException);           // dimension 3
  EXPECT_THROW (readString ("0\n0\n1 0 x\n", ascii), pcl::IOException); // not a number
  // Two edges on the same vertices, two triangles on the same edges.
  EXPECT_THROW (readString ("0\n0\n1 0 1\n1 0 1\n", ascii), pcl::IOException);
  EXPECT_THROW (readString ("0\n0\n0\n1 0 1\n1 1 2\n1 0 2\n2 3 4 5\n2 3 4 5\n", ascii),
                pcl::IOException);

  const auto binary = PHATFormat::BINARY;
  EXPECT_THROW (readString (binaryMatrix ({2, 0, 0}), binary),
                pcl::IOException); // truncated
  EXPECT_THROW (readString (binaryMatrix ({1000000000000, 0, 0}), binary),
                pcl::IOException);
  EXPECT_THROW (readString (binaryMatrix ({1, 0, 99}), binary), pcl::IOException);
  EXPECT_THROW (readString (std::string ("abc"), binary), pcl::IOException);
  EXPECT_NO_THROW (readString (binaryMatrix ({2, 0, 0, 0, 0}), binary));
}

TEST (PHATIO, MissingFileAndUnwritablePathThrow)
{
  EXPECT_THROW (loadPHATBoundaryMatrix ("/nonexistent/matrix.bin", PHATFormat::BINARY),
                pcl::IOException);
  EXPECT_THROW (savePHATBoundaryMatrix ("/nonexistent/matrix.bin",
                                        test::randomComplexCase (1),
                                        PHATFormat::ASCII),
                pcl::IOException);
}
