#include <pcl/tda/apps/category_classification.h>

#include <cmath>

namespace pcl {
namespace tda {
namespace {

/** The views of one trial, by role. */
struct TrialViews {
  /** Training views with a descriptor, and the fold of each. */
  std::vector<std::size_t> training, training_folds;
  /** All held-out views. */
  std::vector<std::size_t> test;
};

TrialViews
trialViews (const std::vector<std::vector<float>>& rows,
            const ViewManifest& manifest,
            const ProtocolTrial& trial)
{
  TrialViews views;
  for (std::size_t i = 0; i < manifest.views.size(); ++i) {
    const std::size_t fold = trial.instance_folds[manifest.views[i].instance];
    if (fold == TEST_FOLD)
      views.test.push_back (i);
    else if (!rows[i].empty()) {
      views.training.push_back (i);
      views.training_folds.push_back (fold);
    }
  }
  return views;
}

/** An SVM trained on the views \a training, its values scaled on them. */
struct TrainedSVM {
  FeatureScaling scaling;
  CategorySVM svm;
  bool trained = false;

  TrainedSVM (const std::vector<std::vector<float>>& rows,
              const std::vector<std::size_t>& parts,
              const ViewManifest& manifest,
              const std::vector<std::size_t>& training,
              const SVMParameters& parameters,
              FeatureScalingMode mode)
  {
    if (training.empty())
      return;
    scaling = fitFeatureScaling (rows, training, parts, mode);
    std::vector<std::vector<float>> scaled;
    std::vector<int> labels;
    for (const std::size_t i : training) {
      scaled.push_back (scaling.apply (rows[i]));
      labels.push_back (static_cast<int> (manifest.views[i].category));
    }
    trained = svm.train (scaled, labels, parameters);
  }

  /** The category of view \a i, -1 when it cannot be told. */
  int
  predict (const std::vector<float>& row)
  {
    return trained && !row.empty() ? svm.predict (scaling.apply (row)) : -1;
  }
};

/** The grid point \a g of \a settings for descriptors of \a dimension values. */
SVMParameters
gridPoint (const ClassificationSettings& settings, std::size_t g, std::size_t dimension)
{
  // gamma outer, C inner: the first best point has the smallest gamma, then C.
  const std::size_t cs = settings.c_values.size();
  return {settings.c_values[g % cs],
          settings.gamma_factors[g / cs] / static_cast<double> (dimension)};
}

} // namespace

double
DescriptorOutcome::meanAccuracy() const
{
  double sum = 0.0;
  for (const TrialOutcome& trial : trials)
    sum += trial.accuracy;
  return trials.empty() ? 0.0 : sum / static_cast<double> (trials.size());
}

double
DescriptorOutcome::accuracyDeviation() const
{
  if (trials.size() < 2)
    return 0.0;
  const double mean = meanAccuracy();
  double squares = 0.0;
  for (const TrialOutcome& trial : trials)
    squares += (trial.accuracy - mean) * (trial.accuracy - mean);
  return std::sqrt (squares / static_cast<double> (trials.size() - 1));
}

std::size_t
classificationWork (const std::vector<ProtocolTrial>& trials,
                    const ClassificationSettings& settings)
{
  const std::size_t grid = settings.c_values.size() * settings.gamma_factors.size();
  std::size_t work = 0;
  for (const ProtocolTrial& trial : trials)
    work += grid * trial.folds + 1;
  return work;
}

DescriptorOutcome
evaluateDescriptor (const std::vector<std::vector<float>>& rows,
                    const std::vector<std::size_t>& parts,
                    const ViewManifest& manifest,
                    const std::vector<ProtocolTrial>& trials,
                    const ClassificationSettings& settings,
                    ParallelProgress* progress)
{
  const std::size_t categories = manifest.categories.size();
  const std::size_t grid = settings.c_values.size() * settings.gamma_factors.size();
  std::size_t dimension = 0;
  for (const auto& row : rows)
    dimension = row.empty() ? dimension : row.size();
  if (dimension == 0) // failed on every view: nothing is trained
    dimension = 1;
  std::vector<TrialViews> views;
  for (const ProtocolTrial& trial : trials)
    views.push_back (trialViews (rows, manifest, trial));

  // The cross-validation: one job per trial, grid point and fold.
  struct Job {
    std::size_t trial, point, fold;
  };
  std::vector<Job> jobs;
  for (std::size_t t = 0; t < trials.size(); ++t)
    for (std::size_t g = 0; g < grid; ++g)
      for (std::size_t f = 0; f < trials[t].folds; ++f)
        jobs.push_back ({t, g, f});
  std::vector<std::size_t> job_correct (jobs.size(), 0);
#pragma omp parallel for schedule(dynamic)
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const Job& job = jobs[j];
    const TrialViews& trial = views[job.trial];
    std::vector<std::size_t> fitting, validation;
    for (std::size_t k = 0; k < trial.training.size(); ++k)
      (trial.training_folds[k] == job.fold ? validation : fitting)
          .push_back (trial.training[k]);
    TrainedSVM svm (rows,
                    parts,
                    manifest,
                    fitting,
                    gridPoint (settings, job.point, dimension),
                    settings.scaling);
    for (const std::size_t i : validation)
      job_correct[j] +=
          svm.predict (rows[i]) == static_cast<int> (manifest.views[i].category);
    if (progress)
      progress->advance (1);
  }

  DescriptorOutcome outcome;
  outcome.trials.resize (trials.size());
  std::vector<std::size_t> point_correct (trials.size() * grid, 0);
  for (std::size_t j = 0; j < jobs.size(); ++j)
    point_correct[jobs[j].trial * grid + jobs[j].point] += job_correct[j];
  for (std::size_t t = 0; t < trials.size(); ++t) {
    std::size_t best = 0;
    for (std::size_t g = 1; g < grid; ++g)
      if (point_correct[t * grid + g] > point_correct[t * grid + best])
        best = g;
    TrialOutcome& trial = outcome.trials[t];
    trial.chosen = gridPoint (settings, best, dimension);
    trial.validation_accuracy =
        views[t].training.empty()
            ? 0.0
            : static_cast<double> (point_correct[t * grid + best]) /
                  static_cast<double> (views[t].training.size());
  }

  // The held-out views, classified by an SVM trained on all training views.
  std::vector<std::vector<int>> predictions (trials.size());
#pragma omp parallel for schedule(dynamic)
  for (std::size_t t = 0; t < trials.size(); ++t) {
    TrainedSVM svm (rows,
                    parts,
                    manifest,
                    views[t].training,
                    outcome.trials[t].chosen,
                    settings.scaling);
    for (const std::size_t i : views[t].test)
      predictions[t].push_back (svm.predict (rows[i]));
    if (progress)
      progress->advance (1);
  }
  outcome.confusion.assign (categories, std::vector<std::size_t> (categories + 1, 0));
  for (std::size_t t = 0; t < trials.size(); ++t) {
    TrialOutcome& trial = outcome.trials[t];
    for (std::size_t k = 0; k < views[t].test.size(); ++k) {
      const std::size_t i = views[t].test[k];
      const std::size_t truth = manifest.views[i].category;
      const int predicted = predictions[t][k];
      ++trial.tested;
      trial.failed += rows[i].empty() ? 1 : 0;
      trial.correct += predicted == static_cast<int> (truth) ? 1 : 0;
      // A failed view goes to the last column; an SVM that could not be trained
      // (no training view) answers nothing, counted there too.
      ++outcome.confusion[truth][predicted < 0 ? categories
                                               : static_cast<std::size_t> (predicted)];
    }
    trial.accuracy = trial.tested == 0 ? 0.0
                                       : static_cast<double> (trial.correct) /
                                             static_cast<double> (trial.tested);
  }
  return outcome;
}

} // namespace tda
} // namespace pcl
