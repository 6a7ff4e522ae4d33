#include <pcl/tda/common/atomic_file.h>
#include <pcl/exceptions.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace pcl {
namespace tda {

namespace {

/** The temporary files of the live FileReplacement objects, for
 * removeTemporaryFiles(): a fixed table, which a signal handler can read at any
 * moment. */
std::array<std::atomic<const char*>, 64> live_temporaries{};

/** Puts \a to in the first slot of live_temporaries that holds \a from (nullptr: a
 * free slot); none when there is no such slot (a table full: that temporary file is
 * not removed on a signal). */
void
replaceLiveTemporary (const char* from, const char* to)
{
  for (auto& slot : live_temporaries) {
    const char* expected = from;
    if (slot.compare_exchange_strong (expected, to))
      return;
  }
}

/** The temporary files named so far by this process: a part of their names. */
std::atomic<unsigned> temporaries_named{0};

/** The longest name of a file in a folder (NAME_MAX on Linux's file systems). */
constexpr std::size_t MAX_FILE_NAME = 255;

/** A temporary file beside \a target, of a name no other has: \a target's with
 * ".tmp.<process>.<number>" after it, \a target's part cut short where the whole
 * would be longer than a file name may be. */
std::string
temporaryBeside (const std::string& target)
{
  const std::string suffix = ".tmp." + std::to_string (::getpid()) + "." +
                             std::to_string (temporaries_named++);
  const std::size_t slash = target.rfind ('/');
  const std::size_t name_begin = slash == std::string::npos ? 0 : slash + 1;
  const std::size_t name_kept =
      std::min (target.size() - name_begin, MAX_FILE_NAME - suffix.size());
  return target.substr (0, name_begin + name_kept) + suffix;
}

} // namespace

std::string
linkTarget (const std::string& path)
{
  namespace fs = std::filesystem;
  constexpr int MAX_LINKS = 40; // as Linux, which then fails with ELOOP
  fs::path target = path;
  std::error_code error;
  for (int links = 0; links < MAX_LINKS && fs::is_symlink (target, error); ++links) {
    const fs::path next = fs::read_symlink (target, error);
    if (error)
      break;
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  return target.string();
}

FileReplacement::FileReplacement (const std::string& path)
: path_ (path), target_ (linkTarget (path)), temporary_ (temporaryBeside (target_))
{
  replaceLiveTemporary (nullptr, temporary_.c_str());
}

FileReplacement::~FileReplacement()
{
  replaceLiveTemporary (temporary_.c_str(), nullptr);
  if (!committed_)
    std::remove (temporary_.c_str());
}

void
FileReplacement::commit()
{
  struct stat replaced;
  if (::stat (target_.c_str(), &replaced) == 0)
    ::chmod (temporary_.c_str(), replaced.st_mode & 07777);
  if (std::rename (temporary_.c_str(), target_.c_str()) != 0)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot replace " << path_ << ": " << std::strerror (errno));
  committed_ = true;
  replaceLiveTemporary (temporary_.c_str(), nullptr);
}

void
removeTemporaryFiles () noexcept
{
  for (auto& slot : live_temporaries)
    if (const char* path = slot.load())
      ::unlink (path);
}

void
replaceFileAtomically (
    const std::string& path,
    const std::function<bool (const std::string& temporary)>& write_file)
{
  FileReplacement file (path);
  if (!write_file (file.temporary()))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write " << path << ": " << std::strerror (errno));
  file.commit();
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
