/** pcl_tda_generate: writes a synthetic point cloud with exact ground truth (a
 * circle, torus or sphere with known Betti numbers, or a labelled tabletop scene)
 * to a binary PCD file. */

#include <pcl/console/print.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/exceptions.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace pcl::console;

namespace {

/** The most points -n asks for: the cloud (32 bytes a point) and its file (16)
 * then take about 0.5 GB. */
constexpr long MAX_POINTS = 10000000;

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s <circle|torus|sphere|tabletop> output.pcd <options>\n",
              program);
  print_info ("  where options are:\n");
  print_info (
      "    -n N       = number of points of a shape, 1 to %ld (default: circle "
      "1000,\n"
      "                 torus 2500, sphere 1500); for tabletop, about N samples "
      "on the table\n"
      "                 top, which sets the sampling density (default: one "
      "point per 1 cm x 1 cm;\n"
      "                 at least 1750)\n",
      MAX_POINTS);
  print_info ("    -noise S   = Gaussian noise sigma of a shape (default 0.01), or the "
              "depth noise sigma at 1 m\n"
              "                 of the tabletop camera (default 0.001)\n");
  print_info ("    -seed S    = random seed, >= 0 (default 0); equal seeds give "
              "identical files\n");
  print_info ("    -objects K = number of tabletop objects, 0 to %zu (default 4)\n",
              pcl::tda::MAX_TABLETOP_OBJECTS);
}

/** The parameters of the command line; n 0, objects and noise < 0 when not
 * given. */
struct Options {
  std::string kind, output;
  long n = 0, seed = 0, objects = -1;
  double noise = -1.0;
};

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
  command_line.addInteger ("-seed", options.seed, 0, std::numeric_limits<long>::max());
  command_line.addInteger ("-objects",
                           options.objects,
                           0,
                           static_cast<long> (pcl::tda::MAX_TABLETOP_OBJECTS));
  const std::vector<std::string> arguments = command_line.parse (argc, argv);
  pcl::tda::checkArguments (arguments, {{"kind", ""}, {"output", ".pcd"}});
  options.kind = arguments[0];
  options.output = arguments[1];
  if (options.kind != "circle" && options.kind != "torus" && options.kind != "sphere" &&
      options.kind != "tabletop")
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Unknown kind '" << options.kind
                                          << "': use circle, torus, sphere or "
                                             "tabletop.");
  if (options.objects >= 0 && options.kind != "tabletop")
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Option -objects applies to tabletop only.");
}

/** Writes the cloud as binary PCD to the temporary file of \a outputs and commits
 * it, as a console step. */
bool
saveCloud (const std::string& path,
           const pcl::PointCloud<pcl::PointXYZRGBL>& cloud,
           pcl::tda::ToolOutputs& outputs,
           pcl::tda::ToolConsole& console)
{
  console.beginStep ("Saving", path);
  try {
    pcl::tda::savePointCloudFile (outputs.temporary (path), cloud);
    outputs.commit();
  }
  catch (const pcl::PCLException& e) {
    console.error ("Cannot write " + path + ": " + pcl::tda::errorMessage (e));
    return false;
  }
  console.endStep (std::to_string (cloud.size()) + " points");
  return true;
}

/** Generates the cloud of \a options and saves it. */
int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  pcl::tda::ToolOutputs outputs ("", {{"output", options.output}});
  const std::string& kind = options.kind;
  const long n = options.n, seed = options.seed, objects = options.objects;
  const double noise = options.noise;
  console.beginStep ("Generating", kind);
  if (kind == "tabletop") {
    pcl::tda::TabletopParameters parameters;
    if (n > 0)
      parameters.point_spacing = static_cast<float> (std::sqrt (
          static_cast<double> (parameters.table_width) * parameters.table_depth / n));
    if (noise >= 0.0)
      parameters.noise_sigma = static_cast<float> (noise);
    if (objects >= 0)
      parameters.num_objects = static_cast<std::size_t> (objects);
    parameters.seed = static_cast<std::uint64_t> (seed);
    const pcl::tda::TabletopScene scene = pcl::tda::generateTabletopScene (parameters);
    console.endStep (std::to_string (scene.cloud->size()) + " points, " +
                     std::to_string (scene.objects.size()) + " objects");
    print_info ("Labels: table ");
    print_value ("%u", pcl::tda::TABLE_LABEL);
    print_info (", objects ");
    print_value ("%u", pcl::tda::FIRST_OBJECT_LABEL);
    print_info (" to ");
    print_value ("%zu\n", pcl::tda::FIRST_OBJECT_LABEL + scene.objects.size() - 1);
    return saveCloud (options.output, *scene.cloud, outputs, console) ? 0 : 1;
  }

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
