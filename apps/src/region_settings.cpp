#include <pcl/tda/apps/region_settings.h>
#include <pcl/tda/search/point_spacing.h>

namespace pcl {
namespace tda {

double
regionRadius (const RegionSettings& settings,
              const pcl::PointCloud<pcl::PointXYZRGB>& cloud)
{
  if (settings.radius > 0.0)
    return settings.radius;
  return RegionSettings::RADIUS_PER_SPACING *
         pointSpacing (
             cloud, RegionSettings::SPACING_QUANTILE, RegionSettings::SPACING_NEIGHBOR);
}

void
configureRegionGrowing (ToolRegionGrowing& growing,
                        const RegionSettings& settings,
                        double radius,
                        const pcl::PointCloud<pcl::Normal>::ConstPtr& normals)
{
  growing.setMaxDistance (radius);
  growing.setMinNeighbors (RegionSettings::MIN_NEIGHBORS);
  growing.setImageNeighborRatio (settings.image_ratio);
  growing.setColorThreshold (settings.point_color);
  growing.setAutoColorThreshold (settings.region_color == 0.0);
  growing.setRegionColorThreshold (settings.region_color == 0.0
                                       ? RegionSettings::MAX_AUTO_COLOR_THRESHOLD
                                       : settings.region_color);
  growing.setInputNormals (normals);
  growing.setEstimateNormals (settings.use_normals);
  growing.setNormalAngleThreshold (settings.angle);
  growing.setMinClusterSize (settings.min_size);
}

} // namespace tda
} // namespace pcl
