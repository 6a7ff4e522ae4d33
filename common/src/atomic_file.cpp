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
writeFileAtomically (const std::string& path,
                     const std::function<void (std::ostream&)>& writer,
                     bool binary)
{
  const std::string temporary = path + ".tmp." + std::to_string (::getpid());
  {
    std::ofstream out (temporary, binary ? std::ios::binary : std::ios::out);
    if (!out)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "cannot write " << path << ": " << std::strerror (errno));
    try {
      writer (out);
    }
    catch (...) {
      out.close();
      std::remove (temporary.c_str());
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::remove (temporary.c_str());
      PCL_THROW_EXCEPTION (pcl::IOException, "writing " << path << " failed");
    }
  }
  if (std::rename (temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove (temporary.c_str());
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot replace " << path << ": " << std::strerror (error));
  }
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
