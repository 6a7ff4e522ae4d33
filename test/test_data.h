#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace pcl {
namespace tda {
namespace test {

/** Path of a real scan of ../shared/data (see its README). */
inline std::string
dataFile (const std::string& name)
{
  return std::string (PCL_TDA_DATA_DIR) + "/" + name;
}

inline bool
haveDataFile (const std::string& name)
{
  return std::ifstream (dataFile (name)).good();
}

} // namespace test
} // namespace tda
} // namespace pcl

/** Skips the current test, saying why, when a real scan is absent. */
#define PCL_TDA_REQUIRE_DATA(name)                                                     \
  if (!pcl::tda::test::haveDataFile (name))                                            \
  GTEST_SKIP() << "skipped: " << pcl::tda::test::dataFile (name)                       \
               << " is absent (the real scans live in ../shared/data)"
