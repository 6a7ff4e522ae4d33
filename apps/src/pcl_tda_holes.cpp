// pcl_tda_holes: the holes of a scanned surface from its minimal 1-cycles (thesis
// Ch. 5): every point labelled by the hole whose rim band it is in, the holes as a
// table, the cloud with its holes filled, the H1 barcode and a picture.

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/tda/apps/cloud_picture.h>
#include <pcl/tda/apps/coordinate_check.h>
#include <pcl/tda/apps/csv_fields.h>
#include <pcl/tda/apps/new_point_fields.h>
#include <pcl/tda/apps/svg_png.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/common/progress_bar.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/features/hole_boundary_estimation.h>
#include <pcl/tda/search/point_spacing.h>
#include <pcl/tda/surface/hole_filling.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace pcl::console;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Estimation = pcl::tda::HoleBoundaryEstimation<pcl::PointXYZ, pcl::Boundary>;

namespace {

struct Options {
  std::string input, output, filled, fill_mode = "surface", csv, barcode_svg,
                                     picture_png;
  double radius = 0.0;
  double min_hole_radius = 0.0;
  long max_cycle = 0;
  std::size_t memory_limit = pcl::tda::defaultMemoryLimit();
};

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s input.pcd output.pcd <options>\n", program);
  print_info ("  Finds the holes of a scanned surface: writes every input point, in "
              "input order,\n  with the number of the hole whose rim band it is in "
              "as label (0: none; 1, 2,\n  ... by decreasing rim length).\n");
  print_info ("  where options are:\n");
  print_info ("    -radius R   = radius of the Vietoris-Rips complex (default: %g "
              "times the\n                  surface spacing, from the distance to "
              "the %zu-th nearest point;\n                  at most %g times it)\n",
              Estimation::AUTO_RADIUS_PER_SPACING,
              pcl::tda::SURFACE_SPACING_NEIGHBORS,
              Estimation::MAX_RADIUS_PER_SPACING);
  print_info ("    -min-hole H = smallest hole radius: the largest empty disk inside "
              "a rim must have\n                  radius H or more (default: %g "
              "times the surface spacing, or\n                  the local spacing "
              "around the rim where the scan is\n                  sparser); "
              "narrower gaps are taken for gaps of the sampling\n",
              Estimation::DEFAULT_MIN_HOLE_RADIUS_PER_SPACING);
  print_info ("    -max-cycle N = report only rims of at most N points (default: no "
              "limit)\n");
  print_info ("    -fill F.pcd = also write the cloud with its holes filled: the "
              "input points,\n                  then the new ones (with the fields "
              "of their nearest rim points)\n");
  print_info ("    -fill-mode M = surface (new points on a surface fitted around "
              "the hole, spaced\n                  like the cloud; the default) or "
              "centroid (one point per hole)\n");
  print_info ("    -csv F.csv  = also write one row per hole: its size, perimeter, "
              "area, centre,\n                  normal, birth and rim points\n");
  print_info ("    -svg F.svg  = also draw the H1 barcode of the complex\n");
  print_info (
      "    -png F.png  = also draw the cloud with its rim bands (and, with "
      "-fill, the new\n                  points) in their holes' colours, and "
      "beside it the bands black and\n                  the new points red; with "
      "-svg, the barcode as PNG beside\n                  its SVG too (B.png "
      "for B.svg)\n");
  print_info ("    -memory M   = refuse complexes over M MiB (default: half of the "
              "memory)\n");
  print_info ("  Outputs are written only when the whole run succeeds.\n");
}

/** Reads the command line into \a options.
 * \throws pcl::BadArgumentException naming the option at fault */
void
parseOptions (int argc, char** argv, Options& options)
{
  pcl::tda::ToolCommandLine command_line;
  command_line.addNumber (
      "-radius", options.radius, pcl::tda::NumberRange::above (0.0, 1e9));
  command_line.addNumber (
      "-min-hole", options.min_hole_radius, pcl::tda::NumberRange::above (0.0, 1e9));
  command_line.addInteger (
      "-max-cycle", options.max_cycle, 3, std::numeric_limits<int>::max());
  command_line.addText ("-fill", options.filled);
  command_line.addText ("-fill-mode", options.fill_mode);
  command_line.addText ("-csv", options.csv);
  command_line.addText ("-svg", options.barcode_svg);
  command_line.addText ("-png", options.picture_png);
  command_line.addMemory ("-memory", options.memory_limit);
  const std::vector<std::string> files = command_line.parse (argc, argv);
  pcl::tda::checkArguments (files, {{"input", ".pcd"}, {"output", ".pcd"}});
  options.input = files[0];
  options.output = files[1];
  if (options.fill_mode != "surface" && options.fill_mode != "centroid")
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-fill-mode must be surface or centroid (got '"
                             << options.fill_mode << "').");
  if (command_line.given ("-fill-mode") && options.filled.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-fill-mode has no use without -fill.");
  pcl::tda::checkOptionExtension ("-fill", options.filled, ".pcd");
  pcl::tda::checkOptionExtension ("-csv", options.csv, ".csv");
  pcl::tda::checkOptionExtension ("-svg", options.barcode_svg, ".svg");
  pcl::tda::checkOptionExtension ("-png", options.picture_png, ".png");
}

/** Writes the holes as CSV to \a path: one row per hole, the rim's input indices
 * space-separated in the last column.
 * \throws pcl::IOException when the file cannot be written */
void
saveHolesCsv (const std::string& path,
              const std::vector<pcl::tda::HoleRim>& holes,
              double radius)
{
  using pcl::tda::formatNumber;
  std::ostringstream text;
  text << "id,rim_points,perimeter,area,clearance,centroid_x,centroid_y,centroid_z,"
          "normal_x,normal_y,normal_z,tilt_degrees,birth,alive_at,rim\n";
  for (std::size_t k = 0; k < holes.size(); ++k) {
    const pcl::tda::HoleRim& hole = holes[k];
    text << k + 1 << ',' << hole.rim.size();
    for (const double value : {hole.perimeter, hole.area, hole.clearance})
      text << ',' << formatNumber (value);
    for (const float value : {hole.centroid.x(),
                              hole.centroid.y(),
                              hole.centroid.z(),
                              hole.normal.x(),
                              hole.normal.y(),
                              hole.normal.z()})
      text << ',' << formatNumber (value);
    for (const double value : {hole.tilt_degrees, hole.birth, radius})
      text << ',' << formatNumber (value);
    text << ',';
    for (std::size_t i = 0; i < hole.rim.size(); ++i)
      text << (i > 0 ? " " : "") << hole.rim[i];
    text << '\n';
  }
  std::ofstream file (path);
  file << text.str();
  if (!file.flush())
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot write " << path << ": " << std::strerror (errno));
}

/** The H1 intervals of a diagram. */
pcl::tda::PersistenceDiagram
h1Intervals (const pcl::tda::PersistenceDiagram& diagram)
{
  pcl::tda::PersistenceDiagram h1;
  for (const auto& interval : diagram)
    if (interval.dimension == 1)
      h1.push_back (interval);
  return h1;
}

int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  const std::string barcode_png =
      pcl::tda::pngBesideSVGWithPNG (options.barcode_svg, options.picture_png);
  pcl::tda::ToolOutputs outputs (options.input,
                                 {{"output", options.output},
                                  {"-fill", options.filled},
                                  {"-csv", options.csv},
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
  Cloud::Ptr cloud (new Cloud);
  if (!blob.data.empty())
    pcl::fromPCLPointCloud2 (blob, *cloud);
  console.endStep (std::to_string (cloud->size()) + " points");
  // Measured once, for the check of the coordinates and for the estimation; 0 when
  // there is no surface (fewer than 7 distinct finite points).
  const double spacing = pcl::tda::surfaceSpacing (*cloud);
  const double radius = options.radius > 0.0
                            ? options.radius
                            : Estimation::AUTO_RADIUS_PER_SPACING * spacing;
  if (radius > 0.0) // else the estimation says there are too few points
    pcl::tda::checkToolCoordinates (
        *cloud,
        radius,
        options.radius > 0.0 ? "-radius" : "the radius from the spacing");

  Estimation estimation;
  estimation.setInputCloud (cloud);
  estimation.setRadius (options.radius);
  estimation.setSpacing (spacing);
  estimation.setMinHoleRadius (options.min_hole_radius);
  estimation.setMaxCycleLength (static_cast<std::size_t> (options.max_cycle));
  estimation.setMemoryLimit (options.memory_limit);
  console.beginStep ("Finding holes");
  pcl::PointCloud<pcl::Boundary> flags;
  {
    pcl::tda::ProgressBar bar ("  complex, then 1-classes");
    estimation.setProgressCallback (
        [&bar] (std::size_t done, std::size_t total) { bar.update (done, total); });
    estimation.compute (flags);
  }
  if (flags.empty()) { // refused, or no surface (an empty cloud too)
    console.error (spacing > 0.0
                       ? "Hole detection failed (see above). For a complex over the "
                         "memory limit: set a larger one with -memory M (MiB), or a "
                         "smaller -radius; for a radius refused, the radius it advises."
                       : "Hole detection failed (see above).");
    const std::string coincident = pcl::tda::coincidentPointsAdvice (*cloud);
    if (!coincident.empty())
      console.error (coincident);
    return 1;
  }
  const std::vector<pcl::tda::HoleRim>& holes = estimation.getHoles();
  std::ostringstream found;
  found << pcl::tda::countOf (holes.size(), "hole") << ", radius "
        << estimation.getUsedRadius()
        << (options.radius > 0.0 ? " (given)" : " (from the spacing)") << ", "
        << estimation.getSearchCounts().edges << " edges, "
        << estimation.getSearchCounts().open_classes << " open 1-classes, "
        << estimation.getSearchCounts().persistent_classes << " alive at "
        << estimation.getUsedPersistenceRadius() << ", "
        << estimation.getSearchCounts().border_polygons << " border polygons";
  console.endStep (found.str());
  constexpr std::size_t MAX_LINES = 30;
  for (std::size_t k = 0; k < holes.size() && k < MAX_LINES; ++k)
    print_info ("  hole %zu: rim of %zu points, perimeter %g, area %g, centre (%g, %g, "
                "%g)\n",
                k + 1,
                holes[k].rim.size(),
                holes[k].perimeter,
                holes[k].area,
                holes[k].centroid.x(),
                holes[k].centroid.y(),
                holes[k].centroid.z());
  if (holes.size() > MAX_LINES)
    print_info ("  ... and %zu more holes\n", holes.size() - MAX_LINES);

  pcl::PointCloud<pcl::PointXYZL> labelled;
  pcl::copyPointCloud (*cloud, labelled);
  const std::vector<std::uint32_t>& labels = estimation.getRimBandLabels();
  for (std::size_t i = 0; i < labelled.size(); ++i)
    labelled[i].label = labels.empty() ? 0 : labels[i];

  Cloud filled;
  pcl::PCLPointCloud2 filled_fields;          // filled, with the input's fields
  std::vector<std::uint32_t> new_point_holes; // per new point, its hole's number
  if (!options.filled.empty()) {
    console.beginStep ("Filling", options.fill_mode);
    pcl::tda::HoleFilling<pcl::PointXYZ> filler;
    filler.setInputCloud (cloud);
    filler.setHoles (holes);
    filler.setMode (options.fill_mode == "centroid"
                        ? pcl::tda::HoleFilling<pcl::PointXYZ>::Mode::CENTROID
                        : pcl::tda::HoleFilling<pcl::PointXYZ>::Mode::SURFACE);
    if (!filler.reconstruct (filled)) {
      console.error ("Hole filling failed (see above).");
      return 1;
    }
    const std::vector<std::size_t>& counts = filler.getNewPointCounts();
    for (std::size_t k = 0; k < counts.size(); ++k)
      new_point_holes.insert (
          new_point_holes.end(), counts[k], static_cast<std::uint32_t> (k + 1));
    filled_fields = pcl::tda::withNewPoints (blob, filled, filler.getNewPointSources());
    console.endStep (std::to_string (filled.size() - cloud->size()) + " new points");
  }

  console.beginStep ("Saving", options.output);
  try {
    pcl::tda::savePointCloudFile (outputs.temporary (options.output), labelled);
    if (!options.filled.empty())
      pcl::tda::savePointCloudFile (outputs.temporary (options.filled),
                                    filled_fields,
                                    cloud->sensor_origin_,
                                    cloud->sensor_orientation_);
    if (!options.csv.empty())
      saveHolesCsv (outputs.temporary (options.csv), holes, estimation.getUsedRadius());
    if (!options.barcode_svg.empty()) {
      pcl::tda::PlotOptions plot;
      std::ostringstream title;
      title << options.input << ": H1 up to radius " << estimation.getUsedRadius()
            << ", " << pcl::tda::countOf (holes.size(), "hole");
      plot.title = title.str();
      plot.max_value = estimation.getUsedRadius();
      pcl::tda::saveBarcodeSVG (outputs.temporary (options.barcode_svg),
                                h1Intervals (estimation.getPersistenceDiagram()),
                                plot);
      if (!barcode_png.empty())
        pcl::tda::renderSVGToPNG (outputs.temporary (options.barcode_svg),
                                  outputs.temporary (barcode_png));
    }
    if (!options.picture_png.empty()) {
      // Left: rim bands and new points in their holes' colours. Right: the surface
      // grey, the rim bands black and the new points red.
      pcl::PointCloud<pcl::PointXYZRGBL> picture;
      pcl::copyPointCloud (labelled, picture);
      for (auto& point : picture) {
        const std::uint8_t shade = point.label == 0 ? 190 : 20;
        point.r = point.g = point.b = shade;
      }
      for (std::size_t i = cloud->size(); i < filled.size(); ++i) {
        pcl::PointXYZRGBL point;
        point.getVector3fMap() = filled[i].getVector3fMap();
        point.r = 230;
        point.g = point.b = 0;
        point.label = new_point_holes[i - cloud->size()];
        picture.push_back (point);
      }
      pcl::tda::saveCloudPicture (
          outputs.temporary (options.picture_png),
          picture,
          {pcl::tda::PictureColors::LABELS, pcl::tda::PictureColors::POINTS});
    }
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
      argc, argv, "Hole boundaries by minimal 1-cycles.", printHelp, parseOptions, run);
}
