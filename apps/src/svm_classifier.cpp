#include <pcl/ml/svm_wrapper.h>
#include <pcl/tda/apps/svm_classifier.h>

#include <algorithm>
#include <cstdlib>

namespace pcl {
namespace tda {
namespace {

/** A descriptor vector as a sample of PCL's wrapper: dense, indices from 1. */
pcl::SVMData
sample (const std::vector<float>& row, double label)
{
  pcl::SVMData data;
  data.label = label;
  data.SV.resize (row.size());
  for (std::size_t d = 0; d < row.size(); ++d) {
    data.SV[d].idx = static_cast<int> (d + 1);
    data.SV[d].value = row[d];
  }
  return data;
}

} // namespace

/** pcl::SVMTrain without its own scaling, freeing the rows of its problem. */
class CategorySVM::Trainer : public pcl::SVMTrain {
public:
  ~Trainer()
  {
    // pcl::SVM frees prob_.x, not the rows it allocated for each sample; the model's
    // support vectors point into them, so they go only now.
    for (int i = 0; i < prob_.l; ++i)
      std::free (prob_.x[i]);
  }

  /** pcl::SVMTrain::trainClassifier() with every scaling factor off (index 0), and
   * false instead of exit(1) when libsvm refuses the parameters. */
  bool
  trainUnscaled (const std::vector<pcl::SVMData>& samples, const pcl::SVMParam& param)
  {
    training_set_ = samples;
    param_ = param;
    int max_index = 0;
    for (const auto& data : training_set_)
      for (const auto& value : data.SV)
        max_index = std::max (max_index, value.idx);
    scaling_.max = max_index + 1;
    scaling_.obj = static_cast<svm_node*> (std::malloc (
        (static_cast<std::size_t> (scaling_.max) + 1) * sizeof (svm_node)));
    for (int i = 0; i < scaling_.max; ++i)
      scaling_.obj[i] = {0, 0.0};
    scaling_.obj[scaling_.max].index = -1;
    adaptInputToLibSVM (training_set_, prob_);
    if (svm_check_parameter (&prob_, &param_) != nullptr)
      return false;
    auto* model = static_cast<pcl::SVMModel*> (svm_train (&prob_, &param_));
    if (model == nullptr)
      return false;
    model_ = *model;
    model_.scaling = scaling_.obj;
    std::free (model);
    return model_.l > 0;
  }
};

CategorySVM::CategorySVM() = default;

CategorySVM::~CategorySVM()
{
  classifier_.reset(); // it refers to the trainer's model
}

bool
CategorySVM::train (const std::vector<std::vector<float>>& rows,
                    const std::vector<int>& labels,
                    const SVMParameters& parameters)
{
  classifier_.reset();
  trainer_.reset();
  single_label_ = -1;
  if (rows.empty() || rows.size() != labels.size())
    return false;
  if (std::all_of (labels.begin(), labels.end(), [&labels] (int label) {
        return label == labels.front();
      })) {
    single_label_ = labels.front();
    return true;
  }
  std::vector<pcl::SVMData> samples;
  samples.reserve (rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    samples.push_back (sample (rows[i], labels[i]));
  pcl::SVMParam param;
  param.svm_type = C_SVC;
  param.kernel_type = RBF;
  param.C = parameters.c;
  param.gamma = parameters.gamma;
  param.shrinking = 1;
  // pcl::SVMTrain's constructor sets libsvm's global print function (to the same
  // function every time): one thread at a time.
  std::unique_ptr<Trainer> trainer;
#pragma omp critical(pcl_tda_svm_print_function)
  trainer = std::make_unique<Trainer>();
  if (!trainer->trainUnscaled (samples, param))
    return false;
  trainer_ = std::move (trainer);
  classifier_ = std::make_unique<pcl::SVMClassify>();
  classifier_->setClassifierModel (trainer_->getClassifierModel());
  return true;
}

int
CategorySVM::predict (const std::vector<float>& row)
{
  if (single_label_ >= 0)
    return single_label_;
  if (!classifier_)
    return -1;
  const std::vector<double> result = classifier_->classification (sample (row, 0.0));
  return result.empty() ? -1 : static_cast<int> (result.front());
}

} // namespace tda
} // namespace pcl
