// Tests of the category protocol of pcl_tda_classify: the view manifest and its
// refusals, the held-out instances and folds of each trial, the scaling fitted on
// training views only, the SVM through PCL's wrapper, and the evaluation of a
// descriptor.

#include <pcl/tda/apps/category_classification.h>
#include <pcl/tda/apps/category_protocol.h>
#include <pcl/tda/apps/feature_scaling.h>
#include <pcl/tda/apps/svm_classifier.h>
#include <pcl/tda/apps/view_manifest.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "tool_runner.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

using namespace pcl::tda;

namespace {

std::string
testFolder ()
{
  return pcl::tda::test::temporaryFolder ("classify_protocol");
}

void
writeFile (const std::string& path, const std::string& content)
{
  std::filesystem::create_directories (std::filesystem::path (path).parent_path());
  std::ofstream (path) << content;
}

/** A manifest in \a folder of \a categories categories, each with \a instances
 * instances of \a views views (empty view files: the manifest only checks that they
 * exist). */
std::string
makeManifest (const std::string& folder,
              std::size_t categories,
              std::size_t instances,
              std::size_t views)
{
  std::string text = "path,category,instance,view\n";
  for (std::size_t c = 0; c < categories; ++c)
    for (std::size_t i = 0; i < instances; ++i)
      for (std::size_t v = 0; v < views; ++v) {
        const std::string file = "views/c" + std::to_string (c) + "_i" +
                                 std::to_string (i) + "_v" + std::to_string (v) +
                                 ".pcd";
        writeFile (folder + "/" + file, "");
        text += file + ",cat" + std::to_string (c) + ",inst" + std::to_string (i) +
                "," + std::to_string (v) + "\n";
      }
  writeFile (folder + "/manifest.csv", text);
  return folder + "/manifest.csv";
}

/** The message readViewManifest() refuses \a text with ("" if it accepts it). */
std::string
refusal (const std::string& folder, const std::string& text)
{
  writeFile (folder + "/bad.csv", text);
  try {
    readViewManifest (folder + "/bad.csv");
  }
  catch (const pcl::PCLException& error) {
    return errorMessage (error);
  }
  return "";
}

} // namespace

TEST (ViewManifest, ReadsCategoriesInstancesAndViews)
{
  const std::string folder = testFolder();
  writeFile (folder + "/a/x.pcd", "");
  writeFile (folder + "/a/y.pcd", "");
  writeFile (folder + "/b,1.pcd", "");
  writeFile (folder + "/c.pcd", "");
  writeFile (folder + "/d.pcd", "");
  // Columns in another order, an extra column, a quoted path, CRLF and a blank line.
  writeFile (folder + "/m.csv",
             "view,extra,category,path,instance\r\n"
             "0,x,mug,a/x.pcd,m1\r\n"
             "1,x,mug,a/y.pcd,m1\r\n"
             "\r\n"
             "0,x,bowl,\"b,1.pcd\",b7\r\n"
             "0,x,mug,c.pcd,m2\r\n"
             "0,x,bowl,d.pcd,b2\r\n");
  const ViewManifest manifest = readViewManifest (folder + "/m.csv");
  ASSERT_EQ (manifest.categories, (std::vector<std::string>{"bowl", "mug"}));
  ASSERT_EQ (manifest.instances.size(), 4u);
  EXPECT_EQ (manifest.instances[0].name, "b2");
  EXPECT_EQ (manifest.instances[1].name, "b7");
  EXPECT_EQ (manifest.instances[2].name, "m1");
  // The views by category, instance and view name: b2 0, b7 0, m1 0, m1 1, m2 0.
  EXPECT_EQ (manifest.instances[2].views, (std::vector<std::size_t>{2, 3}));
  EXPECT_EQ (manifest.category_instances[1], (std::vector<std::size_t>{2, 3}));
  ASSERT_EQ (manifest.views.size(), 5u);
  EXPECT_EQ (manifest.views[1].path, "b,1.pcd");
  EXPECT_EQ (manifest.views[1].file, folder + "/b,1.pcd");
  EXPECT_EQ (manifest.views[1].category, 0u);
  EXPECT_EQ (manifest.views[1].instance, 1u);
  EXPECT_EQ (manifest.views[1].line, 5u);
  EXPECT_EQ (manifest.views[3].name, "1");

  // The same manifest from its rows in another order (the classification changed
  // with the order of the rows), saved with a UTF-8 byte order mark, as spreadsheets
  // save "CSV UTF-8" (its header had no 'path' column).
  writeFile (folder + "/shuffled.csv",
             "\xEF\xBB\xBFpath,category,instance,view\n"
             "d.pcd,bowl,b2,0\n"
             "a/y.pcd,mug,m1,1\n"
             "c.pcd,mug,m2,0\n"
             "\"b,1.pcd\",bowl,b7,0\n"
             "a/x.pcd,mug,m1,0\n");
  const ViewManifest shuffled = readViewManifest (folder + "/shuffled.csv");
  ASSERT_EQ (shuffled.views.size(), manifest.views.size());
  for (std::size_t v = 0; v < manifest.views.size(); ++v) {
    EXPECT_EQ (shuffled.views[v].path, manifest.views[v].path) << v;
    EXPECT_EQ (shuffled.views[v].name, manifest.views[v].name) << v;
    EXPECT_EQ (shuffled.views[v].instance, manifest.views[v].instance) << v;
  }
  for (std::size_t i = 0; i < manifest.instances.size(); ++i)
    EXPECT_EQ (shuffled.instances[i].views, manifest.instances[i].views) << i;
}

TEST (ViewManifest, RefusesWhatTheProtocolCannotUse)
{
  const std::string folder = testFolder();
  for (const char* file : {"a.pcd", "b.pcd", "c.pcd", "d.pcd", "e.txt"})
    writeFile (folder + "/" + file, "");
  const std::string header = "path,category,instance,view\n";
  const std::string good = "a.pcd,mug,1,0\nb.pcd,mug,2,0\nc.pcd,bowl,1,0\n";
  EXPECT_EQ (refusal (folder, header + good + "d.pcd,bowl,2,0\n"), "");
  const std::vector<std::pair<std::string, std::string>> cases{
      {"", "the file is empty"},
      {"path,category,view\n" + good, "the header has no 'instance' column"},
      {"path,category,instance,view,view\n", "the header names 'view' twice"},
      {header + good + "d.pcd,bowl,2\n", "line 5: 3 fields, the header has 4"},
      {header + good + "d.pcd,,2,0\n", "line 5: the category is empty"},
      {header + good + "missing.pcd,bowl,2,0\n",
       "line 5: the view file missing.pcd does not exist"},
      {header + good + "e.txt,bowl,2,0\n", "line 5: the view e.txt is not a .pcd file"},
      {header + good + "a.pcd,bowl,2,0\n",
       "line 5: the view file a.pcd is already listed on line 2"},
      {header + good + "d.pcd,bowl,1,0\n",
       "line 5: view 0 of instance 1 of category bowl is already listed on line 4"},
      {header + good, "category bowl has only one instance (1)"},
      {header + "a.pcd,mug,1,0\nb.pcd,mug,2,0\n", "all views are of one category"},
      {header, "no views are listed"},
      {header + good + "\"d.pcd,bowl,2,0\n",
       "line 5: the quote of field 1 is not closed"},
  };
  for (const auto& [text, message] : cases) {
    const std::string refused = refusal (folder, text);
    EXPECT_NE (refused.find (message), std::string::npos)
        << "manifest:\n"
        << text << "\nrefused with: " << refused;
  }
  try {
    readViewManifest (folder + "/none.csv");
    ADD_FAILURE() << "a missing manifest was read";
  }
  catch (const pcl::IOException& error) {
    EXPECT_NE (errorMessage (error).find ("no such file"), std::string::npos);
  }
}

TEST (CategoryProtocol, HoldsOutOneInstancePerCategoryEachTrial)
{
  const std::string folder = testFolder();
  const ViewManifest manifest = readViewManifest (makeManifest (folder, 4, 5, 2));
  const std::vector<ProtocolTrial> trials = makeProtocolTrials (manifest, 20, 3, 7);
  ASSERT_EQ (trials.size(), 20u);
  std::set<std::size_t> ever_held_out;
  for (const ProtocolTrial& trial : trials) {
    ASSERT_EQ (trial.test_instances.size(), manifest.categories.size());
    EXPECT_EQ (trial.folds, 3u);
    std::vector<std::size_t> fold_sizes (trial.folds, 0);
    for (std::size_t c = 0; c < manifest.categories.size(); ++c) {
      const std::size_t held_out = trial.test_instances[c];
      EXPECT_EQ (manifest.instances[held_out].category, c);
      ever_held_out.insert (held_out);
    }
    for (std::size_t i = 0; i < manifest.instances.size(); ++i) {
      const bool tested =
          std::count (trial.test_instances.begin(), trial.test_instances.end(), i) > 0;
      // An instance is either held out or in one training fold, never both.
      EXPECT_EQ (trial.instance_folds[i] == TEST_FOLD, tested);
      if (!tested) {
        ASSERT_LT (trial.instance_folds[i], trial.folds);
        ++fold_sizes[trial.instance_folds[i]];
      }
    }
    // 16 training instances dealt into 3 folds: 5 or 6 each.
    for (const std::size_t size : fold_sizes) {
      EXPECT_GE (size, 5u);
      EXPECT_LE (size, 6u);
    }
  }
  EXPECT_GT (ever_held_out.size(), 12u) << "the held-out instances hardly vary";
}

TEST (CategoryProtocol, IsDeterministicForASeed)
{
  const std::string folder = testFolder();
  const ViewManifest manifest = readViewManifest (makeManifest (folder, 3, 4, 1));
  const auto first = makeProtocolTrials (manifest, 10, 3, 42);
  const auto again = makeProtocolTrials (manifest, 10, 3, 42);
  const auto other = makeProtocolTrials (manifest, 10, 3, 43);
  const auto loio = makeProtocolTrials (manifest, 10, 0, 42);
  bool differs = false;
  for (std::size_t t = 0; t < first.size(); ++t) {
    EXPECT_EQ (first[t].test_instances, again[t].test_instances);
    EXPECT_EQ (first[t].instance_folds, again[t].instance_folds);
    differs = differs || first[t].test_instances != other[t].test_instances;
    // The held-out instances do not depend on the folds.
    EXPECT_EQ (first[t].test_instances, loio[t].test_instances);
    // Leave-one-instance-out: 9 training instances, one per fold.
    EXPECT_EQ (loio[t].folds, 9u);
    std::set<std::size_t> folds;
    for (const std::size_t fold : loio[t].instance_folds) {
      if (fold != TEST_FOLD) {
        EXPECT_TRUE (folds.insert (fold).second);
      }
    }
  }
  EXPECT_TRUE (differs) << "another seed gave the same held-out instances";
  // More folds than training instances: one instance per fold.
  EXPECT_EQ (makeProtocolTrials (manifest, 1, 50, 1).front().folds, 9u);
  EXPECT_THROW (makeProtocolTrials (manifest, 0, 3, 1), pcl::BadArgumentException);
  EXPECT_THROW (makeProtocolTrials (manifest, 1, 1, 1), pcl::BadArgumentException);
}

TEST (FeatureScaling, UsesTheTrainingRowsOnly)
{
  std::vector<std::vector<float>> rows{{1, 10, 5}, {3, 10, 7}, {5, 10, 9}, {7, 10, 11}};
  const std::vector<std::size_t> training{0, 1, 2};
  const FeatureScaling scaling =
      fitFeatureScaling (rows, training, {}, FeatureScalingMode::Z_SCORE);
  // Training values 1, 3, 5: mean 3, standard deviation sqrt(8/3).
  EXPECT_DOUBLE_EQ (scaling.offset[0], 3.0);
  EXPECT_DOUBLE_EQ (scaling.factor[0], 1.0 / std::sqrt (8.0 / 3.0));
  // A value constant over the training rows is switched off.
  EXPECT_EQ (scaling.factor[1], 0.0);
  double sum = 0.0, squares = 0.0;
  for (const std::size_t i : training) {
    const float z = scaling.apply (rows[i])[2];
    sum += z;
    squares += z * z;
  }
  EXPECT_NEAR (sum, 0.0, 1e-6);
  EXPECT_NEAR (squares / 3.0, 1.0, 1e-6);
  // Whatever the other rows hold, the scaling stays.
  rows[3] = {1e6f, -1e6f, 3e5f};
  const FeatureScaling again =
      fitFeatureScaling (rows, training, {}, FeatureScalingMode::Z_SCORE);
  EXPECT_EQ (again.offset, scaling.offset);
  EXPECT_EQ (again.factor, scaling.factor);

  const FeatureScaling range =
      fitFeatureScaling (rows, training, {}, FeatureScalingMode::MIN_MAX);
  EXPECT_EQ (range.apply (rows[0])[0], 0.0f);
  EXPECT_EQ (range.apply (rows[2])[0], 1.0f);
  EXPECT_THROW (fitFeatureScaling (rows, {}, {}, FeatureScalingMode::Z_SCORE),
                pcl::BadArgumentException);
  EXPECT_THROW (fitFeatureScaling (rows, training, {2, 2}, FeatureScalingMode::Z_SCORE),
                pcl::BadArgumentException);
}

TEST (FeatureScaling, WeighsTheDescriptorsOfACombinationAlike)
{
  // Parts of 1 and 3 values: weights sqrt(4 / (2 * 1)) and sqrt(4 / (2 * 3)).
  const std::vector<std::vector<float>> rows{{0, 0, 0, 0}, {2, 2, 2, 2}};
  const FeatureScaling scaling =
      fitFeatureScaling (rows, {0, 1}, {1, 3}, FeatureScalingMode::Z_SCORE);
  EXPECT_NEAR (scaling.factor[0], std::sqrt (2.0), 1e-12);
  for (std::size_t d = 1; d < 4; ++d)
    EXPECT_NEAR (scaling.factor[d], std::sqrt (2.0 / 3.0), 1e-12);
  // Each part contributes the same squared distance between the two rows.
  const auto a = scaling.apply (rows[0]), b = scaling.apply (rows[1]);
  double first = 0.0, second = 0.0;
  for (std::size_t d = 0; d < 4; ++d)
    (d == 0 ? first : second) += (a[d] - b[d]) * (a[d] - b[d]);
  EXPECT_NEAR (first, second, 1e-5);
}

TEST (CategorySVM, SeparatesCategoriesAndAnswersASingleOne)
{
  std::vector<std::vector<float>> rows;
  std::vector<int> labels;
  for (int k = 0; k < 30; ++k) {
    const float jitter = 0.05f * static_cast<float> (k % 7);
    rows.push_back ({-1.0f + jitter, 0.5f});
    labels.push_back (0);
    rows.push_back ({1.0f - jitter, -0.5f});
    labels.push_back (1);
    rows.push_back ({0.0f, 2.0f + jitter});
    labels.push_back (2);
  }
  CategorySVM svm;
  EXPECT_EQ (svm.predict ({0.0f, 0.0f}), -1) << "an untrained SVM answered";
  ASSERT_TRUE (svm.train (rows, labels, {8.0, 0.5}));
  EXPECT_EQ (svm.predict ({-0.9f, 0.4f}), 0);
  EXPECT_EQ (svm.predict ({0.9f, -0.4f}), 1);
  EXPECT_EQ (svm.predict ({0.1f, 2.1f}), 2);
  // Retrained with a bad parameter, it refuses instead of exiting like PCL's.
  EXPECT_FALSE (svm.train (rows, labels, {-1.0, 0.5}));
  EXPECT_EQ (svm.predict ({-0.9f, 0.4f}), -1);
  CategorySVM single;
  ASSERT_TRUE (single.train ({{0.0f}, {1.0f}}, {4, 4}, {1.0, 1.0}));
  EXPECT_EQ (single.predict ({-7.0f}), 4);
  EXPECT_FALSE (single.train ({}, {}, {1.0, 1.0}));
}

namespace {

/** Descriptor rows for the views of \a manifest: two values near the centre of
 * their category, a little different per instance and view. */
std::vector<std::vector<float>>
separableRows (const ViewManifest& manifest)
{
  std::vector<std::vector<float>> rows;
  for (const ManifestView& view : manifest.views) {
    const auto c = static_cast<float> (view.category);
    const auto i = static_cast<float> (view.instance % 5);
    const auto v = static_cast<float> (std::stoi (view.name));
    rows.push_back ({10.0f * c + 0.3f * i + 0.1f * v, 5.0f - 3.0f * c + 0.2f * v});
  }
  return rows;
}

} // namespace

TEST (EvaluateDescriptor, ClassifiesSeparableCategories)
{
  const std::string folder = testFolder();
  const ViewManifest manifest = readViewManifest (makeManifest (folder, 3, 4, 3));
  const auto trials = makeProtocolTrials (manifest, 5, 3, 3);
  const DescriptorOutcome outcome = evaluateDescriptor (
      separableRows (manifest), {}, manifest, trials, ClassificationSettings());
  ASSERT_EQ (outcome.trials.size(), 5u);
  for (const TrialOutcome& trial : outcome.trials) {
    EXPECT_EQ (trial.tested, 9u); // 3 categories x 1 instance x 3 views
    EXPECT_EQ (trial.correct, 9u);
    EXPECT_EQ (trial.accuracy, 1.0);
    EXPECT_GT (trial.chosen.c, 0.0);
    EXPECT_GT (trial.chosen.gamma, 0.0);
  }
  EXPECT_EQ (outcome.meanAccuracy(), 1.0);
  EXPECT_EQ (outcome.accuracyDeviation(), 0.0);
  ASSERT_EQ (outcome.confusion.size(), 3u);
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_EQ (outcome.confusion[c][c], 15u);
}

TEST (EvaluateDescriptor, CountsFailedViewsAsWrong)
{
  const std::string folder = testFolder();
  const ViewManifest manifest = readViewManifest (makeManifest (folder, 2, 3, 2));
  const auto trials = makeProtocolTrials (manifest, 1, 2, 5);
  std::vector<std::vector<float>> rows = separableRows (manifest);
  // The descriptor failed on one view of a held-out instance and one training view.
  const std::size_t held_out = manifest.instances[trials[0].test_instances[1]].views[0];
  rows[held_out].clear();
  for (const ManifestView& view : manifest.views)
    if (trials[0].instance_folds[view.instance] != TEST_FOLD) {
      rows[&view - manifest.views.data()].clear();
      break;
    }
  const DescriptorOutcome outcome =
      evaluateDescriptor (rows, {}, manifest, trials, ClassificationSettings());
  const TrialOutcome& trial = outcome.trials[0];
  EXPECT_EQ (trial.tested, 4u);
  EXPECT_EQ (trial.failed, 1u);
  EXPECT_EQ (trial.correct, 3u);
  EXPECT_DOUBLE_EQ (trial.accuracy, 0.75);
  // The failed view is in the last column of its true category's row.
  EXPECT_EQ (outcome.confusion[1][2], 1u);
}

TEST (EvaluateDescriptor, ScalesWithTrainingViewsOnly)
{
  // A held-out view far off its category changes nothing for the other held-out
  // views: pooled statistics would shrink every other value to nothing.
  const std::string folder = testFolder();
  const ViewManifest manifest = readViewManifest (makeManifest (folder, 3, 4, 3));
  const auto trials = makeProtocolTrials (manifest, 3, 3, 11);
  std::vector<std::vector<float>> rows = separableRows (manifest);
  for (const ProtocolTrial& trial : trials) {
    const std::size_t outlier = manifest.instances[trial.test_instances[0]].views[0];
    std::vector<std::vector<float>> changed = rows;
    changed[outlier] = {1e7f, -1e7f};
    const auto single = std::vector<ProtocolTrial>{trial};
    const DescriptorOutcome before =
        evaluateDescriptor (rows, {}, manifest, single, ClassificationSettings());
    const DescriptorOutcome after =
        evaluateDescriptor (changed, {}, manifest, single, ClassificationSettings());
    EXPECT_EQ (before.trials[0].correct, 9u);
    EXPECT_GE (after.trials[0].correct, 8u);
    EXPECT_EQ (after.trials[0].chosen.c, before.trials[0].chosen.c);
    EXPECT_EQ (after.trials[0].chosen.gamma, before.trials[0].chosen.gamma);
  }
}
