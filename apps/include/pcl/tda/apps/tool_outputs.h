#pragma once

#include <pcl/tda/common/atomic_file.h>

#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Makes SIGINT, SIGTERM and SIGHUP (where not ignored) remove the temporary
 * files of the outputs being written (removeTemporaryFiles()) before they end the
 * process as they would have: an interrupted tool leaves no file behind. Ignores
 * SIGXFSZ, so that a write past the file size limit fails as a write (EFBIG). */
void
removeTemporaryFilesOnSignals ();

/** \brief The output files of a tool run: checked before the work, written to
 * temporary files and committed together once everything succeeded, so that a
 * failed run changes no output. Links and permission bits of existing outputs are
 * kept (see FileReplacement). */
class ToolOutputs {
public:
  /** \brief An output file and the option that names it ("-svg"; "output" for a
   * positional argument), for messages. */
  struct Output {
    std::string option;
    std::string path;
  };

  /** \brief Checks the outputs (those of empty path are skipped): each one in an
   * existing, writable folder, not a directory or another kind of file, not the
   * file \a input (also through a link; "" for none), no two the same file.
   * \throws pcl::IOException naming the file */
  ToolOutputs (const std::string& input, const std::vector<Output>& outputs);

  /** \brief The same for a tool with several inputs: no output may be one of
   * \a inputs. */
  ToolOutputs (const std::vector<std::string>& inputs,
               const std::vector<Output>& outputs);

  /** \brief The temporary file to write the new content of the output \a path to.
   * \throws pcl::BadArgumentException when \a path is no output */
  const std::string&
  temporary (const std::string& path) const;

  /** \brief Replaces each output with its temporary file.
   * \throws pcl::IOException naming the file that could not be replaced */
  void
  commit ();

  /** \brief The message of \a error (errorMessage()) with each temporary file
   * named by its output, as the user named it: for a failed write. */
  std::string
  message (const std::exception& error) const;

private:
  std::vector<std::unique_ptr<FileReplacement>> files_;
};

} // namespace tda
} // namespace pcl
