// pcl_tda_classify: object category classification with global descriptors and an
// RBF SVM, by the protocol of thesis Sec 6.5 (one instance of each category held
// out per trial, parameters chosen by cross-validation over the other instances).

#include <pcl/console/print.h>
#include <pcl/tda/apps/category_classification.h>
#include <pcl/tda/apps/category_protocol.h>
#include <pcl/tda/apps/classification_tables.h>
#include <pcl/tda/apps/confusion_matrix_plot.h>
#include <pcl/tda/apps/csv_fields.h>
#include <pcl/tda/apps/descriptor_list.h>
#include <pcl/tda/apps/sanitizer_options.h> // this program runs PCL's GRSD and CVFH
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/apps/view_descriptors.h>
#include <pcl/tda/apps/view_files.h>
#include <pcl/tda/apps/view_manifest.h>
#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/progress_bar.h>
#include <pcl/tda/common/resource_settings.h>
#include <pcl/tda/search/parallel_progress.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace pcl::console;

namespace {

struct Options {
  std::string manifest, descriptors = pcl::tda::DEFAULT_DESCRIPTORS, csv, features, svg,
                        png, confusion, scaling = "minmax";
  long trials = 10, folds = 3, seed = 0, threads = 0;
};

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s manifest.csv <options>\n", program);
  print_info ("  Classifies the views of object instances into categories with global "
              "descriptors and\n  an RBF SVM (thesis Sec 6.5): per trial, one instance "
              "of each category is held out\n  for testing and the SVM, its C and "
              "gamma chosen by cross-validation over the other\n  instances, is "
              "trained on their views. The manifest is a CSV file with the columns\n  "
              "path,category,instance,view (paths relative to its folder).\n");
  print_info ("  where options are:\n");
  print_info ("    -descriptors L = comma-separated descriptors, default:\n"
              "                     %s\n"
              "                     known: ",
              pcl::tda::DEFAULT_DESCRIPTORS);
  for (const std::string& name : pcl::tda::viewDescriptorNames())
    print_info ("%s ", name.c_str());
  print_info ("\n                     A+B concatenates A and B\n");
  print_info ("    -trials N      = trials, each with its held-out instances (default "
              "10)\n");
  print_info ("    -folds K       = cross-validation folds of whole instances (default "
              "3; 0: one per\n                     instance)\n");
  print_info ("    -seed S        = seed of the held-out instances and the folds "
              "(default 0)\n");
  print_info ("    -scaling M     = minmax (default: to [0, 1]) or zscore: how "
              "descriptor values are\n                     scaled, on the training "
              "views only\n");
  print_info ("    -threads N     = threads (default: all)\n");
  print_info ("    -csv F.csv     = also write the results, a row per descriptor\n");
  print_info ("    -features F.csv = also write every view's descriptors\n");
  print_info ("    -svg F.svg     = also draw the confusion matrix of the best "
              "descriptor\n");
  print_info ("    -png F.png     = the same picture as PNG\n");
  print_info ("    -confusion D   = draw descriptor D instead of the best\n");
  print_info ("  Outputs are written only when the whole run succeeds.\n");
}

/** Reads the command line into \a options.
 * \throws pcl::BadArgumentException naming the option at fault */
void
parseOptions (int argc, char** argv, Options& options)
{
  pcl::tda::ToolCommandLine command_line;
  command_line.addText ("-descriptors", options.descriptors);
  command_line.addInteger ("-trials", options.trials, 1, 10000);
  command_line.addInteger ("-folds", options.folds, 0, 1000);
  command_line.addInteger ("-seed", options.seed, 0, std::numeric_limits<long>::max());
  command_line.addText ("-scaling", options.scaling);
  command_line.addInteger ("-threads", options.threads, 1, pcl::tda::MAX_THREADS);
  command_line.addText ("-csv", options.csv);
  command_line.addText ("-features", options.features);
  command_line.addText ("-svg", options.svg);
  command_line.addText ("-png", options.png);
  command_line.addText ("-confusion", options.confusion);
  const std::vector<std::string> files = command_line.parse (argc, argv);
  pcl::tda::checkArguments (files, {{"manifest", ".csv"}});
  options.manifest = files[0];
  if (options.folds == 1)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-folds needs at least 2 folds, or 0 for one per instance.");
  if (options.scaling != "zscore" && options.scaling != "minmax")
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-scaling must be zscore or minmax (got '" << options.scaling
                                                                    << "').");
  pcl::tda::checkOptionExtension ("-csv", options.csv, ".csv");
  pcl::tda::checkOptionExtension ("-features", options.features, ".csv");
  pcl::tda::checkOptionExtension ("-svg", options.svg, ".svg");
  pcl::tda::checkOptionExtension ("-png", options.png, ".png");
  const auto specs = pcl::tda::parseDescriptorList (options.descriptors);
  if (!options.confusion.empty() &&
      std::none_of (specs.begin(), specs.end(), [&options] (const auto& spec) {
        return spec.name == options.confusion;
      }))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-confusion " << options.confusion
                                       << " is not one of the -descriptors.");
  if (!options.confusion.empty() && options.svg.empty() && options.png.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-confusion has no use without -svg or -png.");
}

/** The descriptors \a names of every view, computed in parallel; ESF is seeded by
 * the view's path in the manifest, so that it does not depend on the order of the
 * views or on the threads.
 * \return false, with the reason printed, when a view cannot be read */
bool
computeDescriptors (const pcl::tda::ViewManifest& manifest,
                    const std::vector<std::string>& names,
                    pcl::tda::ToolConsole& console,
                    std::vector<std::vector<pcl::tda::ViewDescriptor>>& computed)
{
  std::vector<std::string> files, paths;
  for (const auto& view : manifest.views) {
    files.push_back (view.file);
    paths.push_back (view.path);
  }
  std::vector<pcl::tda::DescribedFile> described =
      pcl::tda::describeViewFiles (files, paths, names, {}, "  views");
  computed.clear();
  for (std::size_t i = 0; i < described.size(); ++i) {
    if (!described[i].error.empty()) {
      console.error ("Cannot read the view " + manifest.views[i].path +
                     " (manifest line " + std::to_string (manifest.views[i].line) +
                     "): " + described[i].error);
      return false;
    }
    computed.push_back (std::move (described[i].descriptors));
  }
  return true;
}

/** The median of \a values (0 for none). */
double
median (std::vector<double> values)
{
  if (values.empty())
    return 0.0;
  const auto middle = values.begin() + static_cast<long> (values.size() / 2);
  std::nth_element (values.begin(), middle, values.end());
  if (values.size() % 2 == 1)
    return *middle;
  return (*middle + *std::max_element (values.begin(), middle)) / 2.0;
}

/** "2^5", or the number itself when it is no power of 2. */
std::string
powerOfTwo (double value)
{
  const double exponent = std::log2 (value);
  if (std::abs (exponent - std::round (exponent)) < 1e-9)
    return "2^" + std::to_string (static_cast<long> (std::round (exponent)));
  return pcl::tda::formatNumber (value);
}

/** Prints the results as a table. */
void
printTable (const std::vector<pcl::tda::DescriptorSummary>& summaries)
{
  print_info ("\n%-16s %6s %8s %16s %6s %9s %6s %10s %9s\n",
              "descriptor",
              "dim",
              "failed",
              "accuracy (%)",
              "C",
              "gamma",
              "chosen",
              "ms/view",
              "total s");
  for (const auto& summary : summaries) {
    const auto [chosen, chosen_in] = pcl::tda::mostChosen (summary.outcome);
    char accuracy[32];
    std::snprintf (accuracy,
                   sizeof (accuracy),
                   "%.1f +- %.1f",
                   100.0 * summary.outcome.meanAccuracy(),
                   100.0 * summary.outcome.accuracyDeviation());
    const std::string gamma =
        summary.dimension == 0
            ? "-"
            : powerOfTwo (chosen.gamma * static_cast<double> (summary.dimension)) +
                  "/d";
    print_info ("%-16s %6zu %8zu %16s %6s %9s %3zu/%-2zu %10.3g %9.3g\n",
                summary.name.c_str(),
                summary.dimension,
                summary.failed_views,
                accuracy,
                summary.dimension == 0 ? "-" : powerOfTwo (chosen.c).c_str(),
                gamma.c_str(),
                chosen_in,
                summary.outcome.trials.size(),
                summary.median_milliseconds,
                summary.total_seconds);
  }
  print_info ("(accuracy: mean +- sample standard deviation over the trials; C, gamma: "
              "the choice of most\n trials, d the dimension; ms/view: median time to "
              "compute the descriptor on a view, normals\n included; total s: its time "
              "on all views, summed over the threads)\n\n");
}

/** Prints the views on which each descriptor failed (the first few). */
void
printFailures (const pcl::tda::ViewManifest& manifest,
               const std::vector<std::string>& names,
               const std::vector<std::vector<pcl::tda::ViewDescriptor>>& computed)
{
  constexpr std::size_t MAX_LINES = 5;
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::size_t failed = 0;
    for (std::size_t i = 0; i < computed.size(); ++i) {
      const std::string& failure = computed[i][k].failure;
      if (failure.empty())
        continue;
      if (failed++ < MAX_LINES)
        print_warn ("  %s failed on %s: %s\n",
                    names[k].c_str(),
                    manifest.views[i].path.c_str(),
                    failure.c_str());
    }
    if (failed > 0)
      print_warn ("  %s failed on %zu of %zu views: they count as misclassified when "
                  "held out\n",
                  names[k].c_str(),
                  failed,
                  computed.size());
  }
}

/** Writes the outputs asked for to the temporary files of \a outputs. */
void
writeOutputs (const Options& options,
              const pcl::tda::ToolOutputs& outputs,
              const pcl::tda::ViewManifest& manifest,
              const std::vector<std::string>& names,
              const std::vector<std::vector<pcl::tda::ViewDescriptor>>& computed,
              const std::vector<pcl::tda::DescriptorSummary>& summaries)
{
  if (!options.csv.empty())
    pcl::tda::writeFileAtomically (outputs.temporary (options.csv),
                                   [&summaries] (std::ostream& out) {
                                     pcl::tda::writeResultsCSV (out, summaries);
                                   });
  if (!options.features.empty())
    pcl::tda::writeFileAtomically (
        outputs.temporary (options.features), [&] (std::ostream& out) {
          pcl::tda::writeFeaturesCSV (out, manifest, names, computed);
        });
  if (options.svg.empty() && options.png.empty())
    return;
  // The descriptor of the picture: the one asked for, or the best (the first of
  // equal mean accuracies).
  const pcl::tda::DescriptorSummary* shown = &summaries.front();
  for (const auto& summary : summaries)
    if (options.confusion.empty()
            ? summary.outcome.meanAccuracy() > shown->outcome.meanAccuracy()
            : summary.name == options.confusion)
      shown = &summary;
  pcl::tda::ConfusionPlot plot;
  char title[160];
  std::snprintf (title,
                 sizeof (title),
                 "%s: accuracy %.1f +- %.1f %% over %zu trials (rows sum to 1)",
                 shown->name.c_str(),
                 100.0 * shown->outcome.meanAccuracy(),
                 100.0 * shown->outcome.accuracyDeviation(),
                 shown->outcome.trials.size());
  plot.title = title;
  plot.categories = manifest.categories;
  plot.counts = shown->outcome.confusion;
  if (!options.svg.empty())
    pcl::tda::saveConfusionMatrixSVG (outputs.temporary (options.svg), plot);
  if (!options.png.empty())
    pcl::tda::saveConfusionMatrixPNG (outputs.temporary (options.png), plot);
}

int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  pcl::tda::ToolOutputs outputs (options.manifest,
                                 {{"-csv", options.csv},
                                  {"-features", options.features},
                                  {"-svg", options.svg},
                                  {"-png", options.png}});
  if (options.threads > 0)
    omp_set_num_threads (static_cast<int> (options.threads));
  const std::vector<pcl::tda::DescriptorSpec> specs =
      pcl::tda::parseDescriptorList (options.descriptors);
  const std::vector<std::string> names = pcl::tda::neededViewDescriptors (specs);

  console.beginStep ("Reading", options.manifest);
  pcl::tda::ViewManifest manifest;
  try {
    manifest = pcl::tda::readViewManifest (options.manifest);
  }
  catch (const pcl::PCLException& error) {
    console.error ("Cannot use the manifest: " + pcl::tda::errorMessage (error));
    return 1;
  }
  const std::vector<pcl::tda::ProtocolTrial> trials =
      pcl::tda::makeProtocolTrials (manifest,
                                    static_cast<std::size_t> (options.trials),
                                    static_cast<std::size_t> (options.folds),
                                    static_cast<std::uint64_t> (options.seed));
  console.endStep (std::to_string (manifest.views.size()) + " views of " +
                   std::to_string (manifest.instances.size()) + " instances in " +
                   std::to_string (manifest.categories.size()) + " categories");

  console.beginStep ("Computing descriptors",
                     pcl::tda::countOf (names.size(), "descriptor") + ", " +
                         std::to_string (omp_get_max_threads()) + " threads");
  std::vector<std::vector<pcl::tda::ViewDescriptor>> computed;
  if (!computeDescriptors (manifest, names, console, computed))
    return 1;
  console.endStep (std::to_string (manifest.views.size()) + " views");
  printFailures (manifest, names, computed);

  pcl::tda::ClassificationSettings settings;
  settings.scaling = options.scaling == "zscore"
                         ? pcl::tda::FeatureScalingMode::Z_SCORE
                         : pcl::tda::FeatureScalingMode::MIN_MAX;
  console.beginStep ("Classifying",
                     std::to_string (specs.size()) + " descriptors, " +
                         std::to_string (trials.size()) + " trials, " +
                         std::to_string (trials.front().folds) + " folds");
  std::vector<pcl::tda::DescriptorSummary> summaries;
  {
    pcl::tda::ProgressBar bar ("  SVMs");
    const pcl::tda::ProgressCallback report =
        [&bar] (std::size_t done, std::size_t total) { bar.update (done, total); };
    pcl::tda::ParallelProgress progress (
        report, specs.size() * pcl::tda::classificationWork (trials, settings));
    for (const pcl::tda::DescriptorSpec& spec : specs) {
      const pcl::tda::DescriptorTable table =
          pcl::tda::assembleDescriptor (spec, names, computed);
      pcl::tda::DescriptorSummary summary;
      summary.name = spec.name;
      summary.dimension = table.dimension;
      summary.views = table.rows.size();
      for (const std::string& failure : table.failures)
        summary.failed_views += failure.empty() ? 0 : 1;
      summary.median_milliseconds = median (table.milliseconds);
      for (const double milliseconds : table.milliseconds)
        summary.total_seconds += milliseconds / 1000.0;
      summary.outcome = pcl::tda::evaluateDescriptor (
          table.rows, table.parts, manifest, trials, settings, &progress);
      summaries.push_back (summary);
    }
  }
  console.endStep (std::to_string (specs.size()) + " descriptors");
  printTable (summaries);

  std::size_t files = 0;
  for (const std::string* path :
       {&options.csv, &options.features, &options.svg, &options.png})
    files += !path->empty();
  if (files == 0)
    return 0; // the table above is the result
  console.beginStep ("Saving");
  try {
    writeOutputs (options, outputs, manifest, names, computed, summaries);
    outputs.commit();
  }
  catch (const std::exception& error) {
    console.error (outputs.message (error));
    return 1;
  }
  console.endStep (pcl::tda::countOf (files, "file"));
  return 0;
}

} // namespace

int
main (int argc, char** argv)
{
  return pcl::tda::runTool<Options> (
      argc, argv, "Object category classification.", printHelp, parseOptions, run, 1);
}
