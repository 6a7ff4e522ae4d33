#include <pcl/tda/common/atomic_file.h>
#include <pcl/exceptions.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace pcl {
namespace tda {

void
replaceFileAtomically (
    const std::string& path,
    const std::function<bool (const std::string& temporary)>& write_file)
{
  const std::string temporary = path + ".tmp." + std::to_string (::getpid());
  bool written = false;
  try {
    written = write_file (temporary);
  }
  catch (...) {
    std::remove (temporary.c_str());
    throw;
  }
  if (!written) {
    const int error = errno;
    std::remove (temporary.c_str());
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write " << path << ": " << std::strerror (error));
  }
  if (std::rename (temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove (temporary.c_str());
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot replace " << path << ": " << std::strerror (error));
  }
}

void
writeFileAtomically (const std::string& path,
                     const std::function<void (std::ostream&)>& writer,
                     bool binary)
{
  replaceFileAtomically (path, [&] (const std::string& temporary) {
    std::ofstream out (temporary, binary ? std::ios::binary : std::ios::out);
    if (!out)
      return false;
    writer (out);
    out.flush();
    return static_cast<bool> (out);
  });
}

bool
isSameFile (const std::string& a, const std::string& b)
{
  struct stat stat_a, stat_b;
  if (::stat (a.c_str(), &stat_a) != 0 || ::stat (b.c_str(), &stat_b) != 0)
    return false;
  return stat_a.st_dev == stat_b.st_dev && stat_a.st_ino == stat_b.st_ino;
}

} // namespace tda
} // namespace pcl
