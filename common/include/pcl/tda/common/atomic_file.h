#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace pcl {
namespace tda {

/** \brief Replaces a file so that readers see either its old content or the whole
 * new content, never a part: \a write_file writes a temporary file beside \a path
 * (whose name it is given), which then replaces \a path. \a write_file throws
 * pcl::IOException or returns false on failure.
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
