/** pcl_tda_generate: writes a synthetic point cloud with exact ground truth (a
 * circle, torus or sphere with known Betti numbers, or a labelled tabletop scene)
 * to a binary PCD file. */

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/exceptions.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace pcl::console;

namespace {

const char* const OPTIONS[] = {"-n", "-noise", "-seed", "-objects"};

void
printHelp (int, char** argv)
{
  print_error ("Syntax is: %s <circle|torus|sphere|tabletop> output.pcd <options>\n",
               argv[0]);
  print_info ("  where options are:\n");
  print_info ("    -n N       = number of points of a shape (default: circle 1000, "
              "torus 2500, sphere 1500);\n"
              "                 for tabletop, about N samples on the table top, which "
              "sets the sampling density\n"
              "                 (default: one point per 1 cm x 1 cm; at least 1750)\n");
  print_info ("    -noise S   = Gaussian noise sigma of a shape (default 0.01), or the "
              "depth noise sigma at 1 m\n"
              "                 of the tabletop camera (default 0.001)\n");
  print_info ("    -seed S    = random seed, >= 0 (default 0); equal seeds give "
              "identical files\n");
  print_info ("    -objects K = number of tabletop objects, 0 to %zu (default 4)\n",
              pcl::tda::MAX_TABLETOP_OBJECTS);
}

/** Checks that every argument after the kind and the output file is a known option
 * followed by a value. */
bool
checkOptions (int argc, char** argv)
{
  for (int i = 3; i < argc; i += 2) {
    bool known = false;
    for (const char* option : OPTIONS)
      known = known || std::strcmp (argv[i], option) == 0;
    if (!known) {
      print_error ("Unknown argument %s.\n", argv[i]);
      return false;
    }
    if (i + 1 >= argc) {
      print_error ("Option %s needs a value.\n", argv[i]);
      return false;
    }
  }
  return true;
}

/** Parses an integer option; false with a message when it is present but invalid
 * or below minimum. */
bool
parseInteger (int argc, char** argv, const char* option, long minimum, long& value)
{
  if (find_argument (argc, argv, option) < 0)
    return true;
  if (parse_argument (argc, argv, option, value) < 0 || value < minimum) {
    print_error ("Option %s needs an integer >= %ld.\n", option, minimum);
    return false;
  }
  return true;
}

/** Writes the cloud as binary PCD, atomically, with the tool's progress lines. */
bool
saveCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZRGBL>& cloud)
{
  TicToc tt;
  tt.tic();
  print_highlight ("Saving ");
  print_value ("%s ", path.c_str());
  try {
    pcl::tda::savePointCloudFile (path, cloud);
  }
  catch (const pcl::PCLException& e) {
    print_error (
        "\nCannot write %s: %s\n", path.c_str(), pcl::tda::errorMessage (e).c_str());
    return false;
  }
  print_info ("[done, ");
  print_value ("%g", tt.toc());
  print_info (" ms : ");
  print_value ("%zu", cloud.size());
  print_info (" points]\n");
  return true;
}

} // namespace

int
main (int argc, char** argv)
{
  print_info ("Generate a synthetic point cloud with exact ground truth. For more "
              "information, use: %s -h\n",
              argv[0]);
  if (find_switch (argc, argv, "-h") || find_switch (argc, argv, "--help")) {
    printHelp (argc, argv);
    return 0;
  }
  if (argc < 3) {
    printHelp (argc, argv);
    return 1;
  }
  const std::string kind = argv[1];
  const std::string output = argv[2];
  if (kind != "circle" && kind != "torus" && kind != "sphere" && kind != "tabletop") {
    print_error ("Unknown kind '%s': use circle, torus, sphere or tabletop.\n",
                 kind.c_str());
    return 1;
  }
  if (!checkOptions (argc, argv))
    return 1;

  long n = 0, seed = 0, objects = -1;
  double noise = -1.0;
  if (!parseInteger (argc, argv, "-n", 1, n) ||
      !parseInteger (argc, argv, "-seed", 0, seed) ||
      !parseInteger (argc, argv, "-objects", 0, objects))
    return 1;
  if (find_argument (argc, argv, "-noise") >= 0 &&
      (parse_argument (argc, argv, "-noise", noise) < 0 || !std::isfinite (noise) ||
       noise < 0.0)) {
    print_error ("Option -noise needs a finite number >= 0.\n");
    return 1;
  }
  if (objects >= 0 && kind != "tabletop") {
    print_error ("Option -objects applies to tabletop only.\n");
    return 1;
  }

  TicToc tt;
  tt.tic();
  print_highlight ("Generating ");
  print_value ("%s ", kind.c_str());
  try {
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
      const pcl::tda::TabletopScene scene =
          pcl::tda::generateTabletopScene (parameters);
      print_info ("[done, ");
      print_value ("%g", tt.toc());
      print_info (" ms : ");
      print_value ("%zu", scene.cloud->size());
      print_info (" points, ");
      print_value ("%zu", scene.objects.size());
      print_info (" objects]\n");
      print_info ("Labels: table ");
      print_value ("%u", pcl::tda::TABLE_LABEL);
      print_info (", objects ");
      print_value ("%u", pcl::tda::FIRST_OBJECT_LABEL);
      print_info (" to ");
      print_value ("%zu\n", pcl::tda::FIRST_OBJECT_LABEL + scene.objects.size() - 1);
      return saveCloud (output, *scene.cloud) ? 0 : 1;
    }

    pcl::tda::SyntheticShape shape;
    if (kind == "circle") {
      pcl::tda::CircleParameters parameters;
      if (n > 0)
        parameters.num_points = static_cast<std::size_t> (n);
      if (noise >= 0.0)
        parameters.noise_sigma = static_cast<float> (noise);
      parameters.seed = static_cast<std::uint64_t> (seed);
      shape = pcl::tda::generateCircle (parameters);
    }
    else if (kind == "torus") {
      pcl::tda::TorusParameters parameters;
      if (n > 0)
        parameters.num_points = static_cast<std::size_t> (n);
      if (noise >= 0.0)
        parameters.noise_sigma = static_cast<float> (noise);
      parameters.seed = static_cast<std::uint64_t> (seed);
      shape = pcl::tda::generateTorus (parameters);
    }
    else {
      pcl::tda::SphereParameters parameters;
      if (n > 0)
        parameters.num_points = static_cast<std::size_t> (n);
      if (noise >= 0.0)
        parameters.noise_sigma = static_cast<float> (noise);
      parameters.seed = static_cast<std::uint64_t> (seed);
      shape = pcl::tda::generateSphere (parameters);
    }
    print_info ("[done, ");
    print_value ("%g", tt.toc());
    print_info (" ms : ");
    print_value ("%zu", shape.cloud->size());
    print_info (" points]\n");
    print_info ("Expected Betti numbers: beta0 = ");
    print_value ("%d", shape.beta0);
    print_info (", beta1 = ");
    print_value ("%d", shape.beta1);
    print_info ("; suggested Vietoris-Rips radius: ");
    print_value ("%g\n", shape.suggested_radius);
    return saveCloud (output, *shape.cloud) ? 0 : 1;
  }
  catch (const pcl::BadArgumentException& e) {
    print_error ("\n%s\n", pcl::tda::errorMessage (e).c_str());
    return 1;
  }
}
