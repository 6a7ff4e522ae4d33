#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The colour of label \a label in the tools' pictures and labelled clouds:
 * grey for 0 (no cluster or region), then twelve well-separated colours in turn. */
std::array<std::uint8_t, 3>
labelColor (std::size_t label);

/** \brief What a picture of a cloud colours its points by. */
enum class PictureColors {
  /** The colour of the point's label (labelColor()). */
  LABELS,
  /** The point's own colour. */
  POINTS
};

/** \brief Draws a labelled cloud as a PNG picture of one or more panels side by
 * side, e.g. the points in their own colours and in the colours of their labels
 * (labelColor()), atomically. An organized cloud (at least 16 x 16) is
 * drawn pixel by pixel, as its sensor saw it (non-finite points black), scaled up
 * towards 640 pixels wide; any other cloud is seen orthographically along its axis of
 * least extent (the smallest principal axis), from the side of its sensor origin,
 * nearer points drawn over farther ones, \a width pixels wide on a white background.
 * \throws pcl::IOException when the file cannot be written
 * \throws pcl::BadArgumentException when the cloud has no finite point */
void
saveCloudPicture (const std::string& path,
                  const pcl::PointCloud<pcl::PointXYZRGBL>& cloud,
                  const std::vector<PictureColors>& panels,
                  std::size_t width = 640);

} // namespace tda
} // namespace pcl
