#include <pcl/tda/apps/data_set_folder.h>
#include <pcl/exceptions.h>

#include <unistd.h>

#include <system_error>

namespace pcl {
namespace tda {

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
  staging_ = folder_ / (".staging." + std::to_string (::getpid()));
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
