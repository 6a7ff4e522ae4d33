#pragma once

// The simulated structured-light depth camera of the ray-cast generators (depth
// camera scenes, object views): a pinhole camera that looks at the origin without
// roll, one ray per pixel, dropouts at grazing angles, Gaussian depth noise growing
// with z^2, disparity quantization, colours shaded by the angle of incidence with
// colour noise; and the sphere tracing of solids given by a signed distance bound.
// Internal to pcl_tda_generators.

#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/random_sampling.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace pcl {
namespace tda {

/** \brief Sphere tracing: a ray hits a surface when its distance bound falls below
 * DEPTH_HIT_EPSILON (metres); rays that take more than DEPTH_MAX_TRACE_STEPS steps
 * pass by (silhouettes). */
constexpr double DEPTH_HIT_EPSILON = 1e-5;
constexpr int DEPTH_MAX_TRACE_STEPS = 500;
/** \brief Step of the central differences that give surface normals, in metres. */
constexpr double DEPTH_NORMAL_STEP = 1e-6;

/** \brief The intrinsics and the measurement model of the camera, as
 * DepthCameraParameters documents them. */
struct DepthSensorModel {
  std::size_t width = 0, height = 0;
  float fx = 0.0f, fy = 0.0f, cx = 0.0f, cy = 0.0f;
  /** Depth noise sigma noise_coefficient * z^2, in 1/m. */
  float noise_coefficient = 0.0f;
  /** Camera to projector along the camera's x axis, in metres. */
  float baseline = 0.0f;
  /** Disparity quantization step in pixels; 0: none. */
  float disparity_step = 0.0f;
  float grazing_start_deg = 0.0f, grazing_full_deg = 0.0f;
};

/** \brief The sensor model of the depth camera scenes' parameters (their defaults:
 * the Kinect-like camera, 640 x 480 pixels, fx = fy = 525). */
DepthSensorModel
depthSensorModel (const DepthCameraParameters& parameters);

/** \brief A camera looking at the origin without roll. */
struct CameraPose {
  /** Camera centre, scene frame. */
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /** Columns: the optical frame's x (right, horizontal), y (down) and z (forward)
   * axes in the scene frame. */
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  /** Distance to the origin in metres; azimuth about the z axis and elevation above
   * the plane z = 0 of the camera centre, in radians. */
  double distance = 0.0, azimuth = 0.0, elevation = 0.0;
};

/** \brief The camera at \a distance from the origin in the direction of
 * (\a azimuth, \a elevation), looking at the origin without roll. */
CameraPose
lookAtOrigin (double distance, double azimuth, double elevation);

/** \brief Draws, in this order, an azimuth uniform in [0, 2 pi), an elevation
 * uniform in [min_elevation_deg, max_elevation_deg] degrees and a distance uniform
 * in [min_distance, max_distance], and gives lookAtOrigin() of them. */
CameraPose
drawCameraPose (PortableRandom& random,
                double min_distance,
                double max_distance,
                double min_elevation_deg,
                double max_elevation_deg);

/** \brief The projector's centre: \a baseline metres along the camera's x axis. */
Eigen::Vector3d
projectorPosition (const DepthSensorModel& sensor, const CameraPose& pose);

/** \brief The pixels u_begin <= u < u_end, v_begin <= v < v_end. */
struct PixelWindow {
  std::size_t u_begin = 0, u_end = 0, v_begin = 0, v_end = 0;
};

/** \brief Every pixel of the image. */
PixelWindow
fullFrame (const DepthSensorModel& sensor);

/** \brief The pixels whose rays may pass within the angle \a half_angle (radians,
 * below pi / 2) of the optical axis, e.g. those that may see a sphere centred on the
 * axis. */
PixelWindow
axisWindow (const DepthSensorModel& sensor, double half_angle);

/** \brief The surface that a pixel's ray meets first. */
struct RayHit {
  /** The point hit, scene frame. */
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  /** Outward unit normal there. */
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  /** Which solid it is on (scene's own numbering). */
  int solid = -1;
};

/** \brief One measured pixel. */
struct DepthPixel {
  std::size_t u = 0, v = 0;
  RayHit hit;
  /** Cosine of the angle between the ray and the surface normal. */
  double cos_incidence = 1.0;
  /** The measured point, in the camera's optical frame (the noisy, quantized depth
   * along the pixel's ray), in metres. */
  Eigen::Vector3d measured = Eigen::Vector3d::Zero();
};

/** \brief Finds what the ray from the camera centre in the unit \a direction (scene
 * frame) meets first; false when it meets nothing or the point is not lit. */
using RayIntersection =
    std::function<bool (const Eigen::Vector3d& direction, RayHit& hit)>;

/** \brief Casts one ray through the centre of every pixel of \a window (row by row)
 * and hands each pixel measured to \a measure: as DepthCameraParameters documents,
 * a ray that \a intersect says meets a lit surface is lost with a probability
 * rising linearly from 0 to 1 as the angle of incidence goes from
 * grazing_start_deg to grazing_full_deg (one uniform draw of \a random, only past
 * grazing_start_deg), else its depth gets truncated Gaussian noise (drawn from
 * \a random) and is quantized in disparity. */
void
castDepthRays (const DepthSensorModel& sensor,
               const CameraPose& pose,
               const PixelWindow& window,
               PortableRandom& random,
               const RayIntersection& intersect,
               const std::function<void (const DepthPixel& pixel)>& measure);

/** \brief The ray from a surface point towards the projector, to test whether the
 * point is in a shadow: it starts a little off the surface. */
struct ShadowRay {
  Eigen::Vector3d origin;
  /** Unit direction. */
  Eigen::Vector3d direction;
  /** Distance to the projector. */
  double length;
};

/** \brief The ray from \a hit towards \a projector. */
ShadowRay
shadowRay (const RayHit& hit, const Eigen::Vector3d& projector);

/** \brief Sphere tracing of the ray origin + t * direction (unit direction),
 * 0 <= t < t_hit, on the solid of signed distance bound \a distance inside its
 * bounding sphere (\a centre, \a radius): true, with t_hit set to the hit, when it
 * meets the solid. */
template <typename Distance>
bool
sphereTrace (const Distance& distance,
             const Eigen::Vector3d& centre,
             double radius,
             const Eigen::Vector3d& origin,
             const Eigen::Vector3d& direction,
             double& t_hit)
{
  const Eigen::Vector3d offset = origin - centre;
  const double b = offset.dot (direction);
  const double discriminant = b * b - offset.squaredNorm() + radius * radius;
  if (discriminant <= 0.0)
    return false;
  const double root = std::sqrt (discriminant);
  const double end = std::min (-b + root, t_hit);
  double t = std::max (-b - root, 0.0);
  for (int step = 0; step < DEPTH_MAX_TRACE_STEPS && t < end; ++step) {
    const double d = distance (origin + t * direction);
    if (d < DEPTH_HIT_EPSILON) {
      t_hit = t;
      return true;
    }
    t += d;
  }
  return false;
}

/** \brief The outward unit normal at a surface point \a p of the solid of signed
 * distance \a distance, by central differences. */
template <typename Distance>
Eigen::Vector3d
distanceNormal (const Distance& distance, const Eigen::Vector3d& p)
{
  Eigen::Vector3d gradient;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d step = DEPTH_NORMAL_STEP * Eigen::Vector3d::Unit (k);
    gradient[k] = distance (p + step) - distance (p - step);
  }
  return gradient.normalized();
}

/** \brief A colour channel as the camera sees it: ambient light plus light
 * proportional to the cosine of the angle of incidence. */
std::uint8_t
shade (std::uint8_t value, double cos_incidence);

/** \brief Adds colour noise to a point's colour: an offset common to the three
 * channels of standard deviation \a sigma plus one per channel of half of it, both
 * Gaussian truncated at NOISE_TRUNCATION standard deviations, drawn from \a random
 * in this order (brightness, r, g, b); rounded and clamped to 0-255. */
template <typename PointT>
void
addColourNoise (PointT& point, double sigma, PortableRandom& random)
{
  const auto add = [] (std::uint8_t value, double offset) {
    return static_cast<std::uint8_t> (
        std::clamp (std::lround (value + offset), 0L, 255L));
  };
  const double brightness = random.truncatedNormal (sigma, NOISE_TRUNCATION);
  point.r = add (point.r,
                 brightness + random.truncatedNormal (0.5 * sigma, NOISE_TRUNCATION));
  point.g = add (point.g,
                 brightness + random.truncatedNormal (0.5 * sigma, NOISE_TRUNCATION));
  point.b = add (point.b,
                 brightness + random.truncatedNormal (0.5 * sigma, NOISE_TRUNCATION));
}

} // namespace tda
} // namespace pcl
