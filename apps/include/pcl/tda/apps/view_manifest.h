#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief One view of an object instance: a row of a view manifest. */
struct ManifestView {
  /** \brief The path as the manifest gives it. */
  std::string path;
  /** \brief The file to read: \a path, relative to the manifest's folder unless it
   * is absolute. */
  std::string file;
  /** \brief The view's name in the manifest (e.g. its number). */
  std::string name;
  /** \brief Index of the view's category in ViewManifest::categories. */
  std::size_t category = 0;
  /** \brief Index of the view's instance in ViewManifest::instances. */
  std::size_t instance = 0;
  /** \brief The view's line in the manifest, for messages. */
  std::size_t line = 0;
};

/** \brief An object instance of a view manifest: a category and a name, unique
 * within its category. */
struct ManifestInstance {
  std::size_t category = 0;
  std::string name;
  /** \brief Its views, as indices in ViewManifest::views, in view name order. */
  std::vector<std::size_t> views;
};

/** \brief The views of an object category data set (thesis Sec 6.5.1: categories,
 * several instances per category, several views per instance), as listed by a
 * manifest CSV file such as `pcl_tda_generate shapes` writes. Categories are sorted
 * by name, the instances by category and name, the views by category, instance and
 * view name, so that everything derived from a manifest is deterministic, whatever
 * the order of its rows. */
struct ViewManifest {
  std::vector<std::string> categories;
  std::vector<ManifestInstance> instances;
  std::vector<ManifestView> views;
  /** \brief The instances of each category, as indices in \a instances. */
  std::vector<std::vector<std::size_t>> category_instances;
};

/** \brief The columns a view manifest must have, named on its first line (in any
 * order; other columns are ignored). */
constexpr const char* MANIFEST_COLUMNS[] = {"path", "category", "instance", "view"};

/** \brief Reads the view manifest \a path: a CSV file (splitCSVLine()) whose first
 * line names the columns path, category, instance and view, then one line per view
 * (blank lines skipped). Refuses a manifest that cannot serve the category protocol,
 * naming the line: a missing column or value, a row with another number of fields
 * than the header, a view file that does not exist or is not a .pcd file, a file or
 * a (category, instance, view) listed twice, no views, fewer than 2 categories, or a
 * category with fewer than 2 instances (one is held out for testing, the others
 * train).
 * \throws pcl::IOException saying what is wrong */
ViewManifest
readViewManifest (const std::string& path);

} // namespace tda
} // namespace pcl
