// pcl_tda_viewer: the results of PCL-TDA in a PCLVisualizer window, in the manner of
// pcl_viewer: a cloud and its Vietoris-Rips barcode with the filtration radius
// stepped by keys (thesis Fig 6.1), or the labelled clouds of pcl_tda_segment,
// pcl_tda_regions and pcl_tda_holes in the colours of their labels; -screenshot
// renders off-screen to a PNG picture and exits.

#include <pcl/console/print.h>
#include <pcl/tda/apps/barcode_overlay.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/cloud_picture.h>
#include <pcl/tda/apps/coordinate_check.h>
#include <pcl/tda/apps/display_connection.h>
#include <pcl/tda/apps/filtration_at_radius.h>
#include <pcl/tda/apps/labelled_cloud.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/apps/viewer_screenshot.h>
#include <pcl/tda/apps/voxel_grid_filter.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/common/progress_bar.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/visualization/pcl_visualizer.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <vtkActor2DCollection.h>
#include <vtkRendererCollection.h>
#include <vtkRenderWindow.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace pcl::console;
using ColorCloud = pcl::PointCloud<pcl::PointXYZRGB>;
using RGBHandler = pcl::visualization::PointCloudColorHandlerRGBField<pcl::PointXYZRGB>;

namespace {

/** What the viewer shows. */
enum class Mode { BARCODE, CLUSTERS, REGIONS, HOLES };

struct Options {
  std::string input, fill, screenshot, camera;
  Mode mode = Mode::BARCODE;
  double radius = 0.0, at = 0.0, leaf = 0.0;
  std::size_t memory_limit = pcl::tda::defaultMemoryLimit();
  /** Window size from -size; 0: the default. */
  int width = 0, height = 0;
};

/** The size of a -screenshot without -size or -camera. */
constexpr int SCREENSHOT_WIDTH = 800, SCREENSHOT_HEIGHT = 600;
/** The -barcode mode's arrow keys step the radius by this part of -radius. */
constexpr double STEPS = 40.0;
/** Points are drawn this many pixels wide. */
constexpr double POINT_SIZE = 3.0;
/** The overlays' font size. */
constexpr int FONT_SIZE = 14;
/** The overlay's text starts this many pixels from the bottom left corner, above
 * PCLVisualizer's frame rate. */
constexpr int TEXT_X = 10, TEXT_Y = 24;
/** Clouds whose coordinates are all below this (2^-40, about 1e-12) are drawn
 * scaled up by a power of two: VTK's camera frames them distorted from about 1e-20
 * and not at all from about 1e-25. */
constexpr double MIN_DRAWN_COORDINATE = 0x1p-40;

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s input.pcd <mode> <options>\n", program);
  print_info (
      "  Shows a cloud in a PCLVisualizer window (mouse and keys as in pcl_viewer; "
      "h: help).\n");
  print_info ("  where the mode is one of:\n");
  print_info ("    -barcode    = the cloud coloured by the components of its "
              "Vietoris-Rips complex\n                  at a radius (grey: points "
              "alone) and beside it the H0 and H1 barcode;\n                  "
              "Left/Right step the radius, a line marks it on the barcode\n");
  print_info ("    -clusters   = the labelled output of pcl_tda_segment, a colour per "
              "cluster (grey: none)\n");
  print_info ("    -regions    = the labelled output of pcl_tda_regions, a colour per "
              "region; keys 1 and 2\n                  switch between the region "
              "colours and the points' own colours\n");
  print_info ("    -holes      = the labelled output of pcl_tda_holes, a colour per "
              "hole's rim band\n");
  print_info ("  and the options are:\n");
  print_info (
      "    -radius R   = -barcode: the radius of the complex, the barcode's end "
      "(required)\n");
  print_info ("    -at A       = -barcode: the radius shown first (default: R)\n");
  print_info ("    -leaf L     = -barcode: voxel grid leaf applied first (default 0 = "
              "off)\n");
  print_info (
      "    -memory M   = -barcode: refuse complexes over M MiB (default: half of "
      "the memory)\n");
  print_info (
      "    -fill F.pcd = -holes: the filled cloud of pcl_tda_holes -fill; its new "
      "points are\n                  drawn white and larger\n");
  print_info ("    -screenshot F.png = render off-screen to the picture F.png and exit "
              "(needs an X\n                  display too: on a headless machine, run "
              "under xvfb-run -a)\n");
  print_info (
      "    -size WxH   = the window's size in pixels (default: -screenshot %dx%d, "
      "else half\n                  the screen)\n",
      SCREENSHOT_WIDTH,
      SCREENSHOT_HEIGHT);
  print_info ("    -camera C   = the camera as pcl_viewer's -cam takes it: a .cam file "
              "(saved with\n                  Ctrl+S) or its line, "
              "near,far/focal x,y,z/position x,y,z/view-up\n                  "
              "x,y,z/fovy (radians)/width,height/window x,y\n");
}

/** Reads "WxH" into \a width and \a height.
 * \throws pcl::BadArgumentException when it is not two whole numbers 16 to 8192 */
void
parseSize (const std::string& text, int& width, int& height)
{
  std::istringstream in (text);
  char times = 0;
  if (!(in >> width >> times >> height) || times != 'x' || in.peek() != EOF ||
      width < 16 || height < 16 || width > 8192 || height > 8192)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-size must be WxH, two whole numbers from 16 to 8192 (got '"
                             << text << "').");
}

/** Reads the command line into \a options.
 * \throws pcl::BadArgumentException naming the option at fault */
void
parseOptions (int argc, char** argv, Options& options)
{
  bool barcode = false, clusters = false, regions = false, holes = false;
  std::string size;
  pcl::tda::ToolCommandLine command_line;
  command_line.addSwitch ("-barcode", barcode);
  command_line.addSwitch ("-clusters", clusters);
  command_line.addSwitch ("-regions", regions);
  command_line.addSwitch ("-holes", holes);
  command_line.addNumber (
      "-radius", options.radius, pcl::tda::NumberRange::above (0.0, 1e9));
  command_line.addNumber ("-at", options.at, pcl::tda::NumberRange::atLeast (0.0, 1e9));
  command_line.addNumber (
      "-leaf",
      options.leaf,
      pcl::tda::NumberRange::atLeast (0.0, std::numeric_limits<float>::max()));
  command_line.addMemory ("-memory", options.memory_limit);
  command_line.addText ("-fill", options.fill);
  command_line.addText ("-screenshot", options.screenshot);
  command_line.addText ("-size", size);
  command_line.addText ("-camera", options.camera);
  const std::vector<std::string> files = command_line.parse (argc, argv);
  std::vector<std::string> paths = files;
  std::vector<pcl::tda::ToolArgument> expected{{"input", ".pcd"}};
  if (!options.fill.empty()) {
    paths.push_back (options.fill);
    expected.push_back ({"-fill cloud", ".pcd"});
  }
  if (!options.screenshot.empty()) {
    paths.push_back (options.screenshot);
    expected.push_back ({"-screenshot picture", ".png"});
  }
  if (files.size() != 1)
    pcl::tda::checkArguments (files, {{"input", ".pcd"}});
  pcl::tda::checkArguments (paths, expected);
  options.input = files[0];

  if (barcode + clusters + regions + holes != 1)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Give one mode: -barcode, -clusters, -regions or -holes.");
  options.mode = barcode    ? Mode::BARCODE
                 : clusters ? Mode::CLUSTERS
                 : regions  ? Mode::REGIONS
                            : Mode::HOLES;
  if (barcode && !command_line.given ("-radius"))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "-barcode needs -radius R.");
  for (const char* option : {"-radius", "-at", "-leaf", "-memory"})
    if (!barcode && command_line.given (option))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           option << " has no use without -barcode.");
  if (!holes && command_line.given ("-fill"))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "-fill has no use without -holes.");
  if (!command_line.given ("-at"))
    options.at = options.radius;
  if (options.at > options.radius)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-at " << options.at << " is beyond -radius " << options.radius
                                << ".");
  if (!size.empty())
    parseSize (size, options.width, options.height);
}

/** \a cloud coloured by \a labels (labelColor()), one per point. */
ColorCloud::Ptr
labelColored (const pcl::PointCloud<pcl::PointXYZ>& cloud,
              const std::vector<std::uint32_t>& labels)
{
  ColorCloud::Ptr colored (new ColorCloud);
  pcl::copyPointCloud (cloud, *colored);
  for (std::size_t i = 0; i < colored->size(); ++i) {
    const auto color = pcl::tda::labelColor (labels[i]);
    (*colored)[i].r = color[0];
    (*colored)[i].g = color[1];
    (*colored)[i].b = color[2];
  }
  return colored;
}

/** The text of the -barcode mode's overlay at \a radius. */
std::string
countsText (const pcl::tda::FiltrationAtRadius& filtration, double radius)
{
  const pcl::tda::RadiusCounts counts = filtration.countsAt (radius);
  std::ostringstream text;
  text << "radius " << radius << ": beta_0 " << counts.beta_0 << ", beta_1 "
       << counts.beta_1 << "\n"
       << filtration.complex().numVertices() << " points, " << counts.edges
       << " edges, " << counts.triangles << " triangles";
  return text.str();
}

/** What a window shows: the cloud in each of its colourings (keys 1, 2, ... switch
 * between them), the new points of -holes -fill, the overlay's text and, in -barcode
 * mode, what to recolour the cloud from at a radius. */
struct Scene {
  std::vector<ColorCloud::Ptr> colorings;
  ColorCloud::Ptr extra; ///< -holes -fill: the new points.
  std::string text;
  std::string help;
  std::unique_ptr<pcl::tda::FiltrationAtRadius> filtration;
  pcl::PointCloud<pcl::PointXYZ>::Ptr points; ///< -barcode: the cloud's points.
};

/** Sets the -barcode mode's scene to \a radius: the cloud coloured by the components
 * there, and the overlay's text. */
void
atRadius (Scene& scene, double radius)
{
  scene.colorings = {labelColored (
      *scene.points, scene.filtration->componentLabels (radius, scene.points->size()))};
  scene.text = countsText (*scene.filtration, radius);
}

/** The points of the -barcode mode (after -leaf).
 * \return false, with the reason printed, when they cannot be read
 * \throws pcl::BadArgumentException when their coordinates do not resolve -radius or
 * -leaf (checkToolCoordinates()) */
bool
loadBarcodePoints (const Options& options, pcl::tda::ToolConsole& console, Scene& scene)
{
  scene.points.reset (new pcl::PointCloud<pcl::PointXYZ>);
  if (!console.loadInput (options.input, *scene.points))
    return false;
  pcl::tda::checkToolCoordinates (*scene.points, options.radius, "-radius");
  if (options.leaf > 0.0) {
    pcl::tda::checkToolCoordinates (*scene.points, options.leaf, "-leaf");
    try {
      scene.points =
          pcl::tda::voxelGridFilter<pcl::PointXYZ> (scene.points, options.leaf);
    }
    catch (const pcl::PCLException& error) {
      console.error (pcl::tda::errorMessage (error));
      return false;
    }
  }
  console.endStep (std::to_string (scene.points->size()) + " points");
  return true;
}

/** The -barcode mode's complex of the points up to -radius and its persistence.
 * \return false, with the reason printed, when it cannot be built */
bool
computeBarcode (const Options& options, pcl::tda::ToolConsole& console, Scene& scene)
{
  std::ostringstream radius;
  radius << options.radius;
  console.beginStep ("Computing the persistence up to radius", radius.str());
  pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (scene.points);
  builder.setRadius (options.radius);
  builder.setMemoryLimit (options.memory_limit);
  pcl::tda::FilteredComplex complex;
  {
    pcl::tda::ProgressBar building ("  building");
    builder.setProgressCallback ([&building] (std::size_t done, std::size_t total) {
      building.update (done, total);
    });
    if (!builder.compute (complex)) {
      console.error (
          "Set a larger limit with -memory M (MiB), or use a smaller -radius "
          "or a voxel grid (-leaf).");
      const std::string coincident = pcl::tda::coincidentPointsAdvice (*scene.points);
      if (!coincident.empty())
        console.error (coincident);
      return false;
    }
  }
  pcl::tda::PersistenceResult result = pcl::tda::computePersistence (complex);
  scene.filtration = std::make_unique<pcl::tda::FiltrationAtRadius> (
      std::move (complex), std::move (result));
  console.endStep (
      std::to_string (scene.filtration->complex().numEdges()) + " edges, " +
      std::to_string (scene.filtration->complex().numTriangles()) + " triangles, " +
      std::to_string (scene.filtration->diagram().size()) + " intervals");
  scene.help = "Left/Right: step the radius by 1/40 of -radius\n";
  return true;
}

/** Whether \a filled starts with the points of \a labelled, at the same positions
 * (non-finite ones alike): the filled cloud of pcl_tda_holes -fill on its input. */
bool
startsWithPoints (const pcl::PointCloud<pcl::PointXYZ>& filled,
                  const pcl::PointCloud<pcl::PointXYZRGBL>& labelled)
{
  if (filled.size() < labelled.size())
    return false;
  for (std::size_t i = 0; i < labelled.size(); ++i) {
    const bool finite = pcl::isXYZFinite (labelled[i]);
    if (finite != pcl::isXYZFinite (filled[i]) ||
        (finite && filled[i].getVector3fMap() != labelled[i].getVector3fMap()))
      return false;
  }
  return true;
}

/** The label modes: the labelled cloud (and the filled cloud of -holes -fill).
 * \return false, with the reason printed, when a file cannot be used */
bool
loadLabelScene (const Options& options, pcl::tda::ToolConsole& console, Scene& scene)
{
  console.beginStep ("Loading", options.input);
  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  pcl::PointCloud<pcl::PointXYZ> filled;
  try {
    labelled = pcl::tda::loadLabelledCloud (options.input);
    if (!options.fill.empty())
      pcl::tda::loadPointCloudFile (options.fill, filled);
  }
  catch (const pcl::PCLException& failure) {
    console.error ("Cannot read the PCD file: " + pcl::tda::errorMessage (failure));
    return false;
  }
  if (!options.fill.empty() && !startsWithPoints (filled, labelled)) {
    console.error ("The -fill cloud " + options.fill + " does not start with the " +
                   std::to_string (labelled.size()) + " points of " + options.input +
                   ": pcl_tda_holes -fill writes the input points first, then the new "
                   "ones (a filled cloud of another input?).");
    return false;
  }
  ColorCloud::Ptr by_label (new ColorCloud), own (new ColorCloud);
  pcl::copyPointCloud (labelled, *by_label);
  pcl::copyPointCloud (labelled, *own);
  std::set<std::uint32_t> labels;
  std::size_t in_labels = 0;
  for (std::size_t i = 0; i < labelled.size(); ++i) {
    const auto color = pcl::tda::labelColor (labelled[i].label);
    (*by_label)[i].r = color[0];
    (*by_label)[i].g = color[1];
    (*by_label)[i].b = color[2];
    if (labelled[i].label != 0 && pcl::isXYZFinite (labelled[i])) {
      labels.insert (labelled[i].label);
      ++in_labels;
    }
  }
  scene.colorings.push_back (by_label);
  const std::string noun = options.mode == Mode::CLUSTERS  ? "cluster"
                           : options.mode == Mode::REGIONS ? "region"
                                                           : "hole";
  std::ostringstream text;
  text << labelled.size() << " points, " << labels.size() << " " << noun
       << (labels.size() == 1 ? "" : "s") << " (" << in_labels
       << " points in them; grey: in none)";
  if (options.mode == Mode::REGIONS) {
    scene.colorings.push_back (own);
    scene.help = "1: region colours, 2: the points' own colours\n";
  }
  if (!options.fill.empty()) {
    scene.extra.reset (new ColorCloud);
    for (std::size_t i = labelled.size(); i < filled.size(); ++i) {
      pcl::PointXYZRGB point;
      point.getVector3fMap() = filled[i].getVector3fMap();
      point.r = point.g = point.b = 255;
      scene.extra->push_back (point);
    }
    text << ", " << scene.extra->size() << " new points (white)";
  }
  scene.text = text.str();
  console.endStep (scene.text);
  return true;
}

/** The parts of the window that the keys change. */
struct ViewerLayout {
  /** The viewport of the cloud (0: the whole window). */
  int cloud_viewport = 0;
  /** The barcode beside the cloud, in -barcode mode. */
  std::unique_ptr<pcl::tda::BarcodeOverlay> overlay;
  /** The filtration radius shown, in -barcode mode. */
  double radius = 0.0;
};

/** Puts \a scene into \a viewer: in -barcode mode the cloud's viewport and the
 * barcode's beside it, the clouds (one colouring per key 1, 2, ...), the new points
 * of -fill and the text overlay. */
ViewerLayout
addScene (pcl::visualization::PCLVisualizer& viewer,
          const Options& options,
          Scene& scene)
{
  ViewerLayout layout;
  layout.radius = options.at;
  if (scene.filtration) {
    int barcode_viewport = 0;
    viewer.createViewPort (0.0, 0.0, 0.62, 1.0, layout.cloud_viewport);
    viewer.createViewPort (0.62, 0.0, 1.0, 1.0, barcode_viewport);
    viewer.setBackgroundColor (0.12, 0.12, 0.12, barcode_viewport);
    // PCLVisualizer's viewport n is the n-th renderer of its collection.
    layout.overlay = std::make_unique<pcl::tda::BarcodeOverlay> (
        static_cast<vtkRenderer*> (
            viewer.getRendererCollection()->GetItemAsObject (barcode_viewport)),
        scene.filtration->diagram(),
        options.radius);
    layout.overlay->setRadius (layout.radius);
    atRadius (scene, layout.radius);
  }
  // Colour handlers of blobs, the kind that PCLVisualizer keeps several of per cloud
  // for the keys 1, 2, ... to switch between.
  for (const ColorCloud::Ptr& colors : scene.colorings) {
    pcl::PCLPointCloud2::Ptr blob (new pcl::PCLPointCloud2);
    pcl::toPCLPointCloud2 (*colors, *blob);
    viewer.addPointCloud (
        blob,
        std::make_shared<
            pcl::visualization::PointCloudGeometryHandlerXYZ<pcl::PCLPointCloud2>> (
            blob),
        std::make_shared<
            pcl::visualization::PointCloudColorHandlerRGBField<pcl::PCLPointCloud2>> (
            blob),
        colors->sensor_origin_,
        colors->sensor_orientation_,
        "cloud",
        layout.cloud_viewport);
  }
  viewer.setPointCloudRenderingProperties (
      pcl::visualization::PCL_VISUALIZER_POINT_SIZE, POINT_SIZE, "cloud");
  if (scene.extra) {
    viewer.addPointCloud<pcl::PointXYZRGB> (
        scene.extra, RGBHandler (scene.extra), "new points", layout.cloud_viewport);
    viewer.setPointCloudRenderingProperties (
        pcl::visualization::PCL_VISUALIZER_POINT_SIZE, 2 * POINT_SIZE, "new points");
  }
  viewer.addText (scene.text,
                  TEXT_X,
                  TEXT_Y,
                  FONT_SIZE,
                  1.0,
                  1.0,
                  1.0,
                  "overlay",
                  layout.cloud_viewport);
  print_info ("%s\n", scene.text.c_str());
  return layout;
}

/** Places the camera: around the clouds, or as -camera says, and sizes the window.
 * \return false, with a message, when -camera cannot be used */
bool
placeCamera (pcl::visualization::PCLVisualizer& viewer,
             const Options& options,
             pcl::tda::ToolConsole& console)
{
  viewer.initCameraParameters();
  viewer.resetCamera();
  if (!options.camera.empty()) {
    char program[] = "pcl_tda_viewer", option[] = "-cam";
    std::vector<char> value (options.camera.begin(), options.camera.end());
    value.push_back ('\0');
    char* arguments[] = {program, option, value.data()};
    if (!viewer.getCameraParameters (3, arguments)) {
      console.error (
          "Cannot use the camera of -camera '" + options.camera +
          "': give a readable .cam file (as Ctrl+S saves them) or a line of one, "
          "near,far/x,y,z/x,y,z/x,y,z/fovy/width,height/x,y.");
      return false;
    }
  }
  if (options.width > 0)
    viewer.setSize (options.width, options.height);
  else if (!options.screenshot.empty() && options.camera.empty())
    viewer.setSize (SCREENSHOT_WIDTH, SCREENSHOT_HEIGHT);
  return true;
}

/** Renders \a viewer off-screen into the picture of -screenshot.
 * \return the exit code */
int
saveScreenshot (pcl::visualization::PCLVisualizer& viewer,
                const Options& options,
                pcl::tda::ToolOutputs& outputs,
                pcl::tda::ToolConsole& console)
{
  console.beginStep ("Rendering", options.screenshot);
  try {
    pcl::tda::saveWindowPicture (viewer.getRenderWindow(),
                                 outputs.temporary (options.screenshot));
    outputs.commit();
  }
  catch (const std::exception& error) {
    console.error (outputs.message (error));
    return 1;
  }
  const int* size = viewer.getRenderWindow()->GetSize();
  console.endStep (std::to_string (size[0]) + " x " + std::to_string (size[1]) +
                   " pixels");
  return 0;
}

/** Divides the positions of \a cloud by \a scale (a power of two: exact). */
template <typename PointT>
void
divideScale (pcl::PointCloud<PointT>& cloud, double scale)
{
  for (PointT& point : cloud)
    point.getVector3fMap() /= static_cast<float> (scale);
}

/** Scales the clouds of \a scene up by a power of two to be drawn when their
 * coordinates are all below MIN_DRAWN_COORDINATE, and says so. Done after the
 * persistence: only the drawing changes. */
void
scaleTinyClouds (Scene& scene)
{
  double largest = 0.0;
  if (scene.points)
    largest = pcl::tda::largestCoordinate (*scene.points);
  for (const ColorCloud::Ptr& colors : scene.colorings)
    largest = std::max (largest, pcl::tda::largestCoordinate (*colors));
  if (scene.extra)
    largest = std::max (largest, pcl::tda::largestCoordinate (*scene.extra));
  if (!(largest > 0.0 && largest < MIN_DRAWN_COORDINATE))
    return;
  const double scale = pcl::tda::powerOfTwoScale (largest);
  if (scene.points)
    divideScale (*scene.points, scale);
  for (const ColorCloud::Ptr& colors : scene.colorings)
    divideScale (*colors, scale);
  if (scene.extra)
    divideScale (*scene.extra, scale);
  print_info ("Coordinates up to %g, too small for VTK's camera: drawn multiplied by "
              "2^%d.\n",
              largest,
              -std::ilogb (scale));
}

/** Runs the window until it is closed: the mouse and keys of pcl_viewer, h for the
 * help, and in -barcode mode Left and Right to step the radius. */
void
interact (pcl::visualization::PCLVisualizer& viewer,
          const Options& options,
          Scene& scene,
          ViewerLayout& layout)
{
  const std::string help =
      "h: this help (again: hide it); mouse and keys as in pcl_viewer:\n"
      "left drag: rotate, wheel: zoom, r: reset the camera, +/-: point size,\n"
      "j: save a screenshot, c: print the camera, Ctrl+S: save it, q: quit\n" +
      scene.help;
  bool help_shown = false;
  viewer.registerKeyboardCallback (
      [&] (const pcl::visualization::KeyboardEvent& event) {
        if (!event.keyDown())
          return;
        const std::string key = event.getKeySym();
        if (key == "h") {
          help_shown = !help_shown;
          if (help_shown)
            viewer.addText (help,
                            TEXT_X,
                            TEXT_Y + 3 * FONT_SIZE,
                            FONT_SIZE,
                            1.0,
                            1.0,
                            0.6,
                            "help",
                            layout.cloud_viewport);
          else
            viewer.removeShape ("help", layout.cloud_viewport);
        }
        else if (scene.filtration && (key == "Left" || key == "Right")) {
          const double step = options.radius / STEPS;
          layout.radius = std::clamp (
              layout.radius + (key == "Right" ? step : -step), 0.0, options.radius);
          atRadius (scene, layout.radius);
          viewer.updatePointCloud<pcl::PointXYZRGB> (
              scene.colorings.front(), RGBHandler (scene.colorings.front()), "cloud");
          layout.overlay->setRadius (layout.radius);
          viewer.updateText (
              scene.text, TEXT_X, TEXT_Y, FONT_SIZE, 1.0, 1.0, 1.0, "overlay");
          print_info ("%s\n", scene.text.c_str());
        }
      });
  std::fflush (stdout); // the overlay's text, for scripts, before the window opens
  viewer.spin();
}

/** Shows \a scene: in a window until it is closed, or off-screen into the picture
 * of -screenshot.
 * \return the exit code */
int
show (const Options& options,
      pcl::tda::ToolOutputs& outputs,
      pcl::tda::ToolConsole& console,
      Scene& scene)
{
  const bool screenshot = !options.screenshot.empty();
  pcl::visualization::PCLVisualizer viewer ("pcl_tda_viewer " + options.input,
                                            !screenshot);
  if (screenshot) {
    viewer.getRenderWindow()->SetOffScreenRendering (1);
    // The frame rate, the only 2D actor so far, would vary from picture to picture.
    vtkActor2DCollection* actors =
        viewer.getRendererCollection()->GetFirstRenderer()->GetActors2D();
    actors->InitTraversal();
    actors->GetNextActor2D()->VisibilityOff();
  }
  ViewerLayout layout = addScene (viewer, options, scene);
  if (!placeCamera (viewer, options, console))
    return 1;
  if (screenshot)
    return saveScreenshot (viewer, options, outputs, console);
  interact (viewer, options, scene, layout);
  return 0;
}

int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  pcl::tda::ToolOutputs outputs (std::vector<std::string>{options.input, options.fill},
                                 {{"-screenshot", options.screenshot}});
  Scene scene;
  // The files are checked first, then the display, then the persistence computed.
  if (!(options.mode == Mode::BARCODE ? loadBarcodePoints (options, console, scene)
                                      : loadLabelScene (options, console, scene)))
    return 1;
  const pcl::tda::DisplayConnection display;
  if (!display.problem().empty()) {
    console.error ("No X display (" + display.problem() +
                   "): the viewer draws with OpenGL on an X display, also for "
                   "-screenshot. On a machine without one, run it on a virtual one: "
                   "xvfb-run -a pcl_tda_viewer ... -screenshot out.png");
    return 1;
  }
  if (options.mode == Mode::BARCODE && !computeBarcode (options, console, scene))
    return 1;
  scaleTinyClouds (scene);
  return show (options, outputs, console, scene);
}

} // namespace

int
main (int argc, char** argv)
{
  return pcl::tda::runTool<Options> (
      argc, argv, "Viewer of persistence results.", printHelp, parseOptions, run, 1);
}
