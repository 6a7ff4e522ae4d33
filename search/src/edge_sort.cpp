#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/search/radius_edges.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace pcl {
namespace tda {

namespace {

constexpr int DIGITS = 8; // bytes of a value's key, each a pass
using DigitCounts = std::array<std::size_t, 256>;

/** The bits of \a value as an unsigned integer in the order of the values (0 and -0
 * alike: adding 0 makes -0 into 0), without a branch. */
inline std::uint64_t
orderedBits (double value)
{
  std::uint64_t bits;
  const double normal = value + 0.0;
  std::memcpy (&bits, &normal, sizeof (bits));
  const std::uint64_t negative = ~((bits >> 63) - 1); // all ones for a negative value
  return bits ^ (negative | (std::uint64_t{1} << 63));
}

inline unsigned
digitOf (const FilteredEdge& edge, int digit)
{
  return static_cast<unsigned> (orderedBits (edge.value) >> (8 * digit)) & 0xffu;
}

} // namespace

void
sortEdges (std::vector<FilteredEdge>& edges, unsigned int threads)
{
  // A stable radix sort by value, byte by byte from the lowest (a byte that is the
  // same in every value is skipped), each pass over chunks of the edges in parallel
  // (a chunk's edges go, in their order, after those of the chunks before with the
  // same byte); then the runs of equal values by their ends. The order is strict and
  // total, so the result does not depend on the threads.
  const std::size_t n = edges.size();
  if (n < 2)
    return;
  constexpr std::size_t EDGES_PER_CHUNK = 1 << 16;
  const auto threads_used = resolveThreads (threads);
  const auto chunks = static_cast<std::int64_t> (std::clamp<std::size_t> (
      n / EDGES_PER_CHUNK, 1, static_cast<std::size_t> (threads_used)));
  const auto chunkBegin = [n, chunks] (std::int64_t chunk) {
    return n * static_cast<std::size_t> (chunk) / static_cast<std::size_t> (chunks);
  };
  std::vector<std::array<DigitCounts, DIGITS>> chunk_totals (chunks);
#pragma omp parallel for schedule(static, 1) num_threads(threads_used) if (chunks > 1)
  for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
    auto& totals = chunk_totals[chunk];
    for (auto& counts : totals)
      counts.fill (0);
    for (std::size_t i = chunkBegin (chunk), end = chunkBegin (chunk + 1); i < end;
         ++i) {
      const std::uint64_t bits = orderedBits (edges[i].value);
      for (int digit = 0; digit < DIGITS; ++digit)
        ++totals[digit][(bits >> (8 * digit)) & 0xffu];
    }
  }

  auto buffer = largeVector<FilteredEdge> (n);
  FilteredEdge* from = edges.data();
  FilteredEdge* to = buffer.data();
  std::vector<DigitCounts> offsets (chunks);
  for (int digit = 0; digit < DIGITS; ++digit) {
    const auto all_alike = [&] (unsigned byte) {
      std::size_t count = 0;
      for (const auto& totals : chunk_totals)
        count += totals[digit][byte];
      return count == n;
    };
    if (all_alike (digitOf (edges[0], digit)))
      continue; // the pass would change nothing
    // The counts per chunk of the order the pass starts from (one chunk: the totals).
    if (chunks == 1)
      offsets[0] = chunk_totals[0][digit];
    else {
#pragma omp parallel for schedule(static, 1) num_threads(threads_used)
      for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
        offsets[chunk].fill (0);
        for (std::size_t i = chunkBegin (chunk), end = chunkBegin (chunk + 1); i < end;
             ++i)
          ++offsets[chunk][digitOf (from[i], digit)];
      }
    }
    std::size_t position = 0;
    for (unsigned byte = 0; byte < 256; ++byte)
      for (DigitCounts& of_chunk : offsets) {
        const std::size_t count = of_chunk[byte];
        of_chunk[byte] = position;
        position += count;
      }
#pragma omp parallel for schedule(static, 1) num_threads(threads_used) if (chunks > 1)
    for (std::int64_t chunk = 0; chunk < chunks; ++chunk)
      for (std::size_t i = chunkBegin (chunk), end = chunkBegin (chunk + 1); i < end;
           ++i)
        to[offsets[chunk][digitOf (from[i], digit)]++] = from[i];
    std::swap (from, to);
  }
  if (from != edges.data())
    std::copy (from, from + n, edges.data());
  for (std::size_t first = 0, last = 0; first < n; first = last) {
    for (last = first + 1; last < n && edges[last].value == edges[first].value;)
      ++last;
    if (last - first > 1)
      std::sort (edges.begin() + first, edges.begin() + last, edgeFiltrationLess);
  }
}

} // namespace tda
} // namespace pcl
