#include <pcl/tda/apps/classification_tables.h>
#include <pcl/tda/apps/csv_fields.h>

#include <map>
#include <tuple>

namespace pcl {
namespace tda {
namespace {

/** The per-trial values \a value (trial) space-separated. */
template <typename Value>
std::string
perTrial (const DescriptorOutcome& outcome, Value value)
{
  std::string text;
  for (const TrialOutcome& trial : outcome.trials)
    text += (text.empty() ? "" : " ") + formatNumber (value (trial));
  return text;
}

} // namespace

std::pair<SVMParameters, std::size_t>
mostChosen (const DescriptorOutcome& outcome)
{
  std::map<std::pair<double, double>, std::size_t> counts;
  for (const TrialOutcome& trial : outcome.trials)
    ++counts[{trial.chosen.c, trial.chosen.gamma}];
  std::pair<SVMParameters, std::size_t> most{{}, 0};
  for (const TrialOutcome& trial : outcome.trials) {
    const std::size_t count = counts[{trial.chosen.c, trial.chosen.gamma}];
    if (count > most.second)
      most = {trial.chosen, count};
  }
  return most;
}

void
writeResultsCSV (std::ostream& out, const std::vector<DescriptorSummary>& summaries)
{
  out << "descriptor,dimension,views,failed_views,trials,accuracy_mean,accuracy_sd,C,"
         "gamma,chosen_in,ms_per_view_median,seconds_total,trial_accuracies,trial_C,"
         "trial_gamma\n";
  for (const DescriptorSummary& summary : summaries) {
    const DescriptorOutcome& outcome = summary.outcome;
    const auto [chosen, chosen_in] = mostChosen (outcome);
    out << csvField (summary.name) << ',' << summary.dimension << ',' << summary.views
        << ',' << summary.failed_views << ',' << outcome.trials.size() << ','
        << formatNumber (outcome.meanAccuracy()) << ','
        << formatNumber (outcome.accuracyDeviation())
        << ','
        // No parameters were chosen for a descriptor that failed on every view.
        << (summary.dimension == 0 ? "," : formatNumber (chosen.c) + ",")
        << (summary.dimension == 0 ? "," : formatNumber (chosen.gamma) + ",")
        << chosen_in << ',' << formatNumber (summary.median_milliseconds) << ','
        << formatNumber (summary.total_seconds) << ','
        << perTrial (outcome, [] (const TrialOutcome& t) { return t.accuracy; }) << ','
        << perTrial (outcome, [] (const TrialOutcome& t) { return t.chosen.c; }) << ','
        << perTrial (outcome, [] (const TrialOutcome& t) { return t.chosen.gamma; })
        << '\n';
  }
}

void
writeFeaturesCSV (std::ostream& out,
                  const ViewManifest& manifest,
                  const std::vector<std::string>& names,
                  const std::vector<std::vector<ViewDescriptor>>& computed)
{
  out << "path,category,instance,view,descriptor,dimension,failure,values\n";
  for (std::size_t i = 0; i < manifest.views.size(); ++i) {
    const ManifestView& view = manifest.views[i];
    for (std::size_t k = 0; k < names.size(); ++k) {
      const ViewDescriptor& descriptor = computed[i][k];
      out << csvField (view.path) << ','
          << csvField (manifest.categories[view.category]) << ','
          << csvField (manifest.instances[view.instance].name) << ','
          << csvField (view.name) << ',' << names[k] << ',' << descriptor.values.size()
          << ',' << csvField (descriptor.failure) << ',';
      for (std::size_t d = 0; d < descriptor.values.size(); ++d)
        out << (d > 0 ? " " : "") << formatNumber (descriptor.values[d]);
      out << '\n';
    }
  }
}

} // namespace tda
} // namespace pcl
