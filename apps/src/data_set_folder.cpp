#include <pcl/tda/apps/data_set_folder.h>
#include <pcl/exceptions.h>

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <system_error>

namespace pcl {
namespace tda {

namespace {

constexpr char STAGING_PREFIX[] = ".staging.";

/** Removes the staging folders in \a folder of runs that ended without removing
 * theirs (killed by a signal): those whose process is gone. */
void
removeStaleStaging (const std::filesystem::path& folder)
{
  namespace fs = std::filesystem;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator (folder, error)) {
    const std::string name = entry.path().filename().string();
    const std::string digits =
        name.substr (std::min (name.size(), sizeof (STAGING_PREFIX) - 1));
    if (name.rfind (STAGING_PREFIX, 0) != 0 || digits.empty() ||
        digits.find_first_not_of ("0123456789") != std::string::npos ||
        digits.size() > 9)
      continue;
    const auto process = static_cast<pid_t> (std::stol (digits));
    if (process != ::getpid() && ::kill (process, 0) != 0 && errno == ESRCH)
      fs::remove_all (entry.path(), error);
  }
}

} // namespace

DataSetFolder::DataSetFolder (const std::string& folder,
                              const std::vector<std::string>& names,
                              const std::string& index)
: folder_ (folder), index_ (index)
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status (folder_, error);
  if (fs::exists (status) && !fs::is_directory (status))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write the data set to " << folder
                                                         << ": it is not a folder");
  if (fs::exists (fs::symlink_status (folder_ / index_, error)))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         folder << " already holds a data set (" << index_
                                << "): refusing to mix two; choose another folder");
  for (const std::string& name : names)
    if (fs::exists (fs::symlink_status (folder_ / name, error)))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           folder << " already holds " << name
                                  << ": refusing to replace it");
  if (!fs::exists (status)) {
    if (!fs::create_directory (folder_, error))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "cannot create the folder " << folder << ": "
                                                       << error.message());
    created_ = true;
  }
  removeStaleStaging (folder_);
  staging_ = folder_ / (STAGING_PREFIX + std::to_string (::getpid()));
  if (!fs::create_directory (staging_, error))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write to the folder " << folder << ": "
                                                       << error.message());
}

DataSetFolder::~DataSetFolder()
{
  std::error_code error;
  std::filesystem::remove_all (staging_, error);
  if (committed_)
    return;
  for (const std::string& name : moved_)
    std::filesystem::remove (folder_ / name, error);
  if (created_)
    std::filesystem::remove (folder_, error);
}

std::string
DataSetFolder::staged (const std::string& name) const
{
  return (staging_ / name).string();
}

void
DataSetFolder::commit (const std::vector<std::string>& names)
{
  std::vector<std::string> all = names;
  all.push_back (index_);
  for (const std::string& name : all) {
    std::error_code error;
    std::filesystem::rename (staging_ / name, folder_ / name, error);
    if (error)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "cannot move " << name << " into " << folder_.string()
                                          << ": " << error.message());
    moved_.push_back (name);
  }
  committed_ = true;
}

} // namespace tda
} // namespace pcl
