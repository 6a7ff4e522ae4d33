#include "depth_camera.h"

namespace pcl {
namespace tda {
namespace {

/** Shadow rays start this far off the surface, in metres. */
constexpr double SHADOW_OFFSET = 1e-4;
/** Shading of the colours: ambient part and part proportional to cos(incidence). */
constexpr double AMBIENT = 0.35, DIFFUSE = 0.65;

} // namespace

DepthSensorModel
depthSensorModel (const DepthCameraParameters& parameters)
{
  DepthSensorModel sensor;
  sensor.width = parameters.width;
  sensor.height = parameters.height;
  sensor.fx = parameters.fx;
  sensor.fy = parameters.fy;
  sensor.cx = parameters.cx;
  sensor.cy = parameters.cy;
  sensor.noise_coefficient = parameters.noise_coefficient;
  sensor.baseline = parameters.baseline;
  sensor.disparity_step = parameters.disparity_step;
  sensor.grazing_start_deg = parameters.grazing_start_deg;
  sensor.grazing_full_deg = parameters.grazing_full_deg;
  return sensor;
}

CameraPose
lookAtOrigin (double distance, double azimuth, double elevation)
{
  CameraPose pose;
  pose.distance = distance;
  pose.azimuth = azimuth;
  pose.elevation = elevation;
  pose.position = distance * Eigen::Vector3d (std::cos (elevation) * std::cos (azimuth),
                                              std::cos (elevation) * std::sin (azimuth),
                                              std::sin (elevation));
  const Eigen::Vector3d forward = -pose.position.normalized();
  const Eigen::Vector3d right = forward.cross (Eigen::Vector3d::UnitZ()).normalized();
  pose.rotation << right, forward.cross (right), forward;
  return pose;
}

CameraPose
drawCameraPose (PortableRandom& random,
                double min_distance,
                double max_distance,
                double min_elevation_deg,
                double max_elevation_deg)
{
  const double azimuth = random.uniform (0.0, 2.0 * M_PI);
  const double elevation =
      random.uniform (min_elevation_deg, max_elevation_deg) * M_PI / 180.0;
  const double distance = random.uniform (min_distance, max_distance);
  return lookAtOrigin (distance, azimuth, elevation);
}

Eigen::Vector3d
projectorPosition (const DepthSensorModel& sensor, const CameraPose& pose)
{
  return pose.position + static_cast<double> (sensor.baseline) * pose.rotation.col (0);
}

PixelWindow
fullFrame (const DepthSensorModel& sensor)
{
  return {0, sensor.width, 0, sensor.height};
}

PixelWindow
axisWindow (const DepthSensorModel& sensor, double half_angle)
{
  const double spread = std::tan (half_angle);
  // Pixel u's ray is (u - cx) / fx off the axis (and likewise for v); one pixel of
  // margin against rounding.
  const auto range = [spread] (double centre, double focal, std::size_t side) {
    const double low = std::floor (centre - focal * spread) - 1.0;
    const double high = std::ceil (centre + focal * spread) + 2.0;
    const double last = static_cast<double> (side);
    return std::make_pair (static_cast<std::size_t> (std::clamp (low, 0.0, last)),
                           static_cast<std::size_t> (std::clamp (high, 0.0, last)));
  };
  const auto [u_begin, u_end] = range (sensor.cx, sensor.fx, sensor.width);
  const auto [v_begin, v_end] = range (sensor.cy, sensor.fy, sensor.height);
  return {u_begin, u_end, v_begin, v_end};
}

void
castDepthRays (const DepthSensorModel& sensor,
               const CameraPose& pose,
               const PixelWindow& window,
               PortableRandom& random,
               const RayIntersection& intersect,
               const std::function<void (const DepthPixel& pixel)>& measure)
{
  const Eigen::Vector3d forward = pose.rotation.col (2);
  const double focal_baseline = static_cast<double> (sensor.fx) * sensor.baseline;
  DepthPixel pixel;
  for (std::size_t v = window.v_begin; v < window.v_end; ++v)
    for (std::size_t u = window.u_begin; u < window.u_end; ++u) {
      const Eigen::Vector3d pixel_ray (
          (static_cast<double> (u) - sensor.cx) / sensor.fx,
          (static_cast<double> (v) - sensor.cy) / sensor.fy,
          1.0);
      const Eigen::Vector3d direction = (pose.rotation * pixel_ray).normalized();
      if (!intersect (direction, pixel.hit))
        continue;
      const double cos_incidence =
          std::min (std::abs (pixel.hit.normal.dot (direction)), 1.0);
      const double incidence = std::acos (cos_incidence) * 180.0 / M_PI;
      if (incidence >= sensor.grazing_full_deg ||
          (incidence > sensor.grazing_start_deg &&
           random.uniform() * (sensor.grazing_full_deg - sensor.grazing_start_deg) <
               incidence - sensor.grazing_start_deg))
        continue;

      const double depth = (pixel.hit.point - pose.position).dot (forward);
      double measured =
          depth + random.truncatedNormal (sensor.noise_coefficient * depth * depth,
                                          NOISE_TRUNCATION);
      if (!(measured > 0.0))
        continue;
      if (sensor.disparity_step > 0.0f) {
        const double steps =
            std::round (focal_baseline / measured / sensor.disparity_step);
        measured = focal_baseline / (std::max (steps, 1.0) * sensor.disparity_step);
      }
      pixel.u = u;
      pixel.v = v;
      pixel.cos_incidence = cos_incidence;
      pixel.measured = measured * pixel_ray;
      measure (pixel);
    }
}

ShadowRay
shadowRay (const RayHit& hit, const Eigen::Vector3d& projector)
{
  ShadowRay ray;
  ray.origin = hit.point + SHADOW_OFFSET * hit.normal;
  const Eigen::Vector3d to_projector = projector - ray.origin;
  ray.length = to_projector.norm();
  ray.direction = to_projector / ray.length;
  return ray;
}

std::uint8_t
shade (std::uint8_t value, double cos_incidence)
{
  return static_cast<std::uint8_t> (
      std::lround (value * (AMBIENT + DIFFUSE * cos_incidence)));
}

} // namespace tda
} // namespace pcl
