#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The folder a tool writes a data set of many files into (e.g. the views of
 * pcl_tda_generate shapes and their manifest), all or nothing: the files are
 * written to a staging folder inside it, then moved in, the index (the manifest)
 * last, once every one is written. A run that fails (the object is destroyed
 * before commit()) leaves the folder as it was, and removes it when it created it;
 * the staging folder of a run killed by a signal is removed by the next run into the
 * folder.
 * Never replaces a file: refuses a folder that already holds the index or one of
 * the files. */
class DataSetFolder {
public:
  /** \brief Checks \a folder, creates it when missing, and the staging folder.
   * \param[in] folder the folder of the data set; its parent must exist
   * \param[in] names the files that will be written into it
   * \param[in] index the file that tells what the data set holds, written last
   * \throws pcl::IOException saying why the data set cannot be written there */
  DataSetFolder (const std::string& folder,
                 const std::vector<std::string>& names,
                 const std::string& index);

  DataSetFolder (const DataSetFolder&) = delete;
  DataSetFolder&
  operator= (const DataSetFolder&) = delete;

  /** \brief Removes what a run that did not commit wrote. */
  ~DataSetFolder();

  /** \brief Where to write the file \a name of the data set. */
  std::string
  staged (const std::string& name) const;

  /** \brief Moves the files \a names, then the index, from the staging folder into
   * the folder.
   * \throws pcl::IOException naming the file that could not be moved */
  void
  commit (const std::vector<std::string>& names);

private:
  std::filesystem::path folder_, staging_;
  std::string index_;
  bool created_ = false, committed_ = false;
  std::vector<std::string> moved_;
};

} // namespace tda
} // namespace pcl
