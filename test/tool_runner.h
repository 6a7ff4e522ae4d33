#pragma once

// Running a command-line tool from a test: its exit code and output, and
// per-test temporary file names.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace pcl {
namespace tda {
namespace test {

struct RunResult {
  int exit_code;
  std::string output; // stdout and stderr
};

/** Runs \a command in a shell and collects its exit code and output. */
inline RunResult
run (const std::string& command)
{
  RunResult result{-1, ""};
  FILE* pipe = ::popen ((command + " 2>&1").c_str(), "r");
  if (!pipe)
    return result;
  std::array<char, 4096> buffer;
  std::size_t read;
  while ((read = std::fread (buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append (buffer.data(), read);
  const int status = ::pclose (pipe);
  result.exit_code = WIFEXITED (status) ? WEXITSTATUS (status) : -1;
  return result;
}

/** A temporary file name of its own for the running test and process (tests run
 * in parallel, and two builds' tests may run at once). */
inline std::string
temporaryPath (const std::string& prefix, const std::string& name)
{
  return testing::TempDir() + prefix + "_" +
         testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
         std::to_string (::getpid()) + "_" + name;
}

/** A fresh, empty folder of its own for the running test. */
inline std::string
temporaryFolder (const std::string& prefix)
{
  const std::string folder = temporaryPath (prefix, "files");
  std::filesystem::remove_all (folder);
  std::filesystem::create_directories (folder);
  return folder;
}

inline bool
exists (const std::string& path)
{
  return std::ifstream (path).good();
}

/** Whether the file \a path starts with the PNG signature. */
inline bool
isPNGFile (const std::string& path)
{
  std::ifstream file (path, std::ios::binary);
  char signature[8] = {};
  file.read (signature, 8);
  return file && std::string (signature, 8) == "\x89PNG\r\n\x1a\n";
}

} // namespace test
} // namespace tda
} // namespace pcl
