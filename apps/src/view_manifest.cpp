#include <pcl/tda/apps/csv_fields.h>
#include <pcl/tda/apps/view_manifest.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace pcl {
namespace tda {
namespace {

/** A view row before the categories and instances are numbered. */
struct Row {
  std::string path, file, category, instance, name;
  std::size_t line = 0;
};

[[noreturn]] void
refuse (const std::string& manifest, std::size_t line, const std::string& problem)
{
  PCL_THROW_EXCEPTION (pcl::IOException,
                       manifest << (line > 0 ? ": line " + std::to_string (line) : "")
                                << ": " << problem);
}

/** The position of each manifest column in the header \a fields. */
std::vector<std::size_t>
columnPositions (const std::string& manifest, const std::vector<std::string>& fields)
{
  std::vector<std::size_t> positions;
  for (const char* column : MANIFEST_COLUMNS) {
    const auto found = std::find (fields.begin(), fields.end(), column);
    if (found == fields.end())
      refuse (manifest,
              1,
              std::string ("the header has no '") + column +
                  "' column (it needs path,category,instance,view)");
    if (std::find (found + 1, fields.end(), column) != fields.end())
      refuse (manifest, 1, std::string ("the header names '") + column + "' twice");
    positions.push_back (static_cast<std::size_t> (found - fields.begin()));
  }
  return positions;
}

/** The view file of \a path, relative to \a folder unless absolute, checked. */
std::string
viewFile (const std::string& manifest,
          std::size_t line,
          const std::filesystem::path& folder,
          const std::string& path)
{
  const std::filesystem::path given (path);
  const std::string file = (given.is_absolute() ? given : folder / given).string();
  if (given.extension() != ".pcd")
    refuse (manifest, line, "the view " + path + " is not a .pcd file");
  std::error_code error;
  if (!std::filesystem::is_regular_file (file, error))
    refuse (manifest,
            line,
            "the view file " + path +
                (std::filesystem::exists (file, error) ? " is not a regular file"
                                                       : " does not exist") +
                (given.is_absolute() ? "" : " (looked for " + file + ")"));
  return file;
}

/** The rows of the manifest, checked one by one. */
std::vector<Row>
readRows (const std::string& manifest)
{
  std::error_code error;
  if (!std::filesystem::is_regular_file (manifest, error))
    refuse (manifest,
            0,
            std::filesystem::exists (manifest, error) ? "not a regular file"
                                                      : "no such file");
  std::ifstream in (manifest);
  if (!in)
    refuse (manifest, 0, "cannot be read");
  skipByteOrderMark (in);
  const std::filesystem::path folder = std::filesystem::path (manifest).parent_path();
  std::vector<Row> rows;
  std::vector<std::size_t> columns;
  std::size_t header_fields = 0;
  std::string line;
  for (std::size_t number = 1; std::getline (in, line); ++number) {
    if (line.find_first_not_of (" \t\r") == std::string::npos) {
      if (number == 1)
        refuse (manifest, 1, "the first line must name the columns");
      continue;
    }
    std::vector<std::string> fields;
    try {
      fields = splitCSVLine (line);
    }
    catch (const pcl::PCLException& bad) {
      refuse (manifest, number, errorMessage (bad));
    }
    if (number == 1) {
      columns = columnPositions (manifest, fields);
      header_fields = fields.size();
      continue;
    }
    if (fields.size() != header_fields)
      refuse (manifest,
              number,
              std::to_string (fields.size()) + " fields, the header has " +
                  std::to_string (header_fields));
    Row row;
    std::string* values[] = {&row.path, &row.category, &row.instance, &row.name};
    for (std::size_t k = 0; k < columns.size(); ++k) {
      *values[k] = fields[columns[k]];
      if (values[k]->empty())
        refuse (
            manifest, number, std::string ("the ") + MANIFEST_COLUMNS[k] + " is empty");
    }
    row.file = viewFile (manifest, number, folder, row.path);
    row.line = number;
    rows.push_back (row);
  }
  if (in.bad())
    refuse (manifest, 0, "read error");
  if (columns.empty())
    refuse (manifest,
            0,
            "the file is empty (it needs a header line: "
            "path,category,instance,view)");
  if (rows.empty())
    refuse (manifest, 0, "no views are listed");
  return rows;
}

/** Refuses a file or a (category, instance, view) listed twice. */
void
checkUnique (const std::string& manifest, const std::vector<Row>& rows)
{
  std::map<std::string, std::size_t> files;
  std::map<std::tuple<std::string, std::string, std::string>, std::size_t> names;
  for (const Row& row : rows) {
    const std::string canonical = std::filesystem::weakly_canonical (row.file).string();
    const auto file = files.emplace (canonical, row.line);
    if (!file.second)
      refuse (manifest,
              row.line,
              "the view file " + row.path + " is already listed on line " +
                  std::to_string (file.first->second));
    const auto name = names.emplace (
        std::make_tuple (row.category, row.instance, row.name), row.line);
    if (!name.second)
      refuse (manifest,
              row.line,
              "view " + row.name + " of instance " + row.instance + " of category " +
                  row.category + " is already listed on line " +
                  std::to_string (name.first->second));
  }
}

} // namespace

ViewManifest
readViewManifest (const std::string& path)
{
  std::vector<Row> rows = readRows (path);
  checkUnique (path, rows);
  // In a canonical order, (category, instance, view) being unique: the rows' order
  // in the file does not change the splits, the training or the scores.
  std::sort (rows.begin(), rows.end(), [] (const Row& a, const Row& b) {
    return std::tie (a.category, a.instance, a.name) <
           std::tie (b.category, b.instance, b.name);
  });

  ViewManifest manifest;
  std::map<std::string, std::map<std::string, std::vector<std::size_t>>> grouped;
  for (std::size_t i = 0; i < rows.size(); ++i)
    grouped[rows[i].category][rows[i].instance].push_back (i);
  if (grouped.size() < 2)
    refuse (path,
            0,
            "all views are of one category (" + grouped.begin()->first +
                "): classification needs at least 2");
  manifest.views.resize (rows.size());
  for (const auto& [category, instances] : grouped) {
    if (instances.size() < 2)
      refuse (path,
              0,
              "category " + category + " has only one instance (" +
                  instances.begin()->first +
                  "): the protocol holds one instance of each category out for "
                  "testing and trains on the others, so each category needs at "
                  "least 2");
    const std::size_t category_index = manifest.categories.size();
    manifest.categories.push_back (category);
    manifest.category_instances.emplace_back();
    for (const auto& [name, view_rows] : instances) {
      const std::size_t instance_index = manifest.instances.size();
      manifest.category_instances.back().push_back (instance_index);
      manifest.instances.push_back ({category_index, name, view_rows});
      for (const std::size_t i : view_rows)
        manifest.views[i] = {rows[i].path,
                             rows[i].file,
                             rows[i].name,
                             category_index,
                             instance_index,
                             rows[i].line};
    }
  }
  return manifest;
}

} // namespace tda
} // namespace pcl
