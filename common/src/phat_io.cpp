#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/phat_io.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace pcl {
namespace tda {

namespace {

/** One column of a boundary matrix: its dimension and its sorted row indices. */
struct BoundaryColumn {
  std::int64_t dimension;
  std::vector<std::int64_t> rows;
};

void
writeInt64 (std::ostream& out, std::int64_t value)
{
  out.write (reinterpret_cast<const char*> (&value), sizeof (value));
}

bool
readInt64 (std::istream& in, std::int64_t& value)
{
  return static_cast<bool> (in.read (reinterpret_cast<char*> (&value), sizeof (value)));
}

void
writeColumn (std::ostream& out, PHATFormat format, const BoundaryColumn& column)
{
  if (format == PHATFormat::ASCII) {
    out << column.dimension;
    for (const auto row : column.rows)
      out << ' ' << row;
    out << '\n';
    return;
  }
  writeInt64 (out, column.dimension);
  writeInt64 (out, static_cast<std::int64_t> (column.rows.size()));
  for (const auto row : column.rows)
    writeInt64 (out, row);
}

std::vector<BoundaryColumn>
readAsciiColumns (std::istream& in)
{
  std::vector<BoundaryColumn> columns;
  std::string line;
  std::size_t line_number = 0;
  while (std::getline (in, line)) {
    ++line_number;
    const auto first = line.find_first_not_of (" \t\r");
    if (first == std::string::npos || line[first] == '#')
      continue;
    std::istringstream fields (line);
    BoundaryColumn column;
    if (!(fields >> column.dimension))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "PHAT line " << line_number << ": no dimension in '" << line
                                        << "'");
    std::int64_t row;
    while (fields >> row)
      column.rows.push_back (row);
    if (!fields.eof())
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "PHAT line " << line_number << ": bad row index in '" << line
                                        << "'");
    std::sort (column.rows.begin(), column.rows.end());
    columns.push_back (std::move (column));
  }
  return columns;
}

std::vector<BoundaryColumn>
readBinaryColumns (std::istream& in)
{
  // Refuse absurd sizes before allocating: every column takes at least 16 bytes.
  const auto start = in.tellg();
  in.seekg (0, std::ios::end);
  const std::int64_t available = static_cast<std::int64_t> (in.tellg() - start);
  in.seekg (start);

  std::int64_t num_columns;
  if (!readInt64 (in, num_columns) || num_columns < 0 ||
      num_columns > (available - 8) / 16)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "PHAT binary matrix: bad column count for a file of "
                             << available << " bytes");
  std::vector<BoundaryColumn> columns (static_cast<std::size_t> (num_columns));
  for (std::int64_t c = 0; c < num_columns; ++c) {
    std::int64_t size;
    if (!readInt64 (in, columns[c].dimension) || !readInt64 (in, size) || size < 0 ||
        size > 3)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "PHAT binary matrix: column "
                               << c << " is truncated or too large");
    columns[c].rows.resize (static_cast<std::size_t> (size));
    for (auto& row : columns[c].rows)
      if (!readInt64 (in, row))
        PCL_THROW_EXCEPTION (pcl::IOException,
                             "PHAT binary matrix: column " << c << " is truncated");
    std::sort (columns[c].rows.begin(), columns[c].rows.end());
  }
  return columns;
}

/** True when two elements of \a simplices have the same \a faces. */
template <typename Simplex, typename Faces>
bool
hasDuplicates (const std::vector<Simplex>& simplices, Faces faces)
{
  std::vector<std::array<SimplexIndex, 3>> keys;
  keys.reserve (simplices.size());
  for (const auto& simplex : simplices)
    keys.push_back (faces (simplex));
  std::sort (keys.begin(), keys.end());
  return std::adjacent_find (keys.begin(), keys.end()) != keys.end();
}

/** Turns boundary columns into a complex, checking that they describe one. */
FilteredComplex
complexFromColumns (const std::vector<BoundaryColumn>& columns)
{
  std::size_t num_vertices = 0;
  std::vector<FilteredEdge> edges;
  std::vector<FilteredTriangle> triangles;
  // Index of every column among the simplices of its dimension.
  std::vector<SimplexIndex> local_index (columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const BoundaryColumn& column = columns[c];
    const auto fail = [&] (const char* what) {
      PCL_THROW_EXCEPTION (pcl::IOException, "PHAT column " << c << ": " << what);
    };
    if (column.dimension < 0 || column.dimension > 2 ||
        column.rows.size() !=
            static_cast<std::size_t> (column.dimension == 0 ? 0 : column.dimension + 1))
      fail ("not a vertex, edge or triangle with the right number of faces");
    for (std::size_t r = 0; r < column.rows.size(); ++r) {
      const std::int64_t row = column.rows[r];
      if (row < 0 || static_cast<std::size_t> (row) >= c ||
          columns[row].dimension != column.dimension - 1 ||
          (r > 0 && row == column.rows[r - 1]))
        fail ("a face is missing, repeated, of the wrong dimension or not earlier");
    }
    const double value = static_cast<double> (c);
    switch (column.dimension) {
    case 0:
      if (!edges.empty() || !triangles.empty())
        fail ("vertices must come before all edges and triangles");
      local_index[c] = static_cast<SimplexIndex> (num_vertices++);
      break;
    case 1:
      local_index[c] = static_cast<SimplexIndex> (edges.size());
      edges.push_back (
          {local_index[column.rows[0]], local_index[column.rows[1]], value});
      break;
    default:
      local_index[c] = static_cast<SimplexIndex> (triangles.size());
      triangles.push_back ({{local_index[column.rows[2]],
                             local_index[column.rows[1]],
                             local_index[column.rows[0]]},
                            value});
    }
  }
  if (hasDuplicates (edges,
                     [] (const FilteredEdge& e) {
                       return std::array<SimplexIndex, 3>{e.source, e.target, 0};
                     }) ||
      hasDuplicates (triangles, [] (const FilteredTriangle& t) { return t.edges; }))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "PHAT matrix lists the same edge or triangle twice");
  try {
    return FilteredComplex (num_vertices, std::move (edges), std::move (triangles));
  }
  catch (const pcl::BadArgumentException& error) {
    PCL_THROW_EXCEPTION (
        pcl::IOException,
        "PHAT matrix is not a simplicial complex: " << errorMessage (error));
  }
}

} // namespace

void
writePHATBoundaryMatrix (std::ostream& out,
                         const FilteredComplex& complex,
                         PHATFormat format)
{
  const std::vector<SimplexRef> order = complex.filtrationOrder();
  std::vector<std::int64_t> edge_position (complex.numEdges());
  for (std::size_t g = 0; g < order.size(); ++g)
    if (order[g].dimension == 1)
      edge_position[order[g].index] = static_cast<std::int64_t> (g);

  if (format == PHATFormat::BINARY)
    writeInt64 (out, static_cast<std::int64_t> (order.size()));
  BoundaryColumn column;
  for (const SimplexRef& simplex : order) {
    column.dimension = simplex.dimension;
    if (simplex.dimension == 0)
      column.rows.clear();
    else if (simplex.dimension == 1) {
      const FilteredEdge& edge = complex.edges()[simplex.index];
      column.rows = {edge.source, edge.target};
    }
    else {
      const auto& ids = complex.triangles()[simplex.index].edges;
      column.rows = {
          edge_position[ids[2]], edge_position[ids[1]], edge_position[ids[0]]};
    }
    writeColumn (out, format, column);
  }
}

void
savePHATBoundaryMatrix (const std::string& path,
                        const FilteredComplex& complex,
                        PHATFormat format)
{
  writeFileAtomically (
      path,
      [&] (std::ostream& out) { writePHATBoundaryMatrix (out, complex, format); },
      format == PHATFormat::BINARY);
}

FilteredComplex
readPHATBoundaryMatrix (std::istream& in, PHATFormat format)
{
  return complexFromColumns (format == PHATFormat::ASCII ? readAsciiColumns (in)
                                                         : readBinaryColumns (in));
}

FilteredComplex
loadPHATBoundaryMatrix (const std::string& path, PHATFormat format)
{
  std::ifstream in (path,
                    format == PHATFormat::BINARY ? std::ios::binary : std::ios::in);
  if (!in)
    PCL_THROW_EXCEPTION (pcl::IOException, "cannot open PHAT matrix " << path);
  return readPHATBoundaryMatrix (in, format);
}

} // namespace tda
} // namespace pcl
