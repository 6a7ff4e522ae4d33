/** pcl_tda_generate: writes a synthetic point cloud with exact ground truth (a
 * circle, torus or sphere with known Betti numbers, a tabletop scene labelled by
 * object, a tabletop or depth camera scene painted in colour regions and labelled by
 * region, or a surface with round holes labelled by hole rim) to a binary PCD
 * file; or a data set of depth camera views of household objects by category, as
 * PCD files and a manifest, to a folder. */

#include <pcl/console/print.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/data_set_folder.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/progress_bar.h>
#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/hole_surfaces.h>
#include <pcl/tda/generators/object_views.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/exceptions.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace pcl::console;

namespace {

/** The most points -n asks for: the cloud (32 bytes a point) and its file (16)
 * then take about 0.5 GB. */
constexpr long MAX_POINTS = 10000000;

/** The most colour noise -colour-noise accepts, in 0-255 levels. */
constexpr double MAX_COLOUR_NOISE = 255.0;

/** -remove must be below this: pcl::tda::MAX_HOLE_REMOVAL_FRACTION in decimal. */
constexpr double MAX_REMOVE = 0.9;
static_assert (static_cast<float> (MAX_REMOVE) == pcl::tda::MAX_HOLE_REMOVAL_FRACTION,
               "MAX_REMOVE is MAX_HOLE_REMOVAL_FRACTION");

/** The most instances per category and views per instance of shapes. */
constexpr long MAX_INSTANCES = 1000, MAX_VIEWS = 1000;
/** At most this many views in a data set: a million files of about 100 KB. */
constexpr std::uint64_t MAX_TOTAL_VIEWS = 1000000;
/** The largest perturbation -perturb accepts, in metres. */
constexpr double MAX_PERTURB = 0.1;
/** The largest noise multiplier -noise accepts for shapes. */
constexpr double MAX_NOISE_MULTIPLIER = 100.0;
/** The manifest of a data set of views, in its folder. */
const char* const MANIFEST = "manifest.csv";

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s "
              "<circle|torus|sphere|tabletop|regions|depth-regions|holes> output.pcd "
              "<options>\n"
              "       or %s shapes OUT_DIR <options>\n",
              program,
              program);
  print_info ("  where the kinds are:\n");
  print_info (
      "    circle, torus, sphere = a noisy shape with known Betti numbers\n"
      "    tabletop      = objects on a table seen by a depth camera, labelled by "
      "object\n"
      "                    (table %u, objects %u..)\n"
      "    regions       = the tabletop scene with its objects painted in colour "
      "regions (faces,\n"
      "                    bands, halves; some adjacent ones only 10-18 Delta E "
      "apart), labelled by\n"
      "                    region (table 1, regions 2..)\n"
      "    depth-regions = an organized 640 x 480 frame of a simulated "
      "structured-light camera,\n"
      "                    objects painted in two tones, labelled by region (table "
      "1, regions 2..;\n"
      "                    0 and NaN coordinates for lost pixels)\n"
      "    holes         = a surface with round holes (pcl::PointXYZL), labelled "
      "by hole rim:\n"
      "                    %u on the surface, k on the rim of hole k (1..), %u "
      "near the surface's\n"
      "                    own border\n"
      "    shapes        = a data set for object category classification: views of "
      "random\n"
      "                    instances of household objects (mug, cup, ring, disc, "
      "frame, tile,\n"
      "                    ball, can, box, cone, bowl, bottle) by a simulated depth "
      "camera, each\n"
      "                    the object's points only (pcl::PointXYZRGB, camera "
      "frame), written to\n"
      "                    OUT_DIR/<category>_<instance>_<view>.pcd with "
      "OUT_DIR/%s\n"
      "                    (path,category,instance,view); OUT_DIR is created if "
      "missing and must\n"
      "                    not hold a manifest already\n",
      pcl::tda::TABLE_LABEL,
      pcl::tda::FIRST_OBJECT_LABEL,
      pcl::tda::SURFACE_LABEL,
      pcl::tda::OUTER_BORDER_LABEL,
      MANIFEST);
  print_info ("  and the options are:\n");
  print_info (
      "    -n N       = number of points of a shape, up to %ld, enough for its "
      "noise (default:\n"
      "                 circle 1000, torus 2500, sphere 1500); for tabletop and "
      "regions, about "
      "N samples on\n"
      "                 the table top, which sets the sampling density (default: "
      "one point per\n"
      "                 1 cm x 1 cm; at least 1750); for holes, the points "
      "sampled before the\n"
      "                 holes are cut, at least %zu (default %zu); not for "
      "depth-regions\n"
      "                 and shapes\n",
      MAX_POINTS,
      pcl::tda::MIN_HOLE_SURFACE_POINTS,
      pcl::tda::HoleSurfaceParameters().num_points);
  print_info ("    -noise S   = Gaussian noise sigma of a shape (default 0.01); the "
              "depth noise sigma at 1 m\n"
              "                 of the tabletop camera (default: tabletop 0.001, "
              "regions 0.0005);\n"
              "                 for depth-regions, the depth noise coefficient k in "
              "1/m, sigma k z^2 at\n"
              "                 depth z (default 0.0015); for holes, sigma in units "
              "of the spacing h,\n"
              "                 below 1 (default 0); for shapes, a multiplier of the "
              "camera's depth\n"
              "                 noise, 0 to %g (default 1, Kinect-like; 3: three "
              "times the noise)\n",
              MAX_NOISE_MULTIPLIER);
  print_info ("    -colour-noise S\n"
              "               = colour noise sigma in levels of 0-255, 0 to %g "
              "(default 4); for tabletop,\n"
              "                 regions, depth-regions and shapes only\n",
              MAX_COLOUR_NOISE);
  print_info ("    -seed S    = random seed, >= 0 (default 0); equal seeds give "
              "identical files\n");
  print_info ("    -objects K = number of objects of tabletop and regions, 0 to %zu "
              "(default 4), or of\n"
              "                 depth-regions, 1 to %zu (default: 3 to 6, from the "
              "seed)\n",
              pcl::tda::MAX_TABLETOP_OBJECTS,
              pcl::tda::MAX_DEPTH_CAMERA_OBJECTS);
  print_info ("  and for shapes only:\n");
  print_info ("    -instances N = instances per category, 1 to %ld (default %zu)\n",
              MAX_INSTANCES,
              pcl::tda::ObjectViewParameters().instances);
  print_info ("    -views N   = views per instance, 1 to %ld (default %zu); at most "
              "%zu views in all\n",
              MAX_VIEWS,
              pcl::tda::ObjectViewParameters().views,
              static_cast<std::size_t> (MAX_TOTAL_VIEWS));
  print_info ("    -categories C1,C2,.. = the categories, each once (default: "
              "all)\n");
  print_info ("    -perturb A = moves every coordinate of every point by a uniform "
              "amount in [-A, A]\n                 metres, 0 to %g (thesis Experiment "
              "3: 0.0005, 0.001, 0.003; default 0)\n",
              MAX_PERTURB);
  print_info ("  and for holes only:\n");
  print_info ("    -surface S = plane, sphere, cylinder, torus or heightfield "
              "(default plane)\n");
  print_info ("    -hole-radii R1,R2,.. = one hole per radius, in units of the "
              "spacing h, each >= %g\n"
              "                 (default 3,5,8)\n",
              pcl::tda::MIN_HOLE_RADIUS);
  print_info ("    -remove F  = fraction of the points removed at random after "
              "cutting, >= 0 and < %g\n"
              "                 (default 0)\n",
              MAX_REMOVE);
  print_info ("    -removed F.pcd = also write the points removed at random (needs "
              "-remove)\n");
}

/** The parameters of the command line; n 0, objects, noise and colour noise < 0
 * when not given. */
struct Options {
  std::string kind, output;
  long n = 0, seed = 0, objects = -1;
  double noise = -1.0, colour_noise = -1.0;
  // holes only
  pcl::tda::HoleSurfaceKind surface = pcl::tda::HoleSurfaceKind::PLANE;
  std::vector<float> hole_radii = pcl::tda::HoleSurfaceParameters().hole_radii;
  double remove = 0.0;
  std::string removed;
  // shapes only; instances and views 0 when not given
  long instances = 0, views = 0;
  double perturb = 0.0;
  std::vector<pcl::tda::ObjectCategory> categories = pcl::tda::allObjectCategories();
};

/** The text that follows the option \a name on the command line. */
std::string
argumentOf (int argc, char** argv, const std::string& name)
{
  for (int i = 1; i + 1 < argc; ++i)
    if (name == argv[i])
      return argv[i + 1];
  return "";
}

/** Reads the value of -hole-radii, numbers >= MIN_HOLE_RADIUS separated by commas.
 * \throws pcl::BadArgumentException naming the option and value */
std::vector<float>
parseHoleRadii (const std::string& text)
{
  std::vector<float> radii;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = std::min (text.find (',', begin), text.size());
    const std::string item = text.substr (begin, end - begin);
    char* stop = nullptr;
    errno = 0;
    const double radius = std::strtod (item.c_str(), &stop);
    if (item.empty() || std::isspace (static_cast<unsigned char> (item[0])) ||
        stop != item.c_str() + item.size() || errno == ERANGE ||
        !std::isfinite (radius) || radius < pcl::tda::MIN_HOLE_RADIUS ||
        radius > std::numeric_limits<float>::max())
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option -hole-radii needs numbers >= "
                               << pcl::tda::MIN_HOLE_RADIUS
                               << " separated by commas (radii in units of the "
                                  "spacing), not '"
                               << text << "'.");
    radii.push_back (static_cast<float> (radius));
    if (end == text.size())
      return radii;
    begin = end + 1;
  }
}

/** Reads the value of -categories, category names separated by commas, each once.
 * \throws pcl::BadArgumentException naming the option and value */
std::vector<pcl::tda::ObjectCategory>
parseCategories (const std::string& text)
{
  std::vector<pcl::tda::ObjectCategory> categories;
  std::istringstream items (text + ",");
  std::string item;
  while (std::getline (items, item, ',')) {
    pcl::tda::ObjectCategory category;
    const bool known = pcl::tda::parseObjectCategory (item, category);
    if (!known || std::find (categories.begin(), categories.end(), category) !=
                      categories.end()) {
      std::string names;
      for (const std::string& name : pcl::tda::objectCategoryNames())
        names += (names.empty() ? "" : ", ") + name;
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option -categories needs category names separated by "
                           "commas, each once, from "
                               << names << "; not '" << text << "'.");
    }
    categories.push_back (category);
  }
  return categories;
}

/** Reads the command line into \a options.
 * \throws pcl::BadArgumentException naming the option at fault */
void
parseOptions (int argc, char** argv, Options& options)
{
  pcl::tda::ToolCommandLine command_line;
  command_line.addInteger ("-n", options.n, 1, MAX_POINTS);
  command_line.addNumber (
      "-noise",
      options.noise,
      pcl::tda::NumberRange::atLeast (0.0, std::numeric_limits<float>::max()));
  command_line.addNumber ("-colour-noise",
                          options.colour_noise,
                          pcl::tda::NumberRange::atLeast (0.0, MAX_COLOUR_NOISE));
  command_line.addInteger ("-seed", options.seed, 0, std::numeric_limits<long>::max());
  static_assert (pcl::tda::MAX_DEPTH_CAMERA_OBJECTS == pcl::tda::MAX_TABLETOP_OBJECTS,
                 "-objects has one range");
  command_line.addInteger ("-objects",
                           options.objects,
                           0,
                           static_cast<long> (pcl::tda::MAX_TABLETOP_OBJECTS));
  std::string surface, hole_radii;
  command_line.addText ("-surface", surface);
  command_line.addText ("-hole-radii", hole_radii);
  // The maximum itself is refused below.
  command_line.addNumber (
      "-remove", options.remove, pcl::tda::NumberRange::atLeast (0.0, MAX_REMOVE));
  command_line.addText ("-removed", options.removed);
  command_line.addInteger ("-instances", options.instances, 1, MAX_INSTANCES);
  command_line.addNumber (
      "-perturb", options.perturb, pcl::tda::NumberRange::atLeast (0.0, MAX_PERTURB));
  command_line.addInteger ("-views", options.views, 1, MAX_VIEWS);
  std::string categories;
  command_line.addText ("-categories", categories);
  const std::vector<std::string> arguments = command_line.parse (argc, argv);
  const bool shapes = !arguments.empty() && arguments[0] == "shapes";
  if (shapes)
    pcl::tda::checkArguments (arguments, {{"kind", ""}, {"output folder", ""}});
  else
    pcl::tda::checkArguments (arguments, {{"kind", ""}, {"output", ".pcd"}});
  options.kind = arguments[0];
  options.output = arguments[1];
  const std::string& kind = options.kind;
  const bool shape = kind == "circle" || kind == "torus" || kind == "sphere";
  const bool holes = kind == "holes";
  if (!shape && !holes && !shapes && kind != "tabletop" && kind != "regions" &&
      kind != "depth-regions")
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Unknown kind '"
                             << kind
                             << "': use circle, torus, sphere, tabletop, regions, "
                                "depth-regions, holes or shapes.");
  if (options.objects >= 0 && (shape || holes || shapes))
    PCL_THROW_EXCEPTION (
        pcl::BadArgumentException,
        "Option -objects applies to tabletop, regions and depth-regions only.");
  if (options.colour_noise >= 0.0 && (shape || holes))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Option -colour-noise applies to tabletop, regions, "
                         "depth-regions and shapes only.");
  for (const char* option : {"-instances", "-views", "-categories", "-perturb"})
    if (command_line.given (option) && !shapes)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option " << option << " applies to shapes only.");
  if (shapes) {
    if (options.n > 0)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option -n does not apply to shapes (views of a depth "
                           "camera).");
    if (options.noise > MAX_NOISE_MULTIPLIER)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option -noise needs a number >= 0 and <= "
                               << MAX_NOISE_MULTIPLIER
                               << " for shapes (a multiplier of the camera's depth "
                                  "noise), not '"
                               << argumentOf (argc, argv, "-noise") << "'.");
    if (!categories.empty())
      options.categories = parseCategories (categories);
    const auto views = static_cast<std::uint64_t> (options.instances) *
                       static_cast<std::uint64_t> (options.views) *
                       options.categories.size();
    if (views > MAX_TOTAL_VIEWS)
      PCL_THROW_EXCEPTION (
          pcl::BadArgumentException,
          "-instances " << options.instances << " x -views " << options.views << " x "
                        << options.categories.size() << " categories would be " << views
                        << " views (files), over " << MAX_TOTAL_VIEWS
                        << ": use fewer instances or views.");
  }
  if (options.n > 0 && kind == "depth-regions")
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Option -n does not apply to depth-regions (a 640 x 480 "
                         "frame).");
  if (options.objects == 0 && kind == "depth-regions")
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Option -objects needs an integer from 1 to "
                             << pcl::tda::MAX_DEPTH_CAMERA_OBJECTS
                             << " for depth-regions, not '0'.");
  for (const char* option : {"-surface", "-hole-radii", "-remove", "-removed"})
    if (command_line.given (option) && !holes)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option " << option << " applies to holes only.");
  if (!holes)
    return;
  if (!surface.empty() && !pcl::tda::parseHoleSurfaceKind (surface, options.surface))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Option -surface needs plane, sphere, cylinder, torus or "
                         "heightfield, not '"
                             << surface << "'.");
  if (!hole_radii.empty())
    options.hole_radii = parseHoleRadii (hole_radii);
  if (options.n > 0 &&
      options.n < static_cast<long> (pcl::tda::MIN_HOLE_SURFACE_POINTS))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Option -n needs an integer from "
                             << pcl::tda::MIN_HOLE_SURFACE_POINTS << " to "
                             << MAX_POINTS << " for holes, not '" << options.n << "'.");
  if (options.noise >= 1.0)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Option -noise needs a number >= 0 and < 1 for holes (in "
                         "units of the spacing), not '"
                             << options.noise << "'.");
  if (static_cast<float> (options.remove) >= pcl::tda::MAX_HOLE_REMOVAL_FRACTION)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Option -remove needs a number >= 0 and < "
                             << MAX_REMOVE << ", not '"
                             << argumentOf (argc, argv, "-remove") << "'.");
  if (!options.removed.empty()) {
    if (options.remove == 0.0)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option -removed needs -remove F with F > 0.");
    pcl::tda::checkArguments ({options.removed}, {{"-removed file", ".pcd"}});
  }
}

/** Writes the cloud as binary PCD to the temporary file of \a outputs and commits
 * it, as a console step; \a write_more writes the other outputs' temporary files
 * before the commit. */
template <typename PointT>
bool
saveCloud (
    const std::string& path,
    const pcl::PointCloud<PointT>& cloud,
    pcl::tda::ToolOutputs& outputs,
    pcl::tda::ToolConsole& console,
    const std::function<void()>& write_more = [] {})
{
  console.beginStep ("Saving", path);
  try {
    pcl::tda::savePointCloudFile (outputs.temporary (path), cloud);
    write_more();
    outputs.commit();
  }
  catch (const pcl::PCLException& e) {
    console.error (outputs.message (e));
    return false;
  }
  console.endStep (std::to_string (cloud.size()) + " points");
  return true;
}

/** Prints the labels \a first to \a last: "none" when there is none, the label
 * alone when there is one. */
void
printLabels (std::size_t first, std::size_t last)
{
  if (last < first)
    print_info ("none");
  else if (last == first)
    print_value ("%zu", first);
  else {
    print_value ("%zu", first);
    print_info (" to ");
    print_value ("%zu", last);
  }
}

/** Prints the region labels of a scene painted in colour regions: the table's
 * (label 1, when \a table), the objects' regions up to \a regions, and the number
 * of similar pairs. */
void
printRegions (bool table, std::size_t regions, std::size_t similar_pairs)
{
  print_info ("Region labels: ");
  if (table) {
    print_info ("table ");
    print_value ("%u", 1u);
    print_info (", ");
  }
  print_info ("object regions ");
  printLabels (table ? 2 : 1, regions);
  print_info ("; ");
  print_value ("%zu", similar_pairs);
  print_info (" pairs of adjacent regions in similar colours\n");
}

/** Generates a tabletop scene (regions: painted in colour regions) and saves it. */
int
runTabletop (const Options& options,
             pcl::tda::ToolOutputs& outputs,
             pcl::tda::ToolConsole& console)
{
  const bool regions = options.kind == "regions";
  pcl::tda::TabletopParameters parameters;
  if (regions) {
    parameters.colour_regions = true;
    parameters.setNoise (pcl::tda::TABLETOP_MODERATE_NOISE);
  }
  if (options.n > 0) {
    const double area =
        static_cast<double> (parameters.table_width) * parameters.table_depth;
    const auto least =
        static_cast<long> (std::ceil (area / (pcl::tda::TABLETOP_MAX_POINT_SPACING *
                                              pcl::tda::TABLETOP_MAX_POINT_SPACING) -
                                      1e-6));
    if (options.n < least)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option -n needs at least "
                               << least << " samples on the table top for "
                               << options.kind << " (a point per "
                               << pcl::tda::TABLETOP_MAX_POINT_SPACING * 100 << " cm x "
                               << pcl::tda::TABLETOP_MAX_POINT_SPACING * 100
                               << " cm), not '" << options.n << "'.");
    parameters.point_spacing = static_cast<float> (std::sqrt (area / options.n));
  }
  if (options.noise >= 0.0)
    parameters.noise_sigma = static_cast<float> (options.noise);
  if (options.colour_noise >= 0.0)
    parameters.colour_noise = static_cast<float> (options.colour_noise);
  if (options.objects >= 0)
    parameters.num_objects = static_cast<std::size_t> (options.objects);
  parameters.seed = static_cast<std::uint64_t> (options.seed);
  const pcl::tda::TabletopScene scene = pcl::tda::generateTabletopScene (parameters);
  console.endStep (
      std::to_string (scene.cloud->size()) + " points, " +
      std::to_string (scene.objects.size()) + " objects" +
      (regions ? ", " + std::to_string (scene.regions.size()) + " colour regions"
               : ""));
  if (regions) {
    printRegions (true, scene.regions.size(), scene.similar_regions.size());
    return saveCloud (
               options.output, *pcl::tda::regionLabelledCloud (scene), outputs, console)
               ? 0
               : 1;
  }
  print_info ("Labels: table ");
  print_value ("%u", pcl::tda::TABLE_LABEL);
  if (scene.objects.empty())
    print_info (", no objects\n");
  else {
    print_info (", objects ");
    print_value ("%u", pcl::tda::FIRST_OBJECT_LABEL);
    print_info (" to ");
    print_value ("%zu\n", pcl::tda::FIRST_OBJECT_LABEL + scene.objects.size() - 1);
  }
  return saveCloud (options.output, *scene.cloud, outputs, console) ? 0 : 1;
}

/** Generates a depth camera frame painted in colour regions, table kept, and saves
 * it labelled by region. */
int
runDepthRegions (const Options& options,
                 pcl::tda::ToolOutputs& outputs,
                 pcl::tda::ToolConsole& console)
{
  pcl::tda::DepthCameraParameters parameters;
  parameters.colour_regions = true;
  parameters.remove_table = false;
  parameters.colour_noise = 4.0f;
  if (options.noise >= 0.0)
    parameters.noise_coefficient = static_cast<float> (options.noise);
  if (options.colour_noise >= 0.0)
    parameters.colour_noise = static_cast<float> (options.colour_noise);
  if (options.objects > 0)
    parameters.min_objects = parameters.max_objects =
        static_cast<std::size_t> (options.objects);
  parameters.seed = static_cast<std::uint64_t> (options.seed);
  const pcl::tda::DepthCameraScene scene =
      pcl::tda::generateDepthCameraScene (parameters);
  std::size_t measured = 0;
  for (const std::uint32_t label : scene.region_labels)
    measured += label != 0;
  console.endStep (std::to_string (measured) + " of " +
                   std::to_string (scene.cloud->size()) + " pixels measured, " +
                   std::to_string (scene.objects.size()) + " objects, " +
                   std::to_string (scene.regions.size()) + " colour regions");
  printRegions (!scene.regions.empty() &&
                    scene.regions[0].object_label == pcl::tda::DEPTH_BACKGROUND_LABEL,
                scene.regions.size(),
                scene.similar_regions.size());
  return saveCloud (
             options.output, *pcl::tda::regionLabelledCloud (scene), outputs, console)
             ? 0
             : 1;
}

/** Generates a surface with round holes and saves it (and the points removed at
 * random, when asked). */
int
runHoles (const Options& options,
          pcl::tda::ToolOutputs& outputs,
          pcl::tda::ToolConsole& console)
{
  pcl::tda::HoleSurfaceParameters parameters;
  parameters.kind = options.surface;
  if (options.n > 0)
    parameters.num_points = static_cast<std::size_t> (options.n);
  parameters.hole_radii = options.hole_radii;
  if (options.noise >= 0.0)
    parameters.noise_sigma = static_cast<float> (options.noise);
  parameters.removal_fraction = static_cast<float> (options.remove);
  parameters.seed = static_cast<std::uint64_t> (options.seed);
  const pcl::tda::HoleSurface surface = pcl::tda::generateHoleSurface (parameters);
  console.endStep (std::to_string (surface.cloud->size()) + " points, " +
                   pcl::tda::countOf (surface.holes.size(), "hole") + ", " +
                   std::to_string (surface.removed->size()) + " removed at random");
  print_info ("Spacing h = ");
  print_value ("%g", surface.spacing);
  print_info ("; labels: surface ");
  print_value ("%u", pcl::tda::SURFACE_LABEL);
  if (!surface.holes.empty()) {
    print_info (surface.holes.size() == 1 ? ", rim of the hole "
                                          : ", rims of the holes ");
    printLabels (1, surface.holes.size());
  }
  if (!surface.closed) {
    print_info (", outer border ");
    print_value ("%u", pcl::tda::OUTER_BORDER_LABEL);
  }
  print_info ("\n");
  for (std::size_t i = 0; i < surface.holes.size(); ++i) {
    const pcl::tda::HoleSurface::Hole& hole = surface.holes[i];
    print_info ("Hole ");
    print_value ("%zu", i + 1);
    print_info (": centre (%g, %g, %g), radius ",
                hole.center.x(),
                hole.center.y(),
                hole.center.z());
    print_value ("%g\n", hole.radius);
  }
  return saveCloud (options.output,
                    *surface.cloud,
                    outputs,
                    console,
                    [&] {
                      if (!options.removed.empty())
                        pcl::tda::savePointCloudFile (
                            outputs.temporary (options.removed), *surface.removed);
                    })
             ? 0
             : 1;
}

/** Generates the data set of views of \a options into its folder. */
int
runShapes (const Options& options, pcl::tda::ToolConsole& console)
{
  pcl::tda::ObjectViewParameters parameters;
  parameters.categories = options.categories;
  if (options.instances > 0)
    parameters.instances = static_cast<std::size_t> (options.instances);
  parameters.perturbation = static_cast<float> (options.perturb);
  if (options.views > 0)
    parameters.views = static_cast<std::size_t> (options.views);
  if (options.noise >= 0.0)
    parameters.noise_multiplier = static_cast<float> (options.noise);
  if (options.colour_noise >= 0.0)
    parameters.colour_noise = static_cast<float> (options.colour_noise);
  parameters.seed = static_cast<std::uint64_t> (options.seed);
  pcl::tda::checkObjectViewParameters (parameters);

  // The rows of the manifest, in the order of the categories given.
  struct Row {
    pcl::tda::ObjectCategory category;
    std::size_t instance, view;
    std::string file;
  };
  std::vector<Row> rows;
  std::vector<std::string> names;
  for (const pcl::tda::ObjectCategory category : parameters.categories)
    for (std::size_t instance = 0; instance < parameters.instances; ++instance)
      for (std::size_t view = 0; view < parameters.views; ++view) {
        rows.push_back ({category,
                         instance,
                         view,
                         pcl::tda::objectCategoryName (category) + "_" +
                             std::to_string (instance) + "_" + std::to_string (view) +
                             ".pcd"});
        names.push_back (rows.back().file);
      }
  pcl::tda::DataSetFolder folder (options.output, names, MANIFEST);

  console.beginStep ("Generating",
                     std::to_string (rows.size()) + " views of " +
                         std::to_string (parameters.categories.size()) + " categories");
  std::size_t points = 0, fewest = std::numeric_limits<std::size_t>::max();
  std::ostringstream manifest;
  manifest << "path,category,instance,view\n";
  {
    pcl::tda::ProgressBar progress ("  rendering");
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const Row& row = rows[k];
      const pcl::tda::ObjectView view =
          pcl::tda::renderObjectView (parameters, row.category, row.instance, row.view);
      pcl::tda::savePointCloudFile (folder.staged (row.file), *view.cloud);
      points += view.cloud->size();
      fewest = std::min (fewest, view.cloud->size());
      manifest << row.file << "," << pcl::tda::objectCategoryName (row.category) << ","
               << row.instance << "," << row.view << "\n";
      progress.update (k + 1, rows.size());
    }
  }
  console.endStep (std::to_string (points) + " points, " +
                   std::to_string (points / rows.size()) + " per view on average, " +
                   std::to_string (fewest) + " at the fewest");

  const std::string manifest_path =
      (std::filesystem::path (options.output) / MANIFEST).string();
  console.beginStep ("Saving", manifest_path);
  pcl::tda::writeFileAtomically (folder.staged (MANIFEST),
                                 [&] (std::ostream& out) { out << manifest.str(); });
  folder.commit (names);
  console.endStep (std::to_string (rows.size()) + " views in " + options.output);
  return 0;
}

/** Generates the cloud of \a options and saves it. */
int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  if (options.kind == "shapes")
    return runShapes (options, console);
  pcl::tda::ToolOutputs outputs (
      "", {{"output", options.output}, {"-removed", options.removed}});
  const std::string& kind = options.kind;
  const long n = options.n, seed = options.seed;
  const double noise = options.noise;
  console.beginStep ("Generating", kind);
  if (kind == "tabletop" || kind == "regions")
    return runTabletop (options, outputs, console);
  if (kind == "depth-regions")
    return runDepthRegions (options, outputs, console);
  if (kind == "holes")
    return runHoles (options, outputs, console);

  // The parameters every shape has, from the options given.
  const auto with_options = [&] (auto parameters) {
    if (n > 0)
      parameters.num_points = static_cast<std::size_t> (n);
    if (noise >= 0.0)
      parameters.noise_sigma = static_cast<float> (noise);
    parameters.seed = static_cast<std::uint64_t> (seed);
    return parameters;
  };
  const pcl::tda::SyntheticShape shape =
      kind == "circle"
          ? pcl::tda::generateCircle (with_options (pcl::tda::CircleParameters{}))
      : kind == "torus"
          ? pcl::tda::generateTorus (with_options (pcl::tda::TorusParameters{}))
          : pcl::tda::generateSphere (with_options (pcl::tda::SphereParameters{}));
  console.endStep (std::to_string (shape.cloud->size()) + " points");
  print_info ("Expected Betti numbers: beta0 = ");
  print_value ("%d", shape.beta0);
  print_info (", beta1 = ");
  print_value ("%d", shape.beta1);
  print_info ("; suggested Vietoris-Rips radius: ");
  print_value ("%g\n", shape.suggested_radius);
  return saveCloud (options.output, *shape.cloud, outputs, console) ? 0 : 1;
}

} // namespace

int
main (int argc, char** argv)
{
  return pcl::tda::runTool<Options> (
      argc,
      argv,
      "Generate a synthetic point cloud with exact ground truth.",
      printHelp,
      parseOptions,
      run);
}
