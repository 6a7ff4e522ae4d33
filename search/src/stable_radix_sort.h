#pragma once

// A stable radix sort, for the sorts of this module that order many items by a
// number: edges by length (sortEdges()) and points by their coordinates
// (sortCanonically()). Private to the module's sources, which are built with OpenMP.

#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/search/radius_edges.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace pcl {
namespace tda {

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

/** orderedBits() of a float. */
inline std::uint32_t
orderedBits (float value)
{
  std::uint32_t bits;
  const float normal = value + 0.0f;
  std::memcpy (&bits, &normal, sizeof (bits));
  const std::uint32_t negative = ~((bits >> 31) - 1);
  return bits ^ (negative | (std::uint32_t{1} << 31));
}

/** Sorts \a items by \a key_of (an item's unsigned 64-bit key), keeping the order
 * of items with equal keys: byte by byte from the lowest (a byte that is the same
 * in every key is skipped), each pass over chunks of the items in parallel (a
 * chunk's items go, in their order, after those of the chunks before with the same
 * byte). The result does not depend on the threads. \a scratch is the memory the
 * passes write to, grown to the items' size: one for several sorts of the same
 * items. */
template <typename Item, typename KeyOf>
void
stableRadixSort (std::vector<Item>& items,
                 const KeyOf& key_of,
                 unsigned int threads,
                 std::vector<Item>& scratch)
{
  constexpr int DIGITS = 8; // bytes of a key, each a pass
  using DigitCounts = std::array<std::size_t, 256>;
  const auto digit_of = [&key_of] (const Item& item, int digit) {
    return static_cast<unsigned> (key_of (item) >> (8 * digit)) & 0xffu;
  };
  const std::size_t n = items.size();
  if (n < 2)
    return;
  constexpr std::size_t ITEMS_PER_CHUNK = 1 << 16;
  const auto threads_used = resolveThreads (threads);
  const auto chunks = static_cast<std::int64_t> (std::clamp<std::size_t> (
      n / ITEMS_PER_CHUNK, 1, static_cast<std::size_t> (threads_used)));
  const auto chunk_begin = [n, chunks] (std::int64_t chunk) {
    return n * static_cast<std::size_t> (chunk) / static_cast<std::size_t> (chunks);
  };
  std::vector<std::array<DigitCounts, DIGITS>> chunk_totals (chunks);
#pragma omp parallel for schedule(static, 1) num_threads(threads_used) if (chunks > 1)
  for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
    auto& totals = chunk_totals[chunk];
    for (auto& counts : totals)
      counts.fill (0);
    for (std::size_t i = chunk_begin (chunk), end = chunk_begin (chunk + 1); i < end;
         ++i) {
      const std::uint64_t key = key_of (items[i]);
      for (int digit = 0; digit < DIGITS; ++digit)
        ++totals[digit][(key >> (8 * digit)) & 0xffu];
    }
  }

  if (scratch.size() < n)
    scratch = largeVector<Item> (n);
  Item* from = items.data();
  Item* to = scratch.data();
  std::vector<DigitCounts> offsets (chunks);
  for (int digit = 0; digit < DIGITS; ++digit) {
    const auto all_alike = [&] (unsigned byte) {
      std::size_t count = 0;
      for (const auto& totals : chunk_totals)
        count += totals[digit][byte];
      return count == n;
    };
    if (all_alike (digit_of (items[0], digit)))
      continue; // the pass would change nothing
    // The counts per chunk of the order the pass starts from (one chunk: the totals).
    if (chunks == 1)
      offsets[0] = chunk_totals[0][digit];
    else {
#pragma omp parallel for schedule(static, 1) num_threads(threads_used)
      for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
        offsets[chunk].fill (0);
        for (std::size_t i = chunk_begin (chunk), end = chunk_begin (chunk + 1);
             i < end;
             ++i)
          ++offsets[chunk][digit_of (from[i], digit)];
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
      for (std::size_t i = chunk_begin (chunk), end = chunk_begin (chunk + 1); i < end;
           ++i)
        to[offsets[chunk][digit_of (from[i], digit)]++] = from[i];
    std::swap (from, to);
  }
  if (from != items.data())
    std::copy (from, from + n, items.data());
}

} // namespace tda
} // namespace pcl
