// pcl_tda_regions: colour region segmentation by topological persistence (thesis
// Sec 4.2): every point labelled by its region, the H0 barcode of the homogeneity
// filtration, and a picture of the regions.

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/tda/apps/cloud_picture.h>
#include <pcl/tda/apps/coordinate_check.h>
#include <pcl/tda/apps/region_settings.h>
#include <pcl/tda/apps/svg_png.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/common/progress_bar.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/segmentation/persistent_region_growing_rgb.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace pcl::console;
using Cloud = pcl::PointCloud<pcl::PointXYZRGB>;
using Normals = pcl::PointCloud<pcl::Normal>;
using pcl::tda::RegionSettings;
using pcl::tda::ToolRegionGrowing;

namespace {

struct Options {
  std::string input, output, barcode_svg, picture_png;
  RegionSettings settings;
  std::size_t memory_limit = pcl::tda::defaultMemoryLimit();
};

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s input.pcd output.pcd <options>\n", program);
  print_info ("  Segments a coloured cloud into regions of similar colour (and surface "
              "normal):\n  writes every input point, in input order, with its colour "
              "and its region as\n  label (0: no region; 1, 2, ... by decreasing "
              "size). The input needs an rgb or\n  rgba field.\n");
  print_info ("  where options are:\n");
  print_info ("    -radius R   = largest distance between neighbours (default: %g "
              "times the\n                  cloud's spacing, the %g quantile of the "
              "distances to the %zu-th\n                  nearest point); a point "
              "with fewer than %zu neighbours within it is\n                  also "
              "joined to its %zu nearest points, whatever their distance\n",
              RegionSettings::RADIUS_PER_SPACING,
              RegionSettings::SPACING_QUANTILE,
              RegionSettings::SPACING_NEIGHBOR,
              RegionSettings::MIN_NEIGHBORS,
              3 * RegionSettings::MIN_NEIGHBORS);
  print_info ("    -image-ratio K = in an organized cloud (a depth image), also join "
              "neighbouring\n                  pixels up to K times their range "
              "apart, beyond the radius\n                  (default %g; 0: not "
              "used)\n",
              RegionSettings::IMAGE_NEIGHBOR_RATIO);
  print_info ("    -point-color DE = largest colour difference of neighbours in a "
              "patch, in CIELAB\n                  Delta E76 (default %g)\n",
              ToolRegionGrowing::DEFAULT_COLOR_THRESHOLD);
  print_info (
      "    -color DE   = largest difference of the mean colours of adjacent "
      "patches in a\n                  region, in Delta E76 (default: -auto)\n");
  print_info ("    -auto       = choose that threshold from the persistence of the "
              "regions, up to\n                  Delta E %g (the default)\n",
              RegionSettings::MAX_AUTO_COLOR_THRESHOLD);
  print_info ("    -angle DEG  = largest angle between the normals of neighbours in a "
              "region\n                  (default %g)\n",
              ToolRegionGrowing::DEFAULT_NORMAL_ANGLE);
  print_info ("    -no-normals = compare colours only; otherwise the input's normals "
              "are used, or\n                  estimated from the neighbours within "
              "the radius when it has none\n");
  print_info ("    -min N      = smallest region, in points; smaller ones join their "
              "most similar\n                  neighbour, or get label 0 when its "
              "colour is over Delta E %g\n                  from theirs (default %u)\n",
              ToolRegionGrowing::DEFAULT_MAX_MERGE_COLOR_DIFFERENCE,
              RegionSettings{}.min_size);
  print_info ("    -memory M   = refuse neighbour graphs over M MiB (default: half of "
              "the memory)\n");
  print_info ("    -svg F.svg  = also draw the H0 barcode over Delta E (with the "
              "threshold)\n");
  print_info (
      "    -png F.png  = also draw the cloud in its colours and in those of "
      "its regions\n                  (no region: grey), side by side; with -svg, the "
      "barcode as PNG\n                  beside its SVG too (B.png for "
      "B.svg)\n");
  print_info ("  Outputs are written only when the whole run succeeds.\n");
}

/** Reads the command line into \a options.
 * \throws pcl::BadArgumentException naming the option at fault */
void
parseOptions (int argc, char** argv, Options& options)
{
  RegionSettings& settings = options.settings;
  bool automatic = false, no_normals = false;
  long min_size = settings.min_size;
  pcl::tda::ToolCommandLine command_line;
  command_line.addNumber (
      "-radius", settings.radius, pcl::tda::NumberRange::above (0.0, 1e9));
  command_line.addNumber (
      "-image-ratio", settings.image_ratio, pcl::tda::NumberRange::atLeast (0.0, 1.0));
  command_line.addNumber (
      "-point-color", settings.point_color, pcl::tda::NumberRange::above (0.0, 1e3));
  command_line.addNumber (
      "-color", settings.region_color, pcl::tda::NumberRange::above (0.0, 1e3));
  command_line.addSwitch ("-auto", automatic);
  command_line.addNumber (
      "-angle", settings.angle, pcl::tda::NumberRange::above (0.0, 90.0));
  command_line.addSwitch ("-no-normals", no_normals);
  command_line.addInteger ("-min", min_size, 1, std::numeric_limits<int>::max());
  command_line.addMemory ("-memory", options.memory_limit);
  command_line.addText ("-svg", options.barcode_svg);
  command_line.addText ("-png", options.picture_png);
  const std::vector<std::string> files = command_line.parse (argc, argv);
  pcl::tda::checkArguments (files, {{"input", ".pcd"}, {"output", ".pcd"}});
  options.input = files[0];
  options.output = files[1];
  if (automatic && command_line.given ("-color"))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-color and -auto exclude each other: give one.");
  if (command_line.given ("-angle") && no_normals)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-angle has no use with -no-normals.");
  settings.use_normals = !no_normals;
  settings.min_size = static_cast<pcl::uindex_t> (min_size);
  pcl::tda::checkOptionExtension ("-svg", options.barcode_svg, ".svg");
  pcl::tda::checkOptionExtension ("-png", options.picture_png, ".png");
}

/** The normals of the input: true with \a normals null when it has none (they are
 * then estimated from the neighbour graph), false after an error. */
bool
inputNormals (const pcl::PCLPointCloud2& blob,
              const Cloud& cloud,
              Normals::Ptr& normals,
              pcl::tda::ToolConsole& console)
{
  normals.reset();
  if (pcl::getFieldIndex (blob, "normal_x") >= 0 &&
      pcl::getFieldIndex (blob, "normal_y") >= 0 &&
      pcl::getFieldIndex (blob, "normal_z") >= 0) {
    console.beginStep ("Normals", "from the input");
    normals.reset (new Normals);
    pcl::fromPCLPointCloud2 (blob, *normals);
    std::size_t invalid = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i)
      invalid +=
          pcl::isXYZFinite (cloud[i]) && !pcl::tda::isUsableNormal ((*normals)[i]);
    if (invalid > 0) {
      console.error (std::to_string (invalid) +
                     " points with a finite position have "
                     "a non-finite or zero normal in the input: use -no-normals, or "
                     "remove the normal fields to have them estimated.");
      return false;
    }
    console.endStep (std::to_string (normals->size()) + " normals");
  }
  return true;
}

/** The mean input colour of a region. */
std::array<double, 3>
meanColor (const Cloud& cloud, const pcl::Indices& indices)
{
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  for (const auto index : indices) {
    sum[0] += cloud[index].r;
    sum[1] += cloud[index].g;
    sum[2] += cloud[index].b;
  }
  for (double& channel : sum)
    channel /= static_cast<double> (indices.size());
  return sum;
}

/** What keeps the colours of \a blob from being read, after the file name ("" when
 * nothing): no rgb or rgba field, or one that is not PCL's packed colour (one 4-byte
 * float or unsigned value per point; PCL reads other layouts as black). */
std::string
colourFieldProblem (const pcl::PCLPointCloud2& blob)
{
  int field = pcl::getFieldIndex (blob, "rgb");
  if (field < 0)
    field = pcl::getFieldIndex (blob, "rgba");
  if (field < 0)
    return " has no colour (no rgb or rgba field): pcl_tda_regions segments by "
           "colour. For segmentation by distance alone, use pcl_tda_segment.";
  const pcl::PCLPointField& colour = blob.fields[field];
  if (colour.count == 1 && (colour.datatype == pcl::PCLPointField::FLOAT32 ||
                            colour.datatype == pcl::PCLPointField::UINT32))
    return "";
  return "'s " + colour.name + " field holds " + std::to_string (colour.count) +
         " value(s) of " + std::to_string (pcl::getFieldSize (colour.datatype)) +
         " byte(s) (" + pcl::getFieldType (colour.datatype) +
         ") per point: pcl_tda_regions reads PCL's packed colour, one 4-byte value "
         "per point (SIZE 4, TYPE F or U, COUNT 1).";
}

int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  const std::string barcode_png =
      pcl::tda::pngBesideSVGWithPNG (options.barcode_svg, options.picture_png);
  pcl::tda::ToolOutputs outputs (options.input,
                                 {{"output", options.output},
                                  {"-svg", options.barcode_svg},
                                  {"-png", options.picture_png},
                                  {"the PNG of -svg", barcode_png}});
  pcl::PCLPointCloud2 blob;
  console.beginStep ("Loading", options.input);
  try {
    pcl::tda::loadPointCloudFile (options.input, blob);
  }
  catch (const pcl::PCLException& failure) {
    console.error ("Cannot read the PCD file: " + pcl::tda::errorMessage (failure));
    return 1;
  }
  const std::string colour_problem = colourFieldProblem (blob);
  if (!colour_problem.empty()) {
    console.error (options.input + colour_problem);
    return 1;
  }
  Cloud::Ptr cloud (new Cloud);
  if (!blob.data.empty())
    pcl::fromPCLPointCloud2 (blob, *cloud);
  console.endStep (std::to_string (cloud->size()) + " points" +
                   (cloud->isOrganized() ? " (organized)" : ""));

  const RegionSettings& settings = options.settings;
  console.beginStep ("Radius");
  const double radius = pcl::tda::regionRadius (settings, *cloud);
  if (!(radius > 0.0)) {
    console.error ("The cloud has fewer than " +
                   std::to_string (RegionSettings::SPACING_NEIGHBOR + 1) +
                   " distinct finite points: no spacing to take the radius from (a "
                   "point's distance to its " +
                   std::to_string (RegionSettings::SPACING_NEIGHBOR) +
                   "th nearest). Give -radius.");
    return 1;
  }
  pcl::tda::checkToolCoordinates (
      *cloud,
      radius,
      settings.radius > 0.0 ? "-radius" : "the radius from the spacing");
  std::ostringstream chosen;
  chosen << radius << (settings.radius > 0.0 ? " (given)" : " (from the spacing)");
  console.endStep (chosen.str());

  Normals::Ptr normals;
  if (settings.use_normals && !inputNormals (blob, *cloud, normals, console))
    return 1;
  ToolRegionGrowing growing;
  growing.setInputCloud (cloud);
  pcl::tda::configureRegionGrowing (growing, settings, radius, normals);
  growing.setMemoryLimit (options.memory_limit);

  console.beginStep ("Growing regions");
  std::vector<pcl::PointIndices> regions;
  {
    pcl::tda::ProgressBar bar ("  neighbour graph");
    growing.setProgressCallback (
        [&bar] (std::size_t done, std::size_t total) { bar.update (done, total); });
    growing.extract (regions);
  }
  if (growing.getPersistenceDiagram().empty()) {
    console.error ("Region growing failed (see above). For a neighbour graph over the "
                   "memory limit: set a larger one with -memory M (MiB), or a smaller "
                   "-radius.");
    const std::string coincident = pcl::tda::coincidentPointsAdvice (*cloud);
    if (!coincident.empty())
      console.error (coincident);
    return 1;
  }
  std::ostringstream grown;
  grown << pcl::tda::countOf (regions.size(), "region") << " at Delta E "
        << growing.getChosenRegionColorThreshold()
        << (settings.region_color == 0.0 ? " (chosen)" : "") << ", radius " << radius
        << ", " << growing.getNumEdges() << " edges";
  console.endStep (grown.str());

  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  pcl::copyPointCloud (*cloud, labelled);
  for (auto& point : labelled)
    point.label = 0;
  const std::vector<pcl::tda::RegionLifetime>& lifetimes = growing.getRegionLifetimes();
  constexpr std::size_t MAX_LINES = 30;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    for (const auto index : regions[k].indices)
      labelled[index].label = static_cast<std::uint32_t> (k + 1);
    if (k < MAX_LINES) {
      const auto mean = meanColor (*cloud, regions[k].indices);
      print_info ("  region %zu: %zu points, mean colour (%.0f, %.0f, %.0f), Delta E "
                  "birth %.2f death %.2f\n",
                  k + 1,
                  regions[k].indices.size(),
                  mean[0],
                  mean[1],
                  mean[2],
                  lifetimes[k].birth,
                  lifetimes[k].death);
    }
  }
  if (regions.size() > MAX_LINES)
    print_info ("  ... and %zu smaller regions\n", regions.size() - MAX_LINES);
  std::size_t in_regions = 0;
  for (const auto& region : regions)
    in_regions += region.indices.size();
  const std::size_t in_specks =
      labelled.size() - in_regions - growing.getNumSkippedPoints();
  if (regions.empty())
    print_info ("  no region of %zu points or more (-min): every point has label 0\n",
                static_cast<std::size_t> (settings.min_size));
  else if (in_specks > 0)
    print_info ("  %s in no region (label 0): specks of another colour under %zu "
                "points\n",
                pcl::tda::countOf (in_specks, "point").c_str(),
                static_cast<std::size_t> (settings.min_size));

  console.beginStep ("Saving", options.output);
  try {
    pcl::tda::savePointCloudFile (outputs.temporary (options.output), labelled);
    if (!options.barcode_svg.empty()) {
      pcl::tda::PlotOptions plot;
      std::ostringstream title;
      title << options.input << ": regions of " << settings.min_size
            << "+ points over Delta E, "
            << pcl::tda::countOf (regions.size(), "region");
      plot.title = title.str();
      plot.unit = "Delta E";
      plot.cut = growing.getChosenRegionColorThreshold();
      plot.max_value =
          std::max (2.0 * plot.cut, RegionSettings::MAX_AUTO_COLOR_THRESHOLD);
      pcl::tda::saveBarcodeSVG (
          outputs.temporary (options.barcode_svg), growing.getRegionBarcode(), plot);
      if (!barcode_png.empty())
        pcl::tda::renderSVGToPNG (outputs.temporary (options.barcode_svg),
                                  outputs.temporary (barcode_png));
    }
    if (!options.picture_png.empty())
      pcl::tda::saveCloudPicture (
          outputs.temporary (options.picture_png),
          labelled,
          {pcl::tda::PictureColors::POINTS, pcl::tda::PictureColors::LABELS});
    outputs.commit();
  }
  catch (const std::exception& error) {
    console.error (outputs.message (error));
    return 1;
  }
  console.endStep (std::to_string (labelled.size()) + " labelled points");
  return 0;
}

} // namespace

int
main (int argc, char** argv)
{
  return pcl::tda::runTool<Options> (
      argc,
      argv,
      "Colour region segmentation by topological persistence.",
      printHelp,
      parseOptions,
      run);
}
