#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace pcl {
namespace tda {

/** \brief Writes a file so that readers see either its old content or the whole
 * new content, never a part: \a writer fills a temporary file beside \a path,
 * which then replaces \a path.
 * \throws pcl::IOException when the file cannot be written (the temporary file is
 * removed and \a path is left as it was)
 */
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
