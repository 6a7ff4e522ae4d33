#include "segmentation/real_object_scenes.h"

#include <pcl/common/common.h>
#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <random>

namespace pcl {
namespace tda {
namespace test {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

constexpr double MIN_GAP = 0.015;
constexpr double AREA = 0.8;
constexpr int PLACEMENT_ATTEMPTS = 200;

/** \a count random points of \a scan (all when it has fewer), turned, scaled to a
 * bounding-box diagonal of \a diagonal, centred at the origin. */
Cloud
randomView (const Cloud& scan,
            std::size_t count,
            const Eigen::Quaternionf& rotation,
            float diagonal,
            std::mt19937_64& random)
{
  std::vector<std::size_t> order (scan.size());
  std::iota (order.begin(), order.end(), std::size_t{0});
  std::shuffle (order.begin(), order.end(), random);
  order.resize (std::min (count, order.size()));
  Cloud view;
  for (const std::size_t i : order) {
    const Eigen::Vector3f turned = rotation * scan[i].getVector3fMap();
    view.push_back (pcl::PointXYZ (turned.x(), turned.y(), turned.z()));
  }
  Eigen::Vector4f low, high;
  pcl::getMinMax3D (view, low, high);
  const Eigen::Vector3f centre = 0.5f * (low + high).head<3>();
  const float scale = diagonal / (high - low).head<3>().norm();
  for (auto& point : view)
    point.getVector3fMap() = scale * (point.getVector3fMap() - centre);
  return view;
}

} // namespace

const std::vector<std::string>&
realObjectScanFiles ()
{
  static const std::vector<std::string> files = {
      "milk.pcd", "rops_cloud.pcd", "car6.pcd"};
  return files;
}

std::vector<Cloud::Ptr>
loadRealObjectScans (const std::string& data_dir)
{
  std::vector<Cloud::Ptr> scans;
  for (const std::string& file : realObjectScanFiles()) {
    const std::string path = data_dir + "/" + file;
    Cloud raw;
    if (!std::filesystem::is_regular_file (path) ||
        pcl::io::loadPCDFile (path, raw) < 0)
      return {};
    Cloud::Ptr finite (new Cloud);
    for (const auto& point : raw)
      if (pcl::isXYZFinite (point))
        finite->push_back (point);
    scans.push_back (finite);
  }
  return scans;
}

pcl::PointCloud<pcl::PointXYZRGBL>
makeRealObjectScene (const std::vector<Cloud::Ptr>& scans, std::uint64_t seed)
{
  std::mt19937_64 random (seed);
  std::uniform_int_distribution<int> num_objects (3, 6);
  std::uniform_int_distribution<std::size_t> which (0, scans.size() - 1);
  std::uniform_int_distribution<std::size_t> count (1000, 4000);
  std::uniform_real_distribution<float> diagonal (0.10f, 0.25f);
  std::uniform_real_distribution<float> spot (-0.5f * AREA, 0.5f * AREA);
  std::normal_distribution<float> gaussian;

  using LabelledCloud = pcl::PointCloud<pcl::PointXYZRGBL>;
  const LabelledCloud::Ptr scene (new LabelledCloud);
  const int objects = num_objects (random);
  for (int object = 0; object < objects; ++object) {
    const Cloud& scan = *scans[which (random)];
    Eigen::Quaternionf rotation (
        gaussian (random), gaussian (random), gaussian (random), gaussian (random));
    rotation.normalize();
    const Cloud view =
        randomView (scan, count (random), rotation, diagonal (random), random);
    pcl::search::KdTree<pcl::PointXYZRGBL> tree;
    if (!scene->empty())
      tree.setInputCloud (scene);
    for (int attempt = 0; attempt < PLACEMENT_ATTEMPTS; ++attempt) {
      const Eigen::Vector3f offset (spot (random), spot (random), 0.0f);
      pcl::Indices nearest (1);
      std::vector<float> squared (1);
      pcl::PointXYZRGBL moved;
      const bool clear =
          std::all_of (view.begin(), view.end(), [&] (const auto& point) {
            moved.getVector3fMap() = point.getVector3fMap() + offset;
            return scene->empty() ||
                   tree.nearestKSearch (moved, 1, nearest, squared) < 1 ||
                   squared[0] >= MIN_GAP * MIN_GAP;
          });
      if (!clear)
        continue;
      const auto label =
          static_cast<std::uint32_t> (scene->empty() ? 1 : scene->back().label + 1);
      for (const auto& point : view) {
        pcl::PointXYZRGBL labelled;
        labelled.getVector3fMap() = point.getVector3fMap() + offset;
        labelled.label = label;
        scene->push_back (labelled);
      }
      break;
    }
  }
  return *scene;
}

} // namespace test
} // namespace tda
} // namespace pcl
