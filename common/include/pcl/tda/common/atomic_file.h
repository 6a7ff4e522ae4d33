#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace pcl {
namespace tda {

/** \brief The file that writing to \a path replaces: \a path itself or, when \a path
 * is a symbolic link, the file it points to (link after link, whether that file
 * exists or not), so that replacing the file keeps the link. */
std::string
linkTarget (const std::string& path);

/** \brief A file being replaced so that readers see either its old content or the
 * whole new content, never a part: the new content goes to temporary(), beside the
 * file, and commit() renames it onto the file. A symbolic link at \a path stays a
 * link (the file it points to is replaced) and the replaced file's permission bits
 * are kept. The destructor removes a temporary file that was not committed; so
 * does removeTemporaryFiles(), for a process ended by a signal. */
class FileReplacement {
public:
  /** \brief Names the temporary file; creates nothing. */
  explicit FileReplacement (const std::string& path);
  ~FileReplacement();
  FileReplacement (const FileReplacement&) = delete;
  FileReplacement&
  operator= (const FileReplacement&) = delete;

  /** \brief The path given, as named in messages. */
  const std::string&
  path () const
  {
    return path_;
  }

  /** \brief The temporary file to write the new content to. */
  const std::string&
  temporary () const
  {
    return temporary_;
  }

  /** \brief Gives the temporary file the replaced file's permission bits and renames
   * it onto that file.
   * \throws pcl::IOException naming path() when the rename fails (the temporary file
   * is removed and the file left as it was) */
  void
  commit ();

private:
  std::string path_;
  std::string target_;
  std::string temporary_;
  bool committed_ = false;
};

/** \brief Removes the temporary files of all FileReplacement objects alive (not yet
 * committed or destroyed): for a handler of the signals that end a process
 * (SIGINT, SIGTERM), which skips the destructors. Async-signal-safe. */
void
removeTemporaryFiles () noexcept;

/** \brief Replaces a file at once (see FileReplacement): \a write_file writes the
 * temporary file whose name it is given, which then replaces \a path. \a write_file
 * throws pcl::IOException or returns false on failure.
 * \throws pcl::IOException when the file cannot be written (the temporary file is
 * removed and \a path is left as it was)
 */
void
replaceFileAtomically (
    const std::string& path,
    const std::function<bool (const std::string& temporary)>& write_file);

/** \brief replaceFileAtomically() for content written to a stream by \a writer. */
void
writeFileAtomically (const std::string& path,
                     const std::function<void (std::ostream&)>& writer,
                     bool binary = false);

/** \brief True when \a a and \a b name the same existing file (after resolving
 * links), so that a tool can refuse to overwrite its input. */
bool
isSameFile (const std::string& a, const std::string& b);

} // namespace tda
} // namespace pcl
