#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

namespace pcl {
namespace tda {

namespace {

extern "C" void
removeTemporaryFilesAndEnd (int signal)
{
  removeTemporaryFiles();
  std::raise (signal); // the default action again (SA_RESETHAND)
}

/** True when writing to \a a and to \a b (links resolved) would write one file. */
bool
sameTarget (const std::string& a, const std::string& b)
{
  // Absolute first: a relative path to a file not there yet stays relative in
  // weakly_canonical() (o.pcd), unless it starts with a folder that is (./o.pcd).
  std::error_code error_a, error_b;
  const auto path_a = std::filesystem::weakly_canonical (
      std::filesystem::absolute (linkTarget (a)), error_a);
  const auto path_b = std::filesystem::weakly_canonical (
      std::filesystem::absolute (linkTarget (b)), error_b);
  return (!error_a && !error_b && path_a == path_b) || isSameFile (a, b);
}

/** Checks that \a path can be replaced by a new file. */
void
checkWritable (const std::string& path)
{
  const std::string target = linkTarget (path);
  const std::filesystem::path target_path (target);
  std::string folder = target_path.parent_path().string();
  if (folder.empty())
    folder = ".";
  struct stat status;
  if (::stat (folder.c_str(), &status) != 0)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write "
                             << path << ": the folder " << folder
                             << (errno == ENOENT
                                     ? " does not exist"
                                     : ": " + std::string (std::strerror (errno))));
  if (!S_ISDIR (status.st_mode))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write " << path << ": " << folder
                                         << " is not a folder");
  if (::access (folder.c_str(), W_OK | X_OK) != 0)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write " << path << ": the folder " << folder
                                         << " is not writable");
  const long max_name = ::pathconf (folder.c_str(), _PC_NAME_MAX);
  const std::size_t name_length = target_path.filename().string().size();
  if (max_name > 0 && name_length > static_cast<std::size_t> (max_name))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write " << path << ": its file name has "
                                         << name_length << " bytes, the folder takes "
                                         << max_name << " at most");
  if (::stat (target.c_str(), &status) == 0) {
    if (S_ISDIR (status.st_mode))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "cannot write " << path << ": it is a directory");
    if (!S_ISREG (status.st_mode))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "cannot write " << path << ": it is not a regular file");
  }
}

} // namespace

ToolOutputs::ToolOutputs (const std::string& input, const std::vector<Output>& outputs)
: ToolOutputs (std::vector<std::string>{input}, outputs)
{}

ToolOutputs::ToolOutputs (const std::vector<std::string>& inputs,
                          const std::vector<Output>& outputs)
{
  std::vector<const Output*> checked;
  for (const Output& output : outputs) {
    if (output.path.empty())
      continue;
    for (const std::string& input : inputs)
      if (!input.empty() && sameTarget (output.path, input))
        PCL_THROW_EXCEPTION (pcl::IOException,
                             "refusing to overwrite the input file "
                                 << input << " (" << output.option << ")");
    for (const Output* other : checked)
      if (sameTarget (output.path, other->path))
        PCL_THROW_EXCEPTION (pcl::IOException,
                             other->option << " and " << output.option
                                           << " name the same file " << output.path);
    checkWritable (output.path);
    checked.push_back (&output);
    files_.push_back (std::make_unique<FileReplacement> (output.path));
  }
}

const std::string&
ToolOutputs::temporary (const std::string& path) const
{
  for (const auto& file : files_)
    if (file->path() == path)
      return file->temporary();
  PCL_THROW_EXCEPTION (pcl::BadArgumentException, path << " is not an output");
}

void
ToolOutputs::commit()
{
  for (const auto& file : files_)
    file->commit();
}

std::string
ToolOutputs::message (const std::exception& error) const
{
  std::string text = errorMessage (error);
  for (const auto& file : files_)
    for (std::size_t at = 0;
         (at = text.find (file->temporary(), at)) != std::string::npos;
         at += file->path().size())
      text.replace (at, file->temporary().size(), file->path());
  return text;
}

void
removeTemporaryFilesOnSignals ()
{
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current;
    if (::sigaction (signal, nullptr, &current) != 0 || current.sa_handler == SIG_IGN)
      continue; // as nohup and background jobs set them
    struct sigaction action = {};
    action.sa_handler = removeTemporaryFilesAndEnd;
    sigemptyset (&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    ::sigaction (signal, &action, nullptr);
  }
  // Past the file size limit (ulimit -f) a write then fails with EFBIG, which the
  // tools report, instead of ending the process with a core dump.
  std::signal (SIGXFSZ, SIG_IGN);
}

} // namespace tda
} // namespace pcl
