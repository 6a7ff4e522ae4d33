#include <pcl/common/centroid.h>
#include <pcl/common/point_tests.h>
#include <pcl/tda/apps/cloud_picture.h>
#include <pcl/tda/apps/rgb_image.h>
#include <pcl/exceptions.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pcl {
namespace tda {
namespace {

/** The smallest width and height of an organized cloud drawn as an image (a cloud of
 * one row or column is organized for PCL, but no image). */
constexpr std::size_t MIN_IMAGE_SIDE = 16;

/** The colour a point is drawn in. */
std::array<std::uint8_t, 3>
colorOf (const pcl::PointXYZRGBL& point, PictureColors colors)
{
  if (colors == PictureColors::LABELS)
    return labelColor (point.label);
  return {point.r, point.g, point.b};
}

/** An organized cloud pixel by pixel, each pixel a square of \a scale pixels. */
RGBImage
drawOrganized (const pcl::PointCloud<pcl::PointXYZRGBL>& cloud, PictureColors colors)
{
  const std::size_t scale = std::max<std::size_t> (
      1, std::min ((640 + cloud.width - 1) / cloud.width, 1280 / cloud.height));
  RGBImage picture (cloud.width * scale, cloud.height * scale, {0, 0, 0});
  for (std::size_t v = 0; v < cloud.height; ++v)
    for (std::size_t u = 0; u < cloud.width; ++u) {
      const pcl::PointXYZRGBL& point = cloud.at (u, v);
      if (!pcl::isXYZFinite (point))
        continue;
      const auto color = colorOf (point, colors);
      for (std::size_t dy = 0; dy < scale; ++dy)
        for (std::size_t dx = 0; dx < scale; ++dx)
          picture.set (u * scale + dx, v * scale + dy, color);
    }
  return picture;
}

/** Any cloud, orthographically along its smallest principal axis. */
RGBImage
drawProjected (const pcl::PointCloud<pcl::PointXYZRGBL>& cloud,
               PictureColors colors,
               std::size_t width)
{
  // In double: a float cloud's squared coordinates stay in its range (float's at
  // 1e-25 or 1e20 underflow or overflow).
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::uint8_t, 3>> point_colors;
  for (const auto& point : cloud)
    if (pcl::isXYZFinite (point)) {
      points.push_back (point.getVector3fMap().cast<double>());
      point_colors.push_back (colorOf (point, colors));
    }
  if (points.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "The cloud has no finite point to draw.");
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points)
    mean += p;
  mean /= static_cast<double> (points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points)
    covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
  // Eigenvalues ascending: view along the first axis, draw the other two.
  Eigen::Vector3d view = solver.eigenvectors().col (0);
  const Eigen::Vector3d sensor = cloud.sensor_origin_.head<3>().cast<double>();
  if (view.dot (sensor - mean) > 0.0)
    view = -view; // looking from the sensor's side
  const Eigen::Vector3d across = solver.eigenvectors().col (2);
  const Eigen::Vector3d up = view.cross (across);
  double min_x = std::numeric_limits<double>::max(), max_x = -min_x;
  double min_y = min_x, max_y = -min_x;
  for (const auto& p : points) {
    const Eigen::Vector3d d = p - mean;
    min_x = std::min (min_x, d.dot (across));
    max_x = std::max (max_x, d.dot (across));
    min_y = std::min (min_y, d.dot (up));
    max_y = std::max (max_y, d.dot (up));
  }
  // The width spans the larger of the two extents (the axis of most variance need
  // not have the larger one); points all alike make a picture one pixel high.
  const double extent = std::max (max_x - min_x, max_y - min_y);
  const double pixel = extent > 0.0 ? extent / static_cast<double> (width - 1) : 1.0;
  const auto height = std::min (
      width, static_cast<std::size_t> (std::ceil ((max_y - min_y) / pixel)) + 1);
  RGBImage picture (width, height, {255, 255, 255});
  std::vector<double> depth (width * height, std::numeric_limits<double>::max());
  const int splat = static_cast<int> (std::max<std::size_t> (1, width / 400));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d d = points[i] - mean;
    const int x = static_cast<int> (std::lround ((d.dot (across) - min_x) / pixel));
    const int y = static_cast<int> (std::lround ((max_y - d.dot (up)) / pixel));
    const double z = d.dot (view);
    for (int dy = -splat; dy <= splat; ++dy)
      for (int dx = -splat; dx <= splat; ++dx) {
        const int px = x + dx, py = y + dy;
        if (px < 0 || py < 0 || px >= static_cast<int> (width) ||
            py >= static_cast<int> (height))
          continue;
        double& nearest = depth[py * width + px];
        if (z < nearest) {
          nearest = z;
          picture.set (px, py, point_colors[i]);
        }
      }
  }
  return picture;
}

} // namespace

std::array<std::uint8_t, 3>
labelColor (std::size_t label)
{
  static const std::array<std::array<std::uint8_t, 3>, 12> PALETTE{{{230, 25, 75},
                                                                    {60, 180, 75},
                                                                    {0, 130, 200},
                                                                    {245, 130, 48},
                                                                    {145, 30, 180},
                                                                    {70, 240, 240},
                                                                    {240, 50, 230},
                                                                    {210, 245, 60},
                                                                    {250, 190, 212},
                                                                    {0, 128, 128},
                                                                    {170, 110, 40},
                                                                    {128, 0, 0}}};
  if (label == 0)
    return {128, 128, 128};
  return PALETTE[(label - 1) % PALETTE.size()];
}

void
saveCloudPicture (const std::string& path,
                  const pcl::PointCloud<pcl::PointXYZRGBL>& cloud,
                  const std::vector<PictureColors>& panels,
                  std::size_t width)
{
  // The panels side by side, 8 pixels apart, each drawn the same way.
  constexpr std::size_t GAP = 8;
  std::vector<RGBImage> drawn;
  for (const PictureColors colors : panels)
    drawn.push_back (cloud.width >= MIN_IMAGE_SIDE && cloud.height >= MIN_IMAGE_SIDE
                         ? drawOrganized (cloud, colors)
                         : drawProjected (cloud, colors, width));
  if (drawn.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "A picture needs a panel.");
  const std::size_t panel_width = drawn.front().width();
  RGBImage picture (drawn.size() * (panel_width + GAP) - GAP,
                    drawn.front().height(),
                    {255, 255, 255});
  for (std::size_t k = 0; k < drawn.size(); ++k)
    picture.paste (drawn[k], static_cast<long> (k * (panel_width + GAP)), 0);
  picture.savePNG (path);
}

} // namespace tda
} // namespace pcl
