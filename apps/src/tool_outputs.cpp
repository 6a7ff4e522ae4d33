#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/exceptions.h>

#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
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
  struct stat status;
  if (::stat (target.c_str(), &status) == 0) {
    if (S_ISDIR (status.st_mode))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "cannot write " << path << ": it is a directory");
    if (!S_ISREG (status.st_mode))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "cannot write " << path << ": it is not a regular file");
  }
  std::string folder = std::filesystem::path (target).parent_path().string();
  if (folder.empty())
    folder = ".";
  if (::stat (folder.c_str(), &status) != 0 || !S_ISDIR (status.st_mode))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write " << path << ": the folder " << folder
                                         << " does not exist");
  if (::access (folder.c_str(), W_OK | X_OK) != 0)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write " << path << ": the folder " << folder
                                         << " is not writable");
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
}

} // namespace tda
} // namespace pcl
