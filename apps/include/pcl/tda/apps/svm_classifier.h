#pragma once

#include <memory>
#include <vector>

namespace pcl {
class SVMClassify;

namespace tda {

/** \brief The parameters of an SVM with RBF kernel exp(-gamma |x - y|^2). */
struct SVMParameters {
  /** \brief The cost of a training error. */
  double c = 1.0;
  double gamma = 1.0;
};

/** \brief A multi-class C-SVM with RBF kernel (thesis Sec 6.5.1: "an SVM classifier
 * and RBF kernel") that tells categories apart by descriptor vectors, trained and
 * applied through PCL's wrapper of libsvm (pcl::SVMTrain, pcl::SVMClassify).
 *
 * It differs from a plain pcl::SVMTrain in three ways. pcl::SVMTrain divides every
 * value by its largest magnitude over the training set, which would undo the
 * caller's scaling: this class trains without that (the caller scales, see
 * FeatureScaling). pcl::SVMTrain never frees its copy of the training set: this
 * class does. libsvm needs two categories: trained on one, this class answers it.
 *
 * Training is deterministic (no probability estimates, no random shuffles), so
 * equal inputs give equal models on any thread. */
class CategorySVM {
public:
  CategorySVM();
  ~CategorySVM();
  CategorySVM (const CategorySVM&) = delete;
  CategorySVM&
  operator= (const CategorySVM&) = delete;

  /** \brief Trains on \a rows (vectors of one size) of categories \a labels (>= 0).
   * \return false when there is no row or libsvm refuses the parameters */
  bool
  train (const std::vector<std::vector<float>>& rows,
         const std::vector<int>& labels,
         const SVMParameters& parameters);

  /** \brief The category of \a row by the last successful train(); -1 without one. */
  int
  predict (const std::vector<float>& row);

private:
  class Trainer;
  std::unique_ptr<Trainer> trainer_;
  std::unique_ptr<pcl::SVMClassify> classifier_;
  /** The answer when the training rows were all of one category, else -1. */
  int single_label_ = -1;
};

} // namespace tda
} // namespace pcl
