// Tests of the object views: determinism and independence of the views, sizes,
// distances and camera of every category, the noise multiplier (residuals on a
// tile's faces), the hole of a ring seen from above, poses drawn again for too few
// points, colours, category names and the parameter checks.

#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/object_views.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "generators/generator_test_utils.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <vector>

using pcl::tda::ObjectCategory;
using pcl::tda::ObjectInstance;
using pcl::tda::ObjectView;
using pcl::tda::ObjectViewParameters;
using pcl::tda::renderObjectView;
using pcl::tda::test::identical;

namespace {

/** Largest distance between two points, over at most about 1500 of them. */
double
diameter (const pcl::PointCloud<pcl::PointXYZRGB>& cloud)
{
  const std::size_t step = std::max<std::size_t> (1, cloud.size() / 1500);
  double largest = 0.0;
  for (std::size_t i = 0; i < cloud.size(); i += step)
    for (std::size_t j = i + step; j < cloud.size(); j += step)
      largest = std::max<double> (
          largest, (cloud[i].getVector3fMap() - cloud[j].getVector3fMap()).norm());
  return largest;
}

/** The view's points in the object's own frame. */
std::vector<Eigen::Vector3f>
inObjectFrame (const ObjectView& view)
{
  const Eigen::Isometry3f to_object = view.object.pose.inverse() * view.camera_pose;
  std::vector<Eigen::Vector3f> points;
  for (const auto& point : *view.cloud)
    points.push_back (to_object * point.getVector3fMap());
  return points;
}

/** Root mean square distance of a tile's points to its faces z = +-t/2, over the
 * points of the faces at least \a margin inside their sides. */
double
faceResidual (const ObjectView& view, float margin, std::size_t& count)
{
  const Eigen::Vector3f half = 0.5f * view.object.dimensions;
  double sum = 0.0;
  count = 0;
  for (const Eigen::Vector3f& p : inObjectFrame (view))
    if (std::abs (p.x()) < half.x() - margin && std::abs (p.y()) < half.y() - margin) {
      const double residual = std::abs (p.z()) - half.z();
      sum += residual * residual;
      ++count;
    }
  return std::sqrt (sum / std::max<std::size_t> (count, 1));
}

/** The smallest distance from the object centre, (0, 0, distance) in the camera
 * frame, to the rays of the view's points. */
double
closestRayToCentre (const ObjectView& view)
{
  const Eigen::Vector3d centre (0.0, 0.0, view.distance);
  double closest = std::numeric_limits<double>::infinity();
  for (const auto& point : *view.cloud) {
    const Eigen::Vector3d ray = point.getVector3fMap().cast<double>().normalized();
    closest = std::min (closest, (centre - centre.dot (ray) * ray).norm());
  }
  return closest;
}

/** The first instance of \a category lying within \a max_tilt of flat. */
ObjectInstance
lyingInstance (const ObjectViewParameters& parameters,
               ObjectCategory category,
               float max_tilt)
{
  for (std::size_t i = 0; i < parameters.instances; ++i) {
    const ObjectInstance object =
        pcl::tda::drawObjectInstance (parameters, category, i);
    if (object.tilt < max_tilt)
      return object;
  }
  ADD_FAILURE() << "no lying instance";
  return {};
}

} // namespace

TEST (ObjectViews, EqualSeedsGiveIdenticalViews)
{
  ObjectViewParameters parameters;
  parameters.seed = 11;
  for (const ObjectCategory category : {ObjectCategory::MUG, ObjectCategory::FRAME}) {
    const ObjectView a = renderObjectView (parameters, category, 1, 2);
    const ObjectView b = renderObjectView (parameters, category, 1, 2);
    EXPECT_TRUE (identical (*a.cloud, *b.cloud));
    EXPECT_TRUE (a.camera_pose.isApprox (b.camera_pose, 0.0f));
    EXPECT_EQ (a.object.dimensions, b.object.dimensions);
    EXPECT_EQ (a.object.yaw, b.object.yaw);
    EXPECT_EQ (a.object.r, b.object.r);
  }
}

TEST (ObjectViews, DifferentSeedsInstancesAndViewsDiffer)
{
  ObjectViewParameters parameters;
  const ObjectView base = renderObjectView (parameters, ObjectCategory::CAN, 0, 0);
  const ObjectView other_view =
      renderObjectView (parameters, ObjectCategory::CAN, 0, 1);
  const ObjectView other_instance =
      renderObjectView (parameters, ObjectCategory::CAN, 1, 0);
  parameters.seed = 1;
  const ObjectView other_seed =
      renderObjectView (parameters, ObjectCategory::CAN, 0, 0);
  EXPECT_FALSE (identical (*base.cloud, *other_view.cloud));
  EXPECT_FALSE (identical (*base.cloud, *other_instance.cloud));
  EXPECT_FALSE (identical (*base.cloud, *other_seed.cloud));
  // Views of one instance show the same object from other poses.
  EXPECT_EQ (base.object.dimensions, other_view.object.dimensions);
  EXPECT_NE (base.distance, other_view.distance);
  EXPECT_NE (base.object.dimensions, other_instance.object.dimensions);
  EXPECT_NE (base.object.dimensions, other_seed.object.dimensions);
}

TEST (ObjectViews, AViewIsTheSameAloneOrAmidOthers)
{
  const ObjectViewParameters all;
  ObjectViewParameters alone;
  alone.categories = {ObjectCategory::BOWL};
  alone.instances = 3;
  alone.views = 8;
  const ObjectView single = renderObjectView (alone, ObjectCategory::BOWL, 2, 7);
  ObjectView amid;
  for (const ObjectCategory category : {ObjectCategory::BOX, ObjectCategory::BOWL})
    for (std::size_t view = 6; view < 9; ++view) {
      const ObjectView rendered = renderObjectView (all, category, 2, view);
      if (category == ObjectCategory::BOWL && view == 7)
        amid = rendered;
    }
  ASSERT_TRUE (amid.cloud);
  EXPECT_TRUE (identical (*single.cloud, *amid.cloud));
  EXPECT_TRUE (single.camera_pose.isApprox (amid.camera_pose, 0.0f));
  // The colour noise has a generator of its own: the points stay where they are.
  alone.colour_noise = 0.0f;
  const ObjectView plain = renderObjectView (alone, ObjectCategory::BOWL, 2, 7);
  ASSERT_EQ (single.cloud->size(), plain.cloud->size());
  std::size_t recoloured = 0;
  for (std::size_t i = 0; i < plain.cloud->size(); ++i) {
    ASSERT_EQ ((*single.cloud)[i].getVector3fMap(), (*plain.cloud)[i].getVector3fMap());
    recoloured += (*single.cloud)[i].rgba != (*plain.cloud)[i].rgba;
  }
  EXPECT_GT (recoloured, plain.cloud->size() / 2);
}

TEST (ObjectViews, EveryCategoryIsSeenWholeAtItsSizeAndDistance)
{
  ObjectViewParameters parameters;
  parameters.instances = 2;
  parameters.views = 2;
  const pcl::tda::DepthCameraParameters camera;
  for (const ObjectCategory category : parameters.categories) {
    SCOPED_TRACE (pcl::tda::objectCategoryName (category));
    for (std::size_t instance = 0; instance < parameters.instances; ++instance)
      for (std::size_t v = 0; v < parameters.views; ++v) {
        const ObjectView view = renderObjectView (parameters, category, instance, v);
        const auto& cloud = *view.cloud;
        const ObjectInstance& object = view.object;
        EXPECT_EQ (category, object.category);
        EXPECT_GE (object.dimensions.maxCoeff(), pcl::tda::OBJECT_MIN_EXTENT);
        EXPECT_LE (object.dimensions.maxCoeff(), pcl::tda::OBJECT_MAX_EXTENT);
        ASSERT_GE (cloud.size(), parameters.min_points);
        EXPECT_EQ (cloud.width, cloud.size());
        EXPECT_EQ (cloud.height, 1u);
        EXPECT_TRUE (cloud.is_dense);
        EXPECT_GE (view.distance, parameters.min_distance);
        EXPECT_LE (view.distance, parameters.max_distance);
        EXPECT_GE (view.elevation_deg, parameters.min_elevation_deg);
        EXPECT_LE (view.elevation_deg, parameters.max_elevation_deg);
        // The camera looks at the object centre from its distance.
        EXPECT_NEAR (view.distance, view.camera_pose.translation().norm(), 1e-5);
        // Every point is a pixel of the camera, on the object up to the noise (4
        // sigma and a disparity step at the farthest point).
        const double radius = 0.5 * object.dimensions.norm();
        const double far = view.distance + radius;
        const double tolerance =
            4.0 * camera.noise_coefficient * far * far +
            far * far * camera.disparity_step / (camera.fx * camera.baseline);
        const Eigen::Vector3f centre (0.0f, 0.0f, view.distance);
        Eigen::Vector3f sum = Eigen::Vector3f::Zero();
        for (const auto& point : cloud) {
          ASSERT_TRUE (std::isfinite (point.x) && point.z > 0.0f);
          const double u = camera.fx * point.x / point.z + camera.cx;
          const double v = camera.fy * point.y / point.z + camera.cy;
          ASSERT_NEAR (u, std::round (u), 1e-3);
          ASSERT_NEAR (v, std::round (v), 1e-3);
          ASSERT_LE ((point.getVector3fMap() - centre).norm(), radius + tolerance);
          sum += point.getVector3fMap();
        }
        // The view spans most of the object: at least its largest side seen at
        // 20 degrees from edge-on, at most its bounding box's diagonal.
        const double span = diameter (cloud);
        EXPECT_LE (span, object.dimensions.norm() + 2.0 * tolerance);
        EXPECT_GE (span, std::sin (M_PI / 9.0) * object.dimensions.maxCoeff());
        EXPECT_LE (std::abs ((sum / cloud.size()).norm() - view.distance), radius);
      }
  }
}

TEST (ObjectViews, InstancesHaveTheirCategorysGroundTruth)
{
  ObjectViewParameters parameters;
  parameters.instances = 30;
  for (const ObjectCategory category : parameters.categories) {
    SCOPED_TRACE (pcl::tda::objectCategoryName (category));
    const bool holed = category == ObjectCategory::MUG ||
                       category == ObjectCategory::RING ||
                       category == ObjectCategory::FRAME;
    const bool tilted =
        category == ObjectCategory::RING || category == ObjectCategory::DISC ||
        category == ObjectCategory::FRAME || category == ObjectCategory::TILE;
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i < parameters.instances; ++i) {
      const ObjectInstance object =
          pcl::tda::drawObjectInstance (parameters, category, i);
      EXPECT_EQ (holed ? 1 : 0, object.genus);
      EXPECT_EQ (holed, object.hole_radius > 0.0f);
      EXPECT_LT (2.0f * object.hole_radius, object.dimensions.maxCoeff());
      EXPECT_GE (object.dimensions.maxCoeff(), pcl::tda::OBJECT_MIN_EXTENT);
      EXPECT_LE (object.dimensions.maxCoeff(), pcl::tda::OBJECT_MAX_EXTENT);
      EXPECT_GE (object.tilt, 0.0f);
      EXPECT_LE (object.tilt, tilted ? M_PI / 2.0 : 0.0);
      EXPECT_TRUE (object.pose.translation().isZero());
      colours.insert (object.r << 16 | object.g << 8 | object.b);
    }
    EXPECT_GT (colours.size(), parameters.instances / 2);
  }
  // A mug's handle sticks out along x; a cup is round.
  for (std::size_t i = 0; i < parameters.instances; ++i) {
    const Eigen::Vector3f mug =
        pcl::tda::drawObjectInstance (parameters, ObjectCategory::MUG, i).dimensions;
    const Eigen::Vector3f cup =
        pcl::tda::drawObjectInstance (parameters, ObjectCategory::CUP, i).dimensions;
    EXPECT_GT (mug.x(), mug.y() + 0.02f);
    EXPECT_EQ (cup.x(), cup.y());
  }
}

TEST (ObjectViews, NoiseMultiplierScalesTheDepthNoise)
{
  ObjectViewParameters parameters;
  parameters.instances = 20;
  const std::size_t tile =
      lyingInstance (parameters, ObjectCategory::TILE, static_cast<float> (M_PI / 4.0))
          .instance;
  double residual[2] = {0.0, 0.0};
  std::size_t counts[2] = {0, 0};
  for (std::size_t k = 0; k < 2; ++k) {
    parameters.noise_multiplier = k == 0 ? 1.0f : 3.0f;
    for (std::size_t view = 0; view < 3; ++view) {
      const ObjectView rendered =
          renderObjectView (parameters, ObjectCategory::TILE, tile, view);
      std::size_t count = 0;
      const double rms = faceResidual (rendered, 0.015f, count);
      residual[k] += rms * rms * count;
      counts[k] += count;
    }
    residual[k] = std::sqrt (residual[k] / counts[k]);
  }
  ASSERT_GT (counts[0], 1000u);
  ASSERT_GT (counts[1], 1000u);
  // Noise sigma 1.5 mm at 1 m and quantization steps of a few mm: millimetres.
  EXPECT_GT (residual[0], 0.0003);
  EXPECT_LT (residual[0], 0.003);
  EXPECT_GT (residual[1], 2.0 * residual[0]);
  EXPECT_LT (residual[1], 3.5 * residual[0]);
  // Without noise only the quantization is left.
  parameters.noise_multiplier = 0.0f;
  std::size_t count = 0;
  EXPECT_LT (faceResidual (renderObjectView (parameters, ObjectCategory::TILE, tile, 0),
                           0.015f,
                           count),
             residual[0]);
}

TEST (ObjectViews, PerturbationMovesEveryCoordinateWithinItsBound)
{
  ObjectViewParameters parameters;
  parameters.seed = 5;
  const auto plain = renderObjectView (parameters, ObjectCategory::BOX, 1, 2);
  for (const float a : {0.0005f, 0.003f}) {
    parameters.perturbation = a;
    const auto moved = renderObjectView (parameters, ObjectCategory::BOX, 1, 2);
    ASSERT_EQ (moved.cloud->size(), plain.cloud->size());
    double largest = 0.0, sum_of_squares = 0.0;
    for (std::size_t i = 0; i < plain.cloud->size(); ++i)
      for (int axis = 0; axis < 3; ++axis) {
        const double offset =
            (*moved.cloud)[i].data[axis] - (*plain.cloud)[i].data[axis];
        largest = std::max (largest, std::abs (offset));
        sum_of_squares += offset * offset;
      }
    EXPECT_LE (largest, a * (1.0 + 1e-3));
    // Uniform in [-a, a]: the standard deviation is a / sqrt(3).
    const double sd = std::sqrt (sum_of_squares / (3.0 * plain.cloud->size()));
    EXPECT_NEAR (sd, a / std::sqrt (3.0), 0.05 * a);
    EXPECT_EQ ((*moved.cloud)[0].rgba, (*plain.cloud)[0].rgba);
  }
}

TEST (ObjectViews, ARingSeenFromAboveShowsItsHole)
{
  ObjectViewParameters parameters;
  parameters.min_elevation_deg = 68.0f;
  parameters.max_elevation_deg = 70.0f;
  parameters.instances = 100;
  const float max_tilt = static_cast<float> (10.0 * M_PI / 180.0);
  const ObjectInstance ring =
      lyingInstance (parameters, ObjectCategory::RING, max_tilt);
  const ObjectInstance disc =
      lyingInstance (parameters, ObjectCategory::DISC, max_tilt);
  for (std::size_t view = 0; view < 3; ++view) {
    const ObjectView seen =
        renderObjectView (parameters, ObjectCategory::RING, ring.instance, view);
    // No ray near the centre meets the ring; the ring is seen around it.
    EXPECT_GT (closestRayToCentre (seen), 0.5 * ring.hole_radius);
    EXPECT_GT (seen.cloud->size(), 500u);
    // A disc as large is seen right through its centre.
    const ObjectView solid =
        renderObjectView (parameters, ObjectCategory::DISC, disc.instance, view);
    EXPECT_LT (closestRayToCentre (solid), 0.005);
  }
}

TEST (ObjectViews, PosesSeeingTooFewPointsAreDrawnAgain)
{
  ObjectViewParameters parameters;
  parameters.categories = {ObjectCategory::RING};
  parameters.views = 20;
  parameters.min_points = 2500;
  std::size_t redrawn = 0;
  for (std::size_t view = 0; view < parameters.views; ++view) {
    const ObjectView seen =
        renderObjectView (parameters, ObjectCategory::RING, 0, view);
    EXPECT_GE (seen.cloud->size(), parameters.min_points);
    redrawn += seen.poses_drawn > 1;
  }
  EXPECT_GT (redrawn, 0u);
  // Far away, no pose sees enough points.
  parameters.min_distance = parameters.max_distance = 10.0f;
  EXPECT_THROW (renderObjectView (parameters, ObjectCategory::RING, 0, 0),
                pcl::BadArgumentException);
}

TEST (ObjectViews, CategoryNames)
{
  const std::vector<std::string> names = pcl::tda::objectCategoryNames();
  ASSERT_EQ (pcl::tda::NUM_OBJECT_CATEGORIES, names.size());
  EXPECT_EQ (names.size(), std::set<std::string> (names.begin(), names.end()).size());
  EXPECT_EQ ("mug", names.front());
  EXPECT_EQ ("bottle", names.back());
  for (const ObjectCategory category : pcl::tda::allObjectCategories()) {
    ObjectCategory parsed = ObjectCategory::BOX;
    ASSERT_TRUE (pcl::tda::parseObjectCategory (pcl::tda::objectCategoryName (category),
                                                parsed));
    EXPECT_EQ (category, parsed);
  }
  ObjectCategory unchanged = ObjectCategory::CONE;
  EXPECT_FALSE (pcl::tda::parseObjectCategory ("Mug", unchanged));
  EXPECT_FALSE (pcl::tda::parseObjectCategory ("", unchanged));
  EXPECT_EQ (ObjectCategory::CONE, unchanged);
}

TEST (ObjectViews, InvalidParametersThrow)
{
  const std::vector<std::function<void (ObjectViewParameters&)>> invalid = {
      [] (ObjectViewParameters& p) { p.categories.clear(); },
      [] (ObjectViewParameters& p) { p.categories.push_back (ObjectCategory::MUG); },
      [] (ObjectViewParameters& p) {
        p.categories.push_back (static_cast<ObjectCategory> (12));
      },
      [] (ObjectViewParameters& p) { p.instances = 0; },
      [] (ObjectViewParameters& p) { p.views = 0; },
      [] (ObjectViewParameters& p) { p.noise_multiplier = -1.0f; },
      [] (ObjectViewParameters& p) { p.noise_multiplier = std::nanf (""); },
      [] (ObjectViewParameters& p) { p.colour_noise = -1.0f; },
      [] (ObjectViewParameters& p) { p.min_distance = 0.2f; },
      [] (ObjectViewParameters& p) { p.min_distance = std::nanf (""); },
      [] (ObjectViewParameters& p) { p.max_distance = 0.5f; },
      [] (ObjectViewParameters& p) { p.max_distance = 11.0f; },
      [] (ObjectViewParameters& p) { p.min_elevation_deg = -1.0f; },
      [] (ObjectViewParameters& p) { p.min_elevation_deg = 80.0f; },
      [] (ObjectViewParameters& p) { p.max_elevation_deg = 90.0f; },
      [] (ObjectViewParameters& p) { p.max_elevation_deg = std::nanf (""); },
      [] (ObjectViewParameters& p) { p.min_points = 0; },
      [] (ObjectViewParameters& p) { p.perturbation = -0.001f; },
      [] (ObjectViewParameters& p) { p.perturbation = 0.2f; },
      [] (ObjectViewParameters& p) { p.perturbation = std::nanf (""); },
  };
  for (std::size_t i = 0; i < invalid.size(); ++i) {
    ObjectViewParameters p;
    invalid[i](p);
    EXPECT_THROW (pcl::tda::checkObjectViewParameters (p), pcl::BadArgumentException)
        << "case " << i;
    EXPECT_THROW (renderObjectView (p, ObjectCategory::MUG, 0, 0),
                  pcl::BadArgumentException)
        << "case " << i;
  }
  // Indices outside the data set.
  ObjectViewParameters p;
  p.categories = {ObjectCategory::MUG, ObjectCategory::CUP};
  EXPECT_NO_THROW (pcl::tda::checkObjectViewParameters (p));
  EXPECT_THROW (renderObjectView (p, ObjectCategory::RING, 0, 0),
                pcl::BadArgumentException);
  EXPECT_THROW (renderObjectView (p, ObjectCategory::MUG, 4, 0),
                pcl::BadArgumentException);
  EXPECT_THROW (renderObjectView (p, ObjectCategory::MUG, 0, 12),
                pcl::BadArgumentException);
  EXPECT_THROW (pcl::tda::drawObjectInstance (p, ObjectCategory::CUP, 4),
                pcl::BadArgumentException);
  EXPECT_THROW (pcl::tda::drawObjectInstance (p, static_cast<ObjectCategory> (40), 0),
                pcl::BadArgumentException);
}
